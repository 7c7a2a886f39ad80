// RVD benchmarks (issue targets, paper §5 timing plot): RVD time against the time of CGAL's 3D
// Delaunay triangulation of the same seeds (the paper's baseline), measured in the same
// process so the ratio survives a noisy machine. The RVD time is all of it: kd-tree, nearest-
// seed lists, and one traversal with integrals.
//   BM_RvdVsDelaunay/N/T: icosphere level 4 (5,120 faces), N random seeds, the RVD on T threads
//     (the Delaunay triangulation is serial); counters delaunay_s, rvd_s and rvd_over_delaunay.
//   BM_RvdLargeMesh/T: ../shared/data/igea.ply (268,686 faces), 10k seeds, T threads; counter
//     rvd_s, and exact_fallback_pct of the predicates.
//   BM_RvdShuffledInput: igea's vertices and triangles shuffled, 10k seeds, 1 thread: an RVD pass
//     on the file's order (stored_s), on the shuffled copy (shuffled_s), and on the shuffled copy
//     sorted by spatially_sorted, the sort included (sorted_s); sorted_over_stored is the
//     order-independence figure (issue 19: at most 1.15), pass_sorted_over_stored the same
//     without the sort, which a remesh makes once for all its passes.
//   BM_SpatialSort/T: the sort alone (spatially_sorted) of igea shuffled, on T threads, against
//     an RVD pass on its output with as many (sort_over_pass): what a remesh pays once.
//   BM_RvdCoarseInput/N/T: a cube of 12 triangles, N random seeds, each triangle thousands of
//     cells wide (issue 19: coarse inputs cost what their cells cost); as above.
//   BM_RvdGradedSeeds/N: the same cube, N seeds of which three quarters crowd one corner (a
//     size field graded beside coarse facets, as on CAD parts): the sparse cells reach past their
//     stored nearest seeds and across several triangles, where radius searches are kept and
//     reused (radius_searches counts those made); as above, on 1 thread.
//   BM_RvdDegenerate: seeds on the vertices of a grid-like cube mesh, where ties abound;
//     compares to random seeds on the same mesh (exact_fallback_pct, ties).
//   BM_RvdNeighborCache/N: icosphere level 5, N seeds (random, then 5 Lloyd steps) moved by 2% of
//     their spacing, as
//     between two steps of the optimization: an RVD pass with integrals whose nearest-seed lists
//     come from a NeighborCache filled before the move (cached_s) against one that searches them
//     (fresh_s); cached_over_fresh (issue 19 item 2).
//   BM_NeighborListsWarm/N: the nearest-seed lists alone (12 a seed, one thread), on the seeds of
//     BM_RvdNeighborCache moved by 20% of their spacing, as early steps of an optimization move
//     them, past what the cache keeps: searched from scratch (cold_s) against searched within the
//     bound that the lists before the move give each seed (warm_s); warm_over_cold.
//   BM_MultiNerveExtraction/N: the output's extraction (restricted Delaunay triangulation with
//     the cells' pieces, paper §4.4: what every polishing and topology round runs) on icosphere
//     level 5 (20,480 faces) with N random seeds, against an RVD pass with integrals on the same
//     seeds (extraction_over_pass).
//   BM_PieceShapes/T: each cell piece's Euler characteristic and farthest vertex (what topology
//     control's check of the ball property reads each round, voronoi/piece_euler), after a
//     traversal with the pieces on icosphere level 5 with 10k random seeds, on T threads:
//     the time of the shapes alone, and shapes_over_traversal.
//   BM_SpreadSamples/N: the initial seeds of a uniform remesh, N points spread by sample
//     elimination (spread_s) on icosphere level 5, against random ones (random_s) and one RVD
//     pass with integrals on them (pass_s); spread_over_pass is the cost in passes (the spread
//     seeds spare the optimization about 5 of its first iterations, paper §4.1's initial
//     sampling), and energy_ratio the spread seeds' CVT energy over the random ones'.
//   BM_CvtPass/M/D: one evaluation of the CVT objective as the optimizer makes it in its steady
//     state, on one thread: a diagram of 5,000 well-spread seeds (sample elimination, as a remesh
//     starts) built with a warm NeighborCache, then traversed with integrals (the surface's unit
//     normals kept, as the objective keeps them); M = 0 on icosphere level 5 (20,480 faces), 1 on
//     ../shared/data/fandisk.off (12,946 faces); D = 1 with a density (ρ from 1 to about 4 across
//     the bounding box, linear over each triangle, as adaptive sizes give one), 0 without. Timed as
//     Google Benchmark times a loop (many iterations; compare runs by their min with repetitions),
//     with counters polygons_per_pass and ns_per_polygon: the cost of the clipping core.
//   BM_SeedOrder/N: N spread seeds (sample elimination, which returns them in Morton order) on
//     icosphere level 6 (81,920 faces), in that order against the same seeds shuffled, on one
//     thread: an RVD pass with integrals and an extraction, each with its build;
//     pass_sorted_over_shuffled and extraction_sorted_over_shuffled (issue 19 item 1: sort the
//     seeds too; every array indexed by seed is then read in runs).
//   BM_ExtractionAfterSeedsAdded/N: that extraction again after 1% more seeds came in, as a round
//     of topology control adds them: with the TraversalMemory of the extraction before
//     (remembered_s: lists carried over, the triangles no new seed reaches replayed) against one
//     made afresh (fresh_s); remembered_over_fresh and replayed_pct (issue 18: topology control
//     works locally).
//   BM_PolishCoarseFacets/N/S: polishing alone (one round of 5 local Lloyd steps around every
//     defect, cvt/polish_defects) on a coarse surface, each triangle many cells wide: S = 0 a cube
//     of 12 triangles, S = 1 a 128-sided cylinder whose sides are 256 slivers 2 long and 0.05
//     wide. N converged seeds (a remesh's), one of every 1,000th triangle dragged towards another,
//     against the same seeds on the same surface cut into triangles smaller than the cells (the
//     cube into 27,648, the cylinder's sides into 64 rings): coarse_over_fine (issue 19 item 3: a
//     facet costs what its cells cost), and the seeds each moved.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include "cvt/polish_defects.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sampling.hpp"
#include "delaunay_baseline.hpp"
#include "geometry/point_tree.hpp"
#include "geometry/spread_samples.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"
#include "voronoi/multi_nerve.hpp"
#include "voronoi/piece_euler.hpp"
#include "voronoi/seed_neighbors.hpp"

