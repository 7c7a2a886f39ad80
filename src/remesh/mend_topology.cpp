#include "remesh/mend_topology.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <tuple>

#include "cvt/cell_islands.hpp"
#include "cvtmesh/quality.hpp"
#include "remesh/flip_links.hpp"

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

// A new surface seed at the nearest surface point of each island's centroid, unless a seed is
// there already. Returns how many came in.
std::size_t seed_islands(const MendContext& m, const std::vector<CellIsland>& islands,
                         std::vector<Vec3>& seeds, SeedConstraints& constraints) {
  std::set<Vec3> occupied(seeds.begin(), seeds.end());
  std::size_t added = 0;
  for (const CellIsland& island : islands) {
    const Vec3 p = m.projector.nearest(island.centroid).point;
    if (!occupied.insert(p).second) continue;
    seeds.push_back(p);
    if (!constraints.empty()) constraints.append(SeedConstraints::Kind::surface);
    ++added;
  }
  return added;
}

// An extraction, finished as it would be returned, and what it lacks: the links it cuts that
// no well-shaped flip makes (left to the seeds), and whether its topology is the surface's.
struct Assessment {
  TriangleMesh finished;  // all the flips made, and the tips closed
  std::vector<FeatureLink> missing;
  bool topology_kept = true;
  std::size_t links_flipped = 0, tips_closed = 0;
  // Better outputs compare greater: the input's topology, then fewer non-manifold edges and
  // vertices, then more corners, then fewer links missing, then the better worst triangle
  // (Qmin: a seed that mends a link is worth it only if it leaves better triangles than a flip).
  std::tuple<bool, std::ptrdiff_t, std::size_t, std::ptrdiff_t, double> score;
};

Assessment assess(const MendContext& m, const TriangleMesh& rdt, const std::vector<Vec3>& seeds,
                  const SeedConstraints& constraints) {
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
  a.topology_kept = t.is_manifold() && same_topology(t, m.surface_topology);
  std::vector<bool> used(seeds.size(), false);
  for (const Triangle& tri : a.finished.triangles)
    for (const Index v : tri) used[v] = true;
  const auto corners = static_cast<std::size_t>(std::count_if(constraints.corner_seed.begin(),
                                                              constraints.corner_seed.end(),
                                                              [&](Index s) { return used[s]; }));
  a.score = {a.topology_kept,
             -static_cast<std::ptrdiff_t>(t.nonmanifold_edges + t.nonmanifold_vertices), corners,
             -static_cast<std::ptrdiff_t>(unmade.size()), measure_quality(a.finished).q_min};
  return a;
}

}  // namespace

std::vector<Edge> sorted_edges(const TriangleMesh& mesh) {
  std::vector<Edge> edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
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
  std::optional<Round> best;
  for (int round = 0;; ++round) {
    Assessment a = assess(m, output.mesh, seeds, constraints);
    // `output` is not read again before the next extraction replaces it, and the kept mesh is
    // the assessment's finished one: moved, not copied.
    if (!best || !(a.score < best->assessment.score))
      best = Round{std::move(output), seeds, constraints, a, report};
    std::size_t changed = 0;
    if (round < rounds) {
      if (!a.missing.empty()) {
        const std::size_t mended =
            mend_missing_links(seeds, constraints, a.missing, m.curves, m.spacing);
        report.links_mended += mended;
        changed += mended;
      }
      // The cells' pieces cost one more RVD: only when the output shows a defect.
      if (!a.topology_kept) {
        const std::size_t added =
            seed_islands(m, cell_islands(m.surface, seeds), seeds, constraints);
        report.islands += added;
        changed += added;
      }
    }
    if (changed == 0) break;
    ++report.rounds;
    output = extract_polished(m.surface, seeds, m.placement, m.polish);
    report.polish_rounds += output.rounds;
  }
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
