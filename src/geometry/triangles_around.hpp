// Per vertex of a mesh, its triangles: the star that local mesh operations (flips, moves,
// vertex removals) walk.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Per vertex of `mesh`, the indices of the triangles that use it, in increasing order.
inline std::vector<std::vector<Index>> triangles_around(const TriangleMesh& mesh) {
  std::vector<std::vector<Index>> around(mesh.vertices.size());
  for (Index t = 0; t < mesh.triangles.size(); ++t)
    for (const Index v : mesh.triangles[t]) around[v].push_back(t);
  return around;
}

}  // namespace cvtmesh
