// The geometry the sheets' zip stands on: which segment a point lies on (geometry/segment_grid),
// where along which polyline (geometry/polyline_index), and edge splits that keep every vertex's
// star (geometry/edge_splitter).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/topology.hpp"
#include "geometry/edge_splitter.hpp"
#include "geometry/polyline_index.hpp"
#include "geometry/segment_grid.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(SegmentGrid, FindsTheSegmentAPointLiesOnToARoundOff) {
  // Many short segments along x, and one long diagonal 500 of them long: a point on it is found
  // anywhere along it, one off it by more than the round-off nowhere.
  std::vector<Vec3> from, to;
  for (int i = 0; i < 1000; ++i) {
    from.push_back({0.01 * i, 0, 0});
    to.push_back({0.01 * (i + 1), 0, 0});
  }
  from.push_back({0, 1, 1});
  to.push_back({5, 6, 6});
  const SegmentGrid grid(from, to, 1e-9);
  const std::optional<SegmentGrid::Hit> on_short = grid.find({0.505, 0, 0});
  ASSERT_TRUE(on_short);
  EXPECT_EQ(on_short->segment, 50u);
  EXPECT_NEAR(on_short->u, 0.5, 1e-9);
  for (const double u : {0.0, 0.123, 0.5, 0.987, 1.0}) {
    const std::optional<SegmentGrid::Hit> hit = grid.find(Vec3{0, 1, 1} + u * Vec3{5, 5, 5});
    ASSERT_TRUE(hit) << u;
    EXPECT_EQ(hit->segment, 1000u);
    EXPECT_NEAR(hit->u, u, 1e-12);
  }
  EXPECT_FALSE(grid.find({2.5, 3.5, 3.5 + 1e-6}));
  EXPECT_FALSE(grid.find({0.505, 1e-6, 0}));
  EXPECT_FALSE(grid.find({20, 0, 0}));
}

TEST(PolylineIndex, GivesThePolylinesEndingAtAPointElseWhereAlongOneItLies) {
  // Two polylines meet at (1, 0, 0); the first bends there from a step 1 long to one 3 long, the
  // second is a closed triangle through that point.
  const std::vector<std::vector<Vec3>> polylines = {
      {{0, 0, 0}, {1, 0, 0}, {1, 3, 0}},
      {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 0, 0}},
  };
  const PolylineIndex index(polylines, 1e-9);
  // At an end exactly: every polyline ending there (the closed one at both of its ends).
  // (1, 0, 0) is inside the first polyline: not reported where one ends.
  std::vector<PolylineIndex::At> at = index.find({1, 0, 0});
  ASSERT_EQ(at.size(), 2u);
  EXPECT_EQ(at[0].polyline, 1u);
  EXPECT_EQ(at[1].polyline, 1u);
  EXPECT_EQ(at[0].t + at[1].t, 1.0);
  at = index.find({0, 0, 0});
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].polyline, 0u);
  EXPECT_EQ(at[0].t, 0.0);
  EXPECT_TRUE(at[0].end);
  at = index.find({1, 3, 0});
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].t, 1.0);
  // Inside: the arc-length fraction, across the bend.
  at = index.find({1, 1.5, 0});
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].polyline, 0u);
  EXPECT_NEAR(at[0].t, 2.5 / 4, 1e-12);
  EXPECT_FALSE(at[0].end);
  at = index.find({1.5, 0, 0});
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].polyline, 1u);
  EXPECT_NEAR(at[0].t, 0.5 / (2 + std::sqrt(2.0)), 1e-12);
  EXPECT_TRUE(index.find({0.5, 1e-6, 0}).empty());
}

TEST(EdgeSplitter, SplitsEveryTriangleOnTheEdgeAndKeepsTheStars) {
  // An edge of a sphere split three times along its length: 2 triangles become 8, the surface
  // stays a closed, consistently oriented sphere, and each star lists exactly its triangles.
  TriangleMesh m = icosphere(2);
  const std::size_t triangles = m.triangles.size();
  EdgeSplitter splitter(m);
  const Index p = m.triangles[0][0], q = m.triangles[0][1];
  Index from = p;
  for (const double u : {0.25, 0.5, 0.75}) {
    const auto x = static_cast<Index>(m.vertices.size());
    m.vertices.push_back(m.vertices[p] + u * (m.vertices[q] - m.vertices[p]));
    splitter.split(m, from, q, x);
    from = x;
  }
  EXPECT_EQ(m.triangles.size(), triangles + 6);
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_EQ(t.euler_characteristic, 2);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    std::vector<Index> around = splitter.around(v), expected;
    for (Index i = 0; i < m.triangles.size(); ++i)
      if (std::ranges::count(m.triangles[i], v)) expected.push_back(i);
    std::sort(around.begin(), around.end());
    EXPECT_EQ(around, expected) << v;
  }
}

}  // namespace
}  // namespace cvtmesh
