#include "remesh/mend_topology.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <set>

#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "remesh/assess_extraction.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

// Rounds in a row whose output is no better than the best so far, after which the rounds stop.
// Where a handle or a gap is far finer than the spacing, Delaunay refinement needs a round per
// halving of its balls, and the defects come and go meanwhile; polishing then pulls the points
// it adds back out of the detail (femur.off at 1k, handles 0.0003 across, spacing 0.026: never
// resolved with polishing, genus kept in 19 rounds without). So the rounds that follow a run
// without the input's topology pin the seeds they add, and only their cap or runaway growth
// stops them: the count of triangles at defects is no measure of their progress (femur.off at
// 5k: 20 to 44 for 16 rounds, its Euler characteristic creeping from 5 to the input's -2, which
// it reached in the 19th).
constexpr int kRoundsWithoutProgress = 4;
// The pinned rounds' cap, in `rounds`: with twice, femur.off at 1k with --seed 3 ended with genus
// 1 for its 2, its defects coming and going from the 17th pinned round to the cap; it keeps its
// genus in the 32nd (1,700 seeds).
constexpr int kPinnedRoundsPerRound = 3;
// Nor do they go on, without progress, once the seeds have grown this many times the best round's:
// where the defects' seeds make as many new defects, the count doubles each round (a fuzzed
// 11-triangle soup went from 40 seeds to 1,057 in 5 rounds, none of them better than the first).
constexpr std::size_t kGrowthWithoutProgress = 2;
// Nor once the seeds each round adds have doubled this many rounds in a row without progress:
// where no sampling resolves a spot (two sheets that touch at a point: the seed nearest to it
// owns both sides, however dense the seeds), each new seed's cell is split again, and the rounds
// add ever more seeds there (diplodocus.off at 10k, adaptive, pinned: 69, 152, 353, 704, 1,406,
// 2,636, 4,724), while refinement that converges adds about as many seeds each round (femur.off
// at 1k, pinned: at most 1.9 times the round before).
constexpr int kDoublingsWithoutProgress = 2;
// Nor, progress or not, once the seeds are this many times those the rounds started from, as the
// count's growth is capped (remesh/topology_first): a genus-73 scan whose handles are far finer
// than the spacing, and whose sheets cross, went from 5,000 seeds to 100,000 in 41 rounds (500 s)
// and still lost its topology, each round a little better than the last. On the 57 shared meshes
// the rounds add at most 0.6 times the count (femur.off at 1k).
constexpr std::size_t kMostGrowth = 4;

// When the rounds stop adding seeds (the rules above). The first rounds stop after
// kRoundsWithoutProgress without a better output; the pinned rounds, which follow them where the
// input's topology was not reached, go on to their own cap.
class RoundStops {
 public:
  // `seeds`: the seeds the rounds start from.
  RoundStops(int rounds, std::size_t seeds)
      : rounds_(rounds), last_round_(rounds), most_seeds_(kMostGrowth * seeds) {}

  // After each round's assessment: whether it was the best so far.
  void scored(bool best) { since_best_ = best ? 0 : since_best_ + 1; }

  // Whether round `round` may add seeds: before the cap, and neither stalled nor running away.
  // `seeds`, `best_seeds`: the seeds now and in the best round; `rescued_at_crossing`: a round
  // was given the input's topology by the last step, and the input crosses itself.
  bool may_add(int round, std::size_t seeds, std::size_t best_seeds,
               bool rescued_at_crossing) const {
    // Refinement shrinks the defects' Delaunay balls round after round where the surface has a
    // detail finer than the spacing; where the rounds only add defects (thin sheets whose
    // boundaries the seeds cannot trace: ALSTOM_TEST4.off went from 483 to 5,736 stray boundary
    // edges in 12 rounds), they stop.
    const bool runaway = since_best_ > 0 && (seeds >= kGrowthWithoutProgress * best_seeds ||
                                             doublings_ >= kDoublingsWithoutProgress);
    // Pinned, the rounds go on without progress to their cap, as refinement needs, except on an
    // input that crosses itself once the last step has given a round the input's topology: no
    // seed separates sheets that cross, so there they stop as the first rounds do (man.off at
    // 10k: 81 s, nearly all of it pinned rounds without progress, to 22 s, the same output).
    const bool stalled = since_best_ >= kRoundsWithoutProgress && (!pinned_ || rescued_at_crossing);
    return round < last_round_ && !stalled && !runaway && seeds < most_seeds_;
  }

  // After each round: how many seeds it added.
  void added(std::size_t count) {
    doublings_ =
        since_best_ > 0 && last_added_ > 0 && count >= 2 * last_added_ ? doublings_ + 1 : 0;
    last_added_ = count;
  }

