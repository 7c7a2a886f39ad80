// Boundary corners whose one triangle holds an obtuse angle (finish/split_obtuse_corners): the
// edge across halved, the corner's angle shared by two triangles, the topology kept; nothing done
// across a feature edge, where the surface is far, at an inner vertex or under 100°. Under the bar
// (ObtuseCorners::under_bar): inner vertices too, the worst first, few at a time; given the
// curves, a feature or boundary edge across halved on its curve; none at a narrow input angle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cvtmesh/topology.hpp"
#include "features/edge_uses.hpp"
#include "finish/split_obtuse_corners.hpp"
#include "geometry/angle.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// A flat strip of two triangles: the ear (c, a, b) with an angle of `deg` at the boundary corner
// c, and (b, a, d) across its edge a-b.
TriangleMesh ear(double deg) {
  const double half = deg / 2 * std::numbers::pi / 180;
  TriangleMesh m;
  // a and b 2 apart, c above their middle at the height that makes the angle; d below.
  m.vertices = {{-1, 0, 0}, {1, 0, 0}, {0, 1 / std::tan(half), 0}, {0, -1.7, 0}};
  m.triangles = {{2, 0, 1}, {1, 0, 3}};
  return m;
}

TEST(SplitObtuseCorners, AnObtuseCornerGetsTwoTrianglesOfHalfItsAngle) {
  TriangleMesh m = ear(114);
  const TopologyReport before = analyze_topology(m);
  const SurfaceProjector plane(m);
  EXPECT_EQ(split_obtuse_corners(m, {}, plane), 1u);
  ASSERT_EQ(m.vertices.size(), 5u);
  ASSERT_EQ(m.triangles.size(), 4u);
  const TopologyReport after = analyze_topology(m);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.consistently_oriented);
  EXPECT_TRUE(same_topology(after, before));
  EXPECT_EQ(after.boundary_loops, 1u);
  for (const Triangle& t : m.triangles) {
    const auto [a, b, c] = std::array{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    EXPECT_GT(cross(b - a, c - a).z, 0) << "orientation kept";
    for (int k = 0; k < 3; ++k)
      if (t[k] == 2) {  // the corner: its angle halved
        const Vec3& p = m.vertices[t[k]];
        EXPECT_NEAR(angle_deg(m.vertices[t[(k + 1) % 3]] - p, m.vertices[t[(k + 2) % 3]] - p), 57,
                    1e-9);
      }
  }
  EXPECT_EQ(distance(m.vertices[4], Vec3{0, 0, 0}), 0);  // the midpoint, on the surface
}

TEST(SplitObtuseCorners, NothingAcrossAFeatureFarFromTheSurfaceAtAnInnerVertexOrUnder100Degrees) {
  TriangleMesh feature = ear(114);
  EXPECT_EQ(split_obtuse_corners(feature, {Edge{0, 1}}, SurfaceProjector(feature)), 0u);
  TriangleMesh far = ear(114);  // the surface half an edge away: another sheet
  TriangleMesh sheet = ear(114);
  for (Vec3& p : sheet.vertices) p.z += 1;
  EXPECT_EQ(split_obtuse_corners(far, {}, SurfaceProjector(sheet)), 0u);
  TriangleMesh acute = ear(95);
  EXPECT_EQ(split_obtuse_corners(acute, {}, SurfaceProjector(acute)), 0u);
  // The corner made an inner vertex: a fan closing round it.
  TriangleMesh inner = ear(114);
  inner.vertices.push_back({-1.5, 2, 0});
  inner.vertices.push_back({1.5, 2, 0});
  inner.triangles.push_back({2, 4, 0});
  inner.triangles.push_back({2, 5, 4});
  inner.triangles.push_back({2, 1, 5});
  const std::size_t triangles = inner.triangles.size();
  EXPECT_EQ(split_obtuse_corners(inner, {}, SurfaceProjector(inner)), 0u);
  EXPECT_EQ(inner.triangles.size(), triangles);
}

