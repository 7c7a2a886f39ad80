// The remeshing pipeline (paper §4): initial seeds, RCVT then CCVT, restricted Delaunay output.
#include "remesh/pipeline.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <span>

#include <tbb/task_group.h>

#include "cvt/interrupt.hpp"
#include "cvt/minimize.hpp"
#include "cvt/polish_defects.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/sampling.hpp"
#include "features/curve_lloyd.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_seeds.hpp"
#include "features/renumber_features.hpp"
#include "geometry/area_sampler.hpp"
#include "quality/hausdorff_with_tree.hpp"
#include "remesh/edge_length_ratio.hpp"
#include "remesh/fit_surface.hpp"
#include "remesh/flat_ears.hpp"
#include "remesh/improve_shapes.hpp"
#include "remesh/last_step.hpp"
#include "remesh/mend_topology.hpp"
#include "remesh/valence_three.hpp"
#include "sizing/size_field.hpp"
#include "system/elapsed.hpp"
#include "system/memory_budget.hpp"

namespace cvtmesh {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kMaxVertices = 50'000'000;

// Rounds of stray-seed snapping after CCVT (each a CCVT run and a relaxation around the evened
// curve seeds); one suffices in practice.
constexpr int kSnapRounds = 3;

// Steps of 1D Lloyd along the curves after CCVT: enough to smooth each bunch of short links over
// about four seeds either way, few enough that the curves keep the density CCVT gave them where it
// differs (fully even spacing lost joint.off and triple_vierbein.obj 5-8° at 2k vertices).
constexpr int kCurveLloydSteps = 30;

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
// or any other end of a traced feature edge, nowhere; the rest on the surface.
std::vector<VertexSupport> vertex_supports(const TriangleMesh& output,
                                           const std::map<Vec3, Index>& id,
                                           const std::vector<Vec3>& seeds,
                                           const SeedConstraints& constraints,
                                           const std::vector<Edge>& feature_edges) {
  using Kind = VertexSupport::Kind;
  std::vector<VertexSupport> support(output.vertices.size());
  for (const Edge& e : feature_edges) support[e[0]].kind = support[e[1]].kind = Kind::fixed;
  for (std::size_t s = 0; s < constraints.kind.size(); ++s)
    if (constraints.kind[s] != SeedConstraints::Kind::surface)
      if (const auto it = id.find(seeds[s]); it != id.end()) {
        const bool curve = constraints.kind[s] == SeedConstraints::Kind::curve;
        support[it->second] = {curve ? Kind::curve : Kind::fixed, constraints.curve[s]};
      }
  return support;
}

// Drops the vertices no triangle uses (repair_mesh), and renumbers the rest in `r`'s vertices
// added and feature edges, and in `flags` (per vertex).
void drop_unused_vertices(RemeshResult& r, std::vector<bool>& flags) {
  std::vector<Index> new_id;
  repair_mesh(r.mesh, &new_id);
  std::erase_if(r.vertices_added, [&](Index v) { return new_id[v] == kRemovedVertex; });
  for (Index& v : r.vertices_added) v = new_id[v];
  r.feature_edges = edges_after_repair(r.feature_edges, new_id);
  std::vector<bool> kept(r.mesh.vertices.size(), false);
  for (std::size_t v = 0; v < new_id.size(); ++v)
    if (new_id[v] != kRemovedVertex) kept[new_id[v]] = flags[v];
  flags = std::move(kept);
}

// One output size at most; none only for initial seeds (their count is the size) or target
// `count` random seeds: area-uniform, or with the density of the target lengths (paper §4.1).
std::vector<Vec3> random_seeds(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
                               const SizeField* field) {
  if (!field) return sample_surface(mesh, count, seed);
  const AreaSampler sampler(mesh, seed, field->seed_weights());
  std::vector<Vec3> points(count);
  for (std::size_t k = 0; k < count; ++k) points[k] = sampler(k);
  return points;
}

// Detects the features at `scale` (unless FeatureSettings::scale is set): in the caller's ids
// into result.features, in the ids of the sorted mesh (`new_id`) into `features`.
void detect_features_at(const TriangleMesh& input, const std::vector<Index>& new_id,
                        const RemeshSettings& settings, double scale, RemeshResult& result,
                        Features& features) {
  FeatureSettings feature_settings = settings.features;
  if (feature_settings.scale == 0) feature_settings.scale = scale;
  result.features = detect_features(input, feature_settings);
  features = renumbered(result.features, new_id);
}

}  // namespace

