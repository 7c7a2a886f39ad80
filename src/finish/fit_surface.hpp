// Fitting the output to the input surface (issue 19 item 6). The remesher's vertices lie on the
// input, so every triangle is a chord: inside convex parts and outside concave ones, by about
// h²/(8R) at its middle for edges h and curvature radius R. Moving each vertex a little along its
// normal, by the weighted mean of the distances from its triangles' points to the surface (one
// least-squares step per round, as geogram's mesh_adjust_surface fits vorpalite's output), puts
// the surface between the vertices and the triangles' middles and roughly halves the distance.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector;

struct SurfaceFit {
  std::size_t vertices_moved = 0;  // movable vertices that ended off where they were
  double offset_max = 0;           // the largest move, in the mesh's units
};

// Moves the vertices of `mesh` flagged in `movable` (feature and corner vertices should not be)
// along their normals towards `surface`, in `rounds` rounds; vertices of an edge with other than
// two triangles (a boundary or non-manifold edge) never move. A move is at most 0.3 times the
// vertex's shortest edge, and it is undone where a triangle it touches would turn by more than
// 25°, or fall below its shape as the round found it where that was under the finishing steps'
// aim (finish/move_limits.hpp) or under the mesh's worst, else below the higher of those: the fit
// never lowers θmin or Qmin, nor a triangle under the aim. The connectivity does not change.
// Deterministic, whatever the thread count.
SurfaceFit fit_to_surface(TriangleMesh& mesh, const SurfaceProjector& surface,
                          std::vector<bool> movable, int rounds);

}  // namespace cvtmesh
