#include "remesh/mend_topology.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

#include "cvtmesh/quality.hpp"
#include "features/edge_uses.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "remesh/flip_links.hpp"
#include "remesh/last_step.hpp"
#include "remesh/output_defects.hpp"

namespace cvtmesh {

namespace {

// Flips that leave no angle under the usual quality bar are as good as moving seeds, and cheaper:
// the links they make are left to them. A link only a worse flip makes gets seeds first (a stray
// surface seed that cuts it joins the curve), and the flip if still missing at the end.
constexpr double kWellShapedFlipDeg = 30;
// A flip that would leave a smaller angle than this is not made: below it, a crease traced
// exactly costs a sliver where the untraced one is a few tenths of a percent off (and where the
// features are finer than the triangles, flips would make slivers by the dozen).
constexpr double kSmallestFlipDeg = 15;

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

// The links whose seeds are not joined by an edge of `rdt` (vertices: the seeds, by id).
std::vector<FeatureLink> missing_links(const std::vector<FeatureLink>& links,
                                       const TriangleMesh& rdt) {
  const std::vector<Edge> edges = sorted_edges(rdt);
  std::vector<FeatureLink> missing;
  for (const FeatureLink& link : links)
    if (!std::binary_search(edges.begin(), edges.end(), link.seeds)) missing.push_back(link);
  return missing;
}

std::vector<Edge> link_seeds(const std::vector<FeatureLink>& links) {
  std::vector<Edge> seeds;
  for (const FeatureLink& link : links) seeds.push_back(link.seeds);
  return seeds;
}

// New surface seeds at the nearest surface points of `points`, unless a seed is there already,
// or one of those added since `first_new` is nearer than a millionth of the spacing: two pieces'
// farthest points may be the same RVD vertex computed from two cells, a rounding apart, and two
// such seeds made femur.off at 10k a triangle of area 1e-22. Returns how many came in.
std::size_t add_surface_seeds(const MendContext& m, const std::vector<Vec3>& points,
                              std::vector<Vec3>& seeds, SeedConstraints& constraints,
                              std::size_t first_new) {
  std::set<Vec3> occupied(seeds.begin(), seeds.end());
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

// Every triangle's three edges, each with the smaller vertex id first, sorted (with repeats).
std::vector<Edge> edges_with_repeats(const TriangleMesh& mesh) {
  std::vector<Edge> edges;
  for (const EdgeUse& use : edge_uses(mesh)) edges.push_back(use.edge);
  return edges;
}

// Where output boundary edges, and output edges of three or more triangles, may run: along the
// input's own boundary (edges of one triangle) and non-manifold edges (three or more), which its
// output keeps (issue 18). Per feature curve, whether it runs along such edges (a curve never
// leaves the edges it was traced along, so its first edge tells), and per input vertex, whether
// such an edge ends there. From the input alone: found once for all the rounds.
struct SpecialEdges {
  std::vector<bool> boundary_curve, boundary_vertex, branch_curve, branch_vertex;
};

SpecialEdges special_edges(const MendContext& m) {
  const std::vector<Edge> uses = edges_with_repeats(m.surface);
  std::vector<Edge> boundary, branch;
  for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {  // runs of equal edges
    while (j < uses.size() && uses[j] == uses[i]) ++j;
    if (j - i == 1) boundary.push_back(uses[i]);
    if (j - i >= 3) branch.push_back(uses[i]);
  }
  const auto curves_along = [&](const std::vector<Edge>& edges) {
    std::vector<bool> along(m.features.curves.size());
    for (std::size_t c = 0; c < along.size(); ++c) {
      const auto& v = m.features.curves[c].vertices;
      along[c] =
          v.size() >= 2 && std::binary_search(edges.begin(), edges.end(), edge_of(v[0], v[1]));
    }
    return along;
  };
  const auto ends_of = [&](const std::vector<Edge>& edges) {
    std::vector<bool> end(m.surface.vertices.size(), false);
    for (const Edge& e : edges) end[e[0]] = end[e[1]] = true;
    return end;
  };
  return {curves_along(boundary), ends_of(boundary), curves_along(branch), ends_of(branch)};
}

// Of the `vertices` of an extraction (the seeds, then the cells' far pieces), the seeds on the
// flagged curves and the corner seeds at the flagged input vertices.
std::vector<bool> seeds_on(const std::vector<bool>& curve, const std::vector<bool>& vertex,
                           const MendContext& m, const SeedConstraints& constraints,
                           std::size_t vertices) {
  std::vector<bool> on(vertices, false);
  for (std::size_t s = 0; s < constraints.kind.size(); ++s)
    on[s] = constraints.kind[s] == SeedConstraints::Kind::curve && curve[constraints.curve[s]];
  for (std::size_t c = 0; c < constraints.corner_seed.size(); ++c)
    if (vertex[m.features.corners[c]]) on[constraints.corner_seed[c]] = true;
  return on;
}

// The vertices of `rdt` that an output boundary edge may join: the seeds on the input's boundary
// curves (corners there included). Without feature seeds (rcvt mode), any vertex of a surface
// with boundaries.
std::vector<bool> boundary_seeds(const MendContext& m, const SpecialEdges& special,
                                 const SeedConstraints& constraints, const TriangleMesh& rdt) {
  const bool open = m.surface_topology.boundary_edges > 0;
  if (constraints.empty() || !open) return std::vector<bool>(rdt.vertices.size(), open);
  return seeds_on(special.boundary_curve, special.boundary_vertex, m, constraints,
                  rdt.vertices.size());
}

// The vertices of `rdt` where an edge of three or more triangles may end, for an input that has
// such edges itself: the seeds on the input's non-manifold curves, corners there included;
// without feature seeds (rcvt mode), any vertex. Empty (nowhere) for an input without them.
std::vector<bool> branch_seeds(const MendContext& m, const SpecialEdges& special,
                               const SeedConstraints& constraints, const TriangleMesh& rdt) {
  if (m.surface_topology.nonmanifold_edges == 0) return {};
  if (constraints.empty()) return std::vector<bool>(rdt.vertices.size(), true);
  return seeds_on(special.branch_curve, special.branch_vertex, m, constraints, rdt.vertices.size());
}

// Whether the triangle of seeds `t` is at a crossing of the input's sheets: one reaches the
// ball around its centroid whose radius is its longest edge. Refining there only makes smaller
// defects, round after round (man.off at 2k, --seed 2: 2,415 seeds added and θmin 0.4° where the
// pinned rounds refined there; 415 and 16.8°, the last step closing one hole, where they do not).
// The first rounds still refine there: a thin part next to a crossing needs it (man.off and
// cow.off at 1k lost their topology without).
bool at_crossing(const SurfaceProjector& crossings, const std::vector<Vec3>& seeds,
                 const Triangle& t) {
  const Vec3 &a = seeds[t[0]], &b = seeds[t[1]], &c = seeds[t[2]];
  const Vec3 centre = (1.0 / 3) * (a + b + c);
  const double reach = std::max({distance(a, b), distance(b, c), distance(c, a)});
  return crossings.distance_to(centre) <= reach;
}

// An extraction, finished as it would be returned, and what it lacks: the links it cuts that
// no well-shaped flip makes (left to the seeds), and whether its topology is the surface's.
struct Assessment {
  TriangleMesh finished;  // all the flips made, and the tips closed
  std::vector<FeatureLink> missing;
  bool topology_kept = true;
  OutputDefects defects;  // of `finished`, if its topology is not kept
  // Its topology kept, or given back by the last step (finish_manifold on a copy).
  bool rescued = true;
  std::size_t links_flipped = 0, tips_closed = 0;
  // Better outputs compare greater: the input's topology, then fewer triangles at defects
  // (non-manifold edges and vertices, stray boundary edges, folds), then more corners, then fewer
  // links missing, then the better worst triangle (Qmin: a seed that mends a link is worth it only
  // if it leaves better triangles than a flip).
  std::tuple<bool, std::ptrdiff_t, std::size_t, std::ptrdiff_t, double> score;
};

Assessment assess(const MendContext& m, const SpecialEdges& special, const TriangleMesh& rdt,
                  const std::vector<Vec3>& seeds, const SeedConstraints& constraints) {
  Assessment a;
  a.finished = rdt;
  std::vector<FeatureLink> cut;
  if (!constraints.empty())
    cut = missing_links(feature_links(seeds, constraints, m.features, m.curves), rdt);
  const std::vector<bool> made = flip_in_links(a.finished, link_seeds(cut), kWellShapedFlipDeg);
  for (std::size_t k = 0; k < cut.size(); ++k)
    if (!made[k]) a.missing.push_back(cut[k]);
  // The last resort, for the links the seeds leave: worse flips, and triangles at tips.
  const std::vector<bool> last = flip_in_links(a.finished, link_seeds(a.missing), kSmallestFlipDeg);
  std::vector<Edge> unmade;
  for (std::size_t k = 0; k < a.missing.size(); ++k)
    if (!last[k]) unmade.push_back(a.missing[k].seeds);
  a.links_flipped = cut.size() - unmade.size();
  a.tips_closed = close_corner_tips(a.finished, constraints.corner_seed, unmade);
  const TopologyReport t = analyze_topology(a.finished);
  const TopologyReport& in = m.surface_topology;
  if (in.is_manifold()) {
    a.topology_kept = t.is_manifold() && same_topology(t, in);
    if (!a.topology_kept) {
      a.defects = find_output_defects(
          a.finished, boundary_seeds(m, special, constraints, a.finished), in.orientable);
      TriangleMesh last = a.finished;
      finish_manifold(last, in, m.projector);
      const TopologyReport after = analyze_topology(last);
      a.rescued = after.is_manifold() && same_topology(after, in);
    }
  } else {
    // The input's own non-manifold edges are no defects of its output: refining around them
    // mended nothing (a T of three sheets lost 1.1 s in rounds that all kept the first output).
    a.defects =
        find_output_defects(a.finished, boundary_seeds(m, special, constraints, a.finished),
                            in.orientable, branch_seeds(m, special, constraints, a.finished));
    a.topology_kept = a.defects.empty() && same_topology(t, in);
    a.rescued = a.topology_kept;  // no last step for a non-manifold input
  }
  std::vector<bool> used(a.finished.vertices.size(), false);
  for (const Triangle& tri : a.finished.triangles)
    for (const Index v : tri) used[v] = true;
  const auto corners = static_cast<std::size_t>(std::count_if(constraints.corner_seed.begin(),
                                                              constraints.corner_seed.end(),
                                                              [&](Index s) { return used[s]; }));
  a.score = {a.topology_kept, -static_cast<std::ptrdiff_t>(a.defects.triangles.size()), corners,
             -static_cast<std::ptrdiff_t>(unmade.size()), measure_quality(a.finished).q_min};
  return a;
}

}  // namespace

std::vector<Edge> sorted_edges(const TriangleMesh& mesh) {
  std::vector<Edge> edges = edges_with_repeats(mesh);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

PolishedOutput mend_topology(const MendContext& m, PolishedOutput output, std::vector<Vec3>& seeds,
                             SeedConstraints& constraints, int rounds, MendReport& report) {
  // Each round's output is kept if it is the best yet: where parts are thinner than the
  // spacing, the seeds a round adds can make more defects than they mend (man.off at 3k
  // vertices: 105 non-manifold edges after the first extraction, 201 after three rounds).
  struct Round {
    PolishedOutput output;
    std::vector<Vec3> seeds;
    SeedConstraints constraints;
    Assessment assessment;
    MendReport report;  // as of this round
  };
  const SpecialEdges special = special_edges(m);
  std::optional<Round> best;
  // The best of the rounds without the input's topology whose output the last step gives it
  // back: the rounds' best by defects may not be one (femur.off at 2k: the best round's defects,
  // removed, cut off a handle; topology lost), and then this one is kept instead (issue 18 item
  // 1: validity). A round that keeps the topology is the best anyway: none is copied for it.
  std::optional<Round> best_rescued;
  int since_best = 0;          // rounds since the best was found
  std::size_t last_added = 0;  // seeds the last round added
  int doublings = 0;           // rounds in a row, without progress, that added twice the last's
  // Where the rounds end without the input's topology, they start again from the best round, for
  // three times as many rounds, with the seeds they add pinned (see kRoundsWithoutProgress).
  PolishSettings polish = m.polish;
  bool pinned = false;
  // No split cell is seeded where the input crosses itself, as no seed separates sheets that
  // cross (at 5k, adaptive, cow.off went from 904 seeds added and θmin 0.4° to 30 and 21.8°,
  // man.off from 665 seeds added to 84). Searched only for an output without the input's
  // topology: searched for every run, it added about 0.3 s to igea's 2.2 s at 10k.
  std::unique_ptr<SurfaceProjector> crossings;
  bool crossings_searched = false;
  int last_round = rounds;
  for (int round = 0;; ++round) {
    Assessment a = assess(m, special, output.mesh, seeds, constraints);
    // `output` is not read again before the next extraction replaces it, and the kept mesh is
    // the assessment's finished one: moved, not copied.
    const std::vector<Index> vertex_seed = output.vertex_seed;
    if (a.rescued && !a.topology_kept &&
        (!best_rescued || !(a.score < best_rescued->assessment.score)))
      best_rescued = Round{output, seeds, constraints, a, report};
    if (!best || !(a.score < best->assessment.score)) {
      best = Round{std::move(output), seeds, constraints, a, report};
      since_best = 0;
    } else {
      ++since_best;
    }
    std::size_t changed = 0;
    // Refinement shrinks the defects' Delaunay balls round after round where the surface has a
    // detail finer than the spacing; where the rounds only add defects (thin sheets whose
    // boundaries the seeds cannot trace: ALSTOM_TEST4.off went from 483 to 5,736 stray boundary
    // edges in 12 rounds), they stop.
    // Out of time (issue 22), the rounds go on for the topology only: validity comes first.
    const bool out_of_time = m.placement.interrupt().out_of_time();
    const bool runaway =
        since_best > 0 && (seeds.size() >= kGrowthWithoutProgress * best->seeds.size() ||
                           doublings >= kDoublingsWithoutProgress);
    // Pinned, the rounds go on without progress to their cap, as refinement needs, except on an
    // input that crosses itself once the last step has given a round the input's topology: no
    // seed separates sheets that cross, so there they stop as the first rounds do (man.off at
    // 10k: 81 s, nearly all of it pinned rounds without progress, to 22 s, the same output).
    const bool stalled = since_best >= kRoundsWithoutProgress &&
                         (!pinned || (best_rescued.has_value() && crossings != nullptr));
    if (round < last_round && !stalled && !runaway) {
      // Where the output shows a defect, from the seeds as extracted (one RVD for both): a seed in
      // each piece of a cell but its largest (near the defects, until the rounds are pinned), and,
      // for each triangle at a defect, seeds where its dual Voronoi edge crosses the surface
      // (Delaunay refinement).
      DefectSeeds found;
      if (!a.topology_kept) {
        const OutputDefects& defects = a.defects;
        if (!crossings_searched) {
          crossings = crossing_surface(m.surface);
          crossings_searched = true;
        }
        std::vector<Triangle> dual;  // the defects' triangles, in seeds
        for (Triangle t : defects.triangles) {
          for (Index& v : t) v = vertex_seed[v];
          // The pinned rounds do not refine at crossings either: the last step mends them.
          if (!pinned || !crossings || !at_crossing(*crossings, seeds, t)) dual.push_back(t);
        }
        // Cells that are no discs: in the first rounds only as a last resort, for an output
        // whose topology differs without a defect to show where; in the pinned rounds, which
        // refine until the topology is the input's, always. A cell that is a band around a limb
        // thinner than the spacing is no disc either, yet the triangulation around it is often
        // right: seeds in every such band from the first round doubled the seeds added on
        // camel.off at 1k, and cost its θmin (23° to 0°).
        const SplitCells split = pinned            ? SplitCells::at_centroids_everywhere
                                 : defects.empty() ? SplitCells::farthest_everywhere
                                                   : SplitCells::near_triangles;
        found = defect_seeds(m.surface, seeds, dual,
                             m.surface_topology.is_manifold() && (pinned || defects.empty()), split,
                             crossings.get());
      }
      if (!a.missing.empty() && !out_of_time) {
        const std::size_t mended =
            mend_missing_links(seeds, constraints, a.missing, m.curves, m.spacing);
        report.links_mended += mended;
        changed += mended;
      }
      const std::size_t first_new = seeds.size();
      const std::size_t islands =
          add_surface_seeds(m, found.islands, seeds, constraints, first_new);
      const std::size_t refined =
          add_surface_seeds(m, found.refinement, seeds, constraints, first_new);
      report.islands += islands;
      report.refined += refined;
      changed += islands + refined;
    }
    doublings = since_best > 0 && last_added > 0 && changed >= 2 * last_added ? doublings + 1 : 0;
    last_added = changed;
    if (changed == 0) {
      if (pinned || rounds == 0 || best->assessment.topology_kept ||
          !m.surface_topology.is_manifold())
        break;
      pinned = true;
      last_round = round + 1 + kPinnedRoundsPerRound * rounds;
      since_best = 0;
      last_added = 0;
      doublings = 0;
      output = best->output;
      seeds = best->seeds;
      constraints = best->constraints;
      report = best->report;
      polish.pinned_from = seeds.size();
      continue;
    }
    ++report.rounds;
    output = extract_polished(m.surface, seeds, m.placement, polish);
    report.polish_rounds += output.rounds;
  }
  if (!best->assessment.rescued && best_rescued) best = std::move(best_rescued);
  output = std::move(best->output);
  output.mesh = std::move(best->assessment.finished);
  seeds = std::move(best->seeds);
  constraints = std::move(best->constraints);
  report = best->report;
  report.links_flipped = best->assessment.links_flipped;
  report.tips_closed = best->assessment.tips_closed;
  return output;
}

}  // namespace cvtmesh
