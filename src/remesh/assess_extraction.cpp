#include "remesh/assess_extraction.hpp"

#include <algorithm>

#include "cvtmesh/quality.hpp"
#include "features/edge_uses.hpp"
#include "finish/own_sheet.hpp"
#include "finish/valence_three.hpp"
#include "geometry/self_crossings.hpp"
#include "remesh/flip_links.hpp"
#include "remesh/last_step.hpp"
#include "remesh/mend_topology.hpp"
#include "remesh/pinch_defects.hpp"

namespace cvtmesh {

namespace {

// Flips that leave no angle under the usual quality bar are as good as moving seeds, and cheaper:
// the links they make are left to them. A link only a worse flip makes gets seeds first (a stray
// surface seed that cuts it joins the curve), and the flip if still missing at the end. Every cut
// link left to the seeds (one floor, 15°) was measured on the corpus (57 meshes at 1k/5k/10k,
// 2k/3k with --seed 2, adaptive 2k): θmin better on 4 runs, worse on 1, but the curves get seeds
// closer than their spacing, and the average triangle worse (spool.off at 5k: θmin_ave 51.51° to
// 51.02°; and adaptive at 2k, seeds 1-3: 49.0° to 48.1°).
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

// Of the `vertices` of an extraction (the seeds, then the cells' far pieces), those that the
// finishing steps may move: surface seeds, and far pieces (all, without feature seeds).
std::vector<bool> surface_seeds(const SeedConstraints& constraints, std::size_t vertices) {
  std::vector<bool> surface(vertices, true);
  for (std::size_t s = 0; s < constraints.kind.size() && s < vertices; ++s)
    surface[s] = constraints.kind[s] == SeedConstraints::Kind::surface;
  for (const Index s : constraints.corner_seed)
    if (s < vertices) surface[s] = false;
  return surface;
}

}  // namespace

SpecialEdges special_edges(const MendContext& m) {
  // A closed manifold input has neither kind: its edges are not walked again (on igea.ply's 270k
  // triangles that walk was 5% of a remesh to 1k, on the serial path).
  const TopologyReport& t = m.surface_topology;
  if (t.boundary_edges == 0 && t.nonmanifold_edges == 0) return {};
  const std::vector<EdgeUse> uses = edge_uses(m.surface);
  std::vector<Edge> boundary, branch;
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i == 1) boundary.push_back(uses[i].edge);
    if (j - i >= 3) branch.push_back(uses[i].edge);
  });
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

Assessment assess(const MendContext& m, const SpecialEdges& special, const TriangleMesh& rdt,
                  const std::vector<Vec3>& seeds, const SeedConstraints& constraints,
                  InputCrossings& crossings) {
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
  a.tips_closed = close_corner_wedges(a.finished, constraints.corner_seed, unmade);
  if (a.tips_closed > 0) {
    // The links along the wedges closed are there now.
    const std::vector<Edge> edges = sorted_edges(a.finished);
    std::erase_if(a.missing, [&](const FeatureLink& link) {
      return std::binary_search(edges.begin(), edges.end(), link.seeds);
    });
  }
  const TopologyReport t = analyze_topology(a.finished);
  const TopologyReport& in = m.surface_topology;
  if (in.is_manifold()) {
    const std::vector<Triangle> pinched = pinch_defects(m.surface, m.features.corners, a.finished);
    a.topology_kept = t.is_manifold() && same_topology(t, in) && pinched.empty();
    if (!a.topology_kept) {
      a.defects = find_output_defects(
          a.finished, boundary_seeds(m, special, constraints, a.finished), in.orientable);
      a.defects.triangles.insert(a.defects.triangles.end(), pinched.begin(), pinched.end());
      TriangleMesh last = a.finished;
      finish_manifold(last, in, m.projector);
      const TopologyReport after = analyze_topology(last);
      a.rescued = after.is_manifold() && same_topology(after, in) && pinched.empty();
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
  // Where the input crosses itself too, only the output's own crossings count, away from the
  // input's (crossings_of_its_own): camel.off, whose input crosses itself at 20 triangles
  // elsewhere, crossed itself at its lips (nearly touching) at 25 and 28 triangles at 5k and 10k
  // while these were not refined; refined, none at 40 and 58 seeds more, θmin and Qmin as they
  // were (Qmin 0.700 -> 0.692 at 10k); no other run of the 57 shared meshes changed.
  if (a.topology_kept) {
    a.crossing = crossings_of_its_own(a.finished, crossings);
    // Folds that the finishing steps mend before any sweep are left to them: a vertex on the far
    // face of a sharp edge, put back on its own (finish/own_sheet), and a vertex of three
    // triangles folded over their neighbours, taken out (finish/valence_three). Refined, two
    // such folds cost spool.off adaptive at 2k 16 seeds, blade.off at 1k 34 of its 80.
    if (!a.crossing.empty()) {
      TriangleMesh mended = a.finished;
      const std::vector<bool> movable = surface_seeds(constraints, mended.vertices.size());
      move_onto_own_sheet(mended, m.projector, movable);
      remove_valence_three(mended, movable, m.projector);
      a.crossing = crossings_of_its_own(mended, crossings);
    }
  }
  std::vector<bool> used(a.finished.vertices.size(), false);
  for (const Triangle& tri : a.finished.triangles)
    for (const Index v : tri) used[v] = true;
  const auto corners = static_cast<std::size_t>(std::count_if(constraints.corner_seed.begin(),
                                                              constraints.corner_seed.end(),
                                                              [&](Index s) { return used[s]; }));
  a.score = {a.topology_kept,
             -static_cast<std::ptrdiff_t>(a.defects.triangles.size()),
             -static_cast<std::ptrdiff_t>(a.crossing.size()),
             corners,
             -static_cast<std::ptrdiff_t>(unmade.size()),
             measure_quality(a.finished).q_min};
  return a;
}

}  // namespace cvtmesh
