// Each connected component of the input is remeshed on its own (issue 18): a seed belongs to one
// component and never owns another's surface, however close the two lie, so no component is
// merged, dropped or cut by its neighbour's cells.
#pragma once

#include <vector>

#include "cvtmesh/remesh.hpp"
#include "geometry/triangle_sides.hpp"

namespace cvtmesh {

// remesh_unit on each connected component (triangles sharing edges) of a mesh of about unit
// size, the outputs side by side in the order of the components' first triangles; a vertex where
// components touch is a corner of each, and their outputs are welded there. The requested count
// is shared in proportion to area (under a sizing, to the vertices that the sizing of the whole
// asks of each), each component getting at least 4 vertices and more than its feature seeds (so
// a small part with many corners still fits); a sizing given as lengths without a count gives
// each component the count its lengths ask for. With initial seeds, or a single component, the
// mesh is remeshed whole. `sides`: the mesh's
// sorted_sides where the caller has them (empty: found here).
RemeshResult remesh_by_component(const TriangleMesh& mesh, const RemeshSettings& settings,
                                 std::vector<TriangleSide> sides = {});

}  // namespace cvtmesh
