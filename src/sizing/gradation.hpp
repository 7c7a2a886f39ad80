// Grading a size field along a mesh's edges.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// A mesh's vertices with, per vertex, its neighbours across the triangles' edges (each edge once
// per triangle that has it) and those edges' lengths: built once for grading many fields on the
// same mesh (fitting a sizing to a vertex count grades one per trial scale).
class EdgeGraph {
 public:
  explicit EdgeGraph(const TriangleMesh& mesh);
  std::size_t vertices() const { return first_.size() - 1; }

 private:
  friend std::vector<double> graded(const EdgeGraph&, std::vector<double>, double);
  std::vector<std::size_t> first_;  // per vertex, where its neighbours start; then the end
  std::vector<Index> neighbour_;
  std::vector<double> length_;  // per neighbour entry, the edge's length
};

// The largest field g <= size with g(v) <= g(u) + |uv| / gradation along every edge uv: sizes
// that change by at most 1/gradation per unit length (Dijkstra from every vertex at once).
// Vertices used by no triangle keep their size.
std::vector<double> graded(const EdgeGraph& graph, std::vector<double> size, double gradation);
std::vector<double> graded(const TriangleMesh& mesh, std::vector<double> size, double gradation);

}  // namespace cvtmesh