  bool pinned() const { return pinned_; }

  // The pinned rounds start after round `round`.
  void pin(int round) {
    pinned_ = true;
    last_round_ = round + 1 + kPinnedRoundsPerRound * rounds_;
    since_best_ = 0;
    last_added_ = 0;
    doublings_ = 0;
  }

 private:
  int rounds_;
  int last_round_;
  std::size_t most_seeds_;
  bool pinned_ = false;
  int since_best_ = 0;          // rounds since the best was found
  std::size_t last_added_ = 0;  // seeds the last round added
  int doublings_ = 0;           // rounds in a row, without progress, that added twice the last's
};

// A round's output with what made it, and its assessment.
struct Round {
  PolishedOutput output;
  std::vector<Vec3> seeds;
  SeedConstraints constraints;
  Assessment assessment;
  MendReport report;  // as of this round
};

// The rounds' outputs worth keeping. Each round's output is kept if it is the best yet: where
// parts are thinner than the spacing, the seeds a round adds can make more defects than they mend
// (man.off at 3k vertices: 105 non-manifold edges after the first extraction, 201 after three
// rounds).
class KeptRounds {
 public:
  // Keeps the round if it is the best so far (or the best the last step rescues); returns
  // whether it is the best. `output` is moved from if so.
  bool keep(PolishedOutput& output, const std::vector<Vec3>& seeds,
            const SeedConstraints& constraints, const Assessment& a, const MendReport& report) {
    if (a.rescued && !a.topology_kept &&
        (!best_rescued_ || !(a.score < best_rescued_->assessment.score)))
      best_rescued_ = Round{output, seeds, constraints, a, report};
    if (best_ && a.score < best_->assessment.score) return false;
    best_ = Round{std::move(output), seeds, constraints, a, report};
    return true;
  }

  const Round& best() const { return *best_; }
  bool any_rescued() const { return best_rescued_.has_value(); }

  // The round to return: the best, unless the last step cannot give it the input's topology and
  // can give it to another.
  Round take() && {
    if (!best_->assessment.rescued && best_rescued_) return std::move(*best_rescued_);
    return std::move(*best_);
  }

 private:
  std::optional<Round> best_;
  // The best of the rounds without the input's topology whose output the last step gives it
  // back: the rounds' best by defects may not be one (femur.off at 2.4k, seed 6: the best
  // round's defects, removed, cut off a handle; topology lost), and then this one is kept instead
  // (issue 18 item 1: validity). A round that keeps the topology is the best anyway: none is
  // copied for it.
  std::optional<Round> best_rescued_;
};

// New surface seeds at the nearest surface points of `points`, unless a seed is there already,
// or one of those added since `first_new` is nearer than a millionth of the spacing: two pieces'
// farthest points may be the same RVD vertex computed from two cells, a rounding apart, and two
// such seeds made femur.off at 10k a triangle of area 1e-22. `occupied`: the positions of all
// the seeds, to which those that come in are added. Returns how many came in.
std::size_t add_surface_seeds(const MendContext& m, const std::vector<Vec3>& points,
                              std::vector<Vec3>& seeds, SeedConstraints& constraints,
                              std::size_t first_new, std::set<Vec3>& occupied) {
  const double apart = 1e-6 * m.spacing.spacing();
  std::size_t added = 0;
  for (const Vec3& point : points) {
    const Vec3 p = m.projector.nearest(point).point;
    if (occupied.contains(p) ||
        std::any_of(seeds.begin() + static_cast<std::ptrdiff_t>(first_new), seeds.end(),
                    [&](const Vec3& s) { return distance(s, p) <= apart; }))
      continue;
    occupied.insert(p);
    seeds.push_back(p);
    if (!constraints.empty()) constraints.append(SeedConstraints::Kind::surface);
    ++added;
  }
  return added;
}

// Triangle `t` of an extraction in seeds (`vertex_seed`: per vertex of the extraction, its seed);
// none for a triangle at an edge that a link flip halved, whose middle has no seed.
std::optional<Triangle> in_seeds(Triangle t, const std::vector<Index>& vertex_seed) {
  for (Index& v : t) {
    if (v >= vertex_seed.size()) return std::nullopt;
    v = vertex_seed[v];
  }
  return t;
}

