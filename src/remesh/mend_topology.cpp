#include "remesh/mend_topology.hpp"

#include <algorithm>
#include <set>

#include "cvt/cell_islands.hpp"
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
  for (int round = 0;; ++round) {
    std::vector<FeatureLink> cut;
    if (!constraints.empty())
      cut = missing_links(feature_links(seeds, constraints, m.features, m.curves), output.mesh);
    // The output with the well-shaped flips made, and the links they leave.
    TriangleMesh flipped;
    std::vector<bool> made;
    if (!cut.empty()) {
      flipped = output.mesh;
      made = flip_in_links(flipped, link_seeds(cut), kWellShapedFlipDeg);
    }
    std::vector<FeatureLink> missing;
    for (std::size_t k = 0; k < cut.size(); ++k)
      if (!made[k]) missing.push_back(cut[k]);
    std::size_t changed = 0;
    if (round < rounds) {
      if (!missing.empty()) {
        const std::size_t mended =
            mend_missing_links(seeds, constraints, missing, m.curves, m.spacing);
        report.links_mended += mended;
        changed += mended;
      }
      // The cells' pieces cost one more RVD: only when the output shows a defect.
      const TopologyReport t = analyze_topology(output.mesh);
      if (!t.is_manifold() || !same_topology(t, m.surface_topology)) {
        const std::size_t added =
            seed_islands(m, cell_islands(m.surface, seeds), seeds, constraints);
        report.islands += added;
        changed += added;
      }
    }
    if (changed == 0) {
      if (!cut.empty()) {
        const std::vector<bool> last =
            flip_in_links(flipped, link_seeds(missing), kSmallestFlipDeg);
        report.links_flipped = static_cast<std::size_t>(std::count(made.begin(), made.end(), true) +
                                                        std::count(last.begin(), last.end(), true));
        std::vector<Edge> unmade;
        for (std::size_t k = 0; k < missing.size(); ++k)
          if (!last[k]) unmade.push_back(missing[k].seeds);
        report.tips_closed = close_corner_tips(flipped, constraints.corner_seed, unmade);
        output.mesh = std::move(flipped);
      }
      return output;
    }
    ++report.rounds;
    output = extract_polished(m.surface, seeds, m.placement, m.polish);
    report.polish_rounds += output.rounds;
  }
}

}  // namespace cvtmesh
