// Edges of no length: where a folded input lies on itself (two sheets in one plane), two pieces
// of one cell come out at one point, and where an edge joins them its triangles have no area,
// whatever the sweeps do (they move neither end of an edge between two fixed vertices, and a
// triangle without a normal gives them nothing to judge a move by). Collapsing such an edge
// moves no point: it only takes away the triangles of no area.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Collapses each edge of `mesh` whose ends are one point to round-off (near_point_tolerance)
// where that keeps the topology: one end merged into the other, the edge's triangles gone, the
// link condition held (the ends' only common neighbours are the edge's opposite corners, each
// left with three triangles or more, two at a boundary edge, and no triangle made twice).
// `features` (sorted edges) are renamed alike. The vertex that goes is left unused. Returns how
// many edges went.
std::size_t collapse_coincident_edges(TriangleMesh& mesh, std::vector<Edge>& features);

}  // namespace cvtmesh
