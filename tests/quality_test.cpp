// Triangle quality and angle figures, checked on triangles whose values are known by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "cvtmesh/quality.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {
namespace {

constexpr double kTol = 1e-12;
const double kDeg = 180 / std::numbers::pi;

TEST(TriangleShape, EquilateralHasQualityOneAndSixtyDegreeAngles) {
  const TriangleShape s = triangle_shape({0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0});
  EXPECT_NEAR(s.quality, 1.0, kTol);
  EXPECT_NEAR(s.min_angle, 60.0, 1e-10);
  EXPECT_NEAR(s.max_angle, 60.0, 1e-10);
}

TEST(TriangleShape, RightIsoscelesMatchesHandComputedValues) {
  // A = 1/2, p = (2 + √2)/2, h = √2: Q = 6/√3 · A/(p·h) = √3/(1 + √2).
  const TriangleShape s = triangle_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(s.quality, std::sqrt(3.0) / (1 + std::sqrt(2.0)), kTol);
  EXPECT_NEAR(s.min_angle, 45.0, 1e-10);
  EXPECT_NEAR(s.max_angle, 90.0, 1e-10);
}

TEST(TriangleShape, SliverMatchesHandComputedValues) {
  // Base 1, apex 0.01 above the base's midpoint.
  const TriangleShape s = triangle_shape({0, 0, 0}, {1, 0, 0}, {0.5, 0.01, 0});
  const double side = std::sqrt(0.25 + 0.0001), p = (1 + 2 * side) / 2;
  EXPECT_NEAR(s.quality, 6 / std::sqrt(3.0) * 0.005 / (p * 1.0), kTol);
  const double base_angle = std::atan(0.01 / 0.5) * kDeg;
  EXPECT_NEAR(s.min_angle, base_angle, 1e-10);
  EXPECT_NEAR(s.max_angle, 180 - 2 * base_angle, 1e-10);
}

TEST(TriangleShape, QualityIsInvariantUnderScalingAndMotion) {
  const TriangleShape a = triangle_shape({0, 0, 0}, {1, 0.2, 0}, {0.3, 0.9, 0.1});
  const TriangleShape b =
      triangle_shape({5, 5, 5}, {5 + 1e3, 5 + 0.2e3, 5}, {5 + 0.3e3, 5 + 0.9e3, 5 + 0.1e3});
  EXPECT_NEAR(a.quality, b.quality, 1e-12);
  EXPECT_NEAR(a.min_angle, b.min_angle, 1e-9);
}

TEST(TriangleShape, AnglesAreTheSmallestAndLargestOfTheThreeInAnyCornerOrder) {
  // Measured only at the corners facing the shortest and the longest edge: checked against all
  // three angles by the law of cosines, on triangles from near-equilateral to needles and caps.
  const std::array<std::array<Vec3, 3>, 5> triangles{{
      {{{0, 0, 0}, {1, 0.2, 0}, {0.3, 0.9, 0.1}}},
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 0.866, 0.001}}},
      {{{0, 0, 0}, {10, 0, 0}, {10.01, 0.02, 0}}},  // needle
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-4, 0}}},     // cap
      {{{1, 2, 3}, {1.5, 2.1, 2.7}, {0.7, 2.9, 3.3}}},
  }};
  for (const auto& t : triangles) {
    const auto angle = [](const Vec3& p, const Vec3& u, const Vec3& v) {
      const long double a2 = dot(u - p, u - p), b2 = dot(v - p, v - p), c2 = dot(u - v, u - v);
      return static_cast<double>(std::acos((a2 + b2 - c2) / (2 * std::sqrt(a2 * b2))) * kDeg);
    };
    const std::array<double, 3> all{angle(t[0], t[1], t[2]), angle(t[1], t[2], t[0]),
                                    angle(t[2], t[0], t[1])};
    for (const auto& [i, j, k] : {std::array{0, 1, 2}, std::array{1, 2, 0}, std::array{2, 0, 1},
                                  std::array{0, 2, 1}, std::array{2, 1, 0}, std::array{1, 0, 2}}) {
      const TriangleShape s = triangle_shape(t[i], t[j], t[k]);
      EXPECT_NEAR(s.min_angle, *std::min_element(all.begin(), all.end()), 1e-5);
      EXPECT_NEAR(s.max_angle, *std::max_element(all.begin(), all.end()), 1e-5);
    }
  }
}

