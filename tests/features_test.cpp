// Feature detection (issue 5, paper §4.3) and remeshing that keeps features and boundaries.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_sectors.hpp"
#include "features/twin_curves.hpp"
#include "geometry/angle.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"
#include "support/temp_dir.hpp"

namespace cvtmesh {
namespace {

using testing::shared_data;
using testing::shared_mesh;

TEST(Features, CubeHasTwelveCreasesAndEightCorners) {
  const Features f = detect_features(testing::cube(4), {});
  EXPECT_EQ(f.edges.size(), 12u * 4);
  EXPECT_EQ(f.corners.size(), 8u);
  ASSERT_EQ(f.curves.size(), 12u);
  for (const FeatureCurve& c : f.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.vertices.size(), 5u);  // corner, three grid vertices, corner
  }
}

TEST(Features, AngleAboveTheCreasesKeepsNone) {
  FeatureSettings s;
  s.angle_deg = 95;  // the cube's creases are 90°
  EXPECT_TRUE(detect_features(testing::cube(4), s).empty());
  s.sharp_edges = false;
  s.angle_deg = 10;
  EXPECT_TRUE(detect_features(testing::cube(4), s).empty());
}

TEST(Features, OpenDiskHasOneBoundaryLoopWithoutCorners) {
  FeatureSettings s;
  s.sharp_edges = false;  // boundaries are kept anyway
  const Features f = detect_features(testing::disk(4, 16), s);
  EXPECT_EQ(f.edges.size(), 16u);
  EXPECT_TRUE(f.corners.empty());
  ASSERT_EQ(f.curves.size(), 1u);
  EXPECT_TRUE(f.curves[0].closed);
  EXPECT_EQ(f.curves[0].vertices.size(), 16u);
}

TEST(Features, SharpTurnOfACurveIsACorner) {
  // A square hole's boundary turns by 90° at each corner, above the 60° default.
  FeatureSettings s;
  s.sharp_edges = false;
  const Features f = detect_features(testing::disk(2, 4), s);
  EXPECT_EQ(f.corners.size(), 4u);
  EXPECT_EQ(f.curves.size(), 4u);
  s.angle_deg = 120;
  EXPECT_TRUE(detect_features(testing::disk(2, 4), s).corners.empty());
}

// A flat square plate of n × n grid cells (side 1) whose bottom row misses every `notch`-th
// cell from the second on: each notch is a step of the rim one cell deep and wide, with four
// sharp turns one cell apart, like the jagged rim of a scan's hole.
TriangleMesh notched_plate(int n, int notch) {
  TriangleMesh m;
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.push_back({double(i) / n, double(j) / n, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (j > 0 || i == 0 || i == n - 1 || i % notch != 0)
        testing::add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

TEST(Features, SharpTurnsCloserThanTheScaleAllowsAreNoCorners) {
  const TriangleMesh plate = notched_plate(40, 4);  // 9 notches, 36 turns 1/40 apart
  FeatureSettings s;
  s.scale = 0.04;  // a cell is 0.625 of the scale: every turn is a corner, with the plate's 4
  EXPECT_EQ(detect_features(plate, s).corners.size(), 40u);
  // Half the scale: a notch's sides are steps between two turns, under 0.55 of it (an edge that
  // short faces an angle under 30°), so the notches go.
  s.scale = 0.05;
  EXPECT_EQ(detect_features(plate, s).corners.size(), 4u);
  s.scale = 0.1;  // a quarter: under 0.3 of it, so only the plate's corners are left
  const Features f = detect_features(plate, s);
  EXPECT_EQ(f.corners.size(), 4u);
  EXPECT_EQ(f.curves.size(), 4u);
  s.scale = 3;  // the whole rim, 4.45 long, is under twice that: a small part's outline, kept
  EXPECT_EQ(detect_features(plate, s).corners.size(), 40u);
  s.scale = 0.1;
  s.creases_at_scale = false;  // a feature angle given: every turn is a corner at any scale
  EXPECT_EQ(detect_features(plate, s).corners.size(), 40u);
}

TEST(Features, ATurnNearAJunctionOfCurvesIsACornerDownToTheShorterBound) {
  // A plain plate (no notch) with a feature edge given from its rim at x = 38/40 inwards: the
  // plate's corner at x = 1 is a turn 0.05 from that junction, as a CAD part's corner next to
  // where a crease meets its outline.
  const TriangleMesh plate = notched_plate(40, 41);
  auto id = [](int i, int j) { return static_cast<Index>(j * 41 + i); };
  FeatureSettings s;
  s.user_edges = {{id(38, 0), id(38, 1)}};
  const auto corner_at_x1 = [&](const Features& f) {
    return std::count(f.corners.begin(), f.corners.end(), id(40, 0)) == 1;
  };
  s.scale = 0.1;  // half the scale: short for a step between two turns, not beside a junction
  const Features f = detect_features(plate, s);
  EXPECT_EQ(f.corners.size(), 6u);  // the plate's 4 and the given edge's ends
  EXPECT_TRUE(corner_at_x1(f));
  s.scale = 0.2;  // a quarter: under 0.3 of it even there
  EXPECT_FALSE(corner_at_x1(detect_features(plate, s)));
}

TEST(Features, NarrowestSectorIsTheAngleBetweenTwoFeaturesAtAVertex) {
  // The cube: 90° at each corner, between each two of its three creases.
  const TriangleMesh box = testing::cube(4);
  EXPECT_NEAR(narrowest_feature_sector_deg(box, detect_features(box, {})), 90, 1e-9);
  // A flat kite whose boundary is the features: its 20° tip is split in two triangles, which
  // the sector sums; its other angles are wider.
  const double s = std::sin(10 * std::numbers::pi / 180), c = std::cos(10 * std::numbers::pi / 180);
  TriangleMesh kite;
  kite.vertices = {{0, 0, 0}, {c, -s, 0}, {1, 0, 0}, {c, s, 0}, {1.2, 0, 0}};
  kite.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}, {2, 4, 3}};
  EXPECT_NEAR(narrowest_feature_sector_deg(kite, detect_features(kite, {})), 20, 1e-9);
  // Only the tip is under 30°, and it is where the kite's vertex 0 is.
  const std::vector<NarrowAngle> narrow =
      narrow_feature_angles(kite, detect_features(kite, {}), 30);
  ASSERT_EQ(narrow.size(), 1u);
  EXPECT_EQ(narrow[0].at, kite.vertices[0]);
  EXPECT_NEAR(narrow[0].angle_deg, 20, 1e-9);
  EXPECT_TRUE(narrow_feature_angles(kite, detect_features(kite, {}), 20).empty());
  // No vertex with two features: 360.
  const TriangleMesh ball = testing::icosphere(2);
  EXPECT_EQ(narrowest_feature_sector_deg(ball, detect_features(ball, {})), 360);
}

TEST(Features, ASectorIsSummedRoundTheSurfaceNotTheAngleBetweenItsEdges) {
  // A fan on a cone of half-angle 30° round the z axis, from (1/2, 0, ..) half way round to
  // (-1/2, 0, ..): its two rim edges are 60° apart in space, but the surface between them spans
  // about pi sin 30° = 90° (eight 22.5° steps of azimuth, each triangle's angle about 11.2°).
  TriangleMesh fan;
  fan.vertices.push_back({0, 0, 0});
  for (int k = 0; k <= 8; ++k) {
    const double phi = k * std::numbers::pi / 8;
    fan.vertices.push_back({0.5 * std::cos(phi), 0.5 * std::sin(phi), std::sqrt(0.75)});
  }
  for (Index k = 1; k <= 8; ++k) fan.triangles.push_back({0, k, k + 1});
  Features f;
  f.edges = {{0, 1}, {0, 9}};
  const std::vector<FeatureSector> sectors = feature_sectors(fan, f);
  ASSERT_EQ(sectors.size(), 2u);  // one each way round
  double summed = 0;              // the fan's angles at its apex
  for (Index k = 1; k <= 8; ++k) summed += angle_deg(fan.vertices[k], fan.vertices[k + 1]);
  for (const FeatureSector& s : sectors) {
    EXPECT_EQ(s.apex, 0u);
    EXPECT_EQ(std::min(s.from, s.to), 1u);
    EXPECT_EQ(std::max(s.from, s.to), 9u);
    EXPECT_NEAR(s.angle_deg, summed, 1e-9);
  }
  EXPECT_GT(sectors[0].angle_deg, 85);
  EXPECT_NEAR(angle_deg(fan.vertices[1], fan.vertices[9]), 60, 1e-9);
  // The rim's own ends have one feature edge each: no sector there.
  EXPECT_NEAR(narrowest_feature_sector_deg(fan, f), summed, 1e-9);
}

TEST(Features, UserEdgesAreKeptAndChecked) {
  const TriangleMesh sphere = testing::icosphere(2);
  FeatureSettings s;
  const Triangle& t = sphere.triangles[0];
  s.user_edges = {{t[1], t[0]}, {t[1], t[2]}};
  const Features f = detect_features(sphere, s);
  EXPECT_EQ(f.edges.size(), 2u);
  // The chain's two ends, and its middle: two sides of a triangle turn by 120° there.
  EXPECT_EQ(f.corners.size(), 3u);
  EXPECT_EQ(f.curves.size(), 2u);

  s.user_edges = {{0, static_cast<Index>(sphere.vertices.size())}};
  EXPECT_THROW(detect_features(sphere, s), InvalidArgument);
  // Two vertices that are not joined by an edge: the pole and the opposite pole.
  Index far = 0;
  for (Index v = 0; v < sphere.vertices.size(); ++v)
    if (distance(sphere.vertices[v], sphere.vertices[0]) >
        distance(sphere.vertices[far], sphere.vertices[0]))
      far = v;
  s.user_edges = {{0, far}};
  EXPECT_THROW(detect_features(sphere, s), InvalidArgument);
}

TEST(Features, ShortSharpCurvesAreDroppedButNeverBoundaries) {
  FeatureSettings s;
  s.scale = 1.5;  // the cube's creases are 2 long, under twice that
  EXPECT_TRUE(detect_features(testing::cube(4), s).empty());
  s.scale = 0.75;
  EXPECT_EQ(detect_features(testing::cube(4), s).curves.size(), 12u);
  s.scale = 50;
  EXPECT_EQ(detect_features(testing::disk(4, 16), s).curves.size(), 1u);
}

// A sphere whose vertices alternate in and out by about an edge length: many of its edges fold by
// more than 60°, but at a scale of a few edges its surface is rough all round, with no crease.
TriangleMesh bumpy_sphere() {
  TriangleMesh m = testing::icosphere(3);
  for (Index v = 0; v < m.vertices.size(); ++v)
    m.vertices[v] = (v % 3 == 0 ? 1.2 : 0.95) * m.vertices[v];
  return m;
}

TEST(Features, JaggedFoldsAreNoCreasesAtTheOutputScaleButFlatSidedCreasesAre) {
  const TriangleMesh bumpy = bumpy_sphere();
  FeatureSettings s;
  EXPECT_FALSE(detect_features(bumpy, s).empty());  // at the input's own scale: sharp edges
  s.scale = 0.2;                                    // a little more than its edge length
  s.creases_at_scale = false;                       // the length rule alone keeps some curves
  EXPECT_FALSE(detect_features(bumpy, s).empty());
  s.creases_at_scale = true;
  EXPECT_TRUE(detect_features(bumpy, s).empty());
  // The cube's creases have flat sides: all kept, at a scale that resolves them.
  s.scale = 0.75;
  EXPECT_EQ(detect_features(testing::cube(8), s).curves.size(), 12u);
  // A boundary is kept whatever the sides look like, and nothing else is.
  TriangleMesh half = testing::hemisphere(6, 12);
  for (Index v = 0; v < half.vertices.size(); ++v)
    half.vertices[v] = (v % 3 == 0 ? 1.2 : 0.95) * half.vertices[v];
  EXPECT_EQ(detect_features(half, s).edges.size(), 12u);  // the 12 boundary edges
}

// A low-poly closed shape: an icosphere of 80 triangles, every third vertex pushed out by 60%.
// 14 of its edges fold by more than 60° between facets that are flat at any finer scale, amid
// edges that all bend by 6° or more: the faceting of a smooth shape, no crease (issue 18 item 5:
// hand.off, pig.off, cow.off at 5k kept such folds and lost up to 23° of θmin to them).
TriangleMesh low_poly_blob() {
  TriangleMesh m = testing::icosphere(1);
  for (Index v = 0; v < m.vertices.size(); ++v)
    if (v % 3 == 0) m.vertices[v] = 1.6 * m.vertices[v];
  return m;
}

TEST(Features, FoldsOfALowPolyModelAreNoCreasesAtAFinerScaleButAPolyhedronsAre) {
  const TriangleMesh blob = low_poly_blob();
  FeatureSettings s;
  s.scale = 0.01;              // far finer than its facets, which are about 0.6 across
  s.creases_at_scale = false;  // a feature angle given: its folds are forced
  const std::size_t forced = detect_features(blob, s).edges.size();
  EXPECT_EQ(forced, 14u);
  s.creases_at_scale = true;
  EXPECT_TRUE(detect_features(blob, s).empty());
  // A cube of 2 × 2 grid cells a side, as coarse, has flat faces around its creases: all kept.
  EXPECT_EQ(detect_features(testing::cube(2), s).curves.size(), 12u);
}

// A cube (side 2, n grid cells a side) with a ridge on its top face: 5 grid vertices in a row
// raised by a grid cell. The ridge folds by 90° and, with a grid diagonal at each end, is 7.5 grid
// cells long (1.87 for n = 8); it ends in the flat face, meeting no other feature.
TriangleMesh cube_with_ridge(int n = 8) {
  TriangleMesh m = testing::cube(n);
  const double cell = 2.0 / n;
  for (Vec3& p : m.vertices)
    if (p.z == 1 && p.y == 0 && std::abs(p.x) < 2.01 * cell) p.z += cell;
  return m;
}

TEST(Features, ShortCreasesFreeAtBothEndsAreDroppedUnlessForced) {
  FeatureSettings s;
  s.scale = 0.25;  // the ridge is 7.5 times that: no crease at this scale
  EXPECT_EQ(detect_features(cube_with_ridge(), s).curves.size(), 12u);  // the cube's stay
  s.scale = 0.2;                                                        // 9.4 times: kept
  EXPECT_EQ(detect_features(cube_with_ridge(), s).curves.size(), 13u);
  s.scale = 0.25;
  s.creases_at_scale = false;  // a feature angle given: every curve of its length is kept
  EXPECT_EQ(detect_features(cube_with_ridge(), s).curves.size(), 13u);
}

// However fine the scale, a free crease under a third of its model across (the square root of
// its component's area, 4.9 for the cube) is a fold of an organic model's polygons, not a designed
// feature: a ridge of 0.94 on the same cube, at a scale it is 9.4 times as long as, goes; forced,
// it stays. The ridge of 1.87 above is over a third: kept.
TEST(Features, FreeCreasesShortAgainstTheirModelAreDroppedAtAnyScale) {
  FeatureSettings s;
  s.scale = 0.1;
  EXPECT_EQ(detect_features(cube_with_ridge(16), s).curves.size(), 12u);
  s.creases_at_scale = false;
  EXPECT_EQ(detect_features(cube_with_ridge(16), s).curves.size(), 13u);
  // Beside a far larger component the ridge's model is still its own cube.
  s.creases_at_scale = true;
  s.scale = 0.2;
  const TriangleMesh two = testing::concatenate(
      cube_with_ridge(), testing::transformed(testing::cube(8), 20, {100, 0, 0}));
  EXPECT_EQ(detect_features(two, s).curves.size(), 25u);
}

// A cube (side 2, 32 grid cells a side) whose top face steps up by `rise` past x = 1/16: the
// grid cells between x = 0 and x = 1/16 make a sloping strip, between two creases that fold by
// atan(16 rise) each.
TriangleMesh cube_with_step(double rise) {
  TriangleMesh m = testing::cube(32);
  for (Vec3& p : m.vertices)
    if (p.z == 1 && p.x > 0.05) p.z += rise;
  return m;
}

// The edges of `f` on the top face's step (both ends at x = 0, or both at x = 1/16, above z = 1
// and off the cube's sides).
std::size_t step_edges(const TriangleMesh& m, const Features& f) {
  std::size_t n = 0;
  for (const Edge& e : f.edges) {
    const Vec3 &a = m.vertices[e[0]], &b = m.vertices[e[1]];
    n += a.z >= 1 && b.z >= 1 && a.x == b.x && (a.x == 0 || a.x == 0.0625) && std::abs(a.y) < 1 &&
         std::abs(b.y) < 1;
  }
  return n;
}

TEST(Features, CreasesAcrossAStripTooNarrowForTheScaleAreNone) {
  // The strip is sqrt(0.0625² + 0.125²) = 0.14 wide, its creases fold by 63° and are 2 long.
  const TriangleMesh step = cube_with_step(0.125);
  FeatureSettings s;
  s.scale = 0.3;  // the strip is wider than 0.3 of it: both creases kept, 30 edges off the sides
  EXPECT_EQ(step_edges(step, detect_features(step, s)), 60u);
  s.scale = 0.8;  // narrower: neither
  EXPECT_EQ(step_edges(step, detect_features(step, s)), 0u);
  s.creases_at_scale = false;  // a feature angle given: kept whatever the scale
  EXPECT_EQ(step_edges(step, detect_features(step, s)), 60u);
}

// A sheet folded by 90° along a crease 2 long on the x axis, each face 0.5 wide, its rims open;
// `shear` slants the face at y > 0 back along the crease, so that at the crease's end x = 2 the
// rim leaves it at atan(1 / shear).
TriangleMesh folded_sheet(double shear) {
  return testing::mapped_grid(16, 8, [shear](double u, double v) {
    if (v <= 0.5) return Vec3{2 * u - shear * (0.5 - v), 0.5 - v, 0};
    return Vec3{2 * u, 0, v - 0.5};
  });
}

std::size_t crease_edges(const TriangleMesh& m, const Features& f) {
  return static_cast<std::size_t>(std::ranges::count_if(f.edges, [&](const Edge& e) {
    const Vec3 &a = m.vertices[e[0]], &b = m.vertices[e[1]];
    return a.y == 0 && a.z == 0 && b.y == 0 && b.z == 0;
  }));
}

TEST(Features, ACreaseMeetingABoundaryAtANarrowAngleIsNoCreaseUnlessForced) {
  FeatureSettings s;
  s.scale = 0.2;
  // Square rims: the crease meets them at 90° and is kept, its 16 edges.
  EXPECT_EQ(crease_edges(folded_sheet(0), detect_features(folded_sheet(0), s)), 16u);
  // Slanted by 4: at x = 2 the rim leaves the crease at 14°, a wedge no triangle can fill well.
  const TriangleMesh slanted = folded_sheet(4);
  EXPECT_EQ(crease_edges(slanted, detect_features(slanted, s)), 0u);
  s.creases_at_scale = false;  // a feature angle given: kept
  EXPECT_EQ(crease_edges(slanted, detect_features(slanted, s)), 16u);
}

// An eighth of a tube (radius 4, height 1; its rims open) whose top turns in by 90° into a flange:
// the crease along the top is an arc π long, between the tube and a strip that ends at the
// flange's rim. The flange is `width` wide half way along and narrows fast towards the ends (a
// lune, as between a scan's lip and the hole's rim it runs along), to a tenth of that.
TriangleMesh flanged_tube_arc(double width) {
  return testing::mapped_grid(64, 24, [width](double u, double v) {
    const double a = std::numbers::pi / 4 * u, row = 24 * v;
    const double in = width * (0.1 + 0.9 * std::pow(std::sin(std::numbers::pi * u), 4));
    const double radius = row <= 20 ? 4 : 4 - in * (row - 20) / 4;
    return Vec3{radius * std::cos(a), radius * std::sin(a), std::min(row, 20.0) / 20};
  });
}

std::size_t flange_crease_edges(const TriangleMesh& m, const Features& f) {
  return static_cast<std::size_t>(std::ranges::count_if(f.edges, [&](const Edge& e) {
    const Vec3 &a = m.vertices[e[0]], &b = m.vertices[e[1]];
    const auto on_crease = [](const Vec3& p) {
      return p.z == 1 && std::abs(std::hypot(p.x, p.y) - 4) < 1e-12;
    };
    return on_crease(a) && on_crease(b);
  }));
}

// A crease beside a boundary leaves a strip between them that, narrower than 0.3 of the scale,
// holds no triangle of 30° (a scan's lip along a hole's rim, lion.off at 5k: θmin 27.5° away from
// narrow input angles with it, 35.3° without). Measured only as how far the side reaches from
// the edge's line, within the scale, the narrow ends of a lune reach its wide middle.
TEST(Features, ACreaseBesideABoundaryTooCloseForTheScaleIsNoCreaseUnlessForced) {
  FeatureSettings s;
  s.scale = 0.8;
  const TriangleMesh wide = flanged_tube_arc(1.0);  // under 0.3 of the scale at 4 of 9 edges
  EXPECT_EQ(flange_crease_edges(wide, detect_features(wide, s)), 64u);
  // At 6 of 9 (measured by the side's reach alone, the crease was kept from a width of 0.5 on).
  const TriangleMesh narrow = flanged_tube_arc(0.55);
  const Features f = detect_features(narrow, s);
  EXPECT_EQ(flange_crease_edges(narrow, f), 0u);
  EXPECT_EQ(f.edges.size(), 2u * 64 + 2 * 24);  // the rims stay, boundaries always
  s.creases_at_scale = false;                   // a feature angle given: kept
  EXPECT_EQ(flange_crease_edges(narrow, detect_features(narrow, s)), 64u);
}

TEST(Features, TwinCurvesGoForTheShorterOrTheOneThatMustStay) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0.1, 0}, {2, 0, 0}, {1, -0.4, 0}};
  const std::vector<FeatureCurve> curves = {
      {{0, 1, 2}, false}, {{0, 2}, false}, {{0, 3, 2}, false}};
  const std::vector<double> lengths = {2 * std::hypot(1, 0.1), 2, 2 * std::hypot(1, 0.4)};
  // At 0.1 the bent curve is 0.1 off the straight one, under half of 0.5: it goes, the
  // straight one stays; the third is 0.4 off and stays.
  EXPECT_EQ(twin_curves(m, curves, lengths, {true, true, true}, 0.5),
            (std::vector<bool>{true, false, false}));
  EXPECT_EQ(twin_curves(m, curves, lengths, {true, true, true}, 1.0),  // 0.4 is under half of 1 too
            (std::vector<bool>{true, false, true}));
  // A curve that must stay (a boundary) keeps its twin's place whatever the lengths.
  EXPECT_EQ(twin_curves(m, curves, lengths, {false, true, false}, 0.5),
            (std::vector<bool>{false, true, false}));
  EXPECT_EQ(twin_curves(m, curves, lengths, {true, true, true}, 0.1),  // resolved at that scale
            (std::vector<bool>{false, false, false}));
}

