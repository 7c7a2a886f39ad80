// Output vertices back onto their own sheet of the surface. Beside a sharp edge whose faces meet
// at a narrow dihedral angle (a blade; 3torus.off's 41° edge), a seed held on one face may serve
// triangles that all lie along the other: its cell reached round the edge, and the nearest
// surface point to the centroid was on the wrong face. Its triangles then cut through the
// wedge (adaptive 3torus.off at 2k, seeds 2-4 and 6: Hausdorff max 0.9-1.2% of the bounding
// box's diagonal, where 0.2% elsewhere).
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector;

// Moves each vertex of `mesh` flagged in `movable` whose triangles face away from the surface
// under it (their mean normal and the normal at its nearest surface point differ by more than
// 90°) while they face towards it under each of its neighbours, to where the line along their
// mean normal meets a sheet facing their way nearest to it, within the vertex's shortest edge;
// vertices of an edge with other than two triangles never move. The sweeps after mend the
// shapes. The connectivity does not change. Deterministic on any thread count. Returns the
// vertices moved.
std::size_t move_onto_own_sheet(TriangleMesh& mesh, const SurfaceProjector& projector,
                                std::vector<bool> movable);

}  // namespace cvtmesh