double scale_before_sizing(const TriangleMesh& mesh, const RemeshSettings& s) {
  if (s.features.scale > 0) return s.features.scale;
  const std::size_t n = s.vertices > 0 ? s.vertices : s.initial_seeds.size();
  if (n > 0) return edge_length_for(surface_area(mesh), n);
  return s.edge_length != 0 ? s.edge_length : s.edge_length_rel * bounding_box(mesh).diagonal();
}

double edge_length_for(double area, std::size_t n) {
  return std::sqrt(area / (std::sqrt(3.0) / 2 * static_cast<double>(n)));
}

// lengths given as they are (RemeshSettings).
void check_output_size(const RemeshSettings& s) {
  const int given = (s.vertices > 0) + (s.edge_length != 0) + (s.edge_length_rel != 0);
  const bool sizes_as_given = s.sizing.active() && !(s.sizing.adaptive > 0);
  if (given > 1 || (given == 0 && !sizes_as_given && s.initial_seeds.empty()))
    throw InvalidArgument(
        "give exactly one output size: a vertex count, an edge length, or a relative edge length");
}

std::size_t unit_vertex_count(const TriangleMesh& mesh, const RemeshSettings& s,
                              const SizeField* field) {
  check_output_size(s);
  double count = static_cast<double>(s.vertices);
  if (s.vertices == 0 && field) {
    count = std::round(field->vertex_count());
  } else if (s.vertices == 0) {
    const double h =
        s.edge_length != 0 ? s.edge_length : s.edge_length_rel * bounding_box(mesh).diagonal();
    if (!(h > 0) || !std::isfinite(h)) throw InvalidArgument("the edge length must be positive");
    // Equilateral triangles of side h, about two per vertex: V ≈ A / (√3/2 · h²).
    count = std::round(surface_area(mesh) / (std::sqrt(3.0) / 2 * h * h));
  }
  if (count < 4)
    throw InvalidArgument("the output would have " + std::to_string(static_cast<long long>(count)) +
                          " vertices; at least 4 are needed");
  if (count > static_cast<double>(kMaxVertices))
    throw InvalidArgument("the output would have " + std::to_string(static_cast<long long>(count)) +
                          " vertices, more than the limit of 50 million");
  return static_cast<std::size_t>(count);
}

