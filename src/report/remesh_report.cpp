#include <fmt/core.h>

#include <cmath>

#include "cvtmesh/report.hpp"

namespace cvtmesh {

namespace {

// A percentage of the diagonal, or null where the distance is infinite (input features but no
// output feature edge: JSON has no infinity).
nlohmann::ordered_json percent_or_null(double distance, double diagonal) {
  return std::isfinite(distance) ? nlohmann::ordered_json(100 * distance / diagonal) : nullptr;
}

}  // namespace

MeshReport remesh_report(const std::string& name, const TriangleMesh& input, const RemeshResult& r,
                         const HoleFilling& filled) {
  MeshReport report = report_mesh(name, r.mesh, &input, r.hausdorff ? &*r.hausdorff : nullptr,
                                  &r.input_topology, &r.features);
  const double diagonal = bounding_box(input).diagonal();
  const FeatureDistance fd = feature_distance(input, r.features.edges, r.mesh, r.feature_edges);
  const std::size_t corners_out = corners_kept(input, r.features, r.mesh);
  // The input's narrowest angle between two feature curves: what θmin can be at best there.
  const double sector = narrowest_feature_sector_deg(input, r.features);
  const double total =
      r.seconds_initialization + r.seconds_rcvt + r.seconds_ccvt + r.seconds_extraction;

  auto& j = report.json;
  j["feature_edges_in"] = r.features.edges.size();
  j["feature_curves_in"] = r.features.curves.size();
  j["corners_in"] = r.features.corners.size();
  j["corners_out"] = corners_out;
  j["feature_edges_out"] = r.feature_edges.size();
  j["feature_edges_missing"] = r.feature_edges_missing;
  j["feature_edges_dropped"] = r.feature_edges_dropped.size();
  j["sizes_adapted"] = r.sizes_adapted;
  j["gap_length_min"] = r.gap_length_min;
  j["feature_sector_min_deg"] = sector;
  j["links_mended"] = r.links_mended;
  j["islands_seeded"] = r.islands_seeded;
  j["seeds_refined"] = r.seeds_refined;
  j["triangles_removed"] = r.triangles_removed;
  j["input_holes_filled"] = filled.filled;
  j["input_hole_triangles_added"] = filled.triangles_added;
  j["input_holes_left_open"] = filled.left_open;
  j["holes_closed"] = r.holes_closed;
  j["input_crossing_triangles"] = r.input_crossing_triangles;
  j["output_crossing_triangles"] = r.output_crossing_triangles;
  j["vertices_guarded"] = r.vertices_guarded;
  j["vertices_splitting_crossings"] = r.vertices_splitting_crossings;
  j["triangles_closing_holes"] = r.triangles_closing_holes;
  j["vertices_closing_holes"] = r.vertices_closing_holes;
  j["flat_ears_removed"] = r.flat_ears_removed;
  j["flat_pairs_merged"] = r.flat_pairs_merged;
  j["valence_three_removed"] = r.valence_three_removed;
  j["obtuse_corners_split"] = r.obtuse_corners_split;
  j["seeds_added"] = r.islands_seeded + r.seeds_refined + r.links_mended + r.count_grown;
  j["count_grown"] = r.count_grown;
  j["sheets_apart"] = r.sheets_apart;
  j["vertices_added"] = r.vertices_added;
  j["links_flipped"] = r.links_flipped;
  j["tips_closed"] = r.tips_closed;
  j["mend_rounds"] = r.mend_rounds;
  j["time_limit_reached"] = r.time_limit_reached;
  j["feature_hausdorff_max_pct"] = percent_or_null(fd.max, diagonal);
  j["feature_hausdorff_mean_pct"] = percent_or_null(fd.mean, diagonal);
  j["edge_length_ratio"] = {{"p5", r.edge_length_ratio.p5},
                            {"median", r.edge_length_ratio.median},
                            {"p95", r.edge_length_ratio.p95}};
  j["iterations"] = r.iterations;
  j["rvd_evaluations"] = r.rvd_evaluations;
  j["energy_initial"] = r.energy_initial;
  j["energy_final"] = r.energy_final;
  j["gradient_norm_final"] = r.gradient_norm_final;
  j["defects_polished"] = r.defects_polished;
  j["polish_rounds"] = r.polish_rounds;
  j["shape_flips"] = r.shape_flips;
  j["shape_moves"] = r.shape_moves;
  j["short_edges_collapsed"] = r.short_edges_collapsed;
  j["vertices_onto_own_sheet"] = r.vertices_onto_own_sheet;
  j["vertices_on_cell_normals"] = r.vertices_on_cell_normals;
  j["vertices_snapped"] = r.vertices_snapped;
  j["vertices_fitted"] = r.vertices_fitted;
  j["time_s"] = total;
  j["timings"] = {{"initialization", r.seconds_initialization},
                  {"rcvt", r.seconds_rcvt},
                  {"ccvt", r.seconds_ccvt},
                  {"extraction", r.seconds_extraction},
                  {"topology_control", r.seconds_topology},
                  {"hausdorff", r.seconds_hausdorff}};

  std::string& text = report.text;
  if (!r.features.empty()) {
    const std::string distance =
        std::isfinite(fd.max) ? fmt::format("distance max {:.4f}% mean {:.4f}% of bbox diagonal",
                                            100 * fd.max / diagonal, 100 * fd.mean / diagonal)
                              : "no distance (no output feature edge)";
    text += fmt::format(
        "  features  {} edges in {} curves, {}/{} corners kept, {} output feature edges ({} "
        "missing, {} mended), {}; narrowest angle between input features {:.2f}° (θmin of a "
        "faithful output is at most about that)\n",
        r.features.edges.size(), r.features.curves.size(), corners_out, r.features.corners.size(),
        r.feature_edges.size(), r.feature_edges_missing, r.links_mended, distance, sector);
  }
  if (!r.feature_edges_dropped.empty())
    text += fmt::format(
        "  features  {} sharp edges dropped: traced, they cost the input's topology or made the "
        "output pass through itself\n",
        r.feature_edges_dropped.size());
  if (r.gap_length_min > 0)
    text += fmt::format(
        "  sizing    even, graded down to feature gaps and handles narrower than half an edge: "
        "shortest target length {:.3g} of the even one\n",
        r.gap_length_min);
  if (r.sizes_adapted)
    text +=
        "  sizing    adaptive: the output of even edge lengths did not keep the input's "
        "topology\n";
  if (r.count_grown > 0)
    text += fmt::format(
        "  sizing    {} vertices asked for on top of the count: fewer did not keep the input's "
        "topology, or left its boundary loops and creases too few\n",
        r.count_grown);
  if (r.sheets_apart > 0)
    text += fmt::format(
        "  topology  {} sheets remeshed apart and zipped along the edges of three or more "
        "triangles where they meet: remeshed whole, they joined beside those edges or lost the "
        "input's topology\n",
        r.sheets_apart);
  text += fmt::format(
      "  sizing    edge length / target: median {:.3f}, 5th-95th percentile {:.3f}-{:.3f}\n",
      r.edge_length_ratio.median, r.edge_length_ratio.p5, r.edge_length_ratio.p95);
  text += fmt::format(
      "  cvt       {} iterations, {} RVD evaluations, energy {:.6e} -> {:.6e}; {} badly shaped "
      "triangles, {} rounds of Lloyd polishing; {} edges flipped, {} collapsed and {} vertices "
      "moved around badly shaped triangles; {} vertices moved onto their cells' normal lines, {} "
      "onto input creases and {} fitted to the input\n",
      r.iterations, r.rvd_evaluations, r.energy_initial, r.energy_final, r.defects_polished,
      r.polish_rounds, r.shape_flips, r.short_edges_collapsed, r.shape_moves,
      r.vertices_on_cell_normals, r.vertices_snapped, r.vertices_fitted);
  if (r.vertices_onto_own_sheet > 0)
    text += fmt::format(
        "  sheets    {} vertices moved onto the sheet of the input their triangles face (they "
        "stood on the other face of a sharp edge)\n",
        r.vertices_onto_own_sheet);
  if (r.flat_ears_removed > 0)
    text += fmt::format(
        "  boundary  {} flat or folded ears removed (a boundary vertex whose one triangle "
        "was flat, or folded back over its neighbour)\n",
        r.flat_ears_removed);
  if (r.flat_pairs_merged > 0)
    text += fmt::format(
        "  boundary  {} flat pairs merged (a boundary vertex with two triangles on a nearly "
        "straight boundary: the two became one without it)\n",
        r.flat_pairs_merged);
  if (r.obtuse_corners_split > 0)
    text += fmt::format(
        "  shapes    {} obtuse corners split (a triangle over 100° at a boundary vertex, or under "
        "Q 0.6 anywhere: the edge across from it halved)\n",
        r.obtuse_corners_split);
  if (r.mend_rounds > 0 || r.links_flipped > 0 || r.tips_closed > 0)
    text += fmt::format(
        "  topology  {} rounds of control: {} seeds added in split or non-disc cells, {} at "
        "defects, {} on cut curves; {} feature edges flipped in, {} triangles added at boundary "
        "tips\n",
        r.mend_rounds, r.islands_seeded, r.seeds_refined, r.links_mended, r.links_flipped,
        r.tips_closed);
  if (r.triangles_removed > 0 || r.holes_closed > 0)
    text += fmt::format(
        "  last step {} triangles removed at defects the rounds left; {} holes closed with {} "
        "triangles and {} new vertices\n",
        r.triangles_removed, r.holes_closed, r.triangles_closing_holes, r.vertices_closing_holes);
  if (r.input_crossing_triangles > 0)
    text +=
        fmt::format("  input     {} triangles pass through others\n", r.input_crossing_triangles);
  if (r.vertices_guarded > 0 || r.output_crossing_triangles > 0)
    text += fmt::format(
        "  crossings the finishing steps run again with their changes at {} vertices checked for "
        "triangles that pass through others; {} output triangles still do where the input does "
        "not\n",
        r.vertices_guarded, r.output_crossing_triangles);
  if (r.vertices_splitting_crossings > 0)
    text += fmt::format(
        "  crossings {} vertices added where edges were halved so that triangles no longer pass "
        "through others\n",
        r.vertices_splitting_crossings);
  return report;
}

}  // namespace cvtmesh
