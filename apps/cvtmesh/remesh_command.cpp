// `cvtmesh remesh IN OUT (--vertices N | --edge-length H | --edge-length-rel R)`: isotropic
// remeshing by CVT, with the quality report of the result against the input.
#include <fmt/core.h>

#include <algorithm>
#include <string>
#include "commands.hpp"

#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "cvtmesh/sampling.hpp"
#include "exit_codes.hpp"
#include "interrupt_signal.hpp"
#include "topology_warnings.hpp"

namespace cvtmesh::cli {

namespace {

struct RemeshOptions {
  std::string input, output, optimizer = "lbfgs", mode = "both", feature_edges, seeds_file,
                             sizing_file;
  RemeshSettings settings;
  int threads = 0;
  std::size_t samples = kRemeshReportSamples;
  double fill_holes = 0;  // in edge lengths; 0: holes stay
  bool quiet = false, json = false, no_features = false, no_hausdorff = false;
  bool feature_angle_given = false;
};

// --fill-holes's default, in edge lengths, and the holes the note about it counts.
constexpr double kHoleHintEdges = 10;

// "IN: 12 holes shorter than 0.42 (10 edge lengths) filled with 15 triangles; 2 left open ...".
void print_holes_filled(const std::string& input, const HoleFilling& f, double longest,
                        double edges) {
  std::string line =
      fmt::format("{}: {} hole{} shorter than {:.4g} ({:g} edge lengths) filled with {} triangles",
                  input, f.filled, f.filled == 1 ? "" : "s", longest, edges, f.triangles_added);
  if (f.left_open > 0)
    line += fmt::format(
        "; {} left open (no triangulation on their own vertices, or one that "
        "joins two vertices joined already)",
        f.left_open);
  if (f.loops_undefined)
    line += " (two fans of triangles meet at a vertex of the boundary: its loops are not defined)";
  if (f.larger > 0)
    line += fmt::format("; {} larger hole{} and rims kept", f.larger, f.larger == 1 ? "" : "s");
  fmt::print(stderr, "{}\n", line);
}

int run_remesh(RemeshOptions o) {
  const auto threads = limit_threads(o.threads);
  ensure_distinct_output(o.input, o.output);
  if (!format_from_extension(o.output))
    throw InvalidArgument(o.output +
                          ": unknown output extension (expected .obj, .off, .ply or .stl)");
  TriangleMesh input = read_mesh(o.input);
  std::vector<Index> new_id;  // the file's vertex ids in the repaired mesh
  if (const RepairReport r = repair_mesh(input, &new_id); r.noteworthy())
    fmt::print(stderr, "{}: repaired: {}\n", o.input, r.summary());
  RemeshSettings& s = o.settings;
  s.features.sharp_edges = !o.no_features;
  s.features.creases_at_scale = !o.feature_angle_given;  // an explicit angle forces its creases
  if (!o.feature_edges.empty()) {
    const std::vector<Edge> edges = read_feature_edges(o.feature_edges);
    try {  // checked here, to name the file in the error
      s.features.user_edges = edges_after_repair(edges, new_id);
      detect_features(input, s.features);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(o.feature_edges + ": " + e.what());
    }
  }
  if (!o.sizing_file.empty()) {
    const std::vector<double> lengths = read_vertex_values(o.sizing_file);
    if (lengths.size() != new_id.size())
      throw InputError(o.sizing_file + ": " + std::to_string(lengths.size()) + " values for the " +
                       std::to_string(new_id.size()) + " vertices of " + o.input);
    s.sizing.edge_lengths = values_after_repair(lengths, new_id, input.vertices.size());
  }
  if (!o.seeds_file.empty()) {
    s.initial_seeds = read_points(o.seeds_file);
    std::vector<Vec3> sorted = s.initial_seeds;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.size() < 4)
      throw InputError(o.seeds_file + ": " + std::to_string(sorted.size()) +
                       " seeds; at least 4 are needed");
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw InputError(o.seeds_file + ": two seeds at the same point");
    s.vertices = s.initial_seeds.size();  // the output size
  }
  HoleFilling filled;
  if (o.fill_holes > 0) {
    // After the sizes are known (a count from the sizing) and before anything reads the mesh's
    // loops: the filled surface is what is remeshed, and what the report compares with.
    const double longest = o.fill_holes * requested_edge_length(input, s);
    filled = fill_holes(input, longest);
    if (!o.quiet) print_holes_filled(o.input, filled, longest, o.fill_holes);
  }
  s.optimizer = o.optimizer == "lloyd" ? Optimizer::lloyd : Optimizer::lbfgs;
  s.mode = o.mode == "rcvt" ? CvtMode::rcvt : o.mode == "ccvt" ? CvtMode::ccvt : CvtMode::both;
  if (!o.quiet) {
    // An adaptive count without --vertices comes from the local feature size: remesh finds it.
    if (s.sizing.adaptive > 0 && s.vertices == 0)
      fmt::print(stderr, "{}: {} triangles -> vertices from the local feature size\n", o.input,
                 input.triangles.size());
    else
      fmt::print(stderr, "{}: {} triangles -> {} vertices\n", o.input, input.triangles.size(),
                 requested_vertex_count(input, s));
    s.progress = [](const RemeshProgress& p) { fmt::print(stderr, "{}", progress_line(p)); };
  }
  if (!o.no_hausdorff) s.hausdorff = HausdorffSettings{.samples = o.samples};
  install_interrupt_handler();
  s.cancel = interrupt_requested;
  const RemeshResult r = remesh(input, s);
  write_mesh(o.output, r.mesh);
  if (r.time_limit_reached)
    fmt::print(stderr,
               "{}: time limit of {:g} s reached: the output is the mesh of the seeds as they were "
               "then (valid, less optimized)\n",
               o.output, s.time_limit);