UnitRemesh remesh_unit(const TriangleMesh& input, const RemeshSettings& settings) {
  const auto start = Clock::now();
  if (settings.iterations < 0) throw InvalidArgument("the iteration cap must not be negative");
  if (settings.polish_rounds < 0)
    throw InvalidArgument("the number of polishing rounds must not be negative");
  if (settings.shape_sweeps < 0)
    throw InvalidArgument("the number of shape sweeps must not be negative");
  if (settings.topology_rounds < 0)
    throw InvalidArgument("the number of topology control rounds must not be negative");
  if (!(settings.gradient_tolerance > 0))
    throw InvalidArgument("the gradient tolerance must be positive");
  if (!(settings.time_limit >= 0)) throw InvalidArgument("the time limit must not be negative");
  const Interrupt interrupt(settings.cancel, settings.time_limit, start);
  if (!(surface_area(input) > 0)) throw InputError("the surface has no area");
  check_output_size(settings);
  // Everything below works on the input in spatial order (issue 19: RVD walks on a file in no
  // spatial order are up to 10x longer); the features are reported in the caller's ids.
  const SpatiallySorted sorted = spatially_sorted(input);
  const TriangleMesh& mesh = sorted.mesh;
  RemeshResult result;
  Features features;  // result.features, in the ids of `mesh`
  // An adaptive sizing narrows to the gaps between features (issue 20 item 1), so it needs them
  // first, detected at the scale its output size gives before the sizes are known.
  const bool adaptive = settings.sizing.adaptive > 0;
  if (adaptive)
    detect_features_at(input, sorted.new_id, settings, scale_before_sizing(mesh, settings), result,
                       features);
  // Target lengths that vary (issue 20) enter the CVT as its density ρ (eq. 1).
  const std::optional<SizeField> sizes =
      make_size_field(mesh, sorted.new_id, settings, adaptive ? &features : nullptr);
  const SizeField* field = sizes ? &*sizes : nullptr;
  const std::size_t count = settings.initial_seeds.empty()
                                ? unit_vertex_count(mesh, settings, field)
                                : settings.initial_seeds.size();
  check_memory_for(input.triangles.size(), count);
  std::vector<Vec3> seeds = settings.initial_seeds.empty()
                                ? random_seeds(mesh, count, settings.seed, field)
                                : settings.initial_seeds;
  // The edge length of the same count spread evenly: the scale of feature detection, and where
  // ρ = 1.
  const double spacing = edge_length_for(surface_area(mesh), seeds.size());
  const std::vector<double> density = sizes ? sizes->density(spacing) : std::vector<double>{};
  // What only CCVT needs (the AABB tree, the features: 0.45 s on igea's 270k triangles, all
  // serial) is built while RCVT runs, so that it fills the cores RCVT leaves idle.
  std::optional<SurfaceProjector> projector;
  std::optional<CurveProjector> curves;
  std::optional<CurveSpacing> curve_spacing;
  tbb::task_group ccvt_setup;
  ccvt_setup.run([&] {
    projector.emplace(mesh);
    if (!adaptive) detect_features_at(input, sorted.new_id, settings, spacing, result, features);
    curves.emplace(mesh, features);
    curve_spacing.emplace(sizes ? CurveSpacing(spacing, *curves, features, *sizes)
                                : CurveSpacing(spacing));
    result.input_topology = analyze_topology(mesh);  // what topology control compares with
  });
  SeedConstraints constraints;
  result.seconds_initialization = seconds_since(start);

  // RCVT when `bound` is null; CCVT with the seeds bound as it says otherwise.
  // Out of time, a phase does not start (issue 22: the seeds as they are make the output).
  auto run_phase = [&](const char* name, const SeedConstraints* bound, double& phase_seconds) {
    if (interrupt.out_of_time()) return;
    const auto phase_start = Clock::now();
    CvtObjective objective(mesh, bound ? &*projector : nullptr, bound, bound ? &*curves : nullptr,
                           &interrupt, &density);
    const PhaseOptions options{name, settings.iterations, settings.gradient_tolerance,
                               &settings.progress, start};
    const PhaseResult phase = settings.optimizer == Optimizer::lbfgs
                                  ? minimize_lbfgs(objective, seeds, options)
                                  : minimize_lloyd(objective, seeds, options);
    if (result.rvd_evaluations == 0) {
      result.energy_initial = phase.energy_initial;
      result.gradient_norm_initial = phase.gradient_initial;
    }
    result.rvd_evaluations += objective.evaluations();
    result.iterations += phase.iterations;
    result.energy_final = phase.energy_final;
    result.gradient_norm_final = phase.gradient_final;
    result.energies.insert(result.energies.end(), phase.energies.begin(), phase.energies.end());
    phase_seconds = seconds_since(phase_start);
  };
  if (settings.mode != CvtMode::ccvt) run_phase("rcvt", nullptr, result.seconds_rcvt);
  ccvt_setup.wait();
  if (settings.mode != CvtMode::rcvt) {
    // The paper's two stages (§4.3): the RCVT spread the seeds; the nearest to the features now
    // move onto them, and CCVT optimizes with them bound there.
    if (!features.empty())
      constraints = place_feature_seeds(seeds, mesh, features, *curves, *curve_spacing);
    run_phase("ccvt", &constraints, result.seconds_ccvt);
    // Surface seeds that took over a stretch of a curve join it, and CCVT resumes. Then the curve
    // seeds even out along their curves and the surface seeds relax around them, held there;
    // that rarely leaves a stray, but if it does, another round.
    for (int round = 0; round < kSnapRounds && !constraints.empty() && !interrupt.timed_out();
         ++round) {
      const std::size_t joined = snap_stray_seeds(seeds, constraints, *curves, *curve_spacing);
      if (round > 0 && joined == 0) break;
      double more = 0;
      if (joined > 0) run_phase("ccvt", &constraints, more);
      result.seconds_ccvt += more;
      relax_curve_seeds(seeds, constraints, *curves, *curve_spacing, kCurveLloydSteps);
      const SeedConstraints held = curve_seeds_held(constraints, seeds);
      run_phase("ccvt-surface", &held, more);
      result.seconds_ccvt += more;
    }
  }

  // Output vertices lie on the surface: project (a no-op after CCVT), then triangulate, with
  // local Lloyd steps around any badly shaped triangles.
  const auto extraction_start = Clock::now();
  CvtObjective placement(mesh, &*projector, &constraints, &*curves, &interrupt, &density);
  placement.project(seeds);
  PolishedOutput output = extract_polished(mesh, seeds, placement, {settings.polish_rounds});
  result.polish_rounds = output.rounds;
  result.defects_polished = output.defects;
  // Topology control (paper §4.4): curves cut by a third cell, cells in several pieces.
  const MendContext context{
      mesh,           result.input_topology,   features, *curves, *projector, placement,
      *curve_spacing, {settings.polish_rounds}};
  MendReport mends;
  const std::size_t optimized_seeds = seeds.size();  // the rounds append theirs
  output = mend_topology(context, std::move(output), seeds, constraints, settings.topology_rounds,
                         mends);
  result.polish_rounds += mends.polish_rounds;
  result.links_mended = mends.links_mended;
  result.islands_seeded = mends.islands;
  result.seeds_refined = mends.refined;
  result.links_flipped = mends.links_flipped;
  result.tips_closed = mends.tips_closed;
  result.mend_rounds = mends.rounds;
  result.mesh = std::move(output.mesh);
  // The guaranteed last step: whatever defect the rounds left goes, leaving a manifold. Only for
  // a manifold input: a non-manifold input edge is a feature the output keeps (issue 18).
  const LastStep last = finish_manifold(result.mesh, result.input_topology, *projector);
  result.triangles_removed = last.triangles_removed;
  result.holes_closed = last.closed.holes;
  result.triangles_closing_holes = last.closed.triangles;
  result.vertices_closing_holes = last.closed.vertices;
  // The mesh's first vertices are the seeds, by id (PolishedOutput).
  std::vector<bool> corners(result.mesh.vertices.size(), false);
  for (const Index s : constraints.corner_seed) corners[s] = true;
  result.flat_ears_removed = remove_flat_ears(result.mesh, corners);
  repair_mesh(result.mesh);  // drops seeds whose cells are empty
  const std::map<Vec3, Index> output_id = vertex_ids(result.mesh);
  result.vertices_added =
      vertices_at(output_id, std::span(seeds).subspan(std::min(optimized_seeds, seeds.size())));
  if (!constraints.empty()) {
    const std::vector<FeatureLink> links = feature_links(seeds, constraints, features, *curves);
    result.feature_edges = traced_edges(links, seeds, result.mesh, output_id);
    std::vector<Edge> wanted;
    for (const FeatureLink& link : links) wanted.push_back(link.seeds);
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    result.feature_edges_missing = wanted.size() - result.feature_edges.size();
  }
  // Last, as it moves vertices off the seeds' positions (which the matching above needs).
  const std::vector<VertexSupport> supports =
      vertex_supports(result.mesh, output_id, seeds, constraints, result.feature_edges);
  const ShapeImprovement shapes = improve_shapes(result.mesh, *projector, &*curves, supports,
                                                 result.feature_edges, settings.shape_sweeps);
  result.shape_flips = shapes.flips;
  result.shape_moves = shapes.moves;
  result.short_edges_collapsed = shapes.collapses;
  // Last of all, as a vertex of three triangles is often what the flips and moves leave.
  std::vector<bool> removable;
  for (const VertexSupport& s : supports)
    removable.push_back(s.kind == VertexSupport::Kind::surface);
  result.valence_three_removed = remove_valence_three(result.mesh, removable, *projector);
  if (result.valence_three_removed + shapes.collapses > 0) drop_unused_vertices(result, removable);
  // Surface vertices only: a feature or corner vertex stays on its curve.
  const SurfaceFit fit =
      fit_to_surface(result.mesh, *projector, std::move(removable), settings.fit_rounds);
  result.vertices_fitted = fit.vertices_moved;
  std::vector<double> ratios = edge_length_ratios(result.mesh, *projector, field, spacing);
  result.edge_length_ratio = ratio_percentiles(ratios);
  result.seconds_extraction = seconds_since(extraction_start);
  result.time_limit_reached = interrupt.timed_out();
  interrupt.check();
  if (settings.hausdorff && !result.mesh.triangles.empty())
    result.hausdorff = hausdorff_distance(result.mesh, input, *projector, *settings.hausdorff);
  return {std::move(result), std::move(ratios)};
}

}  // namespace cvtmesh
