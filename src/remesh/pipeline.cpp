// The remeshing pipeline (paper §4): initial seeds, RCVT then CCVT, restricted Delaunay output,
// topology control (remesh/mend_topology) and its last step (remesh/last_step), the finishing
// steps (finish/finish_output).
#include "remesh/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <set>

#include <tbb/task_group.h>

#include "cvt/interrupt.hpp"
#include "cvt/minimize.hpp"
#include "cvt/polish_defects.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/quality.hpp"
#include "features/curve_lloyd.hpp"
#include "features/feature_seeds.hpp"
#include "features/renumber_features.hpp"
#include "finish/crossing_guard.hpp"
#include "finish/finish_output.hpp"
#include "finish/split_crossings.hpp"
#include "geometry/even_spacing.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/spread_samples.hpp"
#include "quality/hausdorff_with_tree.hpp"
#include "remesh/edge_length_ratio.hpp"
#include "remesh/last_step.hpp"
#include "remesh/mend_topology.hpp"
#include "sizing/size_field.hpp"
#include "system/elapsed.hpp"
#include "system/memory_budget.hpp"
#include "voronoi/cell_normals.hpp"
#include "voronoi/side_rings.hpp"

namespace cvtmesh {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kMaxVertices = 50'000'000;

// Steps of 1D Lloyd along the curves after CCVT: enough to smooth each bunch of short links over
// about four seeds either way, few enough that the curves keep the density CCVT gave them where it
// differs (fully even spacing lost joint.off and triple_vierbein.obj 5-8° at 2k vertices).
constexpr int kCurveLloydSteps = 30;

// Where the finishing steps made the output cross itself: how many times they are run again,
// guarding the extraction's vertices within kGuardReach, then twice and three times that, times
// a crossing triangle's longest edge of its centroid (finish/crossing_guard).
constexpr int kGuardAttempts = 3;
constexpr double kGuardReach = 1.5;
// Rounds of halving at crossings left after that (finish/split_crossings): each halves the
// chords that sag through a thin wall; couplingdown.off at 100 vertices needed four.
constexpr int kSplitRounds = 8;

// `count` seeds spread about the target lengths apart (paper §4.1 draws them ∝ √ρ at random).
std::vector<Vec3> seeds_by_size(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
                                const SizeField& field) {
  return spread_samples(mesh, count, seed, field.seed_weights(),
                        [&](std::size_t t, const Vec3& p) { return field.at(t, p); });
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

// One output size at most; none only for initial seeds (their count is the size) or target
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
  // The AABB tree over the surface (CCVT's projections, the output's fitting, the report's
  // distances) is the setup's largest step, and serial: 0.27 s on igea.ply's 270k triangles. It
  // starts now, on a core that the serial steps up to RCVT leave idle, where it slowed RCVT down
  // (igea.ply at 10k and 5k: whole runs 3.4% and 2.1% shorter), over the sorted input: the surface
  // remeshed, unless sizes split its triangles (then it is built again, over those).
  std::optional<SurfaceProjector> on_sorted, on_split;
  const SurfaceProjector* projector = nullptr;  // on_sorted or on_split, once built
  // Each task group is declared after what its tasks use: where an exception leaves this
  // function, it waits for them before those go.
  tbb::task_group tree_setup;
  tree_setup.run([&] { on_sorted.emplace(sorted.mesh); });
  RemeshResult result;
  Features features;  // result.features, in the ids of `mesh`
  // An adaptive sizing narrows to the gaps between features (issue 20 item 1), so it needs them
  // first, detected at the scale its output size gives before the sizes are known.
  // So does an even sizing graded at the gaps (SizingSettings::gap_gradation), at the scale of
  // its even lengths.
  const bool adaptive = settings.sizing.adaptive > 0;
  const bool gaps = !settings.sizing.active() && settings.sizing.gap_gradation > 0 &&
                    settings.initial_seeds.empty();
  const bool features_first = adaptive || gaps;
  if (features_first)
    detect_features_at(input, sorted.new_id, settings, scale_before_sizing(sorted.mesh, settings),
                       result, features);
  // Target lengths that vary (issue 20) enter the CVT as its density ρ (eq. 1); where they
  // change fast, on a copy of the input with triangles split to follow them.
  std::optional<TriangleMesh> split;
  const std::optional<SizeField> sizes = make_size_field(
      sorted.mesh, sorted.new_id, settings, features_first ? &features : nullptr, &split);
  const TriangleMesh& mesh = split ? *split : sorted.mesh;
  const SizeField* field = sizes ? &*sizes : nullptr;
  const std::size_t count = settings.initial_seeds.empty()
                                ? unit_vertex_count(mesh, settings, field)
                                : settings.initial_seeds.size();
  check_memory_for(input.triangles.size(), count);
  // The caller's; or spread about the target lengths apart.
  const bool spread = settings.initial_seeds.empty();
  std::vector<Vec3> seeds = settings.initial_seeds;
  if (spread && field)
    seeds = seeds_by_size(mesh, count, settings.seed, *field);
  else if (spread)
    seeds = spread_samples(mesh, count, settings.seed);
  // The edge length of the same count spread evenly: the scale of feature detection, and where
  // ρ = 1.
  const double spacing = edge_length_for(surface_area(mesh), seeds.size());
  const std::vector<double> density = sizes ? sizes->density(spacing) : std::vector<double>{};
  if (gaps && sizes) {
    double shortest = spacing;
    for (const Triangle& t : mesh.triangles)
      for (const Index v : t) shortest = std::min(shortest, sizes->at_vertex(v));
    result.gap_length_min = shortest / spacing;
  }
  // What else only CCVT needs (the features, their curves, the input's topology) is built while
  // RCVT runs, so that it fills the cores RCVT leaves idle.
  std::optional<CurveProjector> curves;
  std::optional<CurveSpacing> curve_spacing;
  std::optional<SideRings> rings;  // for every extraction's cell pieces
  tbb::task_group ccvt_setup;
  ccvt_setup.run([&] {
    if (split) on_split.emplace(mesh);
    rings.emplace(mesh);
    if (!features_first)
      detect_features_at(input, sorted.new_id, settings, spacing, result, features);
    curves.emplace(mesh, features);
    curve_spacing.emplace(sizes ? CurveSpacing(spacing, *curves, features, *sizes)
                                : CurveSpacing(spacing));
    result.input_topology = analyze_topology(mesh);  // what topology control compares with
  });
  SeedConstraints constraints;
  result.seconds_initialization = seconds_since(start);

  // On an input without features and with ρ = 1, CCVT has no seed to bind to a curve, and the
  // whole budget goes to RCVT, its seeds projected onto the surface only for the output (issue
  // 19 item 6): the seeds of the unconstrained CVT, projected, approximate the surface better
  // than seeds held on it all along, as measured (bunny.off at 10k, Hausdorff mean unfitted 0.0224%
  // with RCVT then CCVT, 0.0216% with RCVT alone, 0.0200% for vorpalite's output projected onto
  // the input; fitted 0.0171%, 0.0165% and vorpalite's 0.0152%). On the
  // 20 feature-free meshes of the corpus at 1k/5k/10k, seeds 1 and 2: Hausdorff mean lower on
  // 107 of 120 runs (median 0.96×), θmin and Qmin as good on average, 8% fewer RVD evaluations.
  // With a density, measured alike at 2k (--adaptive), the triangles came out a little less
  // regular (θmin_ave lower on 14 of 19): there CCVT stays. Only where the features are known
  // before the CVT starts, as they are unless seeds are given or --gap-gradation is 0 (then they
  // are detected while RCVT runs).
  const bool rcvt_throughout =
      settings.mode == CvtMode::both && features_first && features.empty() && density.empty();
  // RCVT when `bound` is null; CCVT with the seeds bound as it says otherwise.
  // Out of time, a phase does not start (issue 22: the seeds as they are make the output).
  auto run_phase = [&](const char* name, const SeedConstraints* bound, double& phase_seconds) {
    if (interrupt.out_of_time()) return;
    const auto phase_start = Clock::now();
    CvtObjective objective(mesh, bound ? &*projector : nullptr, bound, bound ? &*curves : nullptr,
                           &interrupt, &density);
    // Spread seeds start RCVT about half way: half its iterations take it where random seeds
    // take the whole cap (on the corpus, 57 meshes × 1k/5k/10k, seeds 1 and 2: θmin and Qmin as
    // good on average, the median run 8% faster; adaptive at 2k: θmin 0.2-1.2° higher on
    // average, the median run 10% faster, topology control adds 16-24% more seeds). RCVT
    // throughout also takes CCVT's iterations.
    int cap = bound || !spread ? settings.iterations : (settings.iterations + 1) / 2;
    if (!bound && rcvt_throughout) cap += settings.iterations;
    const PhaseOptions options{name, cap, settings.gradient_tolerance, &settings.progress, start};
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
  // What of the setup RCVT left undone (on one thread, all of it: 0.28 s of igea.ply's 2.4 s at
  // 5k, missing from the report's times) counts where the setup is said to: in RCVT's time.
  const auto setup_wait = Clock::now();
  tree_setup.wait();
  ccvt_setup.wait();
  if (split) on_sorted.reset();
  projector = split ? &*on_split : &*on_sorted;
  (settings.mode != CvtMode::ccvt ? result.seconds_rcvt : result.seconds_initialization) +=
      seconds_since(setup_wait);
  if (settings.mode != CvtMode::rcvt && !rcvt_throughout) {
    // The paper's two stages (§4.3): the RCVT spread the seeds; the nearest to the features now
    // move onto them, and CCVT optimizes with them bound there.
    if (!features.empty())
      constraints = place_feature_seeds(seeds, mesh, features, *curves, *curve_spacing);
    run_phase("ccvt", &constraints, result.seconds_ccvt);
    // The curve seeds even out along their curves and the surface seeds relax around them, held
    // there. Then surface seeds that took over a stretch of a curve join it, and CCVT resumes,
    // followed by the same evening out. Evened first: most stretches a surface seed takes right
    // after CCVT are gaps between curve seeds that it left uneven, and a stray that joins the
    // curve there makes it denser than the spacing (fandisk.off at 5k: 79 strays joined its 537
    // curve seeds where 4 join once they are even; its output's feature edges were 0.88 edge
    // lengths long, θmin_ave 52.7° where it is now 53.5°).
    const auto even_curve_seeds = [&] {
      double more = 0;
      relax_curve_seeds(seeds, constraints, *curves, *curve_spacing, kCurveLloydSteps);
      const SeedConstraints held = curve_seeds_held(constraints, seeds);
      run_phase("ccvt-surface", &held, more);
      result.seconds_ccvt += more;
    };
    // One round of snapping: a second one, where the first left a stray, snapped 1-3 seeds for
    // 20 more iterations (65 in all on fandisk.off at 5k); without it, on the 56 shared meshes at
    // 1k, 5k and 10k (seeds 1 and 2), the 10-13 runs that had one took 31% fewer evaluations, the
    // quality bar missed on 10 and 11 runs in all where it was on 11 and 11 (θmin away from narrow
    // angles 0.9° higher on average over those runs with seed 1, 0.6° lower with seed 2;
    // θmin_ave 0.2-0.3° lower). The one round is kept for its quality: of the 57 shared meshes'
    // 171 runs at 1k, 5k and 10k, 47 have one; without it, the 59 runs of over 40 evaluations
    // (those, and inputs of several parts) took 0.82 of the time, θmin away from narrow angles
    // 0.7° lower on average (13.8° at worst), the bar missed on 5 where on 2; with its evening out
    // but not its CCVT phase, 0.83-0.92 of the time (seeds 1, 2), the bar missed on 4-5.
    if (!constraints.empty() && !interrupt.timed_out()) even_curve_seeds();
    if (!constraints.empty() && !interrupt.timed_out() &&
        snap_stray_seeds(seeds, constraints, *curves, *curve_spacing) > 0) {
      double more = 0;
      run_phase("ccvt", &constraints, more);
      result.seconds_ccvt += more;
      even_curve_seeds();
    }
  }

  // Output vertices lie on the surface: project (a no-op after CCVT), then triangulate, with
  // local Lloyd steps around any badly shaped triangles.
  const auto extraction_start = Clock::now();
  CvtObjective placement(mesh, &*projector, &constraints, &*curves, &interrupt, &density);
  placement.project(seeds);
  MendReport mends;
  const std::size_t optimized_seeds = seeds.size();  // the rounds append theirs
  std::vector<CellNormal> cells;                     // of the seeds as extracted, for the fit
  // Where the surface crosses itself: searched once, where topology control or the finishing
  // steps' check first needs it (most runs never do).
  InputCrossings input_crossings(mesh);
  {
    // Polishing and topology control change few seeds between triangulations: each clips, and
    // collects, only where the last one changed (issue 18: topology control works locally).
    // Freed before the finishing steps.
    ExtractionMemory extraction(mesh, *rings, interrupt);
    PolishedOutput output =
        extract_polished(mesh, seeds, placement,
                         {polished_at_once(placement) ? settings.polish_rounds : 0}, extraction);
    result.polish_rounds = output.rounds;
    result.defects_polished = output.defects;
    // Topology control (paper §4.4): curves cut by a third cell, cells in several pieces.
    const MendContext context{mesh,           result.input_topology,
                              features,       *curves,
                              *projector,     placement,
                              *curve_spacing, {settings.polish_rounds},
                              extraction,     &settings.progress,
                              start};
    const auto mend_start = Clock::now();
    output = mend_topology(context, input_crossings, std::move(output), seeds, constraints,
                           settings.topology_rounds, mends);
    result.seconds_topology = seconds_since(mend_start);
    result.mesh = std::move(output.mesh);
    if (settings.fit_rounds > 0) cells = cell_normals(mesh, seeds, extraction.traversal);
  }
  result.polish_rounds += mends.polish_rounds;
  result.links_mended = mends.links_mended;
  result.islands_seeded = mends.islands;
  result.seeds_refined = mends.refined;
  result.links_flipped = mends.links_flipped;
  result.tips_closed = mends.tips_closed;
  result.mend_rounds = mends.rounds;
  // The guaranteed last step (issue 18 item 1): whatever defect the rounds left goes, leaving a
  // manifold. Only for a manifold input: a non-manifold input edge is a feature the output keeps.
  const auto last_start = Clock::now();
  const LastStep last = finish_manifold(result.mesh, result.input_topology, *projector);
  result.seconds_topology += seconds_since(last_start);
  result.triangles_removed = last.triangles_removed;
  result.holes_closed = last.closed.holes;
  result.triangles_closing_holes = last.closed.triangles;
  result.vertices_closing_holes = last.closed.vertices;
  // Where the finishing steps made the output pass through itself, they are run again with the
  // changes around the crossings checked (finish/crossing_guard).
  const std::vector<NarrowAngle> narrow = narrow_feature_angles(mesh, features, kNarrowAngleDeg);
  std::optional<RemeshResult> unguarded = finish_uncrossed(
      result, input_crossings,
      [&](RemeshResult& r, const std::set<Vec3>& guarded) {
        finish_output(r, seeds, optimized_seeds, cells, constraints, features, *curves, mesh,
                      *projector, narrow, settings, guarded);
      },
      kGuardAttempts, kGuardReach);
  // Where crossings are left, beside walls thinner than the spacing: the edges there halved, on
  // the guarded output and, where crossings are still left, on the unguarded one; the one with
  // fewer crossings is kept.
  if (result.output_crossing_triangles > 0)
    result.vertices_splitting_crossings =
        split_crossings(result, *projector, input_crossings, kSplitRounds);
  if (unguarded && result.output_crossing_triangles > 0) {
    unguarded->vertices_splitting_crossings =
        split_crossings(*unguarded, *projector, input_crossings, kSplitRounds);
    if (unguarded->output_crossing_triangles < result.output_crossing_triangles)
      result = std::move(*unguarded);
  }
  // Input triangles that cross another, where a search needed them (0 otherwise): where sheets
  // cross, no seed tells them apart.
  result.input_crossing_triangles = input_crossings.count();
  std::vector<double> ratios = edge_length_ratios(result.mesh, *projector, field, spacing);
  result.edge_length_ratio = ratio_percentiles(ratios);
  result.seconds_extraction = seconds_since(extraction_start);
  result.time_limit_reached = interrupt.timed_out();
  interrupt.check();
  if (settings.hausdorff && !result.mesh.triangles.empty()) {
    const auto hausdorff_start = Clock::now();
    result.hausdorff = hausdorff_distance(result.mesh, input, *projector, *settings.hausdorff);
    result.seconds_hausdorff = seconds_since(hausdorff_start);
  }
  return {std::move(result), std::move(ratios)};
}

}  // namespace cvtmesh
