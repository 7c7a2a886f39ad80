// Handles thinner than the lengths narrow them, as small holes do (sizing/small_handles): found
// where a vertex's geodesic ball wraps round a handle, on surfaces whose handles are known.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>

#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "sizing/size_field.hpp"
#include "sizing/small_handles.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The angle around z of a point, in [-π, π].
double around_z(const Vec3& p) {
  return std::atan2(p.y, p.x);
}

TEST(SmallHandles, OnlyPartsOfGenusAboveZeroHaveHandles) {
  EXPECT_FALSE(has_handles(icosphere(3)));
  EXPECT_FALSE(has_handles(disk(6, 24)));
  EXPECT_FALSE(has_handles(cylinder(6, 24)));  // open both ends: two holes, no handle
  EXPECT_FALSE(has_handles(concatenate(icosphere(2), transformed(icosphere(2), 1, {3, 0, 0}))));
  EXPECT_TRUE(has_handles(torus(1, 0.3, 32, 12)));
  EXPECT_TRUE(
      has_handles(concatenate(icosphere(2), transformed(torus(1, 0.3, 32, 12), 1, {4, 0, 0}))));
  // A torus with holes cut in it keeps its handle; with a flap on one of its edges (three
  // triangles there) it is no surface, and says nothing.
  EXPECT_TRUE(has_handles(with_one_triangle_holes(torus(1, 0.3, 32, 12), 3, 50)));
  TriangleMesh flapped = torus(1, 0.3, 32, 12);
  const Triangle t = flapped.triangles[0];
  flapped.vertices.push_back({0, 0, 2});
  flapped.triangles.push_back({t[1], t[0], static_cast<Index>(flapped.vertices.size() - 1)});
  EXPECT_FALSE(has_handles(flapped));
}

TEST(SmallHandles, EveryVertexOfAThinTorusIsOnItsThroatAsWideAsTheTube) {
  // Tube radius 0.05: the loop round the tube through any vertex is 2π 0.05 long, a width
  // (loop over π) of 0.1, the tube's diameter; the loop along the ring is 2π long.
  const TriangleMesh thin = torus(1, 0.05, 192, 12);
  const std::vector<double> width = handle_widths(thin, 0.2);
  for (Index v = 0; v < thin.vertices.size(); ++v) {
    // Edge paths are longer than geodesics by a few percent; the polygon's loop is shorter than
    // the circle's.
    EXPECT_GT(width[v], 0.09) << "vertex " << v;
    EXPECT_LT(width[v], 0.12) << "vertex " << v;
  }
  // Looked for under half the tube's diameter, none is thin enough; nor at a reach far below any
  // scale of the mesh (its grid's cells would not number in 64 bits).
  for (const double w : handle_widths(thin, 0.05)) EXPECT_TRUE(std::isinf(w));
  for (const double w : handle_widths(thin, 1e-300)) EXPECT_TRUE(std::isinf(w));
}

TEST(SmallHandles, ANeckedTorusNarrowsAtItsNeckOnlyAndASphereNowhere) {
  const TriangleMesh necked = necked_torus(0.3, 0.02, 240, 24);
  const std::vector<double> width = handle_widths(necked, 0.2);
  double thinnest = INFINITY;
  int at_neck = 0;
  for (Index v = 0; v < necked.vertices.size(); ++v) {
    if (std::isinf(width[v])) continue;
    thinnest = std::min(thinnest, width[v]);
    // Only the throat, not the vertices whose own loops run to it and back.
    EXPECT_LT(std::abs(around_z(necked.vertices[v])), 0.15) << "vertex " << v;
    ++at_neck;
  }
  EXPECT_GE(at_neck, 24);  // the ring of the neck at least
  EXPECT_GT(thinnest, 0.9 * 0.04);
  EXPECT_LT(thinnest, 1.2 * 0.04);
  for (const double w : handle_widths(icosphere(3), 1)) EXPECT_TRUE(std::isinf(w));
}

TEST(SmallHandles, WidthsDoNotDependOnTheThreadCount) {
  const TriangleMesh necked = necked_torus(0.3, 0.02, 240, 24);
  const std::vector<double> all = handle_widths(necked, 0.2);
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(all, handle_widths(necked, 0.2));
}