// Organic models whose polygons fold along the sides of sliver triangles: at a 5k-vertex scale
// the features kept meet at no angle under 30° (cow.off's met at 2.8°, costing θmin 1.7° where
// --no-features gave 21°; triceratops.off's at 2.0°, bones.off's at 5.1°).
TEST(FeaturesSharedData, OrganicModelsKeepNoTwinCreasesAtTheOutputScale) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "cow.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  for (const char* name : {"corpus/cow.off", "corpus/triceratops.off", "corpus/bones.off"}) {
    const TriangleMesh in = shared_mesh(name);
    FeatureSettings s;
    s.scale = std::sqrt(surface_area(in) / (std::sqrt(3.0) / 2 * 5000));
    EXPECT_GE(narrowest_feature_sector_deg(in, detect_features(in, s)), 30.0) << name;
  }
}

// Issue 18 item 5: by default, the folds of low-poly and scanned organic models are no features
// at any output scale (hand.off at 5k kept 105 edges of them: θmin 23° against 40° without), and
// the creases of CAD parts and polyhedra all stay.
TEST(FeaturesSharedData, OrganicModelsKeepNoFoldAndCadPartsEveryCrease) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "hand.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  // The sharp edges among f's: edges of two triangles.
  const auto sharp = [](const TriangleMesh& m, const Features& f) {
    const std::vector<EdgeUse> uses = edge_uses(m);
    std::size_t n = 0;
    for (const Edge& e : f.edges) {
      const auto first = std::lower_bound(
          uses.begin(), uses.end(), e, [](const EdgeUse& u, const Edge& x) { return u.edge < x; });
      n += uses.end() - first >= 2 && first[1].edge == e &&
           (uses.end() - first == 2 || first[2].edge != e);
    }
    return n;
  };
  const auto scale = [](const TriangleMesh& m, double n) {
    return std::sqrt(surface_area(m) / (std::sqrt(3.0) / 2 * n));
  };
  for (const char* name : {"corpus/hand.off", "corpus/pig.off", "corpus/cow.off",
                           "corpus/bones.off", "corpus/helmet.off", "corpus/tripod.off"}) {
    const TriangleMesh in = shared_mesh(name);
    FeatureSettings s;
    EXPECT_GT(sharp(in, detect_features(in, s)), 20u) << name;  // folds over 60°
    for (const double n : {1000.0, 5000.0, 10000.0}) {
      s.scale = scale(in, n);
      EXPECT_EQ(sharp(in, detect_features(in, s)), 0u) << name << " at " << n;
    }
  }
  for (const char* name : {"fandisk.off", "joint.off", "anchor.off", "corpus/part.off",
                           "corpus/u.off", "corpus/pipe.off", "cube.off", "corpus/3torus.off"}) {
    const TriangleMesh in = shared_mesh(name);
    FeatureSettings s;
    const std::size_t all = sharp(in, detect_features(in, s));
    for (const double n : {5000.0, 10000.0}) {
      s.scale = scale(in, n);
      EXPECT_EQ(sharp(in, detect_features(in, s)), all) << name << " at " << n;
    }
  }
}

