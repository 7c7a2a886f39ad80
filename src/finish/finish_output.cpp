#include "finish/finish_output.hpp"

#include <tbb/parallel_invoke.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <utility>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "features/edge_uses.hpp"
#include "finish/bar_shapes.hpp"
#include "finish/best_round.hpp"
#include "finish/cell_normal_points.hpp"
#include "finish/changed_vertices.hpp"
#include "finish/coincident_edges.hpp"
#include "finish/fit_surface.hpp"
#include "finish/flat_ears.hpp"
#include "finish/flat_pairs.hpp"
#include "finish/improve_shapes.hpp"
#include "finish/own_sheet.hpp"
#include "finish/snap_to_creases.hpp"
#include "finish/split_obtuse_corners.hpp"
#include "finish/valence_three.hpp"
#include "geometry/angle.hpp"
#include "quality/narrow_angles.hpp"

namespace cvtmesh {

namespace {

// The output's vertices are seeds, matched by position (repairs renumber them).
std::map<Vec3, Index> vertex_ids(const TriangleMesh& output) {
  std::map<Vec3, Index> id;
  for (Index v = 0; v < output.vertices.size(); ++v) id.emplace(output.vertices[v], v);
  return id;
}

// The ids (`id`: vertex_ids of the output) of the output vertices at `seeds` (those with a
// vertex), sorted.
std::vector<Index> vertices_at(const std::map<Vec3, Index>& id, std::span<const Vec3> seeds) {
  std::vector<Index> found;
  for (const Vec3& p : seeds)
    if (const auto it = id.find(p); it != id.end()) found.push_back(it->second);
  std::sort(found.begin(), found.end());
  return found;
}

// The links that are edges of the output, in output vertex ids (`id`: vertex_ids(output)).
std::vector<Edge> traced_edges(const std::vector<FeatureLink>& links,
                               const std::vector<Vec3>& seeds, const TriangleMesh& output,
                               const std::map<Vec3, Index>& id) {
  const std::vector<Edge> edges = sorted_edges(output);
  std::vector<Edge> traced;
  for (const FeatureLink& link : links) {
    const auto ia = id.find(seeds[link.seeds[0]]), ib = id.find(seeds[link.seeds[1]]);
    if (ia == id.end() || ib == id.end()) continue;
    const Edge e{std::min(ia->second, ib->second), std::max(ia->second, ib->second)};
    if (std::binary_search(edges.begin(), edges.end(), e)) traced.push_back(e);
  }
  std::sort(traced.begin(), traced.end());
  traced.erase(std::unique(traced.begin(), traced.end()), traced.end());
  return traced;
}

// Per output vertex, where improve_shapes may move it: a curve seed along its curve; a corner,
// or any other end of a traced feature edge, nowhere; the rest on the surface. Every vertex at a
// corner is one (a pinch: one vertex per sheet that touches there, welded later). The vertices
// at `guarded` are guarded.
std::vector<VertexSupport> vertex_supports(const TriangleMesh& output,
                                           const std::map<Vec3, Index>& id,
                                           const std::vector<Vec3>& seeds,
                                           const SeedConstraints& constraints,
                                           const std::vector<Edge>& feature_edges,
                                           const std::set<Vec3>& guarded) {
  using Kind = VertexSupport::Kind;
  std::vector<VertexSupport> support(output.vertices.size());
  for (const Edge& e : feature_edges) support[e[0]].kind = support[e[1]].kind = Kind::fixed;
  for (std::size_t s = 0; s < constraints.kind.size(); ++s)
    if (constraints.kind[s] != SeedConstraints::Kind::surface)
      if (const auto it = id.find(seeds[s]); it != id.end()) {
        const bool curve = constraints.kind[s] == SeedConstraints::Kind::curve;
        support[it->second] = {curve ? Kind::curve : Kind::fixed, constraints.curve[s]};
      }
  std::set<Vec3> corners;
  for (const Index s : constraints.corner_seed) corners.insert(seeds[s]);
  for (Index v = 0; v < output.vertices.size(); ++v) {
    if (corners.contains(output.vertices[v])) support[v].kind = Kind::fixed;
    support[v].guarded = guarded.contains(output.vertices[v]);
  }
  return support;
}

// Rounds of halving the obtuse triangles under the bar, each kept only where it shapes the
// output better.
constexpr int kHalvingRounds = 3;

// Per vertex, the input angle under 30° of a tip the output traces there (else 0): a vertex within
// `reach` of one of `narrow` (narrow_angle_at_vertices) with an angle under 1.5 times it in one
// of its triangles. Where the output rounds the tip off, its triangles there are judged as any
// other (lion.off at 1k: its 8° tip's nearest triangle has 41°).
std::vector<double> traced_tips(const TriangleMesh& mesh, const std::vector<NarrowAngle>& narrow,
                                double reach) {
  if (narrow.empty()) return {};  // most inputs: no search, no pass over the triangles
  const std::vector<double> near = narrow_angle_at_vertices(mesh, narrow, reach);
  std::vector<double> tip(near.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index v = t[k];
      if (near[v] == 0) continue;
      const Vec3& p = mesh.vertices[v];
      if (angle_deg(mesh.vertices[t[(k + 1) % 3]] - p, mesh.vertices[t[(k + 2) % 3]] - p) <
          1.5 * near[v])
        tip[v] = near[v];
    }
  return tip;
}

}  // namespace

void finish_output(RemeshResult& result, const std::vector<Vec3>& seeds,
                   std::size_t optimized_seeds, const std::vector<CellNormal>& cells,
                   const SeedConstraints& constraints, const Features& features,
                   const CurveProjector& curves, const TriangleMesh& surface,
                   const SurfaceProjector& projector, const std::vector<NarrowAngle>& narrow,
                   const RemeshSettings& settings, const std::set<Vec3>& guarded) {
  // The mesh's first vertices are the seeds, by id (PolishedOutput).
  std::vector<bool> corners(result.mesh.vertices.size(), false), seedless(corners.size(), false);
  for (const Index s : constraints.corner_seed) corners[s] = true;
  // Past the seeds: the cells' far pieces, and the centres of holes the last step closed.
  for (std::size_t v = seeds.size(); v < seedless.size(); ++v) seedless[v] = true;
  result.flat_ears_removed = remove_flat_ears(result.mesh, corners, seedless);
  repair_mesh(result.mesh);  // drops seeds whose cells are empty
  const std::map<Vec3, Index> output_id = vertex_ids(result.mesh);
  result.vertices_added =
      vertices_at(output_id, std::span(seeds).subspan(std::min(optimized_seeds, seeds.size())));
  if (!constraints.empty()) {
    const std::vector<FeatureLink> links = feature_links(seeds, constraints, features, curves);
    result.feature_edges = traced_edges(links, seeds, result.mesh, output_id);
    std::vector<Edge> wanted;
    for (const FeatureLink& link : links) wanted.push_back(link.seeds);
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    result.feature_edges_missing = wanted.size() - result.feature_edges.size();
  }
  // Last, as it moves vertices off the seeds' positions (which the matching above needs).
  std::vector<VertexSupport> supports =
      vertex_supports(result.mesh, output_id, seeds, constraints, result.feature_edges, guarded);
  // The surface vertices: those that the finishing steps may move or remove; not the guarded
  // ones, which only improve_shapes moves, checked for crossings.
  const auto removable_in = [](const std::vector<VertexSupport>& of) {
    std::vector<bool> removable;
    for (const VertexSupport& s : of)
      removable.push_back(s.kind == VertexSupport::Kind::surface && !s.guarded);
    return removable;
  };
  // Before the sweeps, which mend the shapes the moves leave.
  result.vertices_onto_own_sheet =
      move_onto_own_sheet(result.mesh, projector, removable_in(supports));
  // Obtuse boundary corners split, then swept, against the output swept as it is: the split
  // leaves the triangles across the halved edge obtuse until the sweeps move its midpoint, and
  // where they cannot, the output without it is kept (ALSTOM_TEST4.off at 1k: Qmin 0.592 as it
  // is, 0.540 split).
  // Half an edge: how near a narrow angle a vertex stands for it (as the report has it).
  const double reach = narrow.empty() ? 0 : 0.5 * measure_quality(result.mesh).edge_length_mean;
  TriangleMesh split = result.mesh;
  const std::size_t corners_split = split_obtuse_corners(split, result.feature_edges, projector);
  std::vector<VertexSupport> split_supports;
  std::vector<Edge> split_features;
  ShapeImprovement split_shapes;
  if (corners_split > 0) {
    split_supports = supports;
    split_supports.resize(split.vertices.size());  // the midpoints are surface vertices
    split_features = result.feature_edges;
  }
  // Flat pairs merged, as a second output that goes through the same steps (sweeps, halving
  // rounds) as the first, the better of the two kept.
  std::vector<Vec3> corner_points;
  for (const Index s : constraints.corner_seed) corner_points.push_back(seeds[s]);
  std::vector<bool> corners_now(result.mesh.vertices.size(), false);
  for (const Index v : vertices_at(output_id, corner_points)) corners_now[v] = true;
  TriangleMesh merged = result.mesh;
  // Its features as they are before the sweeps (which change them).
  std::vector<Edge> merged_features = result.feature_edges;
  const std::size_t pairs = merge_flat_pairs(merged, merged_features, corners_now);
  std::vector<VertexSupport> merged_supports;
  if (pairs > 0) merged_supports = supports;
  // Obtuse triangles the sweeps left under the bar, at any vertex (an interior vertex of valence 7
  // among smaller cells, where the sizes grade down to a hole, or one just off a feature curve):
  // the edge across from the obtuse angle halved (on its curve, if it is a feature edge), then
  // swept again (all over the mesh the first time, for whatever the first sweeps left, halved or
  // not). Each round halves what the last one gone on from left; which is kept, and when they
  // end, best_round says.
  struct Round {
    TriangleMesh mesh;
    std::vector<Edge> features;
    std::vector<VertexSupport> supports;
    ShapeImprovement shapes;
    std::size_t added = 0, removed = 0;
  };
  // The halvings of a round from `from`, all or (`held`: narrow_angle_at_vertices) none at a
  // narrow angle.
  const auto halved = [&](const Round& from, const std::vector<double>* held) {
    Round next = from;
    CurveSplits along{curves, next.supports, next.features};
    next.added += split_obtuse_corners(next.mesh, from.features, projector,
                                       ObtuseCorners::under_bar, &along, held);
    return next;
  };
  // The sweeps after round k's halvings, and the shapes they leave.
  const auto swept = [&](Round next, const Round& from, int k) {
    const ShapeImprovement more = improve_shapes(
        next.mesh, projector, &curves, next.supports, next.features, settings.shape_sweeps,
        traced_tips(next.mesh, narrow, reach),
        k == 0 ? std::vector<bool>{} : around_new_vertices(next.mesh, from.mesh.vertices.size()));
    next.shapes.flips += more.flips;
    next.shapes.moves += more.moves;
    next.shapes.collapses += more.collapses;
    next.removed += remove_valence_three(next.mesh, removable_in(next.supports), projector);
    const BarShapes after = bar_shapes(next.mesh, narrow, reach);
    return std::optional(std::pair{std::move(next), after});
  };
  // `halved_all`: the current round's halvings, all of them, before sweeps (one per chain of
  // rounds, as two chains run at once below).
  const auto attempt = [&](std::vector<Triangle>& halved_all, const Round& from, int k,
                           bool again) -> std::optional<std::pair<Round, BarShapes>> {
    if (!again) {
      Round all = halved(from, nullptr);
      if (all.added == from.added && k > 0) return std::nullopt;
      if (!narrow.empty()) halved_all = all.mesh.triangles;  // for the retry below
      return swept(std::move(all), from, k);
    }
    // Halvings at a narrow angle, where the bar does not hold, can cost a round what the others
    // gain (lion.off at 5k: 39.2° away from its 8° tip for none, 40.0° without them; fandisk.off
    // adaptive at 2k, 38.8° and 40.2°), and help at the angle elsewhere (mech-holes-shark.off at
    // 5k: Q 0.41 -> 0.52 there): the round again without them where it is better nowhere with
    // them.
    if (narrow.empty()) return std::nullopt;
    const std::vector<double> narrow_at = narrow_angle_at_vertices(from.mesh, narrow, reach);
    Round held = halved(from, &narrow_at);
    if (held.mesh.triangles == halved_all) return std::nullopt;
    return swept(std::move(held), from, k);
  };
  // The rounds from an output swept once, its vertices of three triangles removed first (a vertex
  // of three triangles is often what the flips and moves leave: each output is judged without).
  const auto rounds_from = [&](Round start) {
    start.removed += remove_valence_three(start.mesh, removable_in(start.supports), projector);
    BarShapes start_shapes = bar_shapes(start.mesh, narrow, reach);
    std::vector<Triangle> halved_all;
    const auto attempt_here = [&](const Round& from, int k, bool again) {
      return attempt(halved_all, from, k, again);
    };
    return best_round(std::move(start), start_shapes, kHalvingRounds, attempt_here, judge_round);
  };
  // The three outputs (as it is, its obtuse boundary corners split, its flat pairs merged) are
  // swept apart, each on one thread in a fixed order, so they run at once: the sweeps are serial
  // (improve_shapes), and one after the other they took a fifth of a whole remesh's time on two
  // cores where all three run (lion.off at 10k: 0.24 s of 1.3 s; at once, 0.17 s). Each goes as
  // it went one after the other: the outcome is the same.
  std::optional<Round> merged_best;
  tbb::task_group merged_work;  // declared after what its task uses, so an exception waits for it
  if (pairs > 0)
    merged_work.run([&] {
      const ShapeImprovement merged_shapes =
          improve_shapes(merged, projector, &curves, merged_supports, merged_features,
                         settings.shape_sweeps, traced_tips(merged, narrow, reach));
      merged_best = rounds_from({std::move(merged), std::move(merged_features),
                                 std::move(merged_supports), merged_shapes});
    });
  ShapeImprovement shapes;
  tbb::parallel_invoke(
      [&] {
        if (corners_split > 0)
          split_shapes = improve_shapes(split, projector, &curves, split_supports, split_features,
                                        settings.shape_sweeps, traced_tips(split, narrow, reach));
      },
      [&] {
        shapes = improve_shapes(result.mesh, projector, &curves, supports, result.feature_edges,
                                settings.shape_sweeps, traced_tips(result.mesh, narrow, reach));
      });
  if (corners_split > 0 &&
      shaped_better(bar_shapes(split, narrow, reach), bar_shapes(result.mesh, narrow, reach))) {
    result.mesh = std::move(split);
    result.feature_edges = std::move(split_features);
    supports = std::move(split_supports);
    shapes = split_shapes;
    result.obtuse_corners_split = corners_split;
  }
  Round best = rounds_from({result.mesh, result.feature_edges, supports, shapes});
  merged_work.wait();
  // The flat pairs merged, swept and taken through the rounds alike, kept where the output ends
  // better so, the worst triangle first: where the sweeps mend a pair, they can do better than
  // the merged triangle, whose boundary edge they cannot flip, and the rounds after can change
  // which is better (beetle.obj of a public test set at 5k: θmin 6.2° as it is, 2.8° merged;
  // beetle-alt.obj 8.7° as it is, 19.5° merged; at 1k, after one sweep, merged was the better,
  // after the rounds the worse, 17.8° against 19.1°).
  if (merged_best) {
    const BarShapes with = bar_shapes(merged_best->mesh, narrow, reach),
                    without = bar_shapes(best.mesh, narrow, reach);
    // Never at the cost of the worst away from narrow angles, where the promise is the bar
    // (lion.off at 10k: merged, 8.0° -> 13.8° at its 8° tip, 36.8° -> 28.2° away from it).
    if (judge_round(with, without) == Verdict::better &&
        with.away.quality >= without.away.quality && with.away.angle >= without.away.angle) {
      best = std::move(*merged_best);
      result.obtuse_corners_split = 0;
      result.flat_pairs_merged = pairs;
    }
  }
  result.mesh = std::move(best.mesh);
  result.feature_edges = std::move(best.features);
  supports = std::move(best.supports);
  shapes = best.shapes;
  result.obtuse_corners_split += best.added;
  result.valence_three_removed = best.removed;
  result.shape_flips = shapes.flips;
  result.shape_moves = shapes.moves;
  result.short_edges_collapsed = shapes.collapses;
  std::vector<bool> removable = removable_in(supports);
  if (result.valence_three_removed + shapes.collapses + result.flat_pairs_merged > 0)
    drop_unused_vertices(result, removable);
  // Surface vertices only: a feature or corner vertex stays on its curve.
  if (!cells.empty())
    result.vertices_on_cell_normals =
        move_onto_cell_normals(result.mesh, seeds, cells, projector, removable);
  if (settings.fit_rounds > 0)
    result.vertices_snapped = snap_to_creases(result.mesh, surface, features, projector, removable);
  const SurfaceFit fit = fit_to_surface(result.mesh, projector, removable, settings.fit_rounds);
  result.vertices_fitted = fit.vertices_moved;
  // Last of all, once no step moves a vertex again (issue 18: no triangle of no area).
  const std::size_t coincident = collapse_coincident_edges(result.mesh, result.feature_edges);
  result.short_edges_collapsed += coincident;
  if (coincident > 0) drop_unused_vertices(result, removable);
}

}  // namespace cvtmesh
