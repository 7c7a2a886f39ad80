// Spatial sorting of the input (issue 19): the sorted mesh is the same surface, in an order of
// its own that a shuffled copy shares, and the remesher's output does not depend on the order
// the input comes in.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvtmesh/features.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(SpatiallySorted, IsTheSameSurfaceRenumbered) {
  const TriangleMesh mesh = torus(1, 0.4, 40, 16);
  const SpatiallySorted sorted = spatially_sorted(mesh);
  ASSERT_EQ(sorted.mesh.vertices.size(), mesh.vertices.size());
  ASSERT_EQ(sorted.mesh.triangles.size(), mesh.triangles.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    EXPECT_EQ(sorted.mesh.vertices[sorted.new_id[v]], mesh.vertices[v]);
  // Every triangle is there, with its orientation: the same cyclic order of new ids.
  auto canonical = [](Triangle t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::vector<Triangle> expected;
  for (Triangle t : mesh.triangles) {
    for (Index& v : t) v = sorted.new_id[v];
    expected.push_back(canonical(t));
  }
  std::vector<Triangle> got = sorted.mesh.triangles;
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
  EXPECT_NEAR(surface_area(sorted.mesh), surface_area(mesh), 1e-12 * surface_area(mesh));
  EXPECT_TRUE(analyze_topology(sorted.mesh).consistently_oriented);
}

TEST(SpatiallySorted, NeighboursInTheOrderAreNeighboursInSpace) {
  // A shuffled torus: consecutive vertex ids are far apart; sorted, they are close.
  const TriangleMesh mixed = shuffled(torus(1, 0.4, 120, 48), 3);
  auto mean_step = [](const TriangleMesh& m) {
    double sum = 0;
    for (std::size_t v = 1; v < m.vertices.size(); ++v)
      sum += distance(m.vertices[v - 1], m.vertices[v]);
    return sum / static_cast<double>(m.vertices.size() - 1);
  };
  EXPECT_LT(mean_step(spatially_sorted(mixed).mesh), 0.1 * mean_step(mixed));
}

TEST(SpatiallySorted, DoesNotDependOnTheGivenOrder) {
  const TriangleMesh mesh = torus(1, 0.4, 40, 16);
  const TriangleMesh a = spatially_sorted(mesh).mesh;
  const TriangleMesh b = spatially_sorted(shuffled(mesh, 11)).mesh;
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(SpatiallySorted, TiesAreBrokenAlikeWhateverTheGivenOrder) {
  // Equal Morton keys: mirrored copies of triangles (the same centroid), and vertices a
  // millionth of a key cell from others (2^-21 of the extent). A sort that kept such ties in the
  // order given would tell the copies apart.
  TriangleMesh mesh = torus(1, 0.4, 40, 16);
  const std::size_t triangles = mesh.triangles.size(), vertices = mesh.vertices.size();
  for (std::size_t t = 0; t < triangles; t += 7) {
    const Triangle& f = mesh.triangles[t];
    mesh.triangles.push_back({f[0], f[2], f[1]});
  }
  for (std::size_t v = 0; v < vertices; v += 5)
    mesh.vertices.push_back(mesh.vertices[v] + Vec3{1e-12, 0, 0});
  const TriangleMesh expected = spatially_sorted(mesh).mesh;
  // The mirrored copies sit next to their originals, in one order.
  std::size_t pairs = 0;
  for (std::size_t t = 1; t < expected.triangles.size(); ++t) {
    Triangle a = expected.triangles[t - 1], b = expected.triangles[t];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    pairs += a == b;
  }
  EXPECT_EQ(pairs, (triangles + 6) / 7);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TriangleMesh got = spatially_sorted(shuffled(mesh, seed)).mesh;
    EXPECT_EQ(got.vertices, expected.vertices) << "seed " << seed;
    EXPECT_EQ(got.triangles, expected.triangles) << "seed " << seed;
  }
}

TEST(RemeshInputOrder, AShuffledInputGivesTheSameOutput) {
  const TriangleMesh mesh = torus(1, 0.4, 60, 24);
  RemeshSettings s;
  s.vertices = 400;
  const RemeshResult a = remesh(mesh, s), b = remesh(shuffled(mesh, 5), s);
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

TEST(RemeshInputOrder, FeaturesAreReportedInTheCallersVertexIds) {
  // A cube's 12 creases, from a shuffled copy: reported in the shuffled copy's ids, they are
  // the original's edges under that renumbering.
  const TriangleMesh mesh = cube(4);
  std::vector<Index> new_id;
  const TriangleMesh mixed = shuffled(mesh, 9, &new_id);
  RemeshSettings s;
  s.vertices = 300;
  const RemeshResult r = remesh(mixed, s);
  const Features original = detect_features(mesh, {});
  ASSERT_FALSE(original.edges.empty());
  std::vector<Edge> expected;
  for (const Edge& e : original.edges)
    expected.push_back(
        {std::min(new_id[e[0]], new_id[e[1]]), std::max(new_id[e[0]], new_id[e[1]])});
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(r.features.edges, expected);
  std::vector<Index> corners;
  for (const Index c : original.corners) corners.push_back(new_id[c]);
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(r.features.corners, corners);
}

}  // namespace
}  // namespace cvtmesh