// A fold kept only for meeting a curve that went is left free at both ends; under 4 output edge
// lengths it goes too (femur.off at 10k kept a 2-edge fold so: θmin 3.8° against 11.0° without
// features; triceratops.off at 10k two), while the longer CAD pieces left so stay (anchor.off's at
// 1k, 7 lengths: its 16 corners).
TEST(FeaturesSharedData, ShortPiecesLeftFreeWhenTheirNetworkWentGoToo) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "femur.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const auto at = [](const TriangleMesh& m, double n) {
    FeatureSettings s;
    s.scale = std::sqrt(surface_area(m) / (std::sqrt(3.0) / 2 * n));
    return detect_features(m, s);
  };
  for (const char* name :
       {"corpus/femur.off", "corpus/triceratops.off", "corpus/ChineseDragon-10kv.off"}) {
    const TriangleMesh in = shared_mesh(name);
    const Features boundaries = at(in, 1000);  // no sharp edge is kept at 1k on any of them
    EXPECT_EQ(at(in, 10000).edges, boundaries.edges) << name;
  }
  EXPECT_EQ(at(shared_mesh("anchor.off"), 1000).corners.size(), 16u);
}

TEST(Features, FeatureEdgeFileIsReadWithCommentsAndCheckedLineByLine) {
  const testing::TempDir dir;
  const auto good = dir.path() / "edges.txt";
  std::ofstream(good) << "# crease\n3 4\n\n  5 6  \n";
  const std::vector<Edge> edges = read_feature_edges(good);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[0], (Edge{3, 4}));
  EXPECT_EQ(edges[1], (Edge{5, 6}));
  const auto bad = dir.path() / "bad.txt";
  std::ofstream(bad) << "1 2\n1 x\n";
  try {
    read_feature_edges(bad);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.txt:2:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_feature_edges(dir.path() / "missing.txt"), InputError);
}

