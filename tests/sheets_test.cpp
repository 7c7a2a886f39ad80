// Non-manifold inputs (issue 18 item 1): where sheets meet along edges of three or more
// triangles, the output has such edges along that junction and nowhere else, and the input's
// topology. Sheets at a shallow angle, remeshed whole, join beside the junction; then each sheet
// is remeshed on its own and the sheets zipped along the junction (remesh/by_component).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

using Segment = std::pair<Vec3, Vec3>;

// The edges of three or more triangles, as segments.
std::vector<Segment> junction_of(const TriangleMesh& mesh) {
  std::map<Edge, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::vector<Segment> segments;
  for (const auto& [e, count] : uses)
    if (count >= 3) segments.push_back({mesh.vertices[e[0]], mesh.vertices[e[1]]});
  return segments;
}

bool on_segments(const Vec3& p, const std::vector<Segment>& segments) {
  return std::ranges::any_of(segments, [&](const Segment& s) {
    const Vec3 d = s.second - s.first;
    const double u = std::clamp(dot(p - s.first, d) / dot(d, d), 0.0, 1.0);
    return distance(p, s.first + u * d) <= 1e-9 * norm(d);
  });
}

// The output keeps the input's topology, and its edges of three or more triangles lie on the
// input's (at least `least` of them).
void expect_junction_kept(const TriangleMesh& in, const RemeshResult& r, std::size_t least) {
  const TopologyReport t = analyze_topology(r.mesh), before = analyze_topology(in);
  EXPECT_TRUE(same_topology(t, before))
      << "components " << t.components << ", Euler characteristic " << t.euler_characteristic
      << ", boundary loops " << t.boundary_loops;
  EXPECT_EQ(t.nonmanifold_vertices, 0u);
  const std::vector<Segment> junction = junction_of(in), out = junction_of(r.mesh);
  EXPECT_GE(out.size(), least);
  std::size_t off = 0;
  for (const Segment& s : out)
    if (!on_segments(s.first, junction) || !on_segments(s.second, junction)) ++off;
  EXPECT_EQ(off, 0u) << "edges of three or more triangles off the input's junction";
}

// icosphere(3) with `count` flaps: at vertices of valence 6 far apart, the triangle (a, v, b)
// over two neighbouring triangles (v, a, c) and (v, c, b) of v's star, glued to the sphere along
// (a, v) and (v, b). Its plane is the chord's: about 5° under the surface.
TriangleMesh sphere_with_flaps(int count) {
  TriangleMesh m = icosphere(3);
  std::vector<Vec3> taken;
  for (Index v = 0; v < m.vertices.size() && static_cast<int>(taken.size()) < count; ++v) {
    std::vector<Triangle> star;  // rotated to start at v
    for (Triangle t : m.triangles)
      if (std::ranges::count(t, v)) {
        std::rotate(t.begin(), std::find(t.begin(), t.end(), v), t.end());
        star.push_back(t);
      }
    if (star.size() != 6 ||
        std::ranges::any_of(taken, [&](const Vec3& p) { return distance(p, m.vertices[v]) < 0.8; }))
      continue;
    const Triangle first = star[0];
    const auto next =
        std::ranges::find_if(star, [&](const Triangle& t) { return t[1] == first[2]; });
    if (next == star.end()) continue;
    m.triangles.push_back({first[1], v, (*next)[2]});
    taken.push_back(m.vertices[v]);
  }
  return m;
}

TEST(Sheets, FlapsAtAShallowAngleComeBackGluedAlongTheirJunctionOnly) {
  const TriangleMesh flaps = sphere_with_flaps(3);
  const TopologyReport in = analyze_topology(flaps);
  ASSERT_EQ(in.nonmanifold_edges, 6u);
  ASSERT_EQ(in.boundary_loops, 3u);
  std::size_t apart = 0;  // runs remeshed sheet by sheet
  for (const std::size_t n : {500u, 1000u, 2000u}) {
    SCOPED_TRACE(n);
    RemeshSettings s;
    s.vertices = n;
    const RemeshResult r = remesh(flaps, s);
    expect_junction_kept(flaps, r, 6);
    EXPECT_TRUE(r.sheets_apart == 0 || r.sheets_apart == 4);  // the sphere and its three flaps
    apart += r.sheets_apart > 0;
  }
  EXPECT_GT(apart, 0u);
}

TEST(Sheets, SliversGluedAlongOneEdgeAreKeptAsTheyAre) {
  // Slivers of about 1e-5 of a vertex's share of the area, each on an edge of a sphere (MeshLab's
  // conrod.stl has three): too small to remesh, each is kept, and the sphere keeps its edge.
  TriangleMesh m = icosphere(3);
  std::vector<Vec3> tips;
  for (const std::size_t i : {0u, 400u, 900u}) {
    const Triangle t = m.triangles[i];
    const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]];
    const auto tip = static_cast<Index>(m.vertices.size());
    tips.push_back(0.5 * (a + b) + 1e-4 * (0.5 * (a + b)));
    m.vertices.push_back(tips.back());
    m.triangles.push_back({t[0], t[1], tip});
  }
  ASSERT_EQ(analyze_topology(m).nonmanifold_edges, 3u);
  RemeshSettings s;
  s.vertices = 1000;
  const RemeshResult r = remesh(m, s);
  expect_junction_kept(m, r, 3);
  EXPECT_EQ(r.sheets_apart, 4u);
  for (const Vec3& tip : tips)
    EXPECT_NE(std::ranges::find(r.mesh.vertices, tip), r.mesh.vertices.end());
}

}  // namespace
}  // namespace cvtmesh
