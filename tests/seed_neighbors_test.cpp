// The RVD's nearest-seed lists (voronoi/seed_neighbors): a search warm-started from earlier lists
// finds the same lists as one from scratch, whatever those earlier lists were.
#include <gtest/gtest.h>

#include <numeric>

#include "cvtmesh/sampling.hpp"
#include "geometry/point_tree.hpp"
#include "geometry/random.hpp"
#include "support/shapes.hpp"
#include "voronoi/seed_neighbors.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

constexpr std::size_t kLists = 12;

TEST(SeedNeighbors, WarmStartedListsAreTheColdOnes) {
  const TriangleMesh m = torus(1, 0.4, 64, 24);
  const std::vector<Vec3> before = sample_surface(m, 3000, 5);
  const SeedNeighbors earlier = nearest_neighbors(before, PointTree(before), kLists);
  CounterRng random(3, 0);
  const auto jitter = [&] { return 2 * random.uniform() - 1; };
  // Moves from a fraction of the spacing (about 0.045) to several spacings: the earlier lists
  // bound the search less and less tightly, never wrongly.
  for (const double step : {0.001, 0.01, 0.05, 0.3}) {
    std::vector<Vec3> after = before;
    for (Vec3& p : after) p += step * Vec3{jitter(), jitter(), jitter()};
    const PointTree tree(after);
    const SeedNeighbors cold = nearest_neighbors(after, tree, kLists);
    const SeedNeighbors warm = nearest_neighbors(after, tree, kLists, &earlier);
    EXPECT_EQ(warm.offsets, cold.offsets) << step;
    EXPECT_EQ(warm.ids, cold.ids) << step;
    EXPECT_EQ(warm.complete2, cold.complete2) << step;
  }
}

TEST(SeedNeighbors, AnyEarlierListsBoundTheSearchCorrectly) {
  // Lists of arbitrary other seeds, and lists too short to bound anything: still the cold lists.
  const TriangleMesh m = icosphere(3);
  const std::vector<Vec3> seeds = sample_surface(m, 800, 2);
  SeedNeighbors arbitrary, short_lists;
  arbitrary.offsets.resize(seeds.size() + 1);
  short_lists.offsets.assign(seeds.size() + 1, 0);
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    arbitrary.offsets[s + 1] = arbitrary.offsets[s] + kLists;
    for (std::size_t i = 1; i <= kLists; ++i)
      arbitrary.ids.push_back(static_cast<Index>((s + 37 * i) % seeds.size()));
  }
  arbitrary.complete2.assign(seeds.size(), 0);
  short_lists.complete2.assign(seeds.size(), 0);
  const PointTree tree(seeds);
  const SeedNeighbors cold = nearest_neighbors(seeds, tree, kLists);
  for (const SeedNeighbors* earlier : {&arbitrary, &short_lists}) {
    const SeedNeighbors warm = nearest_neighbors(seeds, tree, kLists, earlier);
    EXPECT_EQ(warm.ids, cold.ids);
    EXPECT_EQ(warm.complete2, cold.complete2);
  }
}

TEST(PointTree, ABoundPrunesNothingWithinIt) {
  const TriangleMesh m = icosphere(3);
  const std::vector<Vec3> points = sample_surface(m, 500, 7);
  const PointTree tree(points);
  std::vector<Index> unbounded, bounded;
  for (std::size_t p = 0; p < points.size(); p += 17) {
    tree.nearest(points[p], 9, unbounded);
    double farthest = 0;
    for (const Index q : unbounded)
      farthest = std::max(farthest, dot(points[q] - points[p], points[q] - points[p]));
    tree.nearest(points[p], 9, bounded, farthest * (1 + 1e-9));
    std::sort(unbounded.begin(), unbounded.end());
    std::sort(bounded.begin(), bounded.end());
    EXPECT_EQ(bounded, unbounded) << p;
  }
}

}  // namespace
}  // namespace cvtmesh
