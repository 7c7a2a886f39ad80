// `cvtmesh quality MESH [--ref INPUT] [--json]`: the figures users compare remeshers by.
#include <fmt/core.h>

#include <optional>

#include "commands.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "exit_codes.hpp"
#include "topology_warnings.hpp"

namespace cvtmesh::cli {

namespace {

struct QualityOptions {
  std::string mesh, reference;
  bool json = false;
  std::size_t samples = 0;
  int threads = 0;
};

// The mesh is measured as stored: repairs would hide the very defects a quality report is for,
// so they are only mentioned.
void note_possible_repairs(const std::string& file, const TriangleMesh& mesh) {
  RepairReport r = diagnose_repairs(mesh);
  r.unreferenced_vertices_removed = 0;  // reported with the counts already
  if (r.noteworthy())
    fmt::print(stderr, "{}: note: `cvtmesh repair` would change: {}\n", file, r.summary());
}

int run_quality(const QualityOptions& o) {
  const auto threads = limit_threads(o.threads);
  const TriangleMesh mesh = read_mesh(o.mesh);
  note_possible_repairs(o.mesh, mesh);
  std::optional<TriangleMesh> reference;
  if (!o.reference.empty()) reference = read_mesh(o.reference);
  std::optional<HausdorffReport> distance;
  if (reference) distance = hausdorff_distance(mesh, *reference, {.samples = o.samples});
  const MeshReport report =
      report_mesh(o.mesh, mesh, reference ? &*reference : nullptr, distance ? &*distance : nullptr);
  warn_about_topology(o.mesh, report.topology);
  fmt::print("{}", o.json ? report.json.dump(2) + "\n" : report.text);
  return kOk;
}

}  // namespace

void add_quality_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<QualityOptions>();
  CLI::App* cmd =
      app.add_subcommand("quality", "Report a mesh's counts, topology and triangle quality");
  cmd->add_option("MESH", options->mesh, "Mesh to measure (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("--ref", options->reference,
                  "Reference mesh: adds the two-sided Hausdorff distance and a topology check");
  cmd->add_flag("--json", options->json, "Print one JSON object instead of text");
  cmd->add_option("--samples", options->samples,
                  "Hausdorff samples per surface (0 = max(200k, 2 x faces), at most 1M)")
      ->check(CLI::NonNegativeNumber);
  add_threads_option(*cmd, options->threads);
  cmd->callback([options, &run] { run = [options] { return run_quality(*options); }; });
}

}  // namespace cvtmesh::cli
