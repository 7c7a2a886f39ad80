#include "features/edge_uses.hpp"

#include <algorithm>
#include <tuple>

#include "geometry/sort_by_edge.hpp"

namespace cvtmesh {

bool runs_forward(const Triangle& t, Index a, Index b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a && t[(k + 1) % 3] == b) return true;
  return false;
}

std::vector<EdgeUse> edge_uses(const TriangleMesh& mesh,
                               const std::function<bool(const Edge&)>& keep) {
  // Sorted by (edge, corner) in linear time (BM_EdgeUses: about 10 times faster than a comparison
  // sort), straight into EdgeUse.
  const auto make = [](Index lo, Index hi, std::size_t t, int k) {
    return EdgeUse{{lo, hi}, 3 * t + static_cast<std::size_t>(k)};
  };
  const auto before = [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.edge[1], x.corner) < std::tie(y.edge[1], y.corner);
  };
  if (!keep) return sorted_by_edge<EdgeUse>(mesh.vertices.size(), mesh.triangles, make, before);
  return sorted_by_edge<EdgeUse>(mesh.vertices.size(), mesh.triangles, make, before,
                                 [&](Index lo, Index hi) {
                                   return keep(Edge{lo, hi});
                                 });
}

std::vector<bool> on_edges_not_of_two(const TriangleMesh& mesh) {
  std::vector<bool> on(mesh.vertices.size(), false);
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i != 2) on[uses[i].edge[0]] = on[uses[i].edge[1]] = true;
  });
  return on;
}

std::vector<Edge> sorted_edges(const TriangleMesh& mesh) {
  std::vector<Edge> edges;
  for (const EdgeUse& use : edge_uses(mesh)) edges.push_back(use.edge);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

std::optional<std::vector<BoundaryLoop>> boundary_loops(const TriangleMesh& mesh,
                                                        const std::vector<EdgeUse>& uses) {
  // Per vertex, the boundary edge use that arrives at it along its triangle: the loop's step
  // from it goes back along that edge.
  constexpr std::size_t kNone = ~std::size_t{0};
  std::vector<std::size_t> into(mesh.vertices.size(), kNone);
  bool defined = true;
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j != i + 1) return;
    const Triangle& t = mesh.triangles[uses[i].triangle()];
    const Index b = t[(uses[i].corner + 1) % 3];
    if (into[b] != kNone) defined = false;
    into[b] = i;
  });
  if (!defined) return std::nullopt;
  std::vector<BoundaryLoop> loops;
  std::vector<bool> seen(mesh.vertices.size(), false);
  for (Index start = 0; start < into.size(); ++start) {
    if (into[start] == kNone || seen[start]) continue;
    BoundaryLoop& loop = loops.emplace_back();
    Index v = start;
    while (into[v] != kNone && !seen[v]) {
      seen[v] = true;
      loop.vertices.push_back(v);
      loop.uses.push_back(into[v]);
      v = mesh.triangles[uses[into[v]].triangle()][uses[into[v]].corner % 3];
    }
    // A walk that stops short of its start left the boundary through an edge of three or more
    // triangles (a flap glued along two of its sides has its third side alone): no loop.
    if (v != start) return std::nullopt;
  }
  return loops;
}

}  // namespace cvtmesh
