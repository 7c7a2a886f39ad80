// `cvtmesh rvd MESH (--seeds N | --seeds-file FILE)`: one exact restricted Voronoi diagram, its
// CVT energy, and optionally its cells and restricted Delaunay triangulation.
#include <fmt/core.h>
#include <tbb/global_control.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <string>

#include "commands.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sampling.hpp"
#include "exit_codes.hpp"

namespace cvtmesh::cli {

namespace {

struct RvdOptions {
  std::string mesh, seeds_file, cells, rdt;
  std::size_t seeds = 0;
  std::uint64_t seed = 1;
  int threads = 0;
  bool json = false;
};

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// `unit` × 2^exponent, as a number where a double holds it, else as "mantissa×2^exponent" (the
// area of a mesh at 2^-600 underflows, at 2^600 overflows).
std::string scaled_text(double unit, int exponent, int digits) {
  const double value = std::ldexp(unit, exponent);
  if (unit == 0 || std::isnormal(value)) return fmt::format("{:.{}g}", value, digits);
  return fmt::format("{:.{}g}×2^{}", unit, digits, exponent);
}

int run_rvd(const RvdOptions& o) {
  const auto threads = limit_threads(o.threads);
  for (const std::string& out : {o.cells, o.rdt})
    if (!out.empty()) ensure_distinct_output(o.mesh, out);
  TriangleMesh mesh = read_mesh(o.mesh);
  if (const RepairReport r = repair_mesh(mesh); r.noteworthy())
    fmt::print(stderr, "{}: repaired: {}\n", o.mesh, r.summary());
  if (mesh.triangles.empty()) throw InputError(o.mesh + ": no triangle of non-zero area");
  // The traversal walks from vertex to vertex and triangle to triangle: in spatial order, those
  // walks stay short whatever the file's order (the figures here are the surface's alone).
  // And scaled by a power of two to about unit size, exactly (issue 22): areas and energies of
  // a mesh in any units neither underflow nor overflow; they are scaled back when reported.
  const int exponent = size_exponent(mesh);
  mesh = scaled_by_power_of_two(spatially_sorted(mesh).mesh, -exponent);

  Stopwatch clock;
  std::vector<Vec3> seeds;
  if (o.seeds_file.empty()) {
    seeds = sample_surface(mesh, o.seeds, o.seed);
  } else {
    seeds = read_points(o.seeds_file);
    for (Vec3& p : seeds) p = scaled_by_power_of_two(p, -exponent);
  }
  const double sampling = clock.lap();
  const RestrictedVoronoiDiagram rvd(mesh, std::move(seeds));
  clock.lap();

  CellIntegrator integrator(rvd);
  RestrictedDelaunayBuilder rdt(rvd);
  CellCollector cells;
  std::vector<PolygonSink*> sinks{&integrator};
  if (!o.rdt.empty()) sinks.push_back(&rdt);
  if (!o.cells.empty()) sinks.push_back(&cells);
  const TraversalStats stats = rvd.traverse(sinks);
  const double traversal = clock.lap();
  if (!o.cells.empty()) cells.write_ply(o.cells, exponent);
  if (!o.rdt.empty()) {
    TriangleMesh triangulation = scaled_by_power_of_two(rdt.result(), exponent);
    repair_mesh(triangulation);  // drops the seeds whose cell is empty
    write_mesh(o.rdt, triangulation);
  }

  // Areas scale by 4^k and the energy (∫ squared distance dA) by 16^k; the relative difference
  // is taken at unit size, where neither can have overflowed.
  const CellIntegrals& integrals = integrator.result();
  const double unit_area = surface_area(mesh);
  const double area = std::ldexp(unit_area, 2 * exponent);
  const double cells_area = std::ldexp(integrals.total_mass, 2 * exponent);
  const double energy = std::ldexp(integrals.total_energy, 4 * exponent);
  const double relative_difference = std::abs(integrals.total_mass - unit_area) / unit_area;
  const RvdBuildTimes& build = rvd.build_times();
  const double total = sampling + build.kdtree_seconds + build.neighbors_seconds + traversal;
  const std::size_t used_threads =
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  if (o.json) {
    nlohmann::ordered_json j;
    j["seeds"] = rvd.seeds().size();
    j["triangles"] = mesh.triangles.size();
    j["polygons"] = stats.polygons;
    j["cells_clipped"] = stats.cells_clipped;
    j["surface_area"] = area;
    j["cells_area_sum"] = cells_area;
    j["area_relative_difference"] = relative_difference;
    j["energy"] = energy;
    j["predicates"] = stats.predicates;
    j["exact_fallbacks"] = stats.exact_fallbacks;
    j["perturbed_ties"] = stats.perturbed_ties;
    j["radius_searches"] = stats.radius_searches;
    j["threads"] = used_threads;
    j["timings"] = {{"sampling", sampling},
                    {"kdtree", build.kdtree_seconds},
                    {"neighbors", build.neighbors_seconds},
                    {"rvd", traversal},
                    {"total", total}};
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print(
        "{}: {} seeds, {} triangles -> {} polygons\n"
        "  area      cells {}   surface {}   relative difference {:.2e}\n"
        "  energy    {}\n"
        "  exact     {} of {} predicates went exact, {} ties decided by perturbation\n"
        "  time      kd-tree {:.3f}s   neighbours {:.3f}s   rvd {:.3f}s   total {:.3f}s ({} "
        "threads)\n",
        o.mesh, rvd.seeds().size(), mesh.triangles.size(), stats.polygons,
        scaled_text(integrals.total_mass, 2 * exponent, 12),
        scaled_text(unit_area, 2 * exponent, 12), relative_difference,
        scaled_text(integrals.total_energy, 4 * exponent, 9), stats.exact_fallbacks,
        stats.predicates, stats.perturbed_ties, build.kdtree_seconds, build.neighbors_seconds,
        traversal, total, used_threads);
  }
  return kOk;
}

}  // namespace

void add_rvd_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<RvdOptions>();
  CLI::App* cmd = app.add_subcommand(
      "rvd", "Compute the exact restricted Voronoi diagram of seeds on a surface");
  cmd->add_option("MESH", options->mesh, "Surface mesh (.obj, .off, .ply, .stl)")->required();
  auto* count = cmd->add_option("--seeds", options->seeds, "Number of random seeds (area-uniform)")
                    ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  auto* file = cmd->add_option("--seeds-file", options->seeds_file,
                               "Seeds: a text file of \"x y z\" lines, or a mesh's vertices");
  count->excludes(file);
  cmd->add_option("--seed", options->seed, "Random seed of the sampling")->default_val(1);
  cmd->add_option("--cells", options->cells, "Write the cells (PLY, one colour per seed)");
  cmd->add_option("--rdt", options->rdt, "Write the restricted Delaunay triangulation");
  cmd->add_flag("--json", options->json, "Print one JSON object instead of text");
  add_threads_option(*cmd, options->threads);
  cmd->callback([options, &run, count, file] {
    if (count->count() + file->count() == 0)
      throw CLI::RequiredError("--seeds N or --seeds-file FILE");
    run = [options] { return run_rvd(*options); };
  });
}

}  // namespace cvtmesh::cli
