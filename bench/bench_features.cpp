// Remeshing with sharp features (issue 5), each case timed against the same input remeshed
// without features in the same run, as the issue's target asks ("within 2× the time of the
// feature-free remesh at the same size"):
//   BM_RemeshFeatures/<mesh>: remesh to 3k vertices with the default settings (fandisk at a
//     feature angle of 45°, as in the paper's Table 1) and with --no-features (boundaries stay
//     features), each twice, interleaved, the faster run counting; time_ratio = features / no
//     features, ccvt_ratio and extraction_ratio the same for those stages alone, and the
//     feature run's quality, corners lost, links missing and feature Hausdorff distance (max,
//     mean; % of the bounding-box diagonal).
// Meshes: ../shared/data/{fandisk.off, joint.off, mech-holes-shark.off, plane_holes.obj};
// cases skip when they are absent.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <iterator>
#include <string>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace cvtmesh;
using Clock = std::chrono::steady_clock;

struct Case {
  const char* mesh;
  double feature_angle_deg;
};
const Case kCases[] = {
    {"fandisk.off", 45}, {"joint.off", 60}, {"mech-holes-shark.off", 60}, {"plane_holes.obj", 60}};

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

void BM_RemeshFeatures(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  state.SetLabel(c.mesh);
  const auto path = testing::shared_data() / c.mesh;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path.string() + " not found (set CVTMESH_SHARED_DATA)").c_str());
    return;
  }
  const TriangleMesh input = testing::shared_mesh(c.mesh);
  for (auto _ : state) {
    RemeshSettings s;
    s.vertices = 3'000;
    s.features.angle_deg = c.feature_angle_deg;
    RemeshSettings plain_settings = s;
    plain_settings.features.sharp_edges = false;
    // Each twice, interleaved, and the faster run counts: the first remesh of a process pays for
    // starting the thread pool, and the machine is shared.
    RemeshResult r, plain;
    double with = 0, without = 0;
    for (int run = 0; run < 2; ++run) {
      auto start = Clock::now();
      RemeshResult rr = remesh(input, s);
      const double t = seconds(start);
      if (run == 0 || t < with) with = t, r = std::move(rr);
      start = Clock::now();
      RemeshResult pp = remesh(input, plain_settings);
      const double u = seconds(start);
      if (run == 0 || u < without) without = u, plain = std::move(pp);
    }
    state.SetIterationTime(with);
    state.counters["time_s"] = with;
    state.counters["no_features_s"] = without;
    state.counters["time_ratio"] = with / without;
    // Where the extra time goes: the CCVT phases (snapping, curve evening and the relaxation
    // around it) and the extraction (polishing, topology control).
    state.counters["ccvt_ratio"] = r.seconds_ccvt / plain.seconds_ccvt;
    state.counters["extraction_ratio"] = r.seconds_extraction / plain.seconds_extraction;
    const QualityReport q = measure_quality(r.mesh);
    state.counters["q_min"] = q.q_min;
    state.counters["angle_min_deg"] = q.angle_min_deg;
    state.counters["angle_min_avg_deg"] = q.angle_min_avg_deg;
    state.counters["corners_lost"] =
        static_cast<double>(r.features.corners.size() - corners_kept(input, r.features, r.mesh));
    state.counters["links_missing"] = static_cast<double>(r.feature_edges_missing);
    const FeatureDistance d = feature_distance(input, r.features.edges, r.mesh, r.feature_edges);
    const double diagonal = bounding_box(input).diagonal();
    state.counters["feature_hd_max_pct"] = 100 * d.max / diagonal;
    state.counters["feature_hd_mean_pct"] = 100 * d.mean / diagonal;
  }
}
BENCHMARK(BM_RemeshFeatures)
    ->DenseRange(0, std::size(kCases) - 1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
