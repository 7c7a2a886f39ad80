// The local feature size near features (issue 20 item 1): feature curves narrow the sizes of
// their vertices to the gap across which another part of them faces them, on flat sheets whose
// gaps are known.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "cvtmesh/sizing.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The boundary's curves, split at its corners (turns over 60°).
Features outline(const TriangleMesh& mesh) {
  return detect_features(mesh, FeatureSettings{});
}

TEST(FeatureGaps, AStripIsAsNarrowAsItIsWideAndItsRightAngledCornersNarrowNothing) {
  // [0,10] × [0,1]: the long sides face each other 1 apart, corners included; the short sides
  // face only each other, 10 apart, beyond the limit of 3.
  const TriangleMesh strip = mapped_grid(100, 10, [](double u, double v) {
    return Vec3{10 * u, v, 0};
  });
  const std::vector<double> sizes =
      capped_by_feature_gaps(strip, outline(strip), std::vector<double>(strip.vertices.size(), 3));
  int long_side = 0, short_side = 0, corners = 0;
  for (Index v = 0; v < strip.vertices.size(); ++v) {
    const Vec3& p = strip.vertices[v];
    const bool on_long = p.y == 0 || p.y == 1, on_short = p.x == 0 || p.x == 10;
    if (on_long && !on_short) {
      EXPECT_NEAR(sizes[v], 1.0, 1e-12) << "long side at x = " << p.x;
      ++long_side;
    } else if (on_long) {
      EXPECT_NEAR(sizes[v], 1.0, 1e-12) << "corner at " << p.x << ", " << p.y;
      ++corners;
    } else {
      EXPECT_EQ(sizes[v], 3.0) << (on_short ? "short side" : "inside") << " at " << p.x << ", "
                               << p.y;
      short_side += on_short;
    }
  }
  EXPECT_EQ(long_side, 2 * 99);
  EXPECT_EQ(short_side, 2 * 9);
  EXPECT_EQ(corners, 4);
}

TEST(FeatureGaps, AClosedCurveIsAsNarrowAsItsWidth) {
  // A circle of radius 1 faces itself at 120° and beyond: √3 away (on 96 segments, within one
  // segment's turn). As a boundary loop 2π long, it also gets its length over 2π, 1, about six
  // edges around it: the smaller.
  const TriangleMesh round = disk(8, 96);
  const std::vector<double> sizes =
      capped_by_feature_gaps(round, outline(round), std::vector<double>(round.vertices.size(), 5));
  for (Index v = 0; v < round.vertices.size(); ++v) {
    if (std::abs(norm(round.vertices[v]) - 1) < 1e-12)
      EXPECT_NEAR(sizes[v], 1.0, 0.001);
    else
      EXPECT_EQ(sizes[v], 5.0);
  }
  // Sizes under 1 see only the facing rule: none narrower than √3 there.
  const std::vector<double> small = capped_by_feature_gaps(
      round, outline(round), std::vector<double>(round.vertices.size(), 0.9));
  EXPECT_TRUE(std::all_of(small.begin(), small.end(), [](double s) { return s == 0.9; }));
}

TEST(FeatureGaps, AWedgeUnder60DegreesNarrowsTowardsItsTip) {
  // The sheet between two rays 20° apart, from radius 0.1 to 1: a point of one ray at radius r
  // faces the other r sin 20° away. Only gaps under the limit (0.1) are looked for.
  const double wedge = 20 * std::numbers::pi / 180;
  const TriangleMesh sheet = mapped_grid(90, 12, [&](double u, double v) {
    const double r = 0.1 + 0.9 * u, a = wedge * v;
    return Vec3{r * std::cos(a), r * std::sin(a), 0};
  });
  const std::vector<double> sizes = capped_by_feature_gaps(
      sheet, outline(sheet), std::vector<double>(sheet.vertices.size(), 0.1));
  int checked = 0;
  for (Index v = 0; v < sheet.vertices.size(); ++v) {
    const Vec3& p = sheet.vertices[v];
    const double r = norm(p);
    if (p.y != 0 || r < 0.15 || r > 0.95) continue;  // the ray y = 0, away from the arcs
    EXPECT_NEAR(sizes[v], std::min(0.1, r * std::sin(wedge)), 1e-9) << "at radius " << r;
    ++checked;
  }
  EXPECT_GT(checked, 70);
}

