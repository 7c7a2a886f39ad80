// The finishing steps that move many vertices at once (finish/fit_surface,
// finish/cell_normal_points) and then take back the moves that harmed a triangle.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Puts back at `before` the vertices of every triangle t of `mesh` that `keeps(t)` rejects, until
// it rejects none: undoing all gives back `before`, which the caller's test passes, so it ends.
// In triangle order, the same outcome on any thread count.
template <class Keeps>
void undo_moves_unless(TriangleMesh& mesh, const std::vector<Vec3>& before, const Keeps& keeps) {
  for (bool undone = true; undone;) {
    undone = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (keeps(t)) continue;
      for (const Index v : mesh.triangles[t])
        if (mesh.vertices[v] != before[v]) {
          mesh.vertices[v] = before[v];
          undone = true;
        }
    }
  }
}

}  // namespace cvtmesh
