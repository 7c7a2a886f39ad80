// The local feature size from the poles of a dense sample (paper §4.1), on shapes whose medial
// axis is known, and its grading.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/sizing.hpp"
#include "sizing/gradation.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The graded field is the largest one under the sizes that changes by at most 1/G per unit
// length along every edge: each vertex keeps its size or is tight against a neighbour.
TEST(Gradation, GradedSizesAreTheLargestOnesWithinTheBound) {
  const TriangleMesh m = icosphere(2);
  std::vector<double> size(m.vertices.size());
  for (std::size_t v = 0; v < size.size(); ++v)
    size[v] = 0.05 + 0.5 * std::abs(std::sin(37.0 * static_cast<double>(v)));
  constexpr double kG = 2;
  const EdgeGraph graph(m);
  const std::vector<double> g = graded(graph, size, kG);
  EXPECT_EQ(g, graded(m, size, kG));
  std::vector<bool> tight(m.vertices.size(), false);
  for (std::size_t v = 0; v < g.size(); ++v) {
    EXPECT_LE(g[v], size[v]);
    tight[v] = g[v] == size[v];
  }
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const double step = distance(m.vertices[a], m.vertices[b]) / kG;
      EXPECT_LE(g[a], g[b] + step * (1 + 1e-12));
      EXPECT_LE(g[b], g[a] + step * (1 + 1e-12));
      if (std::abs(g[a] - (g[b] + step)) <= 1e-12) tight[a] = true;
      if (std::abs(g[b] - (g[a] + step)) <= 1e-12) tight[b] = true;
    }
  EXPECT_TRUE(std::all_of(tight.begin(), tight.end(), [](bool x) { return x; }));
  std::size_t lowered = 0;
  for (std::size_t v = 0; v < g.size(); ++v) lowered += g[v] < size[v];
  EXPECT_GT(lowered, g.size() / 4);  // the bound binds: the test grades something
}

LfsSettings raw() {
  LfsSettings s;
  s.gradation = 0;
  return s;
}

TEST(LocalFeatureSize, OfASphereIsItsRadius) {
  // The medial axis of a sphere is its centre.
  for (const double r : {1.0, 0.001}) {
    const TriangleMesh sphere = icosphere(4, r);
    const std::vector<double> lfs = local_feature_size(sphere, raw());
    ASSERT_EQ(lfs.size(), sphere.vertices.size());
    for (const double l : lfs) EXPECT_NEAR(l / r, 1.0, 0.1);
  }
}

TEST(LocalFeatureSize, OfATorusIsItsTubeRadius) {
  // The medial axis of a torus (R > 2r) is its core circle: at distance r from every point,
  // the inner equator included.
  const double R = 1, r = 0.3;
  const TriangleMesh ring = torus(R, r, 96, 32);
  const std::vector<double> lfs = local_feature_size(ring, raw());
  int inner = 0;
  for (Index v = 0; v < ring.vertices.size(); ++v) {
    const Vec3& p = ring.vertices[v];
    if (std::abs(std::hypot(p.x, p.y) - (R - r)) < 1e-9) {
      EXPECT_NEAR(lfs[v] / r, 1.0, 0.1) << "inner equator vertex " << v;
      ++inner;
    }
  }
  EXPECT_EQ(inner, 96);
}

TEST(LocalFeatureSize, OfAThinPlateIsHalfItsThickness) {
  // The box [-1,1]² × [-0.05,0.05]: away from its rim, the medial sheet z = 0 is 0.05 away.
  TriangleMesh plate = cube(16);
  for (Vec3& v : plate.vertices) v.z *= 0.05;
  std::vector<Index> inside;  // vertices of the two large faces, away from the rim
  for (Index v = 0; v < plate.vertices.size(); ++v) {
    const Vec3& p = plate.vertices[v];
    if (std::abs(p.z) == 0.05 && std::max(std::abs(p.x), std::abs(p.y)) < 0.7) inside.push_back(v);
  }
  ASSERT_GT(inside.size(), 50u);
  // Its vertices alone, 0.125 apart across a thickness of 0.1, make poles that see it twice as
  // thick (each the centre of a box of 8 of them, 0.1 away); the ray along each vertex's normal
  // crosses it, and bounds that by half its thickness. So do area samples, which its flat faces
  // allow.
  const std::vector<double> sparse = local_feature_size(plate, raw());
  for (const Index v : inside) EXPECT_NEAR(sparse[v] / 0.05, 1.0, 0.01) << "vertex " << v;
  LfsSettings dense = raw();
  dense.samples = 50'000;
  const std::vector<double> lfs = local_feature_size(plate, dense);
  for (const Index v : inside) EXPECT_NEAR(lfs[v] / 0.05, 1.0, 0.2) << "vertex " << v;
}

TEST(LocalFeatureSize, GradingBoundsTheChangeAlongEdgesAndNeverRaisesASize) {
  TriangleMesh plate = cube(16);
  for (Vec3& v : plate.vertices) v.z *= 0.05;
  const std::vector<double> before = local_feature_size(plate, raw());
  for (const double g : {1.0, 1.5, 4.0}) {
    LfsSettings s;
    s.gradation = g;
    const std::vector<double> after = local_feature_size(plate, s);
    for (Index v = 0; v < after.size(); ++v) EXPECT_LE(after[v], before[v]);
    for (const Triangle& t : plate.triangles)
      for (int k = 0; k < 3; ++k) {
        const Index a = t[k], b = t[(k + 1) % 3];
        const double length = distance(plate.vertices[a], plate.vertices[b]);
        EXPECT_LE(std::abs(after[a] - after[b]), length / g * (1 + 1e-12));
      }
  }
}

TEST(LocalFeatureSize, SameSettingsSameSizesAndBadSettingsAreRefused) {
  const TriangleMesh sphere = icosphere(3);
  EXPECT_EQ(local_feature_size(sphere), local_feature_size(sphere));
  LfsSettings s;
  s.gradation = -1;
  EXPECT_THROW(local_feature_size(sphere, s), InvalidArgument);
  // A flat disk's medial axis is at infinity: its sizes are those of the whole.
  const TriangleMesh plane = disk(4, 12);
  for (const double l : local_feature_size(plane)) EXPECT_EQ(l, bounding_box(plane).diagonal());
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(local_feature_size(flat), InvalidArgument);
}

TEST(LocalFeatureSize, SameSizesOnAnyThreadCount) {
  // The poles are found in parallel and gathered in the triangulation's order.
  const TriangleMesh shape = torus(1.0, 0.3, 48, 24);
  std::vector<double> one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = local_feature_size(shape, raw());
  }
  EXPECT_EQ(local_feature_size(shape, raw()), one);
}

}  // namespace
}  // namespace cvtmesh
