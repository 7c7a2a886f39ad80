// A traversal that replays from a TraversalMemory the triangles no changed seed reaches hands
// its sinks exactly what a traversal without it does: the same polygons, to the bit, in the same
// chunks and order, whether seeds moved, came, went or tie with others.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "cvtmesh/rvd.hpp"
#include "cvtmesh/sampling.hpp"
#include "geometry/random.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// Every call a sink gets, per chunk in order, with each vertex to the bit.
class CallLog : public PolygonSink {
 public:
  using Vertex = std::tuple<double, double, double, double, std::int32_t, std::int32_t>;
  using Call = std::tuple<Index, Index, std::vector<Vertex>>;
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    std::vector<Vertex> vertices;
    for (const RvdVertex& v : p.vertices)
      vertices.emplace_back(v.point.x, v.point.y, v.point.z, v.error, v.symbols[0], v.symbols[1]);
    chunks_[chunk].emplace_back(p.seed, p.triangle, std::move(vertices));
  }
  const std::vector<std::vector<Call>>& chunks() const { return chunks_; }

 private:
  std::vector<std::vector<Call>> chunks_;
};

// Traverses the diagram of `seeds` with `memory` (its neighbour lists and its polygons) and
// without; expects the same calls, and returns the traversal's stats with memory.
TraversalStats expect_same_as_fresh(const TriangleMesh& m, const std::vector<Vec3>& seeds,
                                    TraversalMemory& memory) {
  const RestrictedVoronoiDiagram rvd(m, seeds), remembering(m, seeds, memory);
  CallLog fresh, remembered;
  PolygonSink* fresh_sinks[] = {&fresh};
  PolygonSink* remembered_sinks[] = {&remembered};
  const TraversalStats fresh_stats = rvd.traverse(fresh_sinks);
  const TraversalStats stats = remembering.traverse(remembered_sinks, memory);
  EXPECT_EQ(stats.polygons, fresh_stats.polygons);
  EXPECT_EQ(fresh_stats.triangles_replayed, 0u);
  EXPECT_TRUE(fresh.chunks() == remembered.chunks());
  return stats;
}

double spacing_of(const TriangleMesh& m, std::size_t seeds) {
  return std::sqrt(surface_area(m) / static_cast<double>(seeds));
}

TEST(TraversalMemory, SeedsThatMoveComeOrGoChangeOnlyTheTrianglesTheyReach) {
  const TriangleMesh m = torus(1, 0.4, 120, 48);  // 11,520 triangles: many chunks
  std::vector<Vec3> seeds = sample_surface(m, 2000, 9);
  const double spacing = spacing_of(m, seeds.size());
  CounterRng random(5, 0);
  const auto jitter = [&] { return spacing * Vec3{random.uniform(), random.uniform(), 0.5}; };
  TraversalMemory memory;
  EXPECT_EQ(expect_same_as_fresh(m, seeds, memory).triangles_replayed, 0u);  // empty at first
  // The same seeds: every triangle replayed.
  EXPECT_EQ(expect_same_as_fresh(m, seeds, memory).triangles_replayed, m.triangles.size());
  const auto replayed_share = [&] {
    return static_cast<double>(expect_same_as_fresh(m, seeds, memory).triangles_replayed) /
           static_cast<double>(m.triangles.size());
  };
  // Ten seeds nudged, as polishing moves them.
  for (std::size_t s = 0; s < seeds.size(); s += 200) seeds[s] += 0.3 * jitter();
  EXPECT_GT(replayed_share(), 0.8);
  // Twenty seeds come in, as topology control adds them.
  const std::vector<Vec3> more = sample_surface(m, 20, 77);
  seeds.insert(seeds.end(), more.begin(), more.end());
  EXPECT_GT(replayed_share(), 0.8);
  // A seed jumps across the torus, others go (back to an earlier round's seeds).
  seeds[7] = seeds[1500] + 0.01 * jitter();
  seeds.resize(seeds.size() - 35);
  EXPECT_GT(replayed_share(), 0.8);
  // All seeds move: nothing is replayed, all is right.
  for (Vec3& p : seeds) p += 0.01 * jitter();
  EXPECT_EQ(replayed_share(), 0.0);
}

