// Splitting a mesh's edges at new vertices, each split touching only the triangles on the edge:
// the stars of the vertices are kept up to date, so that many splits of a large mesh cost what
// the triangles split cost.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class EdgeSplitter {
 public:
  explicit EdgeSplitter(const TriangleMesh& mesh);
  // Splits every triangle of `mesh` (the mesh given, grown by earlier splits only) on the edge
  // (p, q) at x, a vertex already in `mesh` that no triangle uses yet, keeping orientations.
  void split(TriangleMesh& mesh, Index p, Index q, Index x);
  // The triangles that use v.
  const std::vector<Index>& around(Index v) const { return around_[v]; }

 private:
  std::vector<std::vector<Index>> around_;
};

}  // namespace cvtmesh
