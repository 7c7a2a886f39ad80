// `cvtmesh lfs IN OUT.ply`: the local feature size at each vertex (paper §4.1), written as a
// vertex property and colour to look at.
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "commands.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/sizing.hpp"
#include "exit_codes.hpp"

namespace cvtmesh::cli {

namespace {

struct LfsOptions {
  std::string input, output;
  LfsSettings settings;
  FeatureSettings features;
  std::size_t vertices = 0;  // the output size whose scale the features are detected at
  int threads = 0;
  bool json = false, no_features = false, feature_angle_given = false;
};

int run_lfs(const LfsOptions& o) {
  const auto threads = limit_threads(o.threads);
  ensure_distinct_output(o.input, o.output);
  if (format_from_extension(o.output) != MeshFormat::ply)
    throw InvalidArgument(o.output + ": the sizes are written as PLY vertex properties: use .ply");
  TriangleMesh mesh = read_mesh(o.input);
  if (const RepairReport r = repair_mesh(mesh); r.noteworthy())
    fmt::print(stderr, "{}: repaired: {}\n", o.input, r.summary());
  if (mesh.triangles.empty()) throw InputError(o.input + ": no triangle of non-zero area");
  const auto start = std::chrono::steady_clock::now();
  // Near sharp features and boundaries, the size falls to their gaps (issue 20 item 1), as the
  // remesher detects them: at the scale of `vertices` if given, else every curve.
  FeatureSettings detection = o.features;
  detection.sharp_edges = !o.no_features;
  detection.creases_at_scale = !o.feature_angle_given;
  if (o.vertices > 0)
    detection.scale = std::sqrt(surface_area(mesh) / (std::sqrt(3.0) / 2 * double(o.vertices)));
  const Features features = detect_features(mesh, detection);
  LfsSettings settings = o.settings;
  settings.features = &features;
  const std::vector<double> lfs = local_feature_size(mesh, settings);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_ply_with_vertex_scalar(o.output, mesh, lfs, "lfs");

  std::vector<double> sorted = lfs;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) {
    return sorted[static_cast<std::size_t>(q * (sorted.size() - 1))];
  };
  const double diagonal = bounding_box(mesh).diagonal();
  if (o.json) {
    nlohmann::ordered_json j;
    j["vertices"] = lfs.size();
    j["lfs_min"] = sorted.front();
    j["lfs_median"] = at(0.5);
    j["lfs_max"] = sorted.back();
    j["bbox_diagonal"] = diagonal;
    j["gradation"] = o.settings.gradation;
    j["feature_curves"] = features.curves.size();
    j["time_s"] = seconds;
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print(
        "{}: local feature size at {} vertices: min {:.6g}, median {:.6g}, max {:.6g} (bbox "
        "diagonal {:.6g}; graded by {:g}; {} feature curves) in {:.2f} s\n",
        o.output, lfs.size(), sorted.front(), at(0.5), sorted.back(), diagonal,
        o.settings.gradation, features.curves.size(), seconds);
  }
  return kOk;
}

}  // namespace

void add_lfs_command(CLI::App& app, Action& run) {
  auto o = std::make_shared<LfsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lfs",
      "Local feature size at each vertex, from the poles of a dense sample, rays along the "
      "normals and the gaps between features (PLY out)");
  cmd->add_option("IN", o->input, "Input mesh")->required();
  cmd->add_option("OUT", o->output, "Output PLY: the mesh with vertex property lfs and a colour")
      ->required();
  cmd->add_option("--gradation", o->settings.gradation,
                  "Sizes change by at most 1/G per unit length along edges (0: raw estimate)")
      ->default_val(o->settings.gradation)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--samples", o->settings.samples,
                  "Area samples added to the vertices for the poles (for coarse meshes; they "
                  "make every edge a feature)")
      ->default_val(0);
  cmd->add_option("--seed", o->settings.seed, "Random seed of the sampling")->default_val(1);
  cmd->add_option("--vertices", o->vertices,
                  "Detect the features as a remesh to this many vertices would (default: keep "
                  "every curve)")
      ->check(CLI::PositiveNumber);
  auto* angle = cmd->add_option("--feature-angle", o->features.angle_deg,
                                "Sharp edge: its faces' normals differ by more than this (deg); "
                                "given, it forces them, as in remesh")
                    ->default_val(60)
                    ->check(CLI::Range(0.0, 180.0));
  cmd->add_flag("--no-features", o->no_features,
                "No sharp edges: only boundaries narrow the sizes to their gaps")
      ->excludes(angle);
  cmd->add_flag("--json", o->json, "Print one JSON object instead of text");
  add_threads_option(*cmd, o->threads);
  cmd->callback([o, &run, angle] {
    o->feature_angle_given = angle->count() > 0;
    run = [o] { return run_lfs(*o); };
  });
}

}  // namespace cvtmesh::cli
