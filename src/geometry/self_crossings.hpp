// Where the input surface passes through itself: pairs of triangles that intersect other than
// at the vertices and edges they share. There, every seed near the crossing owns a piece of the
// other sheet at any spacing, so no refinement gives the restricted Delaunay triangulation the
// surface's topology (README: topology control, the last step).
#pragma once

#include <memory>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

// Per triangle of `mesh`, whether it crosses another (exact predicates). Triangles that share an
// edge are not tested: their overlap would be a fold, not a crossing.
std::vector<bool> self_crossing_triangles(const TriangleMesh& mesh);

// The triangles of `mesh` flagged in `crossing` (as self_crossing_triangles gives them) as a
// surface to measure distances to, or null where none is.
std::unique_ptr<SurfaceProjector> crossing_surface(const TriangleMesh& mesh,
                                                   const std::vector<bool>& crossing);

}  // namespace cvtmesh
