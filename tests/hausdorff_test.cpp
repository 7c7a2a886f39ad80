// Hausdorff distance on surfaces whose distance is known in closed form.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "cvtmesh/hausdorff.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(Hausdorff, IdenticalSurfacesAreAtDistanceZero) {
  const TriangleMesh s = icosphere(3);
  const HausdorffReport h = hausdorff_distance(s, s, {.samples = 20'000});
  EXPECT_LT(h.max, 1e-12);
  EXPECT_LT(h.mean, 1e-12);
}

TEST(Hausdorff, UnitSphereAgainstSphereScaledByOnePercent) {
  // Vertices of the scaled sphere sit exactly 0.01 from the unit one; every other point lies
  // between 0.01·d and 0.01, d the distance of a face plane to the centre (d > 0.99 here).
  const TriangleMesh unit = icosphere(4), scaled = transformed(unit, 1.01);
  const HausdorffReport h = hausdorff_distance(scaled, unit, {.samples = 50'000});
  EXPECT_NEAR(h.max, 0.01, 1e-9);
  EXPECT_GT(h.mean, 0.0099);
  EXPECT_LE(h.mean, 0.01 + 1e-12);
  EXPECT_GE(h.rms, h.mean);
  EXPECT_NEAR(h.max_pct(), 100 * 0.01 / bounding_box(unit).diagonal(), 1e-7);
  EXPECT_EQ(h.samples_per_surface, 50'000u);
}

// Issue 22: any units. At 2^600 squared distances overflowed and CGAL's exact fallback raised
// SIGFPE; at 2^-600 they underflowed to a NaN percentage. Both meshes are worked on scaled by one
// power of two, exactly, so the figures are the unit ones scaled, bit for bit.
TEST(Hausdorff, AShapeScaledByAPowerOfTwoGivesTheSameDistancesScaled) {
  const TriangleMesh a = transformed(icosphere(3), 1.01, {0.05, 0, 0}), b = icosphere(3);
  const HausdorffReport unit = hausdorff_distance(a, b, {.samples = 3000});
  ASSERT_GT(unit.max, 0.01);
  for (const int k : {-600, -20, 20, 600}) {
    const HausdorffReport h = hausdorff_distance(scaled_by_power_of_two(a, k),
                                                 scaled_by_power_of_two(b, k), {.samples = 3000});
    EXPECT_EQ(h.max, std::ldexp(unit.max, k)) << "2^" << k;
    EXPECT_EQ(h.mean, std::ldexp(unit.mean, k)) << "2^" << k;
    EXPECT_EQ(h.max_pct(), unit.max_pct()) << "2^" << k;
  }
}

TEST(Hausdorff, DisplacedBumpIsSeenFromTheReferenceSide) {
  // A flat disk against the same disk with its centre vertex lifted by 0.3: the one-sided
  // distance from the bumped disk reaches 0.3 at the apex.
  const TriangleMesh flat = disk(4, 12);
  TriangleMesh bumped = flat;
  bumped.vertices[0].z = 0.3;
  const HausdorffReport h = hausdorff_distance(bumped, flat, {.samples = 20'000});
  EXPECT_NEAR(h.a_to_b.max, 0.3, 1e-12);
  EXPECT_LT(h.b_to_a.max, 0.3);
  EXPECT_NEAR(h.max, 0.3, 1e-12);
}

TEST(Hausdorff, FarVertexAmongManyIsFound) {
  // The vertices count for the max only, and most are not searched for (their distance to the
  // previous foot's triangle is within the max so far): one lifted vertex among thousands, in
  // the middle of the list, must still be found, exactly.
  const TriangleMesh flat = disk(60, 64);
  ASSERT_GT(flat.vertices.size(), 3000u);
  TriangleMesh bumped = flat;
  const std::size_t apex = flat.vertices.size() / 2 + 7;
  bumped.vertices[apex].z = 0.125;
  const HausdorffReport h = hausdorff_distance(bumped, flat, {.samples = 100});
  EXPECT_NEAR(h.a_to_b.max, 0.125, 1e-12);
  EXPECT_NEAR(h.max, 0.125, 1e-12);
}

TEST(Hausdorff, MaxAtAnEdgeMiddleIsFound) {
  // A thin triangle at height 2 over a valley z = |x|: along its long edge, on y = 0 from x = -1
  // to 1, the distance to the valley is (2 - |x|)/√2, √2 at the edge's midpoint, 1/√2 at its
  // ends (and at its third vertex). One sample cannot be expected to land there; the midpoint is
  // measured.
  TriangleMesh thin;
  thin.vertices = {{-1, 0, 2}, {1, 0, 2}, {-1, 0.01, 2}};
  thin.triangles = {{0, 1, 2}};
  TriangleMesh valley;
  valley.vertices = {{-2, -1, 2}, {0, -1, 0}, {0, 1, 0}, {-2, 1, 2}, {2, -1, 2}, {2, 1, 2}};
  valley.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  const HausdorffReport h = hausdorff_distance(thin, valley, {.samples = 1});
  EXPECT_NEAR(h.a_to_b.max, std::sqrt(2.0), 1e-12);
  EXPECT_LT(h.a_to_b.mean, std::sqrt(2.0) - 1e-3);  // the one sample, elsewhere
}

TEST(Hausdorff, ResultDoesNotDependOnThreadCount) {
  const TriangleMesh a = icosphere(3), b = transformed(torus(1, 0.4, 32, 16), 1.0, {0.1, 0, 0});
  HausdorffReport one, all;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = hausdorff_distance(a, b, {.samples = 30'000});
  }
  all = hausdorff_distance(a, b, {.samples = 30'000});
  EXPECT_EQ(one.max, all.max);
  EXPECT_EQ(one.mean, all.mean);
  EXPECT_EQ(one.rms, all.rms);
}

TEST(Hausdorff, DifferentSeedsGiveCloseEstimates) {
  const TriangleMesh a = icosphere(3), b = transformed(icosphere(2), 1.05);
  const HausdorffReport x = hausdorff_distance(a, b, {.samples = 40'000, .seed = 1});
  const HausdorffReport y = hausdorff_distance(a, b, {.samples = 40'000, .seed = 2});
  EXPECT_NE(x.mean, y.mean);
  EXPECT_NEAR(x.mean, y.mean, 0.01 * x.mean);
}

}  // namespace
}  // namespace cvtmesh