// Inserts seeds where the extraction fails the ball property (`a`; `vertex_seed`: per vertex of
// the extraction, its seed): the cut links mended (mend_missing_links); and, where the topology
// is not the input's, from the seeds as extracted (one RVD for both), a seed in each piece of a
// cell but its largest (near the defects, until the rounds are pinned), and, for each triangle at
// a defect, seeds where its dual Voronoi edge crosses the surface (Delaunay refinement). Returns
// how many seeds came in or moved.
std::size_t seed_where_it_fails(const MendContext& m, const Assessment& a,
                                const std::vector<Index>& vertex_seed, bool pinned,
                                InputCrossings& crossings, std::vector<Vec3>& seeds,
                                SeedConstraints& constraints, MendReport& report) {
  // Out of time (issue 22), the rounds go on for the topology only: validity comes first.
  const bool out_of_time = m.placement.interrupt().out_of_time();
  std::size_t changed = 0;
  DefectSeeds found;
  if (!a.topology_kept) {
    // No split cell is seeded where the input crosses itself, as no seed separates sheets that
    // cross (at 5k, adaptive, cow.off went from 904 seeds added and θmin 0.4° to 30 and 21.8°,
    // man.off from 665 seeds added to 84).
    const SurfaceProjector* crossing = crossings.get();
    std::vector<Triangle> dual;  // the defects' triangles, in seeds
    for (const Triangle& t : a.defects.triangles) {
      const std::optional<Triangle> s = in_seeds(t, vertex_seed);
      // The pinned rounds do not refine at crossings either: the last step mends them. Refining
      // there only makes smaller defects, round after round (man.off at 2k, --seed 2: 2,415 seeds
      // added and θmin 0.4° where the pinned rounds refined there; 415 and 16.8°, the last step
      // closing one hole, where they do not). The first rounds still refine there: a thin part
      // next to a crossing needs it (man.off and cow.off at 1k lost their topology without).
      if (s && (!pinned || !crossing || !at_crossing(*crossing, seeds, *s))) dual.push_back(*s);
    }
    // Cells that are no discs: in the first rounds only as a last resort, for an output whose
    // topology differs without a defect to show where; in the pinned rounds, which refine until
    // the topology is the input's, always. A cell that is a band around a limb thinner than the
    // spacing is no disc either, yet the triangulation around it is often right: seeds in every
    // such band from the first round doubled the seeds added on camel.off at 1k, and cost its
    // θmin (23° to 0°).
    const bool no_defect = a.defects.empty();
    const SplitCells split = pinned      ? SplitCells::at_centroids_everywhere
                             : no_defect ? SplitCells::farthest_everywhere
                                         : SplitCells::near_triangles;
    found = defect_seeds(m.surface, seeds, dual,
                         m.surface_topology.is_manifold() && (pinned || no_defect), split, crossing,
                         m.extraction);
  } else if (!a.crossing.empty()) {
    // Triangles that pass through each other, the topology kept, away from where the input
    // crosses itself (assess): Delaunay refinement at them, as at defects (their surface Delaunay
    // balls reach the sheet or tube wall they cross), and seeds in the split cells near them.
    // Without the latter, couplingdown.off at 1k kept about 80 crossing triangles in the narrow
    // holes of its rim for four rounds, and the rounds stopped; with them, none were left after
    // five.
    std::vector<Triangle> dual;
    for (const Triangle& t : a.crossing)
      if (const std::optional<Triangle> s = in_seeds(t, vertex_seed)) dual.push_back(*s);
    found = defect_seeds(m.surface, seeds, dual, false, SplitCells::near_triangles, crossings.get(),
                         m.extraction);
  }
  if (!a.missing.empty() && !out_of_time) {
    const std::size_t mended =
        mend_missing_links(seeds, constraints, a.missing, m.curves, m.spacing);
    report.links_mended += mended;
    changed += mended;
  }
  const std::size_t first_new = seeds.size();
  std::set<Vec3> occupied(seeds.begin(), seeds.end());  // the seeds' positions, and each new one
  const std::size_t islands =
      add_surface_seeds(m, found.islands, seeds, constraints, first_new, occupied);
  const std::size_t refined =
      add_surface_seeds(m, found.refinement, seeds, constraints, first_new, occupied);
  report.islands += islands;
  report.refined += refined;
  return changed + islands + refined;
}

