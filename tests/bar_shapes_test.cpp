// How the output's last steps judge a round (finish/bar_shapes): fewer triangles of no area first;
// then the bar away from the input's narrow angles, and at them, the shapes against the input
// angle, which a round must not lower unless its worst triangle over all is better.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "finish/bar_shapes.hpp"
#include "finish/worst_shape.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {
namespace {

// Three separate triangles: an equilateral one, one with a 20° angle at the origin, and one with
// a 25° angle far from both.
TriangleMesh three_triangles() {
  const double rad = std::numbers::pi / 180;
  TriangleMesh m;
  m.vertices = {{10, 0, 0}, {11, 0, 0}, {10.5, std::sqrt(3.0) / 2, 0},
                {0, 0, 0},  {1, 0, 0},  {std::cos(20 * rad), std::sin(20 * rad), 0},
                {20, 0, 0}, {21, 0, 0}, {20 + std::cos(25 * rad), std::sin(25 * rad), 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return m;
}

MinShape shape_of(const TriangleMesh& m, std::size_t t) {
  const auto [a, b, c] = m.corners(t);
  return min_shape(a, b, c);
}

// WorstShape::add_above, which the shape searches use to stop measuring a place at its first
// triangle that rules it out: where it says the score stays above the bar, the shape is add's to
// the bit; where it says no, add's score is at the bar or under it.
TEST(WorstShape, AddAboveAddsAsAddDoesOrSaysTheScoreFellToTheBar) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(0, 1);
  const auto point = [&] { return Vec3{coordinate(random), coordinate(random), 0.1}; };
  std::size_t fell = 0, stayed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double bar = 0.1 * (trial % 8);
    WorstShape full, above;
    for (int k = 0; k < 4; ++k) {
      const Vec3 a = point(), b = point(), c = point();
      full.add(a, b, c);
      if (!above.add_above(a, b, c, bar)) {
        EXPECT_LE(full.score(), bar);
        ++fell;
        break;
      }
      ++stayed;
      EXPECT_EQ(above.quality, full.quality);
      EXPECT_EQ(above.angle, full.angle);
      EXPECT_GT(full.score(), bar);
    }
  }
  EXPECT_GT(fell, 0u);
  EXPECT_GT(stayed, 0u);
}

TEST(BarShapes, TrianglesAtANarrowAngleAreJudgedAgainstItAndTheRestByTheBar) {
  const TriangleMesh m = three_triangles();
  const MinShape tip = shape_of(m, 1), away = shape_of(m, 2);
  const BarShapes with = bar_shapes(m, {{{0, 0, 0}, 20.0}}, 0.1);
  EXPECT_EQ(with.under, 1u);  // the 25° triangle; the 20° one is at the narrow angle
  EXPECT_DOUBLE_EQ(with.away.quality, away.quality);
  EXPECT_DOUBLE_EQ(with.away.angle, away.min_angle / 60);
  EXPECT_DOUBLE_EQ(with.quality_at, tip.quality);
  EXPECT_NEAR(with.ratio_at, 1, 1e-9);

  const BarShapes without = bar_shapes(m, {}, 0.1);
  EXPECT_EQ(without.under, 2u);
  EXPECT_DOUBLE_EQ(without.away.quality, tip.quality);
  EXPECT_DOUBLE_EQ(without.away.angle, tip.min_angle / 60);
  EXPECT_EQ(without.quality_at, 1);
  EXPECT_EQ(without.ratio_at, 1);
}

TEST(BarShapes, ARoundIsBetterAwayFromNarrowAnglesAndNoWorseAtThem) {
  // under, worst Q and θmin / 60 away, Q and θmin ratio at narrow angles, worst score over all
  const BarShapes kept{2, {0.6, 0.5}, 0.4, 1.0, 0.3};
  const auto judged = [&](auto change) {
    BarShapes s = kept;
    change(s);
    return judge_round(s, kept);
  };
  using enum Verdict;
  // The worst triangle away from them first, then how many are under the bar.
  EXPECT_EQ(judged([](BarShapes& s) { s.away.angle = 0.55; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.away.quality = 0.65; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.away.angle = 0.45; }), no_better);
  EXPECT_EQ(judged([](BarShapes& s) { s.under = 1; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.under = 0, s.away.angle = 0.45; }), no_better);
  // Qmin lower where θmin, which holds the score, is not: worse.
  EXPECT_EQ(judged([](BarShapes& s) { s.under = 0, s.away.quality = 0.55; }), no_better);
  // One better, the other worse: the score.
  EXPECT_EQ(judged([](BarShapes& s) { s.away.quality = 0.58, s.away.angle = 0.56; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.away.quality = 0.65, s.away.angle = 0.48; }), no_better);
  // As good away from them: better at them.
  EXPECT_EQ(judged([](BarShapes& s) { s.quality_at = 0.45; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.ratio_at = 1.1; }), better);
  EXPECT_EQ(judged([](BarShapes& s) { s.quality_at += 1e-12; }), no_better);
  EXPECT_EQ(judge_round(kept, kept), no_better);
  EXPECT_EQ(judged([](BarShapes& s) { s.away.angle = 0.6, s.quality_at -= 1e-12; }), better);
  // Better in one part, worse in the other: better where the worst triangle over all is, else
  // mixed (a round that only takes a triangle from under the bar at the cost of the shapes at a
  // narrow angle, which hold the worst over all).
  EXPECT_EQ(judged([](BarShapes& s) { s.under = 0, s.quality_at = 0.35; }), mixed);
  EXPECT_EQ(judged([](BarShapes& s) { s.away.angle = 0.6, s.ratio_at = 0.9, s.worst_all = 0.25; }),
            mixed);
  EXPECT_EQ(
      judged([](BarShapes& s) { s.away.angle = 0.45, s.quality_at = 0.6, s.worst_all = 0.45; }),
      better);
  EXPECT_EQ(
      judged([](BarShapes& s) { s.away.quality = 0.55, s.quality_at = 0.6, s.worst_all += 1e-15; }),
      mixed);
}

TEST(BarShapes, ASplitIsBetterWithFewerUnderTheBarAndNoWorseAtNarrowAngles) {
  const BarShapes kept{2, {0.6, 0.5}, 0.4, 1.0, 0.4};
  EXPECT_TRUE(shaped_better({1, {0.6, 0.45}, 0.4, 1.0, 0.4}, kept));
  EXPECT_TRUE(shaped_better({2, {0.6, 0.55}, 0.4, 1.0, 0.4}, kept));
  EXPECT_FALSE(shaped_better({2, {0.55, 0.5}, 0.4, 1.0, 0.4}, kept));
  EXPECT_FALSE(shaped_better({3, {0.6, 0.55}, 0.4, 1.0, 0.4}, kept));
  EXPECT_FALSE(shaped_better({1, {0.6, 0.55}, 0.35, 1.0, 0.35}, kept));
  // As in lion.off at 1k: the worst away a little lower, the worst at its tip far better.
  EXPECT_TRUE(
      shaped_better({2, {0.66, 0.67}, 0.66, 1.0, 0.66}, {2, {0.69, 0.67}, 0.47, 1.0, 0.40}));
}

TEST(BarShapes, AFlatTriangleIsCountedAndFewerOfThemComeFirst) {
  TriangleMesh m = three_triangles();
  EXPECT_EQ(bar_shapes(m, {}, 0.1).flat, 0u);
  m.vertices.push_back({30, 0, 0});
  m.vertices.push_back({31, 0, 0});
  m.vertices.push_back({32, 1e-9, 0});  // all but on the line of the other two
  m.triangles.push_back({9, 10, 11});
  const BarShapes flat = bar_shapes(m, {}, 0.1);
  EXPECT_EQ(flat.flat, 1u);
  EXPECT_EQ(flat.under, 3u);
  // Fewer under the bar, a better worst triangle: no better with a flat one more.
  const BarShapes kept{2, {0.6, 0.5}, 0.4, 1.0, 0.3};
  BarShapes one_flat{0, {0.7, 0.6}, 0.5, 1.0, 0.5};
  one_flat.flat = 1;
  EXPECT_FALSE(shaped_better(one_flat, kept));
  EXPECT_EQ(judge_round(one_flat, kept), Verdict::no_better);
  // And a flat one fewer is better, whatever the rest.
  EXPECT_TRUE(shaped_better(kept, one_flat));
  EXPECT_EQ(judge_round(kept, one_flat), Verdict::better);
}

}  // namespace
}  // namespace cvtmesh