// Input corners found exactly among the output's vertices.
std::size_t exact_corners(const TriangleMesh& in, const Features& f, const TriangleMesh& out) {
  return static_cast<std::size_t>(std::count_if(f.corners.begin(), f.corners.end(), [&](Index c) {
    return std::find(out.vertices.begin(), out.vertices.end(), in.vertices[c]) !=
           out.vertices.end();
  }));
}

RemeshResult remesh_to(const TriangleMesh& input, std::size_t vertices, FeatureSettings f = {}) {
  RemeshSettings s;
  s.vertices = vertices;
  s.features = f;
  return remesh(input, s);
}

TEST(RemeshFeatures, CubeKeepsCornersCreasesAndPlanarFaces) {
  const TriangleMesh cube = testing::cube(8);
  const RemeshResult r = remesh_to(cube, 1500);
  EXPECT_EQ(exact_corners(cube, r.features, r.mesh), 8u);
  EXPECT_EQ(r.feature_edges_missing, 0u);
  EXPECT_LT(feature_distance(cube, r.features.edges, r.mesh, r.feature_edges).max, 1e-9);
  // Every triangle lies in one face: its three vertices share a coordinate at ±1.
  for (const Triangle& t : r.mesh.triangles) {
    bool planar = false;
    for (int axis = 0; axis < 3; ++axis) {
      for (double side : {-1.0, 1.0}) {
        planar |= std::all_of(t.begin(), t.end(), [&](Index v) {
          const Vec3& p = r.mesh.vertices[v];
          return std::abs((axis == 0 ? p.x : axis == 1 ? p.y : p.z) - side) < 1e-9;
        });
      }
    }
    EXPECT_TRUE(planar);
  }
  const QualityReport q = measure_quality(r.mesh);
  EXPECT_GE(q.angle_min_deg, 30.0);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(cube)));
}

