// A traversal that replays from a TraversalMemory the triangles no changed seed reaches hands
// its sinks exactly what a traversal without it does: the same polygons, to the bit, in the same
// chunks and order, whether seeds moved, came, went or tie with others.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "cvtmesh/rvd.hpp"
#include "cvtmesh/sampling.hpp"
#include "geometry/random.hpp"
#include "support/shapes.hpp"
#include "voronoi/cell_pieces.hpp"
#include "voronoi/multi_nerve.hpp"

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

 protected:
  std::vector<Call>& chunk(std::size_t c) { return chunks_[c]; }

 private:
  std::vector<std::vector<Call>> chunks_;
};

// Traverses the diagram of `seeds` with `memory` (its neighbour lists and its polygons) into
// `remembered` and without into a fresh log; expects the same calls, and returns the traversal's
// stats with memory.
TraversalStats expect_same_as_fresh(const TriangleMesh& m, const std::vector<Vec3>& seeds,
                                    TraversalMemory& memory, CallLog& remembered) {
  const RestrictedVoronoiDiagram rvd(m, seeds), remembering(m, seeds, memory);
  CallLog fresh;
  PolygonSink* fresh_sinks[] = {&fresh};
  PolygonSink* remembered_sinks[] = {&remembered};
  const TraversalStats fresh_stats = rvd.traverse(fresh_sinks);
  const TraversalStats stats = remembering.traverse(remembered_sinks, memory);
  EXPECT_EQ(stats.polygons, fresh_stats.polygons);
  EXPECT_EQ(fresh_stats.triangles_replayed, 0u);
  EXPECT_TRUE(fresh.chunks() == remembered.chunks());
  return stats;
}

TraversalStats expect_same_as_fresh(const TriangleMesh& m, const std::vector<Vec3>& seeds,
                                    TraversalMemory& memory) {
  CallLog remembered;
  return expect_same_as_fresh(m, seeds, memory, remembered);
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

// A CallLog that keeps its chunks from one traversal to the next (PolygonSink::keeps_chunks),
// counting the polygons it is handed.
class KeepingLog : public CallLog {
 public:
  bool keeps_chunks() const override { return true; }
  void begin_kept(std::size_t chunks, const std::vector<char>& kept) override {
    std::vector<std::vector<Call>> was = this->chunks();
    begin(chunks);
    for (std::size_t c = 0; c < chunks; ++c)
      if (kept[c]) chunk(c) = std::move(was[c]);
  }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    CallLog::polygon(chunk, p);
    ++handed;
  }
  std::atomic<std::size_t> handed = 0;  // chunks come in on several threads
};

// expect_same_as_fresh into `keeping`: returns how many polygons it was handed, and how many
// the diagram has.
std::pair<std::size_t, std::size_t> expect_kept_as_fresh(const TriangleMesh& m,
                                                         const std::vector<Vec3>& seeds,
                                                         TraversalMemory& memory,
                                                         KeepingLog& keeping) {
  keeping.handed = 0;
  const std::size_t polygons = expect_same_as_fresh(m, seeds, memory, keeping).polygons;
  return {keeping.handed, polygons};
}

TEST(TraversalMemory, SinksThatKeepChunksGetOnlyThoseThatChanged) {
  const TriangleMesh m = torus(1, 0.4, 120, 48);  // 11,520 triangles: many chunks
  std::vector<Vec3> seeds = sample_surface(m, 2000, 9);
  const double spacing = spacing_of(m, seeds.size());
  CounterRng random(5, 0);
  const auto jitter = [&] { return spacing * Vec3{random.uniform(), random.uniform(), 0.5}; };
  TraversalMemory memory;
  KeepingLog keeping;
  const auto handed = [&] { return expect_kept_as_fresh(m, seeds, memory, keeping).first; };
  const auto [first, all] = expect_kept_as_fresh(m, seeds, memory, keeping);
  EXPECT_EQ(first, all);    // a first traversal hands over everything
  EXPECT_EQ(handed(), 0u);  // the same seeds: nothing
  // Seeds nudged, seeds that come in, seeds that go, all near one spot (as polishing and
  // topology control change them): only the chunks they reach.
  const Vec3 spot = seeds[0];
  for (Vec3& p : seeds)
    if (distance(p, spot) < 2 * spacing) p += 0.3 * jitter();
  const std::size_t nudged = handed();
  EXPECT_GT(nudged, 0u);
  EXPECT_LT(nudged, all / 4);
  for (int k = 0; k < 5; ++k) seeds.push_back(spot + 0.5 * jitter());
  EXPECT_LT(handed(), all / 4);
  seeds.resize(seeds.size() - 3);
  EXPECT_LT(handed(), all / 4);
  // A traversal without the memory, or with another, leaves the sink holding chunks of no
  // record of this memory: the next one with it hands over every polygon.
  const RestrictedVoronoiDiagram elsewhere(m, seeds);
  elsewhere.traverse(keeping);
  seeds[11] += 0.3 * jitter();
  const auto [after_none, all_now] = expect_kept_as_fresh(m, seeds, memory, keeping);
  EXPECT_EQ(after_none, all_now);
  TraversalMemory other;
  expect_kept_as_fresh(m, seeds, other, keeping);
  seeds[12] += 0.3 * jitter();
  const auto [after_other, polygons] = expect_kept_as_fresh(m, seeds, memory, keeping);
  EXPECT_EQ(after_other, polygons);
  // A sink that did not serve the memory's last traversal gets every polygon too.
  KeepingLog newcomer;
  seeds[13] += 0.3 * jitter();
  const auto [new_handed, new_polygons] = expect_kept_as_fresh(m, seeds, memory, newcomer);
  EXPECT_EQ(new_handed, new_polygons);
}

