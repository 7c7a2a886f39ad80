#include "features/edge_uses.hpp"

#include <algorithm>

namespace cvtmesh {

bool runs_forward(const Triangle& t, Index a, Index b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a && t[(k + 1) % 3] == b) return true;
  return false;
}

std::vector<EdgeUse> edge_uses(const TriangleMesh& mesh) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      uses.push_back({edge_of(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]), 3 * t + k});
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.edge < y.edge || (x.edge == y.edge && x.corner < y.corner);
  });
  return uses;
}

std::vector<Edge> sorted_edges(const TriangleMesh& mesh) {
  std::vector<Edge> edges;
  for (const EdgeUse& use : edge_uses(mesh)) edges.push_back(use.edge);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace cvtmesh