// The ear's corner made an inner vertex: a fan closing round it, shifted by `x`.
TriangleMesh inner_corner(double deg, double x = 0) {
  TriangleMesh m = ear(deg);
  m.vertices.push_back({-1.5, 2, 0});
  m.vertices.push_back({1.5, 2, 0});
  m.triangles.push_back({2, 4, 0});
  m.triangles.push_back({2, 5, 4});
  m.triangles.push_back({2, 1, 5});
  return transformed(m, 1, {x, 0, 0});
}

TEST(SplitObtuseCorners, UnderTheBarAnInnerObtuseCornerIsSplitToo) {
  TriangleMesh m = inner_corner(114);  // Q about 0.5
  const TopologyReport before = analyze_topology(m);
  const SurfaceProjector plane(m);
  EXPECT_EQ(split_obtuse_corners(m, {}, plane, ObtuseCorners::at_boundary), 0u);
  EXPECT_EQ(split_obtuse_corners(m, {}, plane, ObtuseCorners::under_bar), 1u);
  const TopologyReport after = analyze_topology(m);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.consistently_oriented);
  EXPECT_TRUE(same_topology(after, before));
  EXPECT_EQ(m.vertices.back(), (Vec3{0, 0, 0}));
  // At 102°, between two 39° angles, the triangle's Q is 0.61: at the bar, left as it is.
  TriangleMesh at_bar = inner_corner(102);
  EXPECT_EQ(split_obtuse_corners(at_bar, {}, SurfaceProjector(at_bar), ObtuseCorners::under_bar),
            0u);
}

TEST(SplitObtuseCorners, UnderTheBarTheWorstIsSplitFirstAndOnePerHundredVertices) {
  // Two fans apart, 12 vertices: one split; the 124° corner's, not the 114° one's.
  TriangleMesh m = concatenate(inner_corner(114), inner_corner(124, 10));
  EXPECT_EQ(split_obtuse_corners(m, {}, SurfaceProjector(m), ObtuseCorners::under_bar), 1u);
  EXPECT_EQ(m.vertices.back(), (Vec3{10, 0, 0}));
}

TEST(SplitObtuseCorners, UnderTheBarNothingAtANarrowInputAngle) {
  // The 124° corner's triangle has a vertex at a narrow angle: held to that angle, not to the bar,
  // so the 114° one is split in its stead.
  TriangleMesh m = concatenate(inner_corner(114), inner_corner(124, 10));
  std::vector<double> at_narrow(m.vertices.size(), 0);
  for (Index v = 0; v < m.vertices.size(); ++v) at_narrow[v] = m.vertices[v].x > 5 ? 20 : 0;
  EXPECT_EQ(split_obtuse_corners(m, {}, SurfaceProjector(m), ObtuseCorners::under_bar, nullptr,
                                 &at_narrow),
            1u);
  EXPECT_EQ(m.vertices.back(), (Vec3{0, 0, 0}));
  std::fill(at_narrow.begin(), at_narrow.end(), 20);
  at_narrow.push_back(20);
  EXPECT_EQ(split_obtuse_corners(m, {}, SurfaceProjector(m), ObtuseCorners::under_bar, nullptr,
                                 &at_narrow),
            0u);
}

