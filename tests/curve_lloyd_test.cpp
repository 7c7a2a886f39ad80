// 1D Lloyd of the curve seeds along their curves, and holding them for the surface relaxation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "features/curve_lloyd.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using Kind = SeedConstraints::Kind;

struct CurveSetup {
  TriangleMesh mesh;
  Features features;
  CurveProjector curves;
  explicit CurveSetup(TriangleMesh m)
      : mesh(std::move(m)), features(detect_features(mesh, {})), curves(mesh, features) {}
};

// Seeds at arc lengths `at` on curve c, then one surface seed and one corner seed, both off it.
std::vector<Vec3> seeds_on(const CurveSetup& s, std::uint32_t c, const std::vector<double>& at,
                           SeedConstraints& constraints) {
  std::vector<Vec3> seeds;
  for (double t : at) {
    seeds.push_back(s.curves.at(c, t));
    constraints.append(Kind::curve, c);
  }
  seeds.push_back({0.1, 0.2, 5});
  constraints.append(Kind::surface);
  seeds.push_back({0.3, 0.1, 5});
  constraints.append(Kind::corner, 0, seeds.back());
  return seeds;
}

std::vector<double> arclengths(const CurveSetup& s, std::uint32_t c, const std::vector<Vec3>& seeds,
                               std::size_t n) {
  std::vector<double> t;
  for (std::size_t k = 0; k < n; ++k) t.push_back(s.curves.nearest(c, seeds[k]).arclength);
  return t;
}

TEST(CurveLloyd, OpenCurveSeedsSpreadEvenlyBetweenItsCornersAndKeepTheirOrder) {
  const CurveSetup s(testing::cube(4));
  ASSERT_FALSE(s.curves.closed(0));
  const double length = s.curves.length(0);
  const std::vector<double> at{0.05 * length, 0.1 * length, 0.15 * length, 0.8 * length};
  SeedConstraints c;
  std::vector<Vec3> seeds = seeds_on(s, 0, at, c);
  const std::vector<Vec3> before = seeds;

  // A few steps: the crowded links lengthen, order kept, every seed still on the curve.
  relax_curve_seeds(seeds, c, s.curves, CurveSpacing(1.0), 3);
  std::vector<double> t = arclengths(s, 0, seeds, at.size());
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
  EXPECT_GT(t[1] - t[0], at[1] - at[0]);
  EXPECT_GT(t[2] - t[1], at[2] - at[1]);
  for (std::size_t k = 0; k < at.size(); ++k)
    EXPECT_LT(norm(s.curves.nearest(0, seeds[k]).point - seeds[k]), 1e-12);

  // To convergence: evenly spaced, the corners at 0 and `length` counting as neighbours.
  relax_curve_seeds(seeds, c, s.curves, CurveSpacing(1.0), 2000);
  t = arclengths(s, 0, seeds, at.size());
  for (std::size_t k = 0; k < at.size(); ++k)
    EXPECT_NEAR(t[k], length * static_cast<double>(k + 1) / (at.size() + 1), 1e-9 * length);
  // Surface and corner seeds do not move.
  EXPECT_EQ(seeds[at.size()], before[at.size()]);
  EXPECT_EQ(seeds[at.size() + 1], before[at.size() + 1]);
}

TEST(CurveLloyd, ASeedOnTopOfACornerMovesOffIt) {
  // CCVT can slide a curve seed to within a hair of its curve's end, onto the corner there: the
  // output then had a 0° triangle (holes.off at 3k). One step moves it a quarter of the way to
  // its neighbour.
  const CurveSetup s(testing::cube(4));
  const double length = s.curves.length(0);
  SeedConstraints c;
  std::vector<Vec3> seeds = seeds_on(s, 0, {1e-15 * length, 0.5 * length}, c);
  relax_curve_seeds(seeds, c, s.curves, CurveSpacing(1.0), 1);
  EXPECT_GT(s.curves.nearest(0, seeds[0]).arclength, 0.12 * length);
}

TEST(CurveLloyd, ClosedCurveSeedsSpreadEvenlyAroundItKeepingTheirMean) {
  const CurveSetup s(testing::cylinder(8, 48));
  ASSERT_TRUE(s.curves.closed(0));
  const double length = s.curves.length(0);
  const std::vector<double> at{0.1 * length, 0.15 * length, 0.2 * length, 0.6 * length,
                               0.9 * length};
  SeedConstraints c;
  std::vector<Vec3> seeds = seeds_on(s, 0, at, c);
  relax_curve_seeds(seeds, c, s.curves, CurveSpacing(1.0), 5000);
  std::vector<double> t = arclengths(s, 0, seeds, at.size());
  // Each step keeps the seeds' mean arc length (the wrap-around neighbours' shifts by ± the
  // length cancel), up to a whole turn for a seed that crossed the curve's start.
  const double shift =
      std::accumulate(t.begin(), t.end(), 0.0) - std::accumulate(at.begin(), at.end(), 0.0);
  EXPECT_NEAR(shift / length, std::round(shift / length), 1e-9);
  // Evenly spaced all round, the gap across the start included.
  std::sort(t.begin(), t.end());
  t.push_back(t.front() + length);
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    EXPECT_NEAR(t[k + 1] - t[k], length / static_cast<double>(at.size()), 1e-9 * length);
}

TEST(CurveLloyd, ALoopWithFewerThanThreeSeedsStaysPut) {
  const CurveSetup s(testing::cylinder(8, 48));
  SeedConstraints c;
  std::vector<Vec3> seeds = seeds_on(s, 1, {0.1, 0.3}, c);
  const std::vector<Vec3> before = seeds;
  relax_curve_seeds(seeds, c, s.curves, CurveSpacing(1.0), 10);
  EXPECT_EQ(seeds, before);
}

TEST(CurveLloyd, HeldCurveSeedsBecomeAnchoredWhereTheyAre) {
  const CurveSetup s(testing::cube(4));
  SeedConstraints c;
  const std::vector<Vec3> seeds = seeds_on(s, 2, {0.3, 0.9}, c);
  const SeedConstraints held = curve_seeds_held(c, seeds);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(held.kind[k], Kind::corner);
    EXPECT_EQ(held.anchor[k], seeds[k]);
  }
  EXPECT_EQ(held.kind[2], Kind::surface);
  EXPECT_EQ(held.kind[3], Kind::corner);
  EXPECT_EQ(held.anchor[3], c.anchor[3]);
}

}  // namespace
}  // namespace cvtmesh