TEST(TriangleShape, DegenerateTrianglesHaveZeroQuality) {
  const TriangleShape collinear = triangle_shape({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
  EXPECT_EQ(collinear.quality, 0.0);
  EXPECT_NEAR(collinear.min_angle, 0.0, 1e-12);
  EXPECT_NEAR(collinear.max_angle, 180.0, 1e-12);
  const TriangleShape repeated = triangle_shape({0, 0, 0}, {0, 0, 0}, {1, 0, 0});
  EXPECT_EQ(repeated.quality, 0.0);
  EXPECT_EQ(repeated.min_angle, 0.0);
  EXPECT_EQ(repeated.max_angle, 180.0);
}

TEST(MinShape, IsExactlyTriangleShapesQualityAndSmallestAngle) {
  // The output's last steps judge changes by min_shape and the report by triangle_shape: the
  // two must agree to the bit, or a change judged better could report worse.
  const std::array<std::array<Vec3, 3>, 6> triangles{{
      {{{0, 0, 0}, {1, 0.2, 0}, {0.3, 0.9, 0.1}}},
      {{{0, 0, 0}, {10, 0, 0}, {10.01, 0.02, 0}}},  // needle
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-4, 0}}},     // cap
      {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}},          // collinear
      {{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}},          // a repeated corner
      {{{1, 2, 3}, {1.5, 2.1, 2.7}, {0.7, 2.9, 3.3}}},
  }};
  for (const auto& [a, b, c] : triangles) {
    const TriangleShape full = triangle_shape(a, b, c);
    const MinShape least = min_shape(a, b, c);
    EXPECT_EQ(least.quality, full.quality);
    EXPECT_EQ(least.min_angle, full.min_angle);
  }
}

TEST(MinShape, IfAboveIsMinShapeWhereQIsAboveTheBarAndNothingElse) {
  // The shape searches reject places by Q before the arctangent: where a shape is returned, it
  // must be min_shape's to the bit, and nothing must be returned only where Q is at the bar or
  // under it (a triangle with a repeated corner has Q 0).
  const std::array<std::array<Vec3, 3>, 5> triangles{{
      {{{0, 0, 0}, {1, 0.2, 0}, {0.3, 0.9, 0.1}}},
      {{{0, 0, 0}, {10, 0, 0}, {10.01, 0.02, 0}}},
      {{{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}}},
      {{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}},
      {{{1, 2, 3}, {1.5, 2.1, 2.7}, {0.7, 2.9, 3.3}}},
  }};
  for (const auto& [a, b, c] : triangles) {
    const MinShape least = min_shape(a, b, c);
    for (const double bar : {-1.0, 0.0, 0.3, least.quality, std::nextafter(least.quality, 0.0)}) {
      const std::optional<MinShape> above = min_shape_if_above(a, b, c, bar);
      ASSERT_EQ(above.has_value(), least.quality > bar) << "bar " << bar;
      if (!above) continue;
      EXPECT_EQ(above->quality, least.quality);
      EXPECT_EQ(above->min_angle, least.min_angle);
    }
  }
}