// Issue 22: feature distances are measured at about unit size, so any units give the same ones.
TEST(RemeshFeatures, FeatureDistanceOfAShapeScaledByAPowerOfTwoIsTheSameScaled) {
  const TriangleMesh in = testing::cube(4), out = testing::transformed(in, 1.02, {0.01, 0, 0});
  const std::vector<Edge> edges = detect_features(in, {}).edges;
  const FeatureDistance unit = feature_distance(in, edges, out, edges);
  ASSERT_GT(unit.max, 0.01);
  for (const int k : {-600, -20, 20, 600}) {
    const FeatureDistance d = feature_distance(scaled_by_power_of_two(in, k), edges,
                                               scaled_by_power_of_two(out, k), edges);
    EXPECT_EQ(d.max, std::ldexp(unit.max, k)) << "2^" << k;
    EXPECT_EQ(d.mean, std::ldexp(unit.mean, k)) << "2^" << k;
  }
}

TEST(RemeshFeatures, WithoutFeaturesTheCubeLosesItsCorners) {
  // The documented switch does what it says: the corners are no longer output vertices.
  const TriangleMesh cube = testing::cube(8);
  FeatureSettings off;
  off.sharp_edges = false;
  const RemeshResult r = remesh_to(cube, 1500, off);
  EXPECT_TRUE(r.features.empty());
  EXPECT_LT(exact_corners(cube, detect_features(cube, {}), r.mesh), 8u);
}

