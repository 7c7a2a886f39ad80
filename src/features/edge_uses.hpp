// The edges of a triangle soup as the features module walks them: each triangle's three edges,
// sorted, so that the triangles of an edge are neighbours in the list (a soup read from a file
// has no other connectivity).
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

inline Edge edge_of(Index a, Index b) {
  return a < b ? Edge{a, b} : Edge{b, a};
}

// Whether triangle t runs along edge (a, b) from a to b.
bool runs_forward(const Triangle& t, Index a, Index b);

struct EdgeUse {
  Edge edge;
  std::size_t corner;  // 3 t + k: triangle t's edge k, (t[k], t[k+1])
  std::size_t triangle() const { return corner / 3; }
};

// Every triangle's three edges, sorted by edge, then corner.
std::vector<EdgeUse> edge_uses(const TriangleMesh& mesh);

// The distinct edges of a mesh, each with the smaller vertex id first, sorted.
std::vector<Edge> sorted_edges(const TriangleMesh& mesh);

}  // namespace cvtmesh