TEST(SplitObtuseCorners, UnderTheBarAFeatureEdgeAcrossIsHalvedOnItsCurve) {
  // The inner corner's edge across, 0-1, is a crease's: no flip takes it. Given the curves, it
  // is halved at its foot on the crease, which becomes a vertex of that curve, and the edge its
  // two halves; without them, or with its vertices on two curves, it stays.
  TriangleMesh m = inner_corner(114);
  Features crease;
  crease.edges = {Edge{0, 1}};
  crease.curves = {{{0, 1}, false}};
  const CurveProjector curves(m, crease);
  const SurfaceProjector plane(m);
  TriangleMesh alone = m;
  EXPECT_EQ(split_obtuse_corners(alone, crease.edges, plane, ObtuseCorners::under_bar), 0u);
  std::vector<VertexSupport> supports(m.vertices.size());
  supports[0] = supports[1] = {VertexSupport::Kind::curve, 0};
  std::vector<VertexSupport> on_two = supports;
  on_two[1].curve = 1;
  std::vector<Edge> edges = crease.edges;
  CurveSplits apart{curves, on_two, edges};
  TriangleMesh two = m;
  EXPECT_EQ(split_obtuse_corners(two, crease.edges, plane, ObtuseCorners::under_bar, &apart), 0u);
  const TopologyReport before = analyze_topology(m);
  CurveSplits along{curves, supports, edges};
  EXPECT_EQ(split_obtuse_corners(m, crease.edges, plane, ObtuseCorners::under_bar, &along), 1u);
  const auto mid = static_cast<Index>(m.vertices.size() - 1);
  EXPECT_EQ(m.vertices[mid], (Vec3{0, 0, 0}));
  ASSERT_EQ(supports.size(), m.vertices.size());
  EXPECT_EQ(supports[mid].kind, VertexSupport::Kind::curve);
  EXPECT_EQ(supports[mid].curve, 0u);
  EXPECT_EQ(edges, (std::vector<Edge>{Edge{0, mid}, Edge{1, mid}}));
  const TopologyReport after = analyze_topology(m);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.consistently_oriented);
  EXPECT_TRUE(same_topology(after, before));
  for (const Triangle& t : m.triangles) {
    const auto [a, b, c] = std::array{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    EXPECT_GT(cross(b - a, c - a).z, 0) << "orientation kept";
  }
}

TEST(SplitObtuseCorners, TheMiddleOfAnEdgeWithAGuardedEndIsGuarded) {
  // The inner corner's edge across, 0-1, halved under the bar: its middle is guarded (its changes
  // checked for crossings, finish/crossing_guard) where either end is, and not otherwise.
  for (const bool guarded : {false, true}) {
    TriangleMesh m = inner_corner(114);
    std::vector<VertexSupport> supports(m.vertices.size());
    supports[1].guarded = guarded;
    const CurveProjector none(m, Features{});
    std::vector<Edge> edges;
    CurveSplits along{none, supports, edges};
    ASSERT_EQ(split_obtuse_corners(m, {}, SurfaceProjector(m), ObtuseCorners::under_bar, &along),
              1u);
    ASSERT_EQ(supports.size(), m.vertices.size());
    EXPECT_EQ(m.vertices.back(), (Vec3{0, 0, 0}));
    EXPECT_EQ(supports.back().kind, VertexSupport::Kind::surface);
    EXPECT_EQ(supports.back().guarded, guarded);
  }
}

TEST(SplitObtuseCorners, UnderTheBarABoundaryEdgeAcrossIsHalvedOnItsLoop) {
  // An ear of 130° whose edge across is the boundary (the strip without its lower triangle), its
  // corner an inner vertex: the boundary edge halved, one triangle becoming two.
  TriangleMesh m = inner_corner(130);
  m.triangles.erase(m.triangles.begin() + 1);  // (1, 0, 3): vertex 3 left unused
  Features loop;
  loop.edges = sorted_edges(m);
  std::erase_if(loop.edges, [&](const Edge& e) {
    return e != Edge{0, 1} && e != Edge{0, 4} && e != Edge{4, 5} && e != Edge{1, 5};
  });
  loop.curves = {{{0, 1, 5, 4}, true}};
  const CurveProjector curves(m, loop);
  std::vector<VertexSupport> supports(m.vertices.size());
  for (const Index v : {0u, 1u, 4u, 5u}) supports[v] = {VertexSupport::Kind::curve, 0};
  std::vector<Edge> edges = loop.edges;
  CurveSplits along{curves, supports, edges};
  const std::size_t triangles = m.triangles.size();
  EXPECT_EQ(
      split_obtuse_corners(m, loop.edges, SurfaceProjector(m), ObtuseCorners::under_bar, &along),
      1u);
  EXPECT_EQ(m.triangles.size(), triangles + 1);
  EXPECT_EQ(m.vertices.back(), (Vec3{0, 0, 0}));
  EXPECT_EQ(edges.size(), loop.edges.size() + 1);
  const TopologyReport after = analyze_topology(m);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_EQ(after.boundary_loops, 1u);
}

}  // namespace
}  // namespace cvtmesh