TEST(RemeshFeatures, UserEdgesAloneAreKept) {
  // Sharp edges off, one crease of the cube given by the user: its two ends become corners.
  const TriangleMesh cube = testing::cube(8);
  const Features all = detect_features(cube, {});
  FeatureSettings s;
  s.sharp_edges = false;
  for (std::size_t k = 0; k + 1 < all.curves[0].vertices.size(); ++k)
    s.user_edges.push_back({all.curves[0].vertices[k], all.curves[0].vertices[k + 1]});
  const RemeshResult r = remesh_to(cube, 1500, s);
  EXPECT_EQ(r.features.curves.size(), 1u);
  EXPECT_EQ(exact_corners(cube, r.features, r.mesh), 2u);
  EXPECT_EQ(r.feature_edges_missing, 0u);
}

TEST(Features, UserCornersAreCornersAndChecked) {
  const TriangleMesh sphere = testing::icosphere(2);
  FeatureSettings s;
  s.user_corners = {7, 3};
  const Features f = detect_features(sphere, s);
  EXPECT_EQ(f.corners, (std::vector<Index>{3, 7}));
  EXPECT_TRUE(f.edges.empty());
  EXPECT_FALSE(f.empty());
  s.user_corners = {static_cast<Index>(sphere.vertices.size())};
  EXPECT_THROW(detect_features(sphere, s), InvalidArgument);
}

TEST(RemeshFeatures, AUserCornerAloneOnASmoothSurfaceIsAnOutputVertex) {
  const TriangleMesh sphere = testing::icosphere(3);
  FeatureSettings s;
  s.user_corners = {5};
  const RemeshResult r = remesh_to(sphere, 400, s);
  EXPECT_EQ(exact_corners(sphere, r.features, r.mesh), 1u);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(sphere)));
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 25.0);
}

void expect_boundaries_kept(const TriangleMesh& input, std::size_t vertices) {
  const RemeshResult r = remesh_to(input, vertices);
  const TopologyReport in = analyze_topology(input), out = analyze_topology(r.mesh);
  EXPECT_TRUE(out.is_manifold());
  EXPECT_EQ(out.boundary_loops, in.boundary_loops);
  EXPECT_TRUE(same_topology(out, in));
  EXPECT_EQ(r.feature_edges_missing, 0u);
  // Every output boundary edge traces the input boundary.
  EXPECT_EQ(out.boundary_edges == 0, in.boundary_edges == 0);
  const FeatureDistance d = feature_distance(input, r.features.edges, r.mesh, r.feature_edges);
  EXPECT_LT(d.max, 0.01 * bounding_box(input).diagonal());
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 25.0);
}

TEST(RemeshFeatures, OpenDiskKeepsItsBoundary) {
  expect_boundaries_kept(testing::disk(24, 96), 800);
}

