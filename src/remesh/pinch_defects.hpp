// The topological ball property where sheets of the input touch at a point (issue 18): remesh
// splits such a vertex into one copy per sheet, each a corner, and welds the output's vertices
// there again (remesh/by_component).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Where sheets of the input touch at a point (corners at one position: remesh_by_component's
// copies of the vertex there, one per sheet), the output must have a vertex of its triangles per
// sheet at that point, welded into one at the end, and they must share no neighbour, or the weld
// would make their edges to it non-manifold. Either fails where a cell reaches across the sheets
// there, or at the tip of a cone too sharp for the cells around it. The triangles at the shared
// neighbours' edges, and near a point short of vertices (within their longest edge of their
// centroid).
// `corners`: the input's corners (vertices of `surface`); those at one point are the copies
// there. `out`: an extraction.
std::vector<Triangle> pinch_defects(const TriangleMesh& surface, const std::vector<Index>& corners,
                                    const TriangleMesh& out);

}  // namespace cvtmesh
