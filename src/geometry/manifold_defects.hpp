// Where a triangle soup is not an oriented 2-manifold, element by element: edges of three or
// more triangles, vertices whose triangles form several fans (joined across edges of exactly two
// triangles), folds (an edge two triangles use the same way), and boundary edges where the caller
// allows none. Shared by repair (which merges only where no defect appears) and topology control
// (which refines the output at its defects). Triangles with a repeated corner are left out.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct ManifoldDefects {
  std::vector<bool> vertex;    // per vertex: an end of a non-manifold edge, or several fans
  std::vector<bool> triangle;  // per triangle: at any of the defects below
  std::size_t nonmanifold_edges = 0, nonmanifold_vertices = 0;
  std::size_t stray_boundary_edges = 0;  // boundary edges with an end not allowed on a boundary
  std::size_t folded_edges = 0;
};

// `vertices`: the vertex count. `may_bound`: per vertex, whether a boundary edge may end there
// (empty: everywhere). `folds`: whether folds are defects (not for a non-orientable surface).
// `may_branch`: per vertex, whether an edge of three or more triangles may end there, and the
// vertex have several fans (empty: nowhere), for the output of an input that is non-manifold
// itself; such edges and vertices are not defects and are not counted.
ManifoldDefects find_manifold_defects(std::size_t vertices, const std::vector<Triangle>& triangles,
                                      const std::vector<bool>& may_bound, bool folds,
                                      const std::vector<bool>& may_branch = {});

}  // namespace cvtmesh