TEST(RemeshFeatures, OpenHemisphereKeepsItsBoundary) {
  expect_boundaries_kept(testing::hemisphere(24, 96), 1200);
}

TEST(RemeshFeatures, AJaggedRimFinerThanTheEdgesGivesNoNeedles) {
  // Edges of about 0.054 (400 vertices on the unit plate) against notches 1/80 wide: kept as
  // corners, the notches' turns would be output edges a quarter that long.
  const TriangleMesh plate = notched_plate(80, 8);
  const RemeshResult r = remesh_to(plate, 400);
  EXPECT_EQ(r.features.corners.size(), 4u);
  EXPECT_EQ(exact_corners(plate, r.features, r.mesh), 4u);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(plate)));
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 25.0);
}

// The curve seeds are evened out before a surface seed that took a stretch of a curve joins it
// (remesh/pipeline): most such stretches are gaps CCVT left between uneven curve seeds, and
// joining them all made the curves denser than the spacing (this cube at 1k: 160 edges along its
// creases for 144 at the spacing, θmin_ave 52.5°; the shared cube.off: 169 and 51.8°, now 146
// and 53.4°).
TEST(RemeshFeatures, CreasesGetAboutOneEdgePerSpacing) {
  const TriangleMesh cube = testing::cube(8);
  const std::size_t n = 1000;
  const RemeshResult r = remesh_to(cube, n);
  // 12 creases of length 2 on 6 faces of area 4, at the spacing of n vertices.
  const double spacing = std::sqrt(24 / (std::sqrt(3.0) / 2 * static_cast<double>(n)));
  const double at_spacing = 12 * 2 / spacing;
  EXPECT_EQ(r.feature_edges_missing, 0u);
  EXPECT_LE(static_cast<double>(r.feature_edges.size()), 1.05 * at_spacing);
  EXPECT_GE(static_cast<double>(r.feature_edges.size()), 0.95 * at_spacing);
  // θmin_ave varies with the random seeds by about a degree (shared cube.off at 1k, seeds 1-6:
  // 52.4° to 53.4°); the edge count above is what joining every stray changes.
  EXPECT_GE(measure_quality(r.mesh).angle_min_avg_deg, 52);
}

TEST(RemeshFeatures, ClosedCylinderKeepsItsRims) {
  const TriangleMesh cylinder = testing::cylinder(24, 96);
  const RemeshResult r = remesh_to(cylinder, 1500);
  ASSERT_EQ(r.features.curves.size(), 2u);
  EXPECT_TRUE(r.features.corners.empty());
  EXPECT_EQ(r.feature_edges_missing, 0u);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(cylinder)));
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 25.0);
}

TEST(RemeshFeaturesSharedData, FandiskAt3kTracesEveryCrease) {
  if (!std::filesystem::exists(shared_data() / "fandisk.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("fandisk.off");
  FeatureSettings f;
  f.angle_deg = 45;
  const RemeshResult r = remesh_to(in, 3000, f);
  const QualityReport q = measure_quality(r.mesh);
  // The issue asks θmin ≥ 24.35° and Qmin ≥ 0.541 too, but two of fandisk's creases meet at a
  // 19.4° tip: an output that traces both has a triangle about as narrow there (the chords to
  // the next seeds along the curved creases open it a little: 18.0-21.3° over seeds 1-4). θmin
  // is held near that bound instead.
  EXPECT_GE(q.angle_min_deg, 0.9 * narrowest_feature_sector_deg(in, r.features));
  EXPECT_GE(q.angle_min_avg_deg, 51.7);
  EXPECT_EQ(exact_corners(in, r.features, r.mesh), r.features.corners.size());
  EXPECT_EQ(r.feature_edges_missing, 0u);
  const double diagonal = bounding_box(in).diagonal();
  const FeatureDistance d = feature_distance(in, r.features.edges, r.mesh, r.feature_edges);
  EXPECT_LE(100 * d.mean / diagonal, 0.02);
  EXPECT_LE(100 * d.max / diagonal, 0.3);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(in)));
}

// Remeshes `in`, which has one input angle under 30° between features, to `vertices` with the
// defaults, and checks issue 18 item 6's promise there (θmin 30° and Qmin 0.6 away from it, 0.9
// of it at it) and the topology.
RemeshResult remesh_keeping_the_promise_at_one_tip(const TriangleMesh& in, std::size_t vertices) {
  RemeshSettings s;
  s.vertices = vertices;
  RemeshResult r = remesh(in, s);
  const std::vector<NarrowAngle> narrow = narrow_feature_angles(in, r.features, kNarrowAngleDeg);
  EXPECT_EQ(narrow.size(), 1u);
  const NarrowAngleQuality q = measure_away_from(r.mesh, measure_quality(r.mesh), narrow);
  EXPECT_GE(q.angle_min_away_deg, 30.0);
  EXPECT_GE(q.q_min_away, 0.6);
  EXPECT_GE(q.ratio_at_min, 0.9);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(in)));
  return r;
}

