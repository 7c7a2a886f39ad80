// Edges of no length (finish/coincident_edges): collapsed where the topology stays, so that no
// triangle of no area is left; nothing else moves.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvtmesh/topology.hpp"
#include "finish/coincident_edges.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// The two triangles of `mesh` at edge a-b, the one with a -> b first.
std::array<Index, 2> triangles_at(const TriangleMesh& mesh, Index a, Index b) {
  std::array<Index, 2> found{};
  for (Index t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index u = mesh.triangles[t][k], v = mesh.triangles[t][(k + 1) % 3];
      if (u == a && v == b) found[0] = t;
      if (u == b && v == a) found[1] = t;
    }
  return found;
}

Index opposite(const Triangle& t, Index a, Index b) {
  return *std::ranges::find_if(t, [&](Index v) { return v != a && v != b; });
}

// A sphere with edge a-b split at a itself: the new vertex m lies on a, and a-m's two triangles
// have no area. Returns m.
Index split_at_end(TriangleMesh& mesh, Index a, Index b) {
  const auto [ab, ba] = triangles_at(mesh, a, b);
  const Index c = opposite(mesh.triangles[ab], a, b), d = opposite(mesh.triangles[ba], a, b);
  const auto m = static_cast<Index>(mesh.vertices.size());
  mesh.vertices.push_back(mesh.vertices[a]);
  mesh.triangles[ab] = {a, m, c};
  mesh.triangles.push_back({m, b, c});
  mesh.triangles[ba] = {b, m, d};
  mesh.triangles.push_back({m, a, d});
  return m;
}

std::size_t triangles_without_area(const TriangleMesh& mesh) {
  return static_cast<std::size_t>(std::ranges::count_if(mesh.triangles, [&](const Triangle& t) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    return norm(cross(b - a, c - a)) == 0;
  }));
}

// `mesh` a consistently oriented manifold with the topology `before`; its report.
TopologyReport expect_valid_as(const TriangleMesh& mesh, const TopologyReport& before) {
  const TopologyReport after = analyze_topology(mesh);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.consistently_oriented);
  EXPECT_TRUE(same_topology(after, before));
  return after;
}

bool is_edge(const TriangleMesh& mesh, Edge e) {
  return std::ranges::any_of(mesh.triangles, [&](const Triangle& t) {
    return std::ranges::find(t, e[0]) != t.end() && std::ranges::find(t, e[1]) != t.end();
  });
}

TEST(CoincidentEdges, AnEdgeOfNoLengthGoesWithItsTrianglesAndNothingMoves) {
  TriangleMesh m = testing::icosphere(2);
  const Triangle t0 = m.triangles[0];
  const Index a = t0[0], b = t0[1], c = t0[2];
  const Index split = split_at_end(m, a, b);
  ASSERT_EQ(triangles_without_area(m), 2u);
  const TopologyReport before = analyze_topology(m);
  const std::vector<Vec3> points = m.vertices;
  // a on a curve, the split vertex off it: the split vertex goes, the curve stays as it is.
  std::vector<Edge> features{{std::min(a, c), std::max(a, c)}};
  EXPECT_EQ(collapse_coincident_edges(m, features), 1u);
  EXPECT_EQ(triangles_without_area(m), 0u);
  EXPECT_EQ(expect_valid_as(m, before).unreferenced_vertices, 1u);
  EXPECT_EQ(m.vertices, points);
  EXPECT_TRUE(std::ranges::none_of(
      m.triangles, [&](const Triangle& t) { return std::ranges::find(t, split) != t.end(); }));
  ASSERT_EQ(features.size(), 1u);
  EXPECT_TRUE(is_edge(m, features[0]));
}

TEST(CoincidentEdges, BothEndsOnCurvesTheCurveIsRenamed) {
  TriangleMesh m = testing::icosphere(2);
  const Triangle t0 = m.triangles[0];
  const Index a = t0[0], b = t0[1], c = t0[2];
  const Index split = split_at_end(m, a, b);
  // The split vertex (the later) goes into a; its curve edge to b runs from a.
  std::vector<Edge> features{{std::min(a, c), std::max(a, c)},
                             {std::min(split, b), std::max(split, b)}};
  EXPECT_EQ(collapse_coincident_edges(m, features), 1u);
  std::vector<Edge> expected{{std::min(a, c), std::max(a, c)}, {std::min(a, b), std::max(a, b)}};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(features, expected);
  for (const Edge& e : features) EXPECT_TRUE(is_edge(m, e));
}

TEST(CoincidentEdges, AVertexOfThreeTrianglesThatHoldsTheCollapseBackGoesFirst) {
  // As in a fold that lies on itself: a vertex w of three triangles inside the triangle of a, its
  // copy m and c; a-m's common neighbours are then c, w and d, not its two triangles' corners.
  TriangleMesh m = testing::icosphere(2);
  const Triangle t0 = m.triangles[0];
  const Index a = t0[0], b = t0[1], c = t0[2];
  const Index split = split_at_end(m, a, b);
  const auto [amc, unused] = triangles_at(m, a, split);
  const auto w = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(0.5 * (m.vertices[a] + m.vertices[c]) + Vec3{1e-3, 0, 0});
  m.triangles[amc] = {a, split, w};
  m.triangles.push_back({split, c, w});
  m.triangles.push_back({c, a, w});
  const TopologyReport before = analyze_topology(m);
  std::vector<Edge> features;
  EXPECT_EQ(collapse_coincident_edges(m, features), 1u);
  EXPECT_EQ(triangles_without_area(m), 0u);
  EXPECT_EQ(expect_valid_as(m, before).unreferenced_vertices, 2u);
}

TEST(CoincidentEdges, KeptWhereTheTopologyWouldChange) {
  // A tetrahedron with two corners at one point: the collapse would leave two triangles on the
  // same three vertices, and no vertex of three triangles can go first.
  TriangleMesh tet{{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                   {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  const TriangleMesh as_given = tet;
  std::vector<Edge> features;
  EXPECT_EQ(collapse_coincident_edges(tet, features), 0u);
  EXPECT_EQ(tet.triangles, as_given.triangles);
  // Ends that are merely close stay apart: a millionth of an edge is geometry, not rounding.
  TriangleMesh sphere = testing::icosphere(2);
  const Triangle t0 = sphere.triangles[0];
  const Index m = split_at_end(sphere, t0[0], t0[1]);
  sphere.vertices[m] =
      sphere.vertices[m] + 1e-6 * (sphere.vertices[t0[1]] - sphere.vertices[t0[0]]);
  const TriangleMesh sphere_as_given = sphere;
  EXPECT_EQ(collapse_coincident_edges(sphere, features), 0u);
  EXPECT_EQ(sphere.triangles, sphere_as_given.triangles);
}

}  // namespace
}  // namespace cvtmesh