  const MeshReport report = remesh_report(o.output, input, r, filled);
  fmt::print("{}", o.json ? report.json.dump(2) + "\n" : report.text);
  if (r.triangles_removed > 0 && r.holes_closed > 0)
    fmt::print(stderr,
               "{}: warning: {} triangles removed where the triangulation was not a manifold and "
               "topology control could not mend it (where the input crosses itself, or parts are "
               "thinner than the spacing); {} holes were closed again with {} triangles and {} new "
               "vertices\n",
               o.output, r.triangles_removed, r.holes_closed, r.triangles_closing_holes,
               r.vertices_closing_holes);
  else if (r.triangles_removed > 0)
    fmt::print(stderr,
               "{}: warning: {} triangles removed where the triangulation was not a manifold and "
               "topology control could not mend it ({})\n",
               o.output, r.triangles_removed,
               r.input_crossing_triangles > 0 ? "where the input crosses itself, or parts are "
                                                "thinner than the spacing"
                                              : "more vertices would resolve the thin parts");
  else if (r.holes_closed > 0)
    fmt::print(stderr,
               "{}: warning: {} holes that topology control left in the closed surface were "
               "closed with {} triangles and {} new vertices\n",
               o.output, r.holes_closed, r.triangles_closing_holes, r.vertices_closing_holes);
  if (!r.feature_edges_dropped.empty())
    fmt::print(stderr,
               "{}: warning: {} sharp edges not kept as features: tracing them cost the input's "
               "topology or made the output pass through itself\n",
               o.output, r.feature_edges_dropped.size());
  if (r.sizes_adapted)
    fmt::print(stderr,
               "{}: warning: edge lengths adapted to the local feature size: even ones cost the "
               "input's topology\n",
               o.output);
  if (r.count_grown > 0)
    fmt::print(stderr,
               "{}: warning: {} vertices more than asked for: fewer did not keep the input's "
               "topology, or left its boundary loops and creases too few\n",
               o.output, r.count_grown);
  if (!report.same_topology_as_reference) warn_about_topology(o.output, report.topology);
  if (r.output_crossing_triangles > 0 && r.input_crossing_triangles == 0)
    fmt::print(stderr,
               "{}: warning: {} output triangles pass through others: more vertices would "
               "resolve the thin parts there\n",
               o.output, r.output_crossing_triangles);
  else if (r.output_crossing_triangles > 0)
    fmt::print(stderr,
               "{}: warning: {} output triangles pass through others away from where the input "
               "passes through itself ({} input triangles)\n",
               o.output, r.output_crossing_triangles, r.input_crossing_triangles);
  if (r.input_crossing_triangles > 0 && !report.same_topology_as_reference)
    fmt::print(stderr,
               "{}: warning: the input passes through itself ({} triangle{} cross{} another): no "
               "vertex count tells sheets that cross apart, so the output's topology there is not "
               "the input's\n",
               o.input, r.input_crossing_triangles, r.input_crossing_triangles == 1 ? "" : "s",
               r.input_crossing_triangles == 1 ? "es" : "");
  if (o.fill_holes == 0 && !o.quiet && r.input_topology.boundary_loops > 0) {
    // A scan's dropouts were kept, each at a cost in triangles and time: say how to close them.
    // The even length of the output's count (a sizing's would cost the local feature size again).
    RemeshSettings even;
    even.vertices = std::max<std::size_t>(r.mesh.vertices.size(), 4);
    TriangleMesh copy = input;
    const HoleFilling would = fill_holes(copy, kHoleHintEdges * requested_edge_length(input, even));
    if (would.filled > 0)
      fmt::print(stderr,
                 "{}: note: {} hole{} shorter than {:g} edge lengths {} kept, with small "
                 "triangles around {}; --fill-holes closes {} first\n",
                 o.input, would.filled, would.filled == 1 ? "" : "s", kHoleHintEdges,
                 would.filled == 1 ? "was" : "were", would.filled == 1 ? "it" : "each",
                 would.filled == 1 ? "it" : "them");
  }
  return kOk;
}

}  // namespace

