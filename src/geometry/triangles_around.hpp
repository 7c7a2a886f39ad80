// Per vertex of a mesh, its triangles: the star that local mesh operations (flips, moves,
// vertex removals) walk; and the removal of the triangles they took away.
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

// Removes the triangles of `mesh` marked in `gone` (per triangle), the others kept in order:
// what local operations that take triangles away leave, once they are done.
inline void erase_marked_triangles(TriangleMesh& mesh, const std::vector<bool>& gone) {
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!gone[t]) mesh.triangles[kept++] = mesh.triangles[t];
  mesh.triangles.resize(kept);
}

}  // namespace cvtmesh
