// Sizing hot paths (issue 20: adaptive remeshing costs at most 1.3x uniform, lfs included): the
// local feature size, timed against CGAL's 3D Delaunay triangulation of the mesh's vertices in the
// same process (the triangulation whose poles it reads; what is left is the rays along the
// normals, the nearest-pole search and the grading).
//   BM_LocalFeatureSize/M/T: M = 0 icosphere level 6 (40,962 vertices), 1 a thin plate (a cube of
//     96x96 cells a face squashed to a twentieth of its height, 2 wide and 0.1 thick: the inward
//     rays of its top and bottom hit the other side), 2 ../shared/data/igea.ply; on T threads
//     (the Delaunay is serial); counters lfs_s, delaunay_s and lfs_over_delaunay.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <filesystem>
#include <optional>

#include "cvtmesh/io.hpp"
#include "cvtmesh/sizing.hpp"
#include "delaunay_baseline.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace cvtmesh;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

std::optional<TriangleMesh> bench_mesh(benchmark::State& state) {
  switch (state.range(0)) {
    case 0:
      return testing::icosphere(6);
    case 1: {
      TriangleMesh plate = testing::cube(96);
      for (Vec3& p : plate.vertices) p.z *= 0.05;
      return plate;
    }
    default: {
      const auto path = testing::shared_data() / "igea.ply";
      if (!std::filesystem::exists(path)) {
        state.SkipWithError("igea.ply not found (set CVTMESH_SHARED_DATA)");
        return std::nullopt;
      }
      return read_mesh(path);
    }
  }
}

void BM_LocalFeatureSize(benchmark::State& state) {
  const std::optional<TriangleMesh> mesh = bench_mesh(state);
  if (!mesh) return;
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) {
    const double delaunay_s = bench::delaunay_seconds(mesh->vertices);
    const auto start = Clock::now();
    benchmark::DoNotOptimize(local_feature_size(*mesh));
    const double lfs_s = seconds(start);
    state.SetIterationTime(lfs_s);
    state.counters["lfs_s"] = lfs_s;
    state.counters["delaunay_s"] = delaunay_s;
    state.counters["lfs_over_delaunay"] = lfs_s / delaunay_s;
  }
}
BENCHMARK(BM_LocalFeatureSize)
    ->ArgsProduct({{0, 1, 2}, {1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
