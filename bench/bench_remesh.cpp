// Remeshing benchmarks (issue 4). Every figure that compares is measured in this same run.
//   BM_Remesh/<mesh>: cvtmesh remesh to 10k vertices with the default settings (10 L-BFGS
//     iterations of RCVT, then 10 of CCVT, then polishing) but no sharp edges (both are smooth
//     scans, remeshed with --no-features, as CGAL's run below protects none): time,
//     iterations, RVD evaluations, time per iteration, peak memory of the process so far, and
//     the output's quality and Hausdorff distance to the input.
//   BM_CgalIsotropic/<mesh>: CGAL's isotropic_remeshing (Botsch-Kobbelt, 3 iterations, as in
//     CGAL's examples) with the edge length that gives about 10k vertices (calibrated by one
//     untimed run); the same figures, and time_ratio = ours / CGAL's when BM_Remesh ran first.
//   BM_RemeshCoarseFacets: a cube of 12 triangles to 100k vertices, no sharp edges: each input
//     triangle is thousands of cells wide, the case where polishing's local RVDs must not grow
//     with the triangles (they once took 18 s here for CCVT's 6): extraction_over_ccvt = the
//     extraction's time (triangulation, polishing) over CCVT's, and the output's quality.
//   BM_LloydVsLbfgs: RCVT of bunny to 2k vertices; L-BFGS for 20 iterations, then Lloyd until
//     it reaches the same energy: RVD evaluations and seconds of each.
//   BM_AdaptiveVsUniform/<mesh>: the default remesh to 2k vertices, uniform and --adaptive 1.5
//     (issue 20), one after the other: time_ratio = adaptive / uniform (local feature size
//     included), and each one's θmin, Qmin and seeds added by topology control.
//   BM_GapGradedVsEven/<mesh>: the default remesh to 5k vertices, whose even sizes grade down to
//     feature gaps under half an edge (SizingSettings::gap_gradation), and the same with even
//     sizes everywhere, one after the other: time_ratio = graded / even (the size field, the
//     split of the input and the extra topology work included), and each one's θmin and Qmin.
//     Meshes: corpus/ChineseDragon-10kv.off (two holes 0.1-0.3% of an edge across) and
//     corpus/spool.off (a strip a third of an edge wide).
//   BM_ManyHolesVsNone: a level-5 icosphere with 200 holes of one triangle each, against the
//     whole sphere, at 1.5k vertices: time_ratio and initialization_ratio (the size field's fit
//     to the count is most of the latter), and the holed output's θmin; then the holed sphere
//     filled first as `remesh --fill-holes` fills it: filled_time_ratio (the filling included)
//     and its θmin.
//   BM_ReportHausdorff/<vertices>: the default remesh of a generated 20k-face torus, with the
//     report's Hausdorff distance (kRemeshReportSamples, the remesher's tree): hausdorff_share =
//     its time over the remesh's (issue 19 item 7: at most 0.1), and its mean and max over those
//     of a dense measurement (200k samples a surface) of the same output.
// Meshes: ../shared/data/{bunny.off, igea.ply}; cases skip when they are absent.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace cvtmesh;
using Clock = std::chrono::steady_clock;
constexpr std::size_t kVertices = 10'000;
const char* const kMeshes[] = {"bunny.off", "igea.ply"};

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024;  // Linux: kilobytes
}

// The shared mesh `name`, read and repaired as the command line does (once per run), or null
// after marking the case skipped when it is absent.
const TriangleMesh* load(benchmark::State& state, const std::string& name) {
  static std::map<std::string, TriangleMesh> cache;
  state.SetLabel(name);
  const auto path = testing::shared_data() / name;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path.string() + " not found (set CVTMESH_SHARED_DATA)").c_str());
    return nullptr;
  }
  auto it = cache.find(name);
  if (it == cache.end()) {
    TriangleMesh mesh = read_mesh(path);
    repair_mesh(mesh);
    it = cache.emplace(name, std::move(mesh)).first;
  }
  return &it->second;
}

