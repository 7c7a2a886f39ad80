// The local feature size bounded by rays along the normals (sizing/normal_rays): half the
// distance to the first surface point each ray meets, whether it crosses a triangle there or runs
// along one's plane; nothing from a hit at the vertex itself.
#include <gtest/gtest.h>

#include "sizing/normal_rays.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// A unit disk in z = 0 (normal +z; vertex 0 at its centre) and one more triangle, apart.
TriangleMesh disk_and(const std::array<Vec3, 3>& corners) {
  TriangleMesh m = testing::disk(4, 12);
  const auto first = static_cast<Index>(m.vertices.size());
  for (const Vec3& c : corners) m.vertices.push_back(c);
  m.triangles.push_back({first, first + 1, first + 2});
  return m;
}

std::vector<double> bounded(const TriangleMesh& m, double start) {
  std::vector<Vec3> normal(m.vertices.size());  // only the centre casts rays
  normal[0] = {0, 0, 1};
  std::vector<double> lfs(m.vertices.size(), start);
  bound_by_normal_rays(m, normal, lfs);
  return lfs;
}

TEST(NormalRays, AHitAcrossATriangleBoundsAtHalfItsDistance) {
  ASSERT_EQ(testing::disk(4, 12).vertices[0], (Vec3{0, 0, 0}));
  const TriangleMesh m = disk_and({Vec3{-1, -1, 0.6}, Vec3{1, -1, 0.6}, Vec3{0, 1, 0.6}});
  EXPECT_DOUBLE_EQ(bounded(m, 10)[0], 0.3);
  // Within twice the size given, where the hits are looked for.
  EXPECT_DOUBLE_EQ(bounded(m, 0.31)[0], 0.3);
}

TEST(NormalRays, ARayAlongATrianglesPlaneBoundsAtItsNearerEnd) {
  // A wall in the plane x = 0 from z = 0.5 up: the ray from the centre runs along it.
  const TriangleMesh m = disk_and({Vec3{0, -1, 0.5}, Vec3{0, 1, 0.5}, Vec3{0, 0, 1.5}});
  EXPECT_DOUBLE_EQ(bounded(m, 10)[0], 0.25);
}

TEST(NormalRays, AHitAtTheVertexItselfBoundsNothing) {
  // Another sheet's triangle with a corner at the centre (a duplicate vertex kept apart).
  const TriangleMesh m = disk_and({Vec3{0, 0, 0}, Vec3{0, 1, 1}, Vec3{0, -1, 1}});
  EXPECT_DOUBLE_EQ(bounded(m, 10)[0], 10);
}

}  // namespace
}  // namespace cvtmesh
