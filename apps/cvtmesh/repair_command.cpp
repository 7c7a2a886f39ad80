// `cvtmesh repair IN OUT`: the shape-preserving repairs, written to a new file.
#include <fmt/core.h>

#include "commands.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "exit_codes.hpp"
#include "topology_warnings.hpp"

namespace cvtmesh::cli {

namespace {

struct RepairOptions {
  std::string input, output;
  double fill_holes = 0;  // the longest hole boundary to fill, in the mesh's units; 0: none
  bool json = false;
};

int run_repair(const RepairOptions& o) {
  ensure_distinct_output(o.input, o.output);
  TriangleMesh mesh = read_mesh(o.input);
  const RepairReport repairs = repair_mesh(mesh);
  if (mesh.triangles.empty())
    throw InputError(o.input + ": no triangle with non-zero area is left after repair");
  fmt::print(stderr, "{}: {}\n", o.input,
             repairs.noteworthy() ? repairs.summary() : "nothing to repair");
  HoleFilling filled;
  if (o.fill_holes > 0) {
    filled = fill_holes(mesh, o.fill_holes);
    fmt::print(stderr, "{}: {} hole{} shorter than {:g} filled with {} triangles; {} left open\n",
               o.input, filled.filled, filled.filled == 1 ? "" : "s", o.fill_holes,
               filled.triangles_added, filled.left_open + filled.larger);
    if (filled.loops_undefined)
      fmt::print(stderr,
                 "{}: no hole filled: two fans of triangles meet at a vertex of the boundary, "
                 "where its loops are not defined\n",
                 o.input);
  }
  const TopologyReport topology = analyze_topology(mesh);
  warn_about_topology(o.output, topology);
  write_mesh(o.output, mesh);
  if (o.json) {
    auto json = mesh_json(topology, measure_quality(mesh));
    json["duplicate_vertices_merged"] = repairs.duplicate_vertices_merged;
    json["nearly_equal_vertices_merged"] = repairs.nearly_equal_vertices_merged;
    json["duplicate_vertices_kept_apart"] = repairs.duplicate_vertices_kept_apart;
    json["caps_split"] = repairs.caps_split;
    json["degenerate_triangles_removed"] = repairs.degenerate_triangles_removed;
    json["duplicate_triangles_removed"] = repairs.duplicate_triangles_removed;
    json["unreferenced_vertices_removed"] = repairs.unreferenced_vertices_removed;
    json["triangles_flipped"] = repairs.triangles_flipped;
    json["holes_filled"] = filled.filled;
    json["hole_triangles_added"] = filled.triangles_added;
    fmt::print("{}\n", json.dump(2));
  } else {
    fmt::print("{}: {}\n", o.output, topology_line(topology));
  }
  return kOk;
}

}  // namespace

void add_repair_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<RepairOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repair",
      "Merge duplicate vertices, drop zero-area, duplicate triangles and unreferenced vertices");
  cmd->add_option("IN", options->input, "Input mesh")->required();
  cmd->add_option("OUT", options->output, "Output mesh (never the input; written atomically)")
      ->required();
  cmd->add_option("--fill-holes", options->fill_holes,
                  "Then fill the holes whose boundary is shorter than LENGTH (the mesh's units) "
                  "on their own vertices; never a sheet's rim")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--json", options->json, "Print the repaired mesh's report as JSON");
  cmd->callback([options, &run] { run = [options] { return run_repair(*options); }; });
}

}  // namespace cvtmesh::cli