TEST(SmallHandles, EvenSizesNarrowToANeckUnlessItsGradingTakesTooMany) {
  const TriangleMesh necked = necked_torus(0.3, 0.02, 240, 24);
  std::vector<Index> same(necked.vertices.size());
  std::iota(same.begin(), same.end(), Index{0});
  RemeshSettings s;
  s.vertices = 400;  // edges about 0.18: the neck, 0.04 across, is under half of that
  std::optional<TriangleMesh> split;
  const std::optional<SizeField> field = make_size_field(necked, same, s, nullptr, &split);
  ASSERT_TRUE(field.has_value());
  const TriangleMesh& on = split ? *split : necked;
  double at_neck = INFINITY, far = 0;
  for (Index v = 0; v < on.vertices.size(); ++v) {
    const double u = std::abs(around_z(on.vertices[v]));
    if (u < 0.02) at_neck = std::min(at_neck, field->at_vertex(v));
    if (u > 3) far = std::max(far, field->at_vertex(v));
  }
  EXPECT_LT(at_neck, 0.05);
  EXPECT_GT(far, 3 * at_neck);
  // A neck a hundredth as wide at a quarter of the count: graded down to it at a gradation of 1,
  // the sizes would take more than a tenth of the vertices; the even sizes stay even (no field,
  // no split copy) and topology control keeps the handle.
  const TriangleMesh hair = necked_torus(0.3, 0.0002, 240, 24);
  s.vertices = 100;
  split.reset();
  EXPECT_FALSE(make_size_field(hair, same, s, nullptr, &split).has_value());
  EXPECT_FALSE(split.has_value());
}

TEST(SmallHandles, AdaptiveSizesKeepSixEdgesRoundANeckAsRoundAHole) {
  // Even sizes cap a throat at its width (π edges round it), adaptive ones at half of it (six
  // edges round it, as cap_at_small_holes does round a hole): the neck is 0.04 across.
  const TriangleMesh necked = necked_torus(0.3, 0.02, 240, 24);
  std::vector<Index> same(necked.vertices.size());
  std::iota(same.begin(), same.end(), Index{0});
  RemeshSettings s;
  s.vertices = 400;
  s.sizing.adaptive = 1.5;
  const std::optional<SizeField> field = make_size_field(necked, same, s);
  ASSERT_TRUE(field.has_value());
  const std::vector<double> width = handle_widths(necked, 0.2);
  double at_neck = INFINITY;
  for (Index v = 0; v < necked.vertices.size(); ++v)
    if (std::isfinite(width[v])) {
      EXPECT_LE(field->at_vertex(v), width[v] / 2 * (1 + 1e-9)) << "vertex " << v;
      at_neck = std::min(at_neck, field->at_vertex(v));
    }
  EXPECT_GT(at_neck, 0.9 * 0.02);
}

TEST(SmallHandles, ANeckThinnerThanTheEdgesGetsItsCellsFromTheStart) {
  // At 400 vertices the edges are about 0.18 long, and the neck 0.04 across: the even sizes
  // grade down to it, so the first extraction keeps the handle and topology control adds no
  // seed (without the handle's sizes the rounds added 22, the run 2.7 times as long).
  const TriangleMesh necked = necked_torus(0.3, 0.02, 240, 24);
  RemeshSettings s;
  s.vertices = 400;
  const RemeshResult r = remesh(necked, s);
  EXPECT_TRUE(same_topology(analyze_topology(r.mesh), analyze_topology(necked)));
  EXPECT_EQ(r.islands_seeded + r.seeds_refined, 0u);
  EXPECT_EQ(r.mesh.vertices.size(), 400u);
  // The ring round the neck: output vertices within the neck's 0.15-radian stretch.
  int near_neck = 0;
  for (const Vec3& p : r.mesh.vertices) near_neck += std::abs(around_z(p)) < 0.15;
  EXPECT_GE(near_neck, 6);
  // Adaptive sizes narrow there too.
  s.sizing.adaptive = 1.5;
  const RemeshResult a = remesh(necked, s);
  EXPECT_TRUE(same_topology(analyze_topology(a.mesh), analyze_topology(necked)));
  EXPECT_EQ(a.islands_seeded + a.seeds_refined, 0u);
}

}  // namespace
}  // namespace cvtmesh