// The seeds where the extraction `rdt` fails: those of the triangles at `defects`, and those whose
// cells are in several pieces (a vertex of `rdt` past the seeds stands for a cell's far piece;
// `vertex_seed`: per vertex, its seed), sorted. `defects` are the assessment's, whose mesh may
// have more vertices than `rdt`: the middles of edges that link flips halved, of no seed.
std::vector<Index> failing_seeds(const TriangleMesh& rdt, const OutputDefects& defects,
                                 const std::vector<Index>& vertex_seed, std::size_t seeds) {
  std::vector<Index> ids;
  for (const Triangle& t : defects.triangles)
    for (const Index v : t)
      if (v < vertex_seed.size()) ids.push_back(vertex_seed[v]);
  for (std::size_t v = seeds; v < rdt.vertices.size(); ++v) ids.push_back(vertex_seed[v]);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

bool crosses_itself_widely(std::size_t crossing, std::size_t triangles) {
  constexpr std::size_t kWidely = 20;  // one triangle in this many
  return crossing > 0 && kWidely * crossing >= triangles;
}

// The paper's loop (§2 Theorem 1, §4.4): check the extraction, insert seeds where it fails the
// topological ball property, extract again; the best round is returned, and the pipeline's last
// step (finish_manifold) mends what the rounds leave.
PolishedOutput mend_topology(const MendContext& m, InputCrossings& crossings, PolishedOutput output,
                             std::vector<Vec3>& seeds, SeedConstraints& constraints, int rounds,
                             MendReport& report) {
  const SpecialEdges special = special_edges(m);
  KeptRounds kept;
  RoundStops stops(rounds, seeds.size());
  // Where the rounds end without the input's topology, they start again from the best round, for
  // three times as many rounds, with the seeds they add pinned (see kRoundsWithoutProgress).
  PolishSettings polish = m.polish;
  for (int round = 0;; ++round) {
    Assessment a = assess(m, special, output.mesh, seeds, constraints, crossings);
    // An output not polished at once (polished_at_once) is polished before seeds are added to
    // it: unpolished, the cells of thin parts are in more pieces, and the seeds added there left
    // worse triangles (man.off adaptive at 2k: 103 islands where 38, 137 seeds added where 53,
    // θmin 29.7° -> 18.4°; with seed 2, 34 seeds where 103, θmin 36.7° -> 22.8°). Only around
    // where the extraction fails (failing_seeds): elsewhere its badly shaped triangles are the
    // grading's, which Lloyd steps barely change (bull.off at 2k: 227, and 180 after 30 steps
    // over 1,410 of its 2,000 seeds; its whole run now 0.6 of the time). 12 meshes × 3 seeds that
    // polish here: the same seeds added on 29 of 36 runs, as good on average (θmin 37.5° vs 37.2°,
    // Qmin 0.652 vs 0.655), 0.83 of the time; within 2 rings of the failing seeds, man.off with
    // seed 2 fell to 22.0°, within 6 femur.off lost 1-2° (kAroundRings in polish_defects.cpp).
    if (round == 0 && !polished_at_once(m.placement) && !a.topology_kept && polish.rounds > 0) {
      PolishSettings around_defects = polish;
      around_defects.around =
          failing_seeds(output.mesh, a.defects, output.vertex_seed, seeds.size());
      output = extract_polished(m.surface, seeds, m.placement, around_defects, m.extraction);
      report.polish_rounds += output.rounds;
      a = assess(m, special, output.mesh, seeds, constraints, crossings);
    }
    // `output` is not read again before the next extraction replaces it, and the kept mesh is
    // the assessment's finished one: moved, not copied.
    const std::vector<Index> vertex_seed = output.vertex_seed;
    const std::vector<Vec3> polished = seeds;  // those of `output`, polished
    stops.scored(kept.keep(output, seeds, constraints, a, report));
    std::size_t added = 0;
    if (stops.may_add(round, seeds.size(), kept.best().seeds.size(),
                      kept.any_rescued() && crossings.found()))
      added = seed_where_it_fails(m, a, vertex_seed, stops.pinned(), crossings, seeds, constraints,
                                  report);
    stops.added(added);
    if (added > 0 && m.progress && *m.progress)
      (*m.progress)({"topology", round + 1, 0, 0, seconds_since(m.start), seeds.size(),
                     a.defects.triangles.size()});
    if (added == 0) {
      if (stops.pinned() || rounds == 0 || kept.best().assessment.topology_kept ||
          !m.surface_topology.is_manifold())
        break;
      crossings.get();  // searched here if no round needed it
      if (crosses_itself_widely(crossings.count(), m.surface.triangles.size())) break;
      stops.pin(round);
      const Round& best = kept.best();
      output = best.output;
      seeds = best.seeds;
      constraints = best.constraints;
      report = best.report;
      polish.pinned_from = seeds.size();
      continue;
    }
    ++report.rounds;
    output = extract_polished(m.surface, seeds, m.placement, polish, m.extraction, &polished);
    report.polish_rounds += output.rounds;
  }
  Round best = std::move(kept).take();
  output = std::move(best.output);
  output.mesh = std::move(best.assessment.finished);
  seeds = std::move(best.seeds);
  constraints = std::move(best.constraints);
  report = best.report;
  report.links_flipped = best.assessment.links_flipped;
  report.tips_closed = best.assessment.tips_closed;
  return output;
}

}  // namespace cvtmesh