void report_output(benchmark::State& state, const TriangleMesh& output, const TriangleMesh& input) {
  const QualityReport q = measure_quality(output);
  state.counters["vertices"] = static_cast<double>(output.vertices.size());
  state.counters["q_min"] = q.q_min;
  state.counters["angle_min_deg"] = q.angle_min_deg;
  state.counters["pct_below_30"] = q.pct_angle_below_30;
  state.counters["hausdorff_mean_pct"] =
      hausdorff_distance(output, input, {.samples = 200'000}).mean_pct();
  state.counters["same_topology"] =
      same_topology(analyze_topology(output), analyze_topology(input)) ? 1 : 0;
}

std::map<std::string, double> our_seconds;  // per mesh, for the ratio against CGAL

void BM_Remesh(benchmark::State& state) {
  const TriangleMesh* input = load(state, kMeshes[state.range(0)]);
  if (!input) return;
  for (auto _ : state) {
    RemeshSettings s;
    s.vertices = kVertices;
    s.features.sharp_edges = false;
    const auto start = Clock::now();
    const RemeshResult r = remesh(*input, s);
    const double total = seconds(start);
    state.SetIterationTime(total);
    our_seconds[kMeshes[state.range(0)]] = total;
    state.counters["time_s"] = total;
    state.counters["iterations"] = r.iterations;
    state.counters["rvd_evaluations"] = r.rvd_evaluations;
    state.counters["s_per_iteration"] = (r.seconds_rcvt + r.seconds_ccvt) / r.iterations;
    state.counters["peak_mb"] = peak_memory_mb();
    report_output(state, r.mesh, *input);
  }
}
BENCHMARK(BM_Remesh)->DenseRange(0, 1)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

// One way to remesh in a comparison: its counters' prefix, and what it changes in the defaults.
struct Way {
  const char* name;
  void (*set)(RemeshSettings&);
};

// The default remesh of `input` to `vertices`, one way and then the other, in the same run: each
// one's θmin, Qmin and seeds added by topology control as counters, and time_ratio = the second's
// time over the first's.
void remesh_two_ways(benchmark::State& state, const TriangleMesh& input, std::size_t vertices,
                     const Way& first, const Way& second) {
  for (auto _ : state) {
    double time[2];
    for (const int k : {0, 1}) {
      const Way& way = k == 0 ? first : second;
      RemeshSettings s;
      s.vertices = vertices;
      way.set(s);
      const auto start = Clock::now();
      const RemeshResult r = remesh(input, s);
      time[k] = seconds(start);
      const QualityReport q = measure_quality(r.mesh);
      const std::string name = way.name;
      state.counters[name + "theta_min"] = q.angle_min_deg;
      state.counters[name + "q_min"] = q.q_min;
      state.counters[name + "seeds_added"] =
          static_cast<double>(r.islands_seeded + r.seeds_refined + r.links_mended);
    }
    state.SetIterationTime(time[0] + time[1]);
    state.counters["time_ratio"] = time[1] / time[0];
  }
}

void BM_AdaptiveVsUniform(benchmark::State& state) {
  const TriangleMesh* input = load(state, kMeshes[state.range(0)]);
  if (!input) return;
  remesh_two_ways(state, *input, 2000, {"uniform_", [](RemeshSettings&) {}},
                  {"adaptive_", [](RemeshSettings& s) { s.sizing.adaptive = 1.5; }});
}
BENCHMARK(BM_AdaptiveVsUniform)
    ->DenseRange(0, 1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

const char* const kGapMeshes[] = {"corpus/ChineseDragon-10kv.off", "corpus/spool.off"};

void BM_GapGradedVsEven(benchmark::State& state) {
  const TriangleMesh* input = load(state, kGapMeshes[state.range(0)]);
  if (!input) return;
  remesh_two_ways(state, *input, 5000,
                  {"even_", [](RemeshSettings& s) { s.sizing.gap_gradation = 0; }},
                  {"graded_", [](RemeshSettings&) {}});
}
BENCHMARK(BM_GapGradedVsEven)
    ->DenseRange(0, 1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// A scan with dropouts (issue 18's fuzz cases): the sizes grade down to each hole, fit to the
// count by bisection, and the input is split where they change fast. Against the same sphere
// without holes, one after the other.
void BM_ManyHolesVsNone(benchmark::State& state) {
  const TriangleMesh whole = testing::icosphere(5);
  const TriangleMesh holed = testing::with_one_triangle_holes(whole, 200, 97);
  for (auto _ : state) {
    double time[3], initialization[2];
    for (const int k : {0, 1, 2}) {
      RemeshSettings s;
      s.vertices = 1500;
      s.hausdorff.reset();
      const auto start = Clock::now();
      TriangleMesh input = k == 0 ? whole : holed;
      if (k == 2) fill_holes(input, 10 * requested_edge_length(input, s));
      const RemeshResult r = remesh(input, s);
      time[k] = seconds(start);
      if (k < 2) initialization[k] = r.seconds_initialization;
      if (k == 1) state.counters["holes_theta_min"] = measure_quality(r.mesh).angle_min_deg;
      if (k == 2) state.counters["filled_theta_min"] = measure_quality(r.mesh).angle_min_deg;
    }
    state.SetIterationTime(time[0] + time[1] + time[2]);
    state.counters["time_ratio"] = time[1] / time[0];
    state.counters["initialization_ratio"] = initialization[1] / initialization[0];
    state.counters["filled_time_ratio"] = time[2] / time[0];
  }
}
BENCHMARK(BM_ManyHolesVsNone)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_CgalIsotropic(benchmark::State& state) {
  const TriangleMesh* input = load(state, kMeshes[state.range(0)]);
  if (!input) return;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto to_surface_mesh = [&] {
    std::vector<Kernel::Point_3> points;
    for (const Vec3& p : input->vertices) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& t : input->triangles) polygons.push_back({t[0], t[1], t[2]});
    SurfaceMesh mesh;
    PMP::orient_polygon_soup(points, polygons);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    return mesh;
  };
  const auto run = [&](SurfaceMesh& mesh, double h) {
    PMP::isotropic_remeshing(faces(mesh), h, mesh, CGAL::parameters::number_of_iterations(3));
  };
  // The edge length of equilateral triangles that cover the area with kVertices vertices,
  // corrected once by an untimed run for the vertex count it actually gives.
  double h = std::sqrt(surface_area(*input) / (std::sqrt(3.0) / 2 * kVertices));
  {
    SurfaceMesh trial = to_surface_mesh();
    run(trial, h);
    h *= std::sqrt(static_cast<double>(trial.number_of_vertices()) / kVertices);
  }
  for (auto _ : state) {
    SurfaceMesh mesh = to_surface_mesh();
    const auto start = Clock::now();
    run(mesh, h);
    const double total = seconds(start);
    state.SetIterationTime(total);
    state.counters["time_s"] = total;
    state.counters["peak_mb"] = peak_memory_mb();
    if (const auto ours = our_seconds.find(kMeshes[state.range(0)]); ours != our_seconds.end())
      state.counters["time_ratio"] = ours->second / total;
    TriangleMesh output;
    std::map<SurfaceMesh::Vertex_index, Index> index;
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      index[v] = static_cast<Index>(output.vertices.size());
      output.vertices.push_back({p.x(), p.y(), p.z()});
    }
    for (const auto f : mesh.faces()) {
      Triangle t{};
      int k = 0;
      for (const auto v : vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = index[v];
      output.triangles.push_back(t);
    }
    report_output(state, output, *input);
  }
}
BENCHMARK(BM_CgalIsotropic)
    ->DenseRange(0, 1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void BM_RemeshCoarseFacets(benchmark::State& state) {
  const TriangleMesh cube = testing::cube(1);
  for (auto _ : state) {
    RemeshSettings s;
    s.vertices = 100'000;
    s.features.sharp_edges = false;
    const RemeshResult r = remesh(cube, s);
    state.SetIterationTime(r.seconds_extraction);
    state.counters["extraction_s"] = r.seconds_extraction;
    state.counters["extraction_over_ccvt"] = r.seconds_extraction / r.seconds_ccvt;
    state.counters["defects_polished"] = static_cast<double>(r.defects_polished);
    const QualityReport q = measure_quality(r.mesh);
    state.counters["q_min"] = q.q_min;
    state.counters["angle_min_deg"] = q.angle_min_deg;
  }
}
BENCHMARK(BM_RemeshCoarseFacets)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_LloydVsLbfgs(benchmark::State& state) {
  const TriangleMesh* bunny = load(state, "bunny.off");
  if (!bunny) return;
  const TriangleMesh& input = *bunny;
  for (auto _ : state) {
    RemeshSettings s;
    s.vertices = 2'000;
    s.mode = CvtMode::rcvt;
    s.iterations = 20;
    auto start = Clock::now();
    const RemeshResult lbfgs = remesh(input, s);
    const double lbfgs_s = seconds(start);
    s.optimizer = Optimizer::lloyd;
    s.iterations = 300;
    start = Clock::now();
    const RemeshResult lloyd = remesh(input, s);
    const double lloyd_s = seconds(start);
    // energies[k] follows Lloyd's iteration k + 1, measured by its evaluation k + 2 (the first
    // evaluates the start).
    double needed = 0;
    for (std::size_t k = 0; k < lloyd.energies.size() && needed == 0; ++k)
      if (lloyd.energies[k] <= lbfgs.energy_final) needed = static_cast<double>(k + 2);
    state.SetIterationTime(lbfgs_s);
    state.counters["lbfgs_evaluations"] = lbfgs.rvd_evaluations;
    state.counters["lbfgs_s"] = lbfgs_s;
    if (needed == 0) {
      state.counters["lloyd_not_reached_in"] = lloyd.rvd_evaluations;
      continue;
    }
    state.counters["lloyd_evaluations"] = needed;
    state.counters["lloyd_s"] = needed * lloyd_s / lloyd.rvd_evaluations;
    state.counters["evaluation_ratio"] = needed / lbfgs.rvd_evaluations;
  }
}
BENCHMARK(BM_LloydVsLbfgs)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_ReportHausdorff(benchmark::State& state) {
  static const TriangleMesh torus = testing::torus(1, 0.4, 200, 50);
  for (auto _ : state) {
    RemeshSettings s;
    s.vertices = static_cast<std::size_t>(state.range(0));
    s.hausdorff = HausdorffSettings{.samples = kRemeshReportSamples};
    const RemeshResult r = remesh(torus, s);
    const double remeshing =
        r.seconds_initialization + r.seconds_rcvt + r.seconds_ccvt + r.seconds_extraction;
    state.SetIterationTime(remeshing + r.seconds_hausdorff);
    state.counters["hausdorff_s"] = r.seconds_hausdorff;
    state.counters["hausdorff_share"] = r.seconds_hausdorff / remeshing;
    const HausdorffReport dense = hausdorff_distance(r.mesh, torus, {.samples = 200'000});
    state.counters["mean_vs_dense"] = r.hausdorff->mean / dense.mean;
    state.counters["max_vs_dense"] = r.hausdorff->max / dense.max;
  }
}
BENCHMARK(BM_ReportHausdorff)
    ->Arg(1000)
    ->Arg(10'000)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
