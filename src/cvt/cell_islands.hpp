// Topology control (paper §4.4): the restricted Delaunay triangulation is homeomorphic to the
// surface when every restricted Voronoi cell is a topological disc. A cell in several pieces
// (typically a seed next to a sharp, thin wedge whose cell reaches around onto the other face)
// breaks that: its Voronoi edges cross the surface twice, and the output gets overlapping
// triangles or slits. A new seed in each extra piece removes it.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"
#include "voronoi/cell_pieces.hpp"

namespace cvtmesh {

struct CellIsland {
  Index seed;     // the cell it belongs to
  Vec3 centroid;  // its area centroid
  double area;
  std::size_t piece;  // its index in the collector's pieces()
};

// The pieces of restricted Voronoi cells beyond each cell's largest, in seed order, then by
// the input triangle they start on. Pieces are joined across input edges they share a stretch
// of; the surface's connectivity comes from its vertex ids. Independent of the thread count.
std::vector<CellIsland> cell_islands(const TriangleMesh& surface, const std::vector<Vec3>& seeds);
// The same, from a traversal already made (CellPieceCollector as one of its sinks).
std::vector<CellIsland> cell_islands(const CellPieceCollector& pieces);

}  // namespace cvtmesh