TEST(TraversalMemory, CoarseTrianglesAndTiesAreReplayedExactly) {
  // A coarse input (each triangle hundreds of cells wide), seeds come in.
  const TriangleMesh coarse = cube(1);
  std::vector<Vec3> seeds = sample_surface(coarse, 3000, 2);
  TraversalMemory memory;
  expect_same_as_fresh(coarse, seeds, memory);
  // The seeds that came in are missing from the others' carried lists, where a fresh search
  // puts them first: the cells clip in another order, yet come in the same order.
  const std::vector<Vec3> more = sample_surface(coarse, 100, 8);
  seeds.insert(seeds.end(), more.begin(), more.end());
  expect_same_as_fresh(coarse, seeds, memory);
  // Seeds on a grid at the mesh's vertices, where the perturbation decides ties; seeds come in
  // at the middles of edges, ties again, and one moves onto a free vertex.
  const TriangleMesh grid = cube(4);
  TraversalMemory tied;
  std::vector<Vec3> at_vertices(grid.vertices.begin(), grid.vertices.begin() + 40);
  EXPECT_GT(expect_same_as_fresh(grid, at_vertices, tied).perturbed_ties, 0u);
  for (std::size_t t = 0; t < grid.triangles.size(); t += 37)
    at_vertices.push_back(
        0.5 * (grid.vertices[grid.triangles[t][0]] + grid.vertices[grid.triangles[t][1]]));
  at_vertices[3] = grid.vertices[60];
  const TraversalStats stats = expect_same_as_fresh(grid, at_vertices, tied);
  EXPECT_GT(stats.triangles_replayed, 0u);
  EXPECT_LT(stats.triangles_replayed, grid.triangles.size());
}

// Counts the vertices whose error bound is infinite: crossings that the formula could not place,
// placed by interpolation between the edge's ends.
class PlacedByInterpolation : public PolygonSink {
 public:
  void begin(std::size_t) override {}
  void polygon(std::size_t, const RvdPolygon& p) override {
    for (const RvdVertex& v : p.vertices) count += !std::isfinite(v.error);
  }
  std::size_t count = 0;
};

TEST(TraversalMemory, CrossingsPlacedByInterpolationAreReplayedAsTheyWere) {
  // Two seeds mirrored across a flat square, one a single rounding step off: their bisector is
  // all but the square's own plane, and where it crosses an edge the formula is ill-conditioned.
  const TriangleMesh square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  std::vector<Vec3> seeds{{0.1, 0.2, 1}, {std::nextafter(0.1, 1.0), 0.2, -1}, {0.8, 0.7, 0.3}};
  const RestrictedVoronoiDiagram rvd(square, seeds);
  PlacedByInterpolation placed;
  rvd.traverse(placed);
  ASSERT_GT(placed.count, 0u) << "no crossing was ill-conditioned: the test tests nothing";
  TraversalMemory memory;
  expect_same_as_fresh(square, seeds, memory);
  EXPECT_EQ(expect_same_as_fresh(square, seeds, memory).triangles_replayed, 2u);
}

TEST(TraversalMemory, AnotherSurfaceStartsAfresh) {
  const TriangleMesh sphere = icosphere(3), torus_mesh = torus(1, 0.4, 24, 12);
  TraversalMemory memory;
  expect_same_as_fresh(sphere, sample_surface(sphere, 300, 1), memory);
  EXPECT_EQ(expect_same_as_fresh(torus_mesh, sample_surface(torus_mesh, 300, 1), memory)
                .triangles_replayed,
            0u);
}

}  // namespace
}  // namespace cvtmesh
