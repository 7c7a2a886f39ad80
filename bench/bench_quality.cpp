// Hot paths of the quality report: topology analysis, per-triangle metrics, Hausdorff distance
// and mesh reading; the walk of a mesh's edges that feature detection, components, topology
// control and the finishing steps share (edge_uses); the search for triangles through others that
// checks every output; and the passes over the whole input before the CVT starts (repair, feature
// detection), on one thread while the other builds the AABB tree, so that a large scan's remesh
// to a few thousand vertices spends a third of its time there (igea.ply at 1k); on generated
// meshes (icosphere level 6 = 81,920 triangles, level 7 = 327,680, about igea's size). Compare a
// figure against `BM_SurfaceArea` of the same size, the cheapest possible pass over the
// triangles, run in the same process.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

#include "cvtmesh/features.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "features/edge_uses.hpp"
#include "geometry/self_crossings.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"

namespace {

using namespace cvtmesh;

const TriangleMesh& sphere(int level) {
  static std::map<int, TriangleMesh> cache;
  auto it = cache.find(level);
  if (it == cache.end()) it = cache.emplace(level, testing::icosphere(level)).first;
  return it->second;
}

void BM_SurfaceArea(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(surface_area(m));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_SurfaceArea)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

void BM_AnalyzeTopology(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(analyze_topology(m));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_AnalyzeTopology)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

void BM_EdgeUses(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(edge_uses(m));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_EdgeUses)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

// The repair every read input goes through (duplicate vertices and triangles, zero-area
// triangles, orientation), on a clean mesh, as most inputs are: each pass finds nothing.
void BM_RepairMesh(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    TriangleMesh copy = m;
    state.ResumeTiming();
    benchmark::DoNotOptimize(repair_mesh(copy));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_RepairMesh)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

// Feature detection as a remesh to 10k vertices runs it, on a surface without creases (the
// default's walk over every edge and triangle, before the CVT starts).
void BM_DetectFeatures(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  FeatureSettings settings;
  settings.scale = std::sqrt(surface_area(m) / (std::sqrt(3.0) / 2 * 10'000));
  for (auto _ : state) benchmark::DoNotOptimize(detect_features(m, settings));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_DetectFeatures)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

void BM_MeasureQuality(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(measure_quality(m));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_MeasureQuality)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

// The search for triangles that pass through others (geometry/self_crossings), which topology
// control runs on its extractions and the finishing steps on every output: on a closed sphere,
// where every pair it tests shares a vertex or an edge, as on nearly every output.
void BM_SelfCrossings(benchmark::State& state) {
  const TriangleMesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(self_crossing_triangles(m));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(m.triangles.size()));
}
BENCHMARK(BM_SelfCrossings)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

// Sphere level 6 against a 1% larger level-5 sphere; range(0) = samples per surface.
void BM_Hausdorff(benchmark::State& state) {
  const TriangleMesh& a = sphere(6);
  const TriangleMesh b = testing::transformed(sphere(5), 1.01);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        hausdorff_distance(a, b, {.samples = static_cast<std::size_t>(state.range(0))}));
  state.SetItemsProcessed(state.iterations() * 2 * state.range(0));
}
BENCHMARK(BM_Hausdorff)->Arg(20'000)->Arg(200'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Reading a binary PLY, an ASCII OFF and an OBJ of the level-7 sphere (327,680 triangles).
void BM_ReadMesh(benchmark::State& state, const char* extension) {
  testing::TempDir dir;
  const auto path = dir / (std::string("sphere.") + extension);
  write_mesh(path, sphere(7));
  for (auto _ : state) benchmark::DoNotOptimize(read_mesh(path));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(sphere(7).triangles.size()));
}
BENCHMARK_CAPTURE(BM_ReadMesh, ply, "ply")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReadMesh, off, "off")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReadMesh, obj, "obj")->Unit(benchmark::kMillisecond);

}  // namespace