void add_remesh_command(CLI::App& app, Action& run) {
  auto o = std::make_shared<RemeshOptions>();
  CLI::App* cmd =
      app.add_subcommand("remesh", "Isotropic remeshing by centroidal Voronoi tessellation");
  cmd->add_option("IN", o->input, "Input mesh")->required();
  cmd->add_option("OUT", o->output, "Output mesh (never the input; written atomically)")
      ->required();
  auto* vertices = cmd->add_option("--vertices", o->settings.vertices, "Number of output vertices");
  auto* length = cmd->add_option("--edge-length", o->settings.edge_length, "Target edge length");
  auto* relative = cmd->add_option("--edge-length-rel", o->settings.edge_length_rel,
                                   "Target edge length as a fraction of the bbox diagonal");
  auto* seeds = cmd->add_option("--seeds-file", o->seeds_file,
                                "Initial seeds instead of random ones (a text file of \"x y z\" "
                                "lines, or a mesh's vertices); their count is the output size");
  vertices->excludes(length)->excludes(relative)->excludes(seeds);
  length->excludes(relative)->excludes(seeds);
  relative->excludes(seeds);
  auto* adaptive =
      cmd->add_option("--adaptive", o->settings.sizing.adaptive,
                      "Edge lengths ∝ √(local feature size), the paper's density 1/lfs² (short on "
                      "thin parts and tight curves), graded: G or more edge lengths to double in "
                      "size")
          ->expected(0, 1)
          ->default_str("1.5")
          ->check(CLI::PositiveNumber);
  auto* sizing = cmd->add_option("--sizing", o->sizing_file,
                                 "Target edge length per input vertex: a text file of one number "
                                 "a line, in vertex order, or a PLY with a vertex scalar");
  adaptive->excludes(sizing);
  cmd->add_option("--gap-gradation", o->settings.sizing.gap_gradation,
                  "Even sizes only: edges grade down towards holes, slots, strips and handles "
                  "narrower than half an edge length, G or more edge lengths to double in size "
                  "(0: even everywhere, slivers at such gaps)")
      ->default_val(5)
      ->check(CLI::NonNegativeNumber)
      ->excludes(adaptive)
      ->excludes(sizing);
  cmd->add_option("--fill-holes", o->fill_holes,
                  "Fill the input's holes whose boundary is shorter than E edge lengths (the "
                  "even length of the vertex count) before remeshing: a scan's dropouts, which "
                  "kept would each cost many small triangles. Never a sheet's rim (a loop as "
                  "long as the square root of its part's area)")
      ->expected(0, 1)
      ->default_str(fmt::format("{:g}", kHoleHintEdges))
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-edge-length", o->settings.sizing.min_edge_length,
                  "Clamp of the target lengths (with --adaptive or --sizing)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-edge-length", o->settings.sizing.max_edge_length,
                  "Clamp of the target lengths (with --adaptive or --sizing)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--iterations", o->settings.iterations,
                  "Iteration cap per phase (half for RCVT from the evenly spread initial seeds; "
                  "RCVT alone, on a surface without features, takes CCVT's too)")
      ->default_val(10)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--samples", o->samples,
                  "Hausdorff samples per surface for the report, spread evenly, besides all "
                  "vertices and edge midpoints (0 = as `quality`)")
      ->default_val(kRemeshReportSamples);
  cmd->add_flag("--no-hausdorff", o->no_hausdorff,
                "Skip the report's Hausdorff distance (its JSON keys are null)");
  cmd->add_option("--polish-rounds", o->settings.polish_rounds,
                  "Rounds of local Lloyd steps around badly shaped triangles (0: none)")
      ->default_val(3)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--shape-sweeps", o->settings.shape_sweeps,
                  "Sweeps of edge flips and vertex moves along the surface around badly shaped "
                  "triangles, then short-edge collapses where those do not help (at most 1% of "
                  "the vertices), last (0: none)")
      ->default_val(5)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--fit-rounds", o->settings.fit_rounds,
                  "Rounds of moving surface vertices along their normals so that the input lies "
                  "between them and their triangles' middles, last, after the vertices move onto "
                  "their Voronoi cells' normal lines and those beside the input's untraced creases "
                  "onto them; never lowers θmin or Qmin (0: none of it; vertices stay on the input "
                  "where the sweeps left them)")
      ->default_val(RemeshSettings{}.fit_rounds)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--topology-rounds", o->settings.topology_rounds,
                  "Rounds of topology control: seeds added where the output misses feature "
                  "edges or differs in topology; the best round is kept; up to three times as "
                  "many more where the topology still differs (0: none)")
      ->default_val(12)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--optimizer", o->optimizer, "lbfgs or lloyd")
      ->default_val("lbfgs")
      ->check(CLI::IsMember({"lbfgs", "lloyd"}));
  cmd->add_option("--mode", o->mode,
                  "rcvt, ccvt or both (RCVT then CCVT; RCVT alone on a surface without features "
                  "and with uniform sizes)")
      ->default_val("both")
      ->check(CLI::IsMember({"rcvt", "ccvt", "both"}));
  cmd->add_option("--seed", o->settings.seed, "Random seed of the initial sampling")
      ->default_val(1);
  auto* angle =
      cmd->add_option(
             "--feature-angle", o->settings.features.angle_deg,
             "Sharp edge: its faces' normals differ by more than this (deg). Given, it forces "
             "them; by default, only creases with flat sides at the output's "
             "scale, amid an input that is smooth at its own resolution, are kept")
          ->default_val(60)
          ->check(CLI::Range(0.0, 180.0));
  cmd->add_flag("--no-features", o->no_features,
                "Keep no sharp edges (boundaries and --feature-edges are still kept)")
      ->excludes(angle);
  cmd->add_option("--feature-edges", o->feature_edges,
                  "File of feature edges to keep: \"a b\" vertex ids per line, # comments");
  cmd->add_option("--time-limit", o->settings.time_limit,
                  "Seconds: then the optimization and the rounds stop, and the mesh of the seeds "
                  "as they are is written (valid; the report says so). 0: no limit")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quiet", o->quiet, "No progress on stderr");
  cmd->add_flag("--json", o->json, "Print one JSON object instead of text");
  add_threads_option(*cmd, o->threads);
  cmd->callback([o, &run, vertices, length, relative, seeds, angle, sizing] {
    if (vertices->count() + length->count() + relative->count() + seeds->count() +
            sizing->count() ==
        0)
      throw CLI::RequiredError(
          "--vertices, --edge-length, --edge-length-rel, --seeds-file or --sizing");
    o->feature_angle_given = angle->count() > 0;
    run = [o] { return run_remesh(*o); };
  });
}

}  // namespace cvtmesh::cli