// The sheet between two rays `deg` apart from their common tip (vertex 0) to `radius`, in rings:
// the tip a corner with a sector of `deg`. Vertex at(i, 0) lies on the ray y = 0 at radius
// i / kRings of `radius`.
constexpr int kRings = 90, kAcross = 12;
Index at(int i, int j) {
  return wedge_sheet_vertex(i, j, kAcross);
}
TriangleMesh wedge_with_tip(double deg, double radius) {
  return wedge_sheet(deg, radius, kRings, kAcross);
}

// The sizes on the ray y = 0, away from the tip's own edges and the arc.
std::vector<double> on_the_ray(const std::vector<double>& sizes) {
  std::vector<double> out;
  for (int i = 14; i <= 85; ++i) out.push_back(sizes[at(i, 0)]);
  return out;
}

bool all_equal(const std::vector<double>& sizes, double size) {
  return std::all_of(sizes.begin(), sizes.end(), [&](double s) { return s == size; });
}

TEST(FeatureGaps, ANarrowWedgeWithLongSidesNarrowsTowardsItsTipForEvenSizesToo) {
  // 20°, sides 10 sizes long: the output traces it, and even sizes would leave a sliver beside
  // the triangle at its tip (WedgeGaps::traced_narrow).
  const TriangleMesh sheet = wedge_with_tip(20, 1);
  const Features features = outline(sheet);
  ASSERT_EQ(narrow_feature_angles(sheet, features, 30).size(), 1u);
  const std::vector<double> even(sheet.vertices.size(), 0.1);
  const std::vector<double> all = capped_by_feature_gaps(sheet, features, even);
  const std::vector<double> traced =
      capped_by_feature_gaps(sheet, features, even, WedgeGaps::traced_narrow);
  EXPECT_EQ(all, traced);
  const double wedge = 20 * std::numbers::pi / 180;
  for (int i = 14; i <= 85; ++i) {
    const double r = static_cast<double>(i) / kRings;
    EXPECT_NEAR(traced[at(i, 0)], std::min(0.1, r * std::sin(wedge)), 1e-9) << "at radius " << r;
  }
}

TEST(FeatureGaps, EvenSizesLeaveTheWedgesAnOutputDoesNotTraceAsNarrow) {
  const auto narrows = [](const TriangleMesh& sheet, const Features& features, double size,
                          WedgeGaps wedges) {
    const std::vector<double> sizes = capped_by_feature_gaps(
        sheet, features, std::vector<double>(sheet.vertices.size(), size), wedges);
    return !all_equal(on_the_ray(sizes), size);
  };
  // Sides 3.3 sizes long, under the 4 asked for.
  const TriangleMesh short_sides = wedge_with_tip(20, 1);
  EXPECT_TRUE(narrows(short_sides, outline(short_sides), 0.3, WedgeGaps::all));
  EXPECT_FALSE(narrows(short_sides, outline(short_sides), 0.3, WedgeGaps::traced_narrow));
  // 40°, sides 8 sizes long: not a narrow input angle; even sizes shape it well.
  const TriangleMesh wider = wedge_with_tip(40, 4);
  EXPECT_TRUE(narrows(wider, outline(wider), 0.5, WedgeGaps::all));
  EXPECT_FALSE(narrows(wider, outline(wider), 0.5, WedgeGaps::traced_narrow));
  // 20°, sides 10 sizes long, but one curve folds back through the tip, which is no corner: no
  // output keeps it as a vertex.
  const TriangleMesh folded = wedge_with_tip(20, 1);
  Features fold = outline(folded);
  std::vector<std::size_t> at_tip;  // the two curves with an end at the tip
  for (std::size_t c = 0; c < fold.curves.size(); ++c)
    if (fold.curves[c].vertices.front() == 0 || fold.curves[c].vertices.back() == 0)
      at_tip.push_back(c);
  ASSERT_EQ(at_tip.size(), 2u);
  std::vector<Index>& in = fold.curves[at_tip[0]].vertices;
  std::vector<Index> out = fold.curves[at_tip[1]].vertices;
  if (in.back() != 0) std::reverse(in.begin(), in.end());
  if (out.front() != 0) std::reverse(out.begin(), out.end());
  in.insert(in.end(), out.begin() + 1, out.end());
  fold.curves.erase(fold.curves.begin() + static_cast<std::ptrdiff_t>(at_tip[1]));
  fold.corners.erase(std::find(fold.corners.begin(), fold.corners.end(), Index{0}));
  EXPECT_TRUE(narrows(folded, fold, 0.1, WedgeGaps::all));
  EXPECT_FALSE(narrows(folded, fold, 0.1, WedgeGaps::traced_narrow));
}