TEST(RemeshFeaturesSharedData, FandiskAt10kMeetsTheQualityBarAwayFromItsTip) {
  if (!std::filesystem::exists(shared_data() / "fandisk.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("fandisk.off");
  // Its 19.4° tip ends a narrow face between two creases: with even sizes up to the tip, the
  // triangle beside the tip's own was a sliver (θmin 22.9° away from the tip, Qmin 0.558); the
  // sizes now grade down into that wedge (WedgeGaps::traced_narrow).
  const RemeshResult r = remesh_keeping_the_promise_at_one_tip(in, 10000);
  EXPECT_EQ(exact_corners(in, r.features, r.mesh), r.features.corners.size());
}

TEST(RemeshFeatures, ANarrowTipTheOutputTracesHoldsItsNeighboursToTheBar) {
  // An 8° tip: its own triangle cannot be better than 8°. The last sweeps judge it against that
  // angle, so that lifting it never pays for a worse triangle beside it (judged against 60°, the
  // sweeps left Qmin 0.587 away from the tip at 1,500 vertices; lion.off's 8° tip at 10k, 15.3°).
  remesh_keeping_the_promise_at_one_tip(testing::wedge_sheet(8, 4, 60, 8), 1500);
}

TEST(RemeshFeaturesSharedData, ObtuseBoundaryCornersAreSplitWhereThatShapesBetter) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "blobby_3cc.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("corpus/blobby_3cc.off");
  // At 1k its worst triangle was the only one at a boundary corner of 114° (Q 0.513).
  RemeshSettings s;
  s.vertices = 1000;
  const RemeshResult r = remesh(in, s);
  EXPECT_GT(r.obtuse_corners_split, 0u);
  const QualityReport q = measure_quality(r.mesh);
  EXPECT_GE(q.q_min, 0.6);
  EXPECT_GE(q.angle_min_deg, 30.0);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(in)));
  EXPECT_EQ(exact_corners(in, r.features, r.mesh), r.features.corners.size());
}

TEST(RemeshFeaturesSharedData, TheFinishingSweepsRunAtOnceAndGiveTheSameOutputOnAnyThreadCount) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "ALSTOM_TEST4.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  // At 1k, components of this CAD part get both other candidate outputs, obtuse boundary
  // corners split and flat pairs merged (as measured), whose sweeps run beside the main one's
  // (finish_output): each chain in its fixed order, so one thread and two give the same.
  const TriangleMesh in = shared_mesh("corpus/ALSTOM_TEST4.off");
  RemeshSettings s;
  s.vertices = 1000;
  const RemeshResult all = remesh(in, s);
  RemeshResult one;
  {
    const tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
    one = remesh(in, s);
  }
  EXPECT_EQ(all.mesh.vertices, one.mesh.vertices);
  EXPECT_EQ(all.mesh.triangles, one.mesh.triangles);
  EXPECT_EQ(all.obtuse_corners_split, one.obtuse_corners_split);
  EXPECT_EQ(all.flat_pairs_merged, one.flat_pairs_merged);
}

TEST(RemeshFeaturesSharedData, JointAt3kKeepsCornersAndCreases) {
  if (!std::filesystem::exists(shared_data() / "joint.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("joint.off");
  // The targets are the paper's Table 1 (θmin 31.89°, Qmin 0.585), which one random
  // sampling meets and the next misses: over seeds 1-6, θmin spans 29.5-34.9° and Qmin
  // 0.47-0.61 (README). Each seed is held to what every one of them gives, and the mean θmin to
  // the paper's.
  double theta_sum = 0;
  constexpr int kSeeds = 6;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    RemeshSettings s;
    s.vertices = 3000;
    s.seed = static_cast<std::uint64_t>(seed);
    const RemeshResult r = remesh(in, s);
    EXPECT_EQ(exact_corners(in, r.features, r.mesh), r.features.corners.size()) << "seed " << seed;
    EXPECT_EQ(r.feature_edges_missing, 0u) << "seed " << seed;
    EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(in))) << "seed " << seed;
    const QualityReport q = measure_quality(r.mesh);
    EXPECT_GE(q.angle_min_deg, 29.0) << "seed " << seed;
    EXPECT_GE(q.q_min, 0.45) << "seed " << seed;
    theta_sum += q.angle_min_deg;
  }
  EXPECT_GE(theta_sum / kSeeds, 31.89);
}

// Boundary loops, topology and every corner kept; the curves traced closely on average.
void expect_boundary_loops_and_corners_kept(const TriangleMesh& in, const RemeshResult& r) {
  EXPECT_EQ(exact_corners(in, r.features, r.mesh), r.features.corners.size());
  const TopologyReport a = analyze_topology(r.mesh), b = analyze_topology(in);
  EXPECT_EQ(a.boundary_loops, b.boundary_loops);
  EXPECT_TRUE(same_topology(a, b));
  EXPECT_TRUE(a.is_manifold());
  const double diagonal = bounding_box(in).diagonal();
  const FeatureDistance d = feature_distance(in, r.features.edges, r.mesh, r.feature_edges);
  EXPECT_LE(100 * d.mean / diagonal, 0.1);
}

TEST(RemeshFeaturesSharedData, SharkKeepsItsBoundaryLoops) {
  if (!std::filesystem::exists(shared_data() / "mech-holes-shark.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("mech-holes-shark.off");
  // One corner is a 27° tip of a single input triangle, whose cell meets its neighbours'
  // only off the surface: it is kept by the triangle added there.
  const RemeshResult r = remesh_to(in, 3000);
  expect_boundary_loops_and_corners_kept(in, r);
  // A boundary there is a saw of teeth a third of the edge length deep, each one triangle:
  // its long sides were missed, until new seeds split them where both halves are then traced.
  const std::size_t links = r.feature_edges.size() + r.feature_edges_missing;
  EXPECT_LE(r.feature_edges_missing, links / 50) << "of " << links << " links";
}

// Thin wedges next to its creases: without topology control, cells there come in two pieces
// and the output had non-manifold edges and extra boundary loops; and creases were cut.
TEST(RemeshFeaturesSharedData, PlaneHolesKeepsItsBoundaryLoopsAndCreases) {
  if (!std::filesystem::exists(shared_data() / "plane_holes.obj"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh in = shared_mesh("plane_holes.obj");
  const RemeshResult r = remesh_to(in, 3000);
  expect_boundary_loops_and_corners_kept(in, r);
  EXPECT_EQ(r.feature_edges_missing, 0u);
}

}  // namespace
}  // namespace cvtmesh
