// The output's last step (remesh/improve_shapes: flips, moves and balancing flips around badly
// shaped triangles), against projecting every vertex onto the surface once, measured in the same
// process so the ratio survives a noisy machine: the step's main cost is its projections.
//   BM_ImproveShapes/J: an icosphere of level 4 (2,562 vertices) with each vertex moved at random
//     by up to J% of the unit sphere's radius along it (edges are about 8% long), improved on an
//     icosphere of level 6; counters shapes_s, projections_s (every vertex once),
//     shapes_over_projections, flips, moves, and Qmin and θmin before and after.
#include <benchmark/benchmark.h>

#include <chrono>

#include "cvtmesh/quality.hpp"
#include "geometry/surface_projector.hpp"
#include "remesh/improve_shapes.hpp"
#include "support/shapes.hpp"

namespace {

using namespace cvtmesh;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BM_ImproveShapes(benchmark::State& state) {
  const TriangleMesh fine = testing::icosphere(6);
  const SurfaceProjector surface(fine);
  const TriangleMesh start = testing::jittered_on_sphere(
      testing::icosphere(4), 0.01 * static_cast<double>(state.range(0)), 1);
  const QualityReport before = measure_quality(start);
  for (auto _ : state) {
    TriangleMesh mesh = start;
    const auto shapes_start = std::chrono::steady_clock::now();
    const ShapeImprovement done = improve_shapes(mesh, surface, nullptr, {}, {}, 5);
    const double shapes_s = seconds_since(shapes_start);
    const auto projections_start = std::chrono::steady_clock::now();
    double sum = 0;
    for (const Vec3& v : start.vertices) sum += surface.nearest(v).point.x;
    benchmark::DoNotOptimize(sum);
    const double projections_s = seconds_since(projections_start);
    state.SetIterationTime(shapes_s);
    const QualityReport after = measure_quality(mesh);
    state.counters["shapes_s"] = shapes_s;
    state.counters["projections_s"] = projections_s;
    state.counters["shapes_over_projections"] = shapes_s / projections_s;
    state.counters["flips"] = static_cast<double>(done.flips);
    state.counters["moves"] = static_cast<double>(done.moves);
    state.counters["q_min_before"] = before.q_min;
    state.counters["q_min_after"] = after.q_min;
    state.counters["theta_min_before"] = before.angle_min_deg;
    state.counters["theta_min_after"] = after.angle_min_deg;
  }
}
BENCHMARK(BM_ImproveShapes)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