TEST(TraversalMemory, AKeptMultiNerveIsTheFreshOne) {
  // Two sheets closer than the spacing: cells in several pieces, which the multi-nerve gives one
  // vertex each, come and go as seeds change.
  const TriangleMesh sheets = concatenate(icosphere(4), icosphere(4, 1.03));
  std::vector<Vec3> seeds = sample_surface(sheets, 600, 3);
  const double spacing = spacing_of(sheets, seeds.size());
  CounterRng random(2, 0);
  const auto jitter = [&] { return spacing * Vec3{random.uniform(), random.uniform(), 0.5}; };
  TraversalMemory memory;
  MultiNerveBuilder kept(CellPieceCollector::Keeping{}, sheets, nullptr);
  std::size_t far_pieces = 0;
  const auto expect_fresh = [&] {
    const RestrictedVoronoiDiagram rvd(sheets, seeds), remembering(sheets, seeds, memory);
    MultiNerveBuilder fresh(rvd);
    rvd.traverse(fresh);
    kept.for_diagram(remembering);
    PolygonSink* sinks[] = {&kept};
    remembering.traverse(sinks, memory);
    EXPECT_EQ(kept.result().vertices, fresh.result().vertices);
    EXPECT_EQ(kept.result().triangles, fresh.result().triangles);
    EXPECT_EQ(kept.vertex_seed(), fresh.vertex_seed());
    // The cells' pieces too: those of cells that no change reached are kept as they were.
    const std::vector<CellPiece>& a = kept.pieces().pieces();
    const std::vector<CellPiece>& b = fresh.pieces().pieces();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(std::tie(a[i].seed, a[i].first, a[i].area, a[i].largest_area),
                std::tie(b[i].seed, b[i].first, b[i].area, b[i].largest_area));
      EXPECT_EQ(a[i].moment, b[i].moment);
      EXPECT_EQ(a[i].largest_centre, b[i].largest_centre);
    }
    far_pieces += fresh.result().vertices.size() - seeds.size();
  };
  expect_fresh();
  expect_fresh();
  for (std::size_t s = 0; s < seeds.size(); s += 50) seeds[s] += 0.3 * jitter();
  expect_fresh();
  const std::vector<Vec3> more = sample_surface(sheets, 15, 5);
  seeds.insert(seeds.end(), more.begin(), more.end());
  expect_fresh();
  seeds.resize(seeds.size() - 25);
  expect_fresh();
  // One seed at a time, as topology control's rounds add them where defects are.
  for (const Vec3& p : sample_surface(sheets, 30, 11)) {
    seeds.push_back(p);
    expect_fresh();
  }
  EXPECT_GT(far_pieces, 0u) << "no cell in several pieces: the test tests too little";
}

// A cell that leaves a chunk that changed, and keeps its polygons in a chunk kept, is joined
// again: its pieces are not as they were.
TEST(TraversalMemory, KeptCellPiecesJoinAgainACellThatLeftAChangedChunk) {
  const TriangleMesh square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  // The whole of triangle t as seed s's polygon (corner k on edges k and k + 2 mod 3).
  std::array<RvdVertex, 3> corners;
  const auto whole = [&](Index s, Index t) {
    for (int k = 0; k < 3; ++k)
      corners[k] = {square.vertices[square.triangles[t][k]], 0, {-(k + 1), -((k + 2) % 3 + 1)}};
    return RvdPolygon{s, t, corners};
  };
  // One chunk per triangle. First seed 0 has both triangles; then chunk 0 is kept and seed 1
  // takes triangle 1.
  CellPieceCollector kept(CellPieceCollector::Keeping{}, square, nullptr);
  kept.begin(2);
  kept.polygon(0, whole(0, 0));
  kept.polygon(1, whole(0, 1));
  kept.end();
  ASSERT_EQ(kept.pieces().size(), 1u);
  EXPECT_DOUBLE_EQ(kept.pieces()[0].area, 1.0);
  kept.begin_kept(2, {1, 0});
  kept.polygon(1, whole(1, 1));
  kept.end();
  CellPieceCollector fresh(square);
  fresh.begin(2);
  fresh.polygon(0, whole(0, 0));
  fresh.polygon(1, whole(1, 1));
  fresh.end();
  ASSERT_EQ(kept.pieces().size(), fresh.pieces().size());
  for (std::size_t i = 0; i < fresh.pieces().size(); ++i) {
    EXPECT_EQ(kept.pieces()[i].seed, fresh.pieces()[i].seed);
    EXPECT_EQ(kept.pieces()[i].area, fresh.pieces()[i].area);
  }
  EXPECT_EQ(kept.piece_at(0, 0), fresh.piece_at(0, 0));
  EXPECT_EQ(kept.piece_at(1, 1), fresh.piece_at(1, 1));
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