// Curves along polylines that join end to start (a corner where one ends and the next starts).
std::pair<TriangleMesh, Features> chained(const std::vector<std::vector<Vec3>>& lines) {
  TriangleMesh mesh;
  Features features;
  for (const std::vector<Vec3>& line : lines) {
    FeatureCurve curve;
    if (!mesh.vertices.empty()) curve.vertices.push_back(mesh.vertices.size() - 1);
    for (std::size_t i = mesh.vertices.empty() ? 0 : 1; i < line.size(); ++i) {
      curve.vertices.push_back(mesh.vertices.size());
      mesh.vertices.push_back(line[i]);
    }
    features.curves.push_back(curve);
  }
  return {mesh, features};
}

double narrowest(const std::vector<std::vector<Vec3>>& lines, double limit) {
  const auto [mesh, features] = chained(lines);
  const std::vector<double> sizes =
      capped_by_feature_gaps(mesh, features, std::vector<double>(mesh.vertices.size(), limit));
  return *std::min_element(sizes.begin(), sizes.end());
}

TEST(FeatureGaps, AZigzagOfAJaggedRimIsNoNarrowPlace) {
  // A scan's rim that doubles back for one short edge (4.4 long) and goes on: its two corners
  // face each other's curves across that edge, 2.2 apart, but a gap further along, the curves
  // have parted.
  EXPECT_EQ(
      narrowest({{{24.5, -45.9, -10.5}, {27.2, -46, -10.5}, {29.7, -46.6, -9.4}, {35.4, -47.4, -7}},
                 {{35.4, -47.4, -7}, {33.9, -47.9, -2.9}},
                 {{33.9, -47.9, -2.9}, {36.7, -47.6, 0}, {36.3, -48, 2.1}, {37.6, -48.5, 7.6}}},
                10),
      10);
  // A rim that doubles back and runs beside itself, 2 apart, is a slot.
  EXPECT_NEAR(narrowest({{{25, 0, 0}, {30, 0, 0}, {35, 0, 0}},
                         {{35, 0, 0}, {35, 0, 2}},
                         {{35, 0, 2}, {30, 0, 2}, {25, 0, 2}}},
                        10),
              2, 1e-12);
}

TEST(FeatureGaps, TheLocalFeatureSizeFallsToThemAndIsTheSameOnAnyThreadCount) {
  // A flat sheet has no poles: its lfs is the size of the whole, but near its sides the strip's
  // width.
  const TriangleMesh strip = mapped_grid(60, 6, [](double u, double v) {
    return Vec3{6 * u, v, 0};
  });
  const Features features = outline(strip);
  LfsSettings s;
  s.gradation = 0;
  s.features = &features;
  const std::vector<double> lfs = local_feature_size(strip, s);
  for (Index v = 0; v < strip.vertices.size(); ++v) {
    const Vec3& p = strip.vertices[v];
    if ((p.y == 0 || p.y == 1) && p.x > 0 && p.x < 6) {
      EXPECT_NEAR(lfs[v], 1.0, 1e-12);
    }
  }
  std::vector<double> one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = local_feature_size(strip, s);
  }
  EXPECT_EQ(one, lfs);
}

}  // namespace
}  // namespace cvtmesh