TEST(MeasureQuality, AggregatesOverTrianglesAndDistinctEdges) {
  // Triangle 0: equilateral (side 2). Triangle 1: right isosceles (legs 1). Triangle 2: sliver.
  TriangleMesh m;
  m.vertices = {{0, 0, 0},  {2, 0, 0},  {1, std::sqrt(3.0), 0}, {10, 0, 0}, {11, 0, 0}, {10, 1, 0},
                {20, 0, 0}, {21, 0, 0}, {20.5, 0.01, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const QualityReport q = measure_quality(m);
  const double q_right = std::sqrt(3.0) / (1 + std::sqrt(2.0));
  const double side = std::sqrt(0.25 + 0.0001);
  const double q_sliver = 6 / std::sqrt(3.0) * 0.005 / ((1 + 2 * side) / 2);
  const double sliver_angle = std::atan(0.01 / 0.5) * kDeg;
  EXPECT_NEAR(q.q_min, q_sliver, kTol);
  EXPECT_NEAR(q.q_avg, (1 + q_right + q_sliver) / 3, kTol);
  EXPECT_NEAR(q.angle_min_deg, sliver_angle, 1e-10);
  EXPECT_NEAR(q.angle_min_avg_deg, (60 + 45 + sliver_angle) / 3, 1e-10);
  EXPECT_NEAR(q.angle_max_deg, 180 - 2 * sliver_angle, 1e-10);
  EXPECT_NEAR(q.pct_angle_below_30, 100.0 / 3, 1e-12);
  const double lengths[] = {2, 2, 2, 1, 1, std::sqrt(2.0), 1, side, side};
  double mean = 0, var = 0;
  for (double l : lengths) mean += l / 9;
  for (double l : lengths) var += (l - mean) * (l - mean) / 9;
  EXPECT_NEAR(q.edge_length_mean, mean, kTol);
  EXPECT_NEAR(q.edge_length_std, std::sqrt(var), kTol);
}

TEST(MeasureQuality, SharedEdgesCountOnce) {
  // Unit square as two triangles: four sides of 1 and one diagonal of √2.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const QualityReport q = measure_quality(m);
  const double mean = (4 + std::sqrt(2.0)) / 5;
  EXPECT_NEAR(q.edge_length_mean, mean, kTol);
  const double var =
      (4 * (1 - mean) * (1 - mean) + (std::sqrt(2.0) - mean) * (std::sqrt(2.0) - mean)) / 5;
  EXPECT_NEAR(q.edge_length_std, std::sqrt(var), kTol);
  EXPECT_EQ(q.pct_angle_below_30, 0.0);
}

// Two separate triangles: a sliver with a 10° angle at the origin, and an equilateral one far
// away. With a narrow input angle of 20° at the origin, the sliver is at it (0.5 × the input
// angle) and the equilateral one is away (60°).
TEST(NarrowAngleQuality, SeparatesTrianglesAtNarrowInputAnglesFromTheRest) {
  const double s = std::sin(10 / kDeg), c = std::cos(10 / kDeg);
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0},  {1, 0, 0},  {c, s, 0},
                   {10, 0, 0}, {11, 0, 0}, {10.5, std::sqrt(0.75), 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const QualityReport quality = measure_quality(mesh);
  const NarrowAngleQuality at = measure_away_from(mesh, quality, {{{0, 0, 0}, 20}});
  EXPECT_EQ(at.narrow_angles, 1u);
  EXPECT_EQ(at.triangles_at, 1u);
  EXPECT_NEAR(at.angle_min_away_deg, 60, 1e-9);
  EXPECT_NEAR(at.q_min_away, 1, 1e-9);
  EXPECT_NEAR(at.ratio_at_min, 0.5, 1e-9);
  // No narrow angle: every triangle is away, and θmin is the mesh's.
  const NarrowAngleQuality none = measure_away_from(mesh, quality, {});
  EXPECT_EQ(none.triangles_at, 0u);
  EXPECT_NEAR(none.angle_min_away_deg, 10, 1e-9);
  EXPECT_NEAR(none.q_min_away, quality.q_min, 1e-12);
  EXPECT_LT(none.q_min_away, 0.5);
  // A narrow angle far from every vertex (more than half an edge): nothing is at it.
  EXPECT_EQ(measure_away_from(mesh, quality, {{{5, 5, 0}, 20}}).triangles_at, 0u);
}

}  // namespace
}  // namespace cvtmesh
