// The lists of a mesh's triangle sides that the remesher sorts in linear time (sorted_sides,
// edge_uses: geometry/sort_by_edge.hpp) and the duplicate-triangle removal bucketed alike: on a
// random soup with repeated corners, edges of many triangles and copies of triangles, each must
// give exactly what a comparison sort of the whole gives, on any thread count.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>

#include "cvtmesh/repair.hpp"
#include "features/edge_uses.hpp"
#include "geometry/orient_triangles.hpp"
#include "geometry/triangle_sides.hpp"

namespace cvtmesh {
namespace {

// `triangles` triangles over a tenth as many vertices: most edges have several triangles, some
// sides have one vertex twice, and a tenth of the triangles repeat an earlier one in another
// order.
TriangleMesh random_soup(std::size_t triangles) {
  std::mt19937 rng(7);
  const auto vertices = static_cast<Index>(triangles / 10);
  std::uniform_int_distribution<Index> vertex(0, vertices - 1);
  TriangleMesh m;
  for (Index v = 0; v < vertices; ++v)
    m.vertices.push_back(
        {static_cast<double>(v % 7), static_cast<double>(v / 7 % 5), static_cast<double>(v / 35)});
  for (std::size_t t = 0; t < triangles; ++t) {
    if (t > 0 && t % 10 == 0) {
      Triangle copy = m.triangles[vertex(rng) % m.triangles.size()];
      std::rotate(copy.begin(), copy.begin() + static_cast<std::ptrdiff_t>(t % 3), copy.end());
      if (t % 20 == 0) std::swap(copy[1], copy[2]);
      m.triangles.push_back(copy);
      continue;
    }
    Triangle f{vertex(rng), vertex(rng), vertex(rng)};
    if (t % 37 == 0) f[2] = f[0];  // a side from a vertex to itself
    m.triangles.push_back(f);
  }
  return m;
}

constexpr std::size_t kLarge = 150'000;

TEST(TriangleSides, AreSortedAsAComparisonSortOfAllSidesSortsThem) {
  const TriangleMesh m = random_soup(kLarge);
  std::vector<TriangleSide> expected;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      expected.push_back({std::min(a, b), std::max(a, b), static_cast<Index>(t), a < b,
                          static_cast<std::uint8_t>(k)});
    }
  const auto key = [](const TriangleSide& s) { return std::tie(s.lo, s.hi, s.triangle, s.side); };
  std::sort(expected.begin(), expected.end(),
            [&](const TriangleSide& x, const TriangleSide& y) { return key(x) < key(y); });
  const std::vector<TriangleSide> sides = sorted_sides(m);
  ASSERT_EQ(sides.size(), expected.size());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    EXPECT_EQ(key(sides[i]), key(expected[i])) << i;
    EXPECT_EQ(sides[i].forward, expected[i].forward) << i;
  }
}

TEST(TriangleSides, EdgeUsesAreSortedByEdgeThenCorner) {
  const TriangleMesh m = random_soup(kLarge);
  std::vector<EdgeUse> expected;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      expected.push_back({edge_of(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), 3 * t + k});
  std::sort(expected.begin(), expected.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.edge, x.corner) < std::tie(y.edge, y.corner);
  });
  const std::vector<EdgeUse> uses = edge_uses(m);
  // The same on one thread (the buckets are sorted in parallel).
  std::vector<EdgeUse> on_one;
  tbb::task_arena(1).execute([&] { on_one = edge_uses(m); });
  ASSERT_EQ(uses.size(), expected.size());
  ASSERT_EQ(on_one.size(), expected.size());
  for (std::size_t i = 0; i < uses.size(); ++i) {
    EXPECT_EQ(uses[i].edge, expected[i].edge) << i;
    EXPECT_EQ(uses[i].corner, expected[i].corner) << i;
    EXPECT_EQ(on_one[i].edge, expected[i].edge) << i;
    EXPECT_EQ(on_one[i].corner, expected[i].corner) << i;
  }
}

TEST(TriangleSides, EdgeUsesKeepOnlyTheEdgesAsked) {
  const TriangleMesh m = random_soup(kLarge);
  const auto keep = [](const Edge& e) { return (e[0] + e[1]) % 3 == 0; };
  std::vector<EdgeUse> expected;
  for (const EdgeUse& use : edge_uses(m))
    if (keep(use.edge)) expected.push_back(use);
  const std::vector<EdgeUse> uses = edge_uses(m, keep);
  ASSERT_EQ(uses.size(), expected.size());
  for (std::size_t i = 0; i < uses.size(); ++i) {
    EXPECT_EQ(uses[i].edge, expected[i].edge) << i;
    EXPECT_EQ(uses[i].corner, expected[i].corner) << i;
  }
}

TEST(TriangleSides, TheSidesGivenServeTheOrientationCheck) {
  TriangleMesh m = random_soup(3000);
  // Two triangles that walk their shared edge the same way, apart from the soup's: one must flip.
  const auto n = static_cast<Index>(m.vertices.size());
  for (const Vec3& p : {Vec3{10, 0, 0}, Vec3{11, 0, 0}, Vec3{10, 1, 0}, Vec3{11, 1, 0}})
    m.vertices.push_back(p);
  m.triangles.push_back({n, n + 1, n + 2});
  m.triangles.push_back({n + 1, n + 2, n + 3});
  const std::vector<std::size_t> flips = triangles_to_flip(m);
  EXPECT_FALSE(flips.empty());
  EXPECT_EQ(triangles_to_flip(m, sorted_sides(m)), flips);
}

TEST(RemoveDuplicateTriangles, KeepsTheFirstOfEachSetOfCornersInFileOrder) {
  TriangleMesh m = random_soup(kLarge);
  std::vector<Triangle> expected;
  std::set<Triangle> seen;  // sorted corners of those kept
  for (const Triangle& t : m.triangles) {
    Triangle k = t;
    std::sort(k.begin(), k.end());
    if (seen.insert(k).second) expected.push_back(t);
  }
  ASSERT_LT(expected.size(), m.triangles.size());  // the soup has copies
  const std::size_t removed = remove_duplicate_triangles(m);
  EXPECT_EQ(removed, kLarge - expected.size());
  EXPECT_EQ(m.triangles, expected);
}

}  // namespace
}  // namespace cvtmesh
