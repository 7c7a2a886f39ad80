// Where a triangle soup fails to be an oriented 2-manifold (geometry/manifold_defects), on small
// soups whose every defect is known: the counts, and the vertices and triangles flagged.
#include <gtest/gtest.h>

#include <vector>

#include "geometry/manifold_defects.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

std::vector<std::size_t> flagged(const std::vector<bool>& flags) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) out.push_back(i);
  return out;
}

TEST(ManifoldDefects, AClosedSurfaceHasNone) {
  const TriangleMesh sphere = testing::icosphere(2);
  const ManifoldDefects d =
      find_manifold_defects(sphere.vertices.size(), sphere.triangles, {}, true);
  EXPECT_EQ(d.nonmanifold_edges, 0u);
  EXPECT_EQ(d.nonmanifold_vertices, 0u);
  EXPECT_EQ(d.folded_edges, 0u);
  EXPECT_EQ(d.stray_boundary_edges, 0u);
  EXPECT_TRUE(flagged(d.triangle).empty());
  EXPECT_TRUE(flagged(d.vertex).empty());
}

TEST(ManifoldDefects, TwoFansAtAVertexAreOneNonManifoldVertex) {
  // Two fans of two triangles each around vertex 0, touching only there (a bow tie), listed in
  // an order that interleaves them; vertex 9 is unused. Each fan is flagged by one triangle of it.
  const std::vector<Triangle> tris = {{0, 1, 2}, {0, 5, 6}, {0, 2, 3}, {0, 6, 7}};
  const ManifoldDefects d = find_manifold_defects(10, tris, {}, true);
  EXPECT_EQ(d.nonmanifold_vertices, 1u);
  EXPECT_EQ(d.nonmanifold_edges, 0u);
  EXPECT_EQ(flagged(d.vertex), std::vector<std::size_t>{0});
  const std::vector<std::size_t> t = flagged(d.triangle);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_TRUE(t[0] == 0 || t[0] == 2) << t[0];  // one of the first fan
  EXPECT_TRUE(t[1] == 1 || t[1] == 3) << t[1];  // one of the second
  // A vertex whose fans may branch (a non-manifold input's) is no defect.
  std::vector<bool> may_branch(10, false);
  may_branch[0] = true;
  EXPECT_EQ(find_manifold_defects(10, tris, {}, true, may_branch).nonmanifold_vertices, 0u);
}

TEST(ManifoldDefects, EdgesOfThreeTrianglesFoldsAndStrayBoundaries) {
  // Edge (0, 1) in three triangles; edge (4, 5) used the same way by two (a fold).
  const std::vector<Triangle> tris = {{0, 1, 2}, {1, 0, 3}, {0, 1, 7}, {4, 5, 6}, {4, 5, 8}};
  const ManifoldDefects d = find_manifold_defects(9, tris, {}, true);
  EXPECT_EQ(d.nonmanifold_edges, 1u);
  EXPECT_EQ(d.folded_edges, 1u);
  EXPECT_EQ(flagged(d.vertex), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(flagged(d.triangle), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  // Without folds as defects (a non-orientable surface's), the two are fine.
  EXPECT_EQ(find_manifold_defects(9, tris, {}, false).folded_edges, 0u);
  // Boundary edges where none may end: every edge of one triangle, here.
  const std::vector<Triangle> one = {{0, 1, 2}};
  EXPECT_EQ(find_manifold_defects(3, one, std::vector<bool>(3, false), true).stray_boundary_edges,
            3u);
  EXPECT_EQ(find_manifold_defects(3, one, std::vector<bool>(3, true), true).stray_boundary_edges,
            0u);
}

}  // namespace
}  // namespace cvtmesh
