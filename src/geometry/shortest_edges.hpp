// Per vertex, the length of its shortest edge: how far a last step may move it (the fit, the snap
// onto creases) without reaching across a neighbour or a part thinner than its edges.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Infinity for a vertex of no triangle.
inline std::vector<double> shortest_edges(const TriangleMesh& mesh) {
  std::vector<double> shortest(mesh.vertices.size(), std::numeric_limits<double>::infinity());
  for (const Triangle& f : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const double l = distance(mesh.vertices[f[i]], mesh.vertices[f[(i + 1) % 3]]);
      shortest[f[i]] = std::min(shortest[f[i]], l);
      shortest[f[(i + 1) % 3]] = std::min(shortest[f[(i + 1) % 3]], l);
    }
  return shortest;
}

}  // namespace cvtmesh