namespace {

using namespace cvtmesh;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

struct Pass {
  double delaunay_s, rvd_s;
  TraversalStats stats;
};

Pass rvd_pass(const TriangleMesh& mesh, const std::vector<Vec3>& seeds) {
  const double delaunay_s = bench::delaunay_seconds(seeds);
  const auto start = Clock::now();
  const RestrictedVoronoiDiagram rvd(mesh, seeds);
  CellIntegrator integrator(rvd);
  const TraversalStats stats = rvd.traverse(integrator);
  const double rvd_s = seconds(start);
  benchmark::DoNotOptimize(integrator.result().total_energy);
  return {delaunay_s, rvd_s, stats};
}

void report(benchmark::State& state, const Pass& p) {
  state.SetIterationTime(p.delaunay_s + p.rvd_s);
  state.counters["delaunay_s"] = p.delaunay_s;
  state.counters["rvd_s"] = p.rvd_s;
  state.counters["rvd_over_delaunay"] = p.rvd_s / p.delaunay_s;
  state.counters["exact_fallback_pct"] = 100.0 * static_cast<double>(p.stats.exact_fallbacks) /
                                         static_cast<double>(p.stats.predicates);
  state.counters["ties"] = static_cast<double>(p.stats.perturbed_ties);
  state.counters["radius_searches"] = static_cast<double>(p.stats.radius_searches);
}

// RVD against Delaunay with `seeds` on `mesh`, the RVD on `threads` threads (CGAL's Delaunay is
// serial: the ratio is for one thread each).
void seeds_pass(benchmark::State& state, const TriangleMesh& mesh, const std::vector<Vec3>& seeds,
                std::size_t threads) {
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  for (auto _ : state) report(state, rvd_pass(mesh, seeds));
}

// As seeds_pass, with state.range(0) random seeds, on state.range(1) threads.
void random_seeds_pass(benchmark::State& state, const TriangleMesh& mesh) {
  seeds_pass(state, mesh, sample_surface(mesh, static_cast<std::size_t>(state.range(0)), 1),
             static_cast<std::size_t>(state.range(1)));
}

void BM_RvdVsDelaunay(benchmark::State& state) {
  random_seeds_pass(state, testing::icosphere(4));
}
BENCHMARK(BM_RvdVsDelaunay)
    ->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000}, {1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_RvdLargeMesh(benchmark::State& state) {
  const auto path = testing::shared_data() / "igea.ply";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("igea.ply not found (set CVTMESH_SHARED_DATA)");
    return;
  }
  const TriangleMesh mesh = read_mesh(path);
  const auto seeds = sample_surface(mesh, 10'000, 1);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) report(state, rvd_pass(mesh, seeds));
}
BENCHMARK(BM_RvdLargeMesh)
    ->Arg(1)
    ->Arg(2)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_RvdShuffledInput(benchmark::State& state) {
  const auto path = testing::shared_data() / "igea.ply";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("igea.ply not found (set CVTMESH_SHARED_DATA)");
    return;
  }
  const TriangleMesh stored = read_mesh(path), mixed = testing::shuffled(stored, 7);
  const auto seeds = sample_surface(stored, 10'000, 1);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state) {
    const Pass as_stored = rvd_pass(stored, seeds), as_shuffled = rvd_pass(mixed, seeds);
    const auto start = Clock::now();
    const SpatiallySorted sorted = spatially_sorted(mixed);
    const double sort_s = seconds(start);
    const Pass after_sort = rvd_pass(sorted.mesh, seeds);
    state.SetIterationTime(as_stored.rvd_s + as_shuffled.rvd_s + sort_s + after_sort.rvd_s);
    state.counters["stored_s"] = as_stored.rvd_s;
    state.counters["shuffled_s"] = as_shuffled.rvd_s;
    state.counters["sort_s"] = sort_s;
    state.counters["sorted_s"] = sort_s + after_sort.rvd_s;
    state.counters["sorted_over_stored"] = (sort_s + after_sort.rvd_s) / as_stored.rvd_s;
    state.counters["pass_sorted_over_stored"] = after_sort.rvd_s / as_stored.rvd_s;
  }
}
BENCHMARK(BM_RvdShuffledInput)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_SpatialSort(benchmark::State& state) {
  const auto path = testing::shared_data() / "igea.ply";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("igea.ply not found (set CVTMESH_SHARED_DATA)");
    return;
  }
  const TriangleMesh mixed = testing::shuffled(read_mesh(path), 7);
  const auto seeds = sample_surface(mixed, 10'000, 1);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const auto start = Clock::now();
    const SpatiallySorted sorted = spatially_sorted(mixed);
    const double sort_s = seconds(start);
    const Pass pass = rvd_pass(sorted.mesh, seeds);
    state.SetIterationTime(sort_s);
    state.counters["sort_over_pass"] = sort_s / pass.rvd_s;
  }
}
BENCHMARK(BM_SpatialSort)
    ->Arg(1)
    ->Arg(2)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_RvdCoarseInput(benchmark::State& state) {
  random_seeds_pass(state, testing::cube(1));
}
BENCHMARK(BM_RvdCoarseInput)
    ->ArgsProduct({{5'000, 50'000}, {1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_RvdGradedSeeds(benchmark::State& state) {
  const TriangleMesh mesh = testing::cube(1);
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<Vec3> seeds = sample_surface(mesh, n / 4, 1);
  for (const Vec3& p : sample_surface(mesh, 4 * n, 2))
    if (seeds.size() < n && p.x > 0.25 && p.y > 0.25 && p.z > 0.25) seeds.push_back(p);
  seeds_pass(state, mesh, seeds, 1);
}
BENCHMARK(BM_RvdGradedSeeds)
    ->Arg(5'000)
    ->Arg(50'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_RvdDegenerate(benchmark::State& state) {
  const TriangleMesh mesh = testing::cube(40);  // 19,200 faces, 9,602 grid vertices
  const bool grid = state.range(0) == 1;
  const auto seeds = grid ? mesh.vertices : sample_surface(mesh, mesh.vertices.size(), 1);
  for (auto _ : state) report(state, rvd_pass(mesh, seeds));
  state.SetLabel(grid ? "seeds on grid vertices" : "random seeds");
}
BENCHMARK(BM_RvdDegenerate)
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_SpreadSamples(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto energy = [&](const std::vector<Vec3>& seeds) {
    const RestrictedVoronoiDiagram rvd(mesh, seeds);
    CellIntegrator integrator(rvd);
    rvd.traverse(integrator);
    return integrator.result().total_energy;
  };
  for (auto _ : state) {
    auto start = Clock::now();
    const std::vector<Vec3> random = sample_surface(mesh, n, 1);
    const double random_s = seconds(start);
    start = Clock::now();
    const std::vector<Vec3> spread = spread_samples(mesh, n, 1);
    const double spread_s = seconds(start);
    start = Clock::now();
    const double random_energy = energy(random);
    const double pass_s = seconds(start);
    state.SetIterationTime(spread_s);
    state.counters["random_s"] = random_s;
    state.counters["spread_s"] = spread_s;
    state.counters["pass_s"] = pass_s;
    state.counters["spread_over_pass"] = spread_s / pass_s;
    state.counters["energy_ratio"] = energy(spread) / random_energy;
  }
}
BENCHMARK(BM_SpreadSamples)
    ->Arg(5'000)
    ->Arg(50'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// N seeds on the unit sphere spread as in an optimization's later steps: random seeds, then a
// few Lloyd steps (each seed to its cell's centroid, back onto the sphere).
std::vector<Vec3> lloyd_spread_seeds(const TriangleMesh& mesh, std::size_t n) {
  std::vector<Vec3> seeds = sample_surface(mesh, n, 1);
  for (int step = 0; step < 5; ++step) {
    const RestrictedVoronoiDiagram rvd(mesh, seeds);
    CellIntegrator integrator(rvd);
    rvd.traverse(integrator);
    for (std::size_t s = 0; s < n; ++s)
      if (integrator.result().mass[s] > 0)
        seeds[s] = (1 / norm(integrator.result().centroid(static_cast<Index>(s)))) *
                   integrator.result().centroid(static_cast<Index>(s));
  }
  return seeds;
}

// `seeds` moved by `fraction` of their spacing on the unit sphere, in a fixed, spread-out pattern
// (no random numbers needed).
std::vector<Vec3> moved_seeds(std::vector<Vec3> seeds, double fraction) {
  const double spacing = std::sqrt(4 * 3.141592653589793 / static_cast<double>(seeds.size()));
  for (std::size_t s = 0; s < seeds.size(); ++s)
    seeds[s] += fraction * spacing * Vec3{std::sin(3.0 * s), std::cos(5.0 * s), std::sin(7.0 * s)};
  return seeds;
}

void BM_RvdNeighborCache(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<Vec3> before = lloyd_spread_seeds(mesh, n);
  const std::vector<Vec3> after = moved_seeds(before, 0.02);
  const auto pass = [&](const RestrictedVoronoiDiagram& rvd, const Clock::time_point start) {
    CellIntegrator integrator(rvd);
    const TraversalStats stats = rvd.traverse(integrator);
    benchmark::DoNotOptimize(integrator.result().total_energy);
    return std::pair(seconds(start), stats.radius_searches);
  };
  for (auto _ : state) {
    NeighborCache cache;
    const RestrictedVoronoiDiagram first(mesh, before, cache);
    auto start = Clock::now();
    const auto [fresh_s, fresh_searches] = pass(RestrictedVoronoiDiagram(mesh, after), start);
    start = Clock::now();
    const auto [cached_s, cached_searches] =
        pass(RestrictedVoronoiDiagram(mesh, after, cache), start);
    state.SetIterationTime(fresh_s + cached_s);
    state.counters["fresh_s"] = fresh_s;
    state.counters["cached_s"] = cached_s;
    state.counters["cached_over_fresh"] = cached_s / fresh_s;
    state.counters["radius_searches_fresh"] = static_cast<double>(fresh_searches);
    state.counters["radius_searches_cached"] = static_cast<double>(cached_searches);
  }
}
BENCHMARK(BM_RvdNeighborCache)
    ->Arg(5'000)
    ->Arg(20'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_NeighborListsWarm(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<Vec3> before = lloyd_spread_seeds(mesh, n);
  const std::vector<Vec3> after = moved_seeds(before, 0.2);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  constexpr std::size_t kLists = 12;  // as the RVD stores
  const SeedNeighbors earlier = nearest_neighbors(before, PointTree(before), kLists);
  const PointTree tree(after);
  for (auto _ : state) {
    auto start = Clock::now();
    const SeedNeighbors cold = nearest_neighbors(after, tree, kLists);
    const double cold_s = seconds(start);
    start = Clock::now();
    const SeedNeighbors warm = nearest_neighbors(after, tree, kLists, &earlier);
    const double warm_s = seconds(start);
    if (warm.ids != cold.ids || warm.complete2 != cold.complete2)
      state.SkipWithError("the warm-started lists differ from the cold ones");
    state.SetIterationTime(cold_s + warm_s);
    state.counters["cold_s"] = cold_s;
    state.counters["warm_s"] = warm_s;
    state.counters["warm_over_cold"] = warm_s / cold_s;
  }
}
BENCHMARK(BM_NeighborListsWarm)
    ->Arg(10'000)
    ->Arg(100'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

// The time of the output's extraction of `seeds` (the multi-nerve RDT), its diagram's build
// included.
double extraction_seconds(const TriangleMesh& mesh, const std::vector<Vec3>& seeds) {
  const auto start = Clock::now();
  const RestrictedVoronoiDiagram rvd(mesh, seeds);
  MultiNerveBuilder rdt(rvd);
  rvd.traverse(rdt);
  benchmark::DoNotOptimize(rdt.result().triangles.size());
  return seconds(start);
}

void BM_MultiNerveExtraction(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto seeds = sample_surface(mesh, static_cast<std::size_t>(state.range(0)), 1);
  for (auto _ : state) {
    const Pass pass = rvd_pass(mesh, seeds);
    const double extraction_s = extraction_seconds(mesh, seeds);
    state.SetIterationTime(pass.rvd_s + extraction_s);
    state.counters["pass_s"] = pass.rvd_s;
    state.counters["extraction_s"] = extraction_s;
    state.counters["extraction_over_pass"] = extraction_s / pass.rvd_s;
  }
}
BENCHMARK(BM_MultiNerveExtraction)
    ->Arg(10'000)
    ->Arg(100'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_PieceShapes(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto seeds = sample_surface(mesh, 10'000, 1);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const RestrictedVoronoiDiagram rvd(mesh, seeds);
    CellPieceCollector pieces(mesh);
    PieceEulerCollector euler(mesh, seeds);
    PolygonSink* sinks[] = {&pieces, &euler};
    const auto start = Clock::now();
    rvd.traverse(sinks);
    const double traverse_s = seconds(start);
    const auto shapes_start = Clock::now();
    benchmark::DoNotOptimize(euler.shapes(pieces).size());
    const double shapes_s = seconds(shapes_start);
    state.SetIterationTime(shapes_s);
    state.counters["shapes_over_traversal"] = shapes_s / traverse_s;
  }
}
BENCHMARK(BM_PieceShapes)
    ->Arg(1)
    ->Arg(2)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

void BM_CvtPass(benchmark::State& state) {
  const bool shared = state.range(0) == 1;
  const bool dense = state.range(1) == 1;
  if (shared && !std::filesystem::exists(testing::shared_data() / "fandisk.off")) {
    state.SkipWithError("fandisk.off not found (set CVTMESH_SHARED_DATA)");
    return;
  }
  const TriangleMesh mesh = shared ? testing::shared_mesh("fandisk.off") : testing::icosphere(5);
  const std::vector<Vec3> seeds = spread_samples(mesh, 5'000, 1);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  NeighborCache cache;
  { const RestrictedVoronoiDiagram warm(mesh, seeds, cache); }
  const std::vector<Vec3> normals = unit_normals(mesh);  // as the objective keeps them
  // A density that varies over the whole surface, as adaptive sizes give one (issue 20).
  std::vector<double> density;
  if (dense) {
    const BoundingBox box = bounding_box(mesh);
    for (const Vec3& v : mesh.vertices)
      density.push_back(1 + 3 * distance(v, box.min) / box.diagonal());
  }
  std::size_t polygons = 0;
  for (auto _ : state) {
    const RestrictedVoronoiDiagram rvd(mesh, seeds, cache);
    CellIntegrator integrator(rvd, density, normals);
    polygons = rvd.traverse(integrator).polygons;
    benchmark::DoNotOptimize(integrator.result().total_energy);
  }
  state.counters["polygons_per_pass"] = static_cast<double>(polygons);
  state.counters["ns_per_polygon"] =
      benchmark::Counter(static_cast<double>(polygons) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(std::string(shared ? "fandisk.off" : "icosphere level 5") +
                 (dense ? ", with a density" : ""));
}
BENCHMARK(BM_CvtPass)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", [](const std::vector<double>& v) {
      return *std::min_element(v.begin(), v.end());
    });

// One pass with integrals and one extraction of `seeds`, each with its diagram's build, on one
// thread: their times.
std::pair<double, double> pass_and_extraction(const TriangleMesh& mesh,
                                              const std::vector<Vec3>& seeds) {
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const auto start = Clock::now();
  {
    const RestrictedVoronoiDiagram rvd(mesh, seeds);
    CellIntegrator integrator(rvd);
    rvd.traverse(integrator);
    benchmark::DoNotOptimize(integrator.result().total_energy);
  }
  const double pass_s = seconds(start);
  return {pass_s, extraction_seconds(mesh, seeds)};
}

void BM_SeedOrder(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(6);
  const std::vector<Vec3> sorted =
      spread_samples(mesh, static_cast<std::size_t>(state.range(0)), 1);
  std::vector<Vec3> shuffled = sorted;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(1));
  for (auto _ : state) {
    const auto [sorted_pass, sorted_extraction] = pass_and_extraction(mesh, sorted);
    const auto [shuffled_pass, shuffled_extraction] = pass_and_extraction(mesh, shuffled);
    state.SetIterationTime(sorted_pass + sorted_extraction + shuffled_pass + shuffled_extraction);
    state.counters["sorted_pass_s"] = sorted_pass;
    state.counters["shuffled_pass_s"] = shuffled_pass;
    state.counters["pass_sorted_over_shuffled"] = sorted_pass / shuffled_pass;
    state.counters["extraction_sorted_over_shuffled"] = sorted_extraction / shuffled_extraction;
  }
}
BENCHMARK(BM_SeedOrder)
    ->Arg(10'000)
    ->Arg(50'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_ExtractionAfterSeedsAdded(benchmark::State& state) {
  const TriangleMesh mesh = testing::icosphere(5);
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<Vec3> before = sample_surface(mesh, n, 1);
  std::vector<Vec3> after = before;
  const std::vector<Vec3> added = sample_surface(mesh, n / 100, 2);
  after.insert(after.end(), added.begin(), added.end());
  // An extraction of `seeds`, the diagram's build (kd-tree, lists) included; with `memory` if
  // given, whose triangulation keeps the chunks that no added seed reaches. Returns its time and
  // the triangles it did not clip.
  const auto extract = [&](const std::vector<Vec3>& seeds, ExtractionMemory* memory) {
    const auto start = Clock::now();
    const RestrictedVoronoiDiagram rvd =
        memory ? RestrictedVoronoiDiagram(mesh, seeds, memory->traversal)
               : RestrictedVoronoiDiagram(mesh, seeds);
    std::optional<MultiNerveBuilder> fresh;
    if (memory)
      memory->nerve.for_diagram(rvd);
    else
      fresh.emplace(rvd);
    MultiNerveBuilder& rdt = memory ? memory->nerve : *fresh;
    PolygonSink* sinks[] = {&rdt};
    const TraversalStats stats =
        memory ? rvd.traverse(sinks, memory->traversal) : rvd.traverse(sinks);
    benchmark::DoNotOptimize(rdt.result().triangles.size());
    return std::pair(seconds(start), stats.triangles_replayed);
  };
  const Interrupt never;
  for (auto _ : state) {
    ExtractionMemory memory(mesh, never);
    extract(before, &memory);
    const double fresh_s = extract(after, nullptr).first;
    const auto [remembered_s, replayed] = extract(after, &memory);
    state.SetIterationTime(fresh_s + remembered_s);
    state.counters["fresh_s"] = fresh_s;
    state.counters["remembered_s"] = remembered_s;
    state.counters["remembered_over_fresh"] = remembered_s / fresh_s;
    state.counters["replayed_pct"] =
        100.0 * static_cast<double>(replayed) / static_cast<double>(mesh.triangles.size());
  }
}
BENCHMARK(BM_ExtractionAfterSeedsAdded)
    ->Arg(10'000)
    ->Arg(100'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_PolishCoarseFacets(benchmark::State& state) {
  const bool slivers = state.range(1) == 1;
  const TriangleMesh coarse = slivers ? testing::cylinder(1, 128) : testing::cube(1);
  const TriangleMesh fine = slivers ? testing::cylinder(64, 128) : testing::cube(48);
  // Converged seeds (a remesh's output vertices, unpolished and unfitted), one of every 1,000th
  // triangle dragged 80% of the way to a neighbour: a few dozen defects apart from each other.
  RemeshSettings settings;
  settings.vertices = static_cast<std::size_t>(state.range(0));
  settings.features.sharp_edges = false;
  settings.polish_rounds = settings.shape_sweeps = settings.fit_rounds = 0;
  const TriangleMesh converged = remesh(coarse, settings).mesh;
  std::vector<Vec3> seeds = converged.vertices;
  for (std::size_t t = 0; t < converged.triangles.size(); t += 1000) {
    const Triangle& f = converged.triangles[t];
    seeds[f[0]] = seeds[f[0]] + 0.8 * (seeds[f[1]] - seeds[f[0]]);
  }
  // Polishing's time on `surface`; `moved`: the seeds it moved.
  const auto polish = [&](const TriangleMesh& surface, std::size_t& moved) {
    const SurfaceProjector projector(surface);
    const CvtObjective placement(surface, &projector);
    std::vector<Vec3> polished = seeds;
    ExtractionMemory memory(surface, placement.interrupt());
    const auto start = Clock::now();
    extract_polished(surface, polished, placement, {1, 5}, memory);
    const double s = seconds(start);
    moved = 0;
    for (std::size_t k = 0; k < seeds.size(); ++k) moved += polished[k] != seeds[k];
    return s;
  };
  for (auto _ : state) {
    std::size_t moved_coarse = 0, moved_fine = 0;
    const double coarse_s = polish(coarse, moved_coarse);
    const double fine_s = polish(fine, moved_fine);
    state.SetIterationTime(coarse_s);
    state.counters["coarse_s"] = coarse_s;
    state.counters["fine_s"] = fine_s;
    state.counters["coarse_over_fine"] = coarse_s / fine_s;
    state.counters["moved_coarse"] = static_cast<double>(moved_coarse);
    state.counters["moved_fine"] = static_cast<double>(moved_fine);
  }
}
BENCHMARK(BM_PolishCoarseFacets)
    ->Args({20'000, 0})
    ->Args({20'000, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
