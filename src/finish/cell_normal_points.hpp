// Output vertices onto their cells' normal lines (issue 19 item 6, the Hausdorff distance). A
// seed held on the surface stands at the surface point nearest to its cell's centroid. Where the
// surface bends within the cell (a tip, a ridge narrower than an edge), that point lies on a
// flank, and the triangles around cut the tip off; the point where the cell's mean normal line
// through its centroid meets the surface lies on the tip. (Measured: "Output vertices on their
// cells' normal lines" in docs/benchmarks.md.)
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "voronoi/cell_normals.hpp"

namespace cvtmesh {

class SurfaceProjector;

// Moves each vertex of `mesh` flagged in `movable` that stands at a seed (by position; `cells`:
// per seed) to the surface point on its cell's normal line nearest to the cell's centroid, if
// that lies within half the vertex's shortest edge of the centroid; vertices of an edge with
// other than two triangles never move. A move is undone where a triangle it touches would fall
// below its own θmin or Q or below 40° and 0.7, whichever are lower (never below the mesh's θmin
// and Qmin), or turn by 25° or more. The connectivity does not change. Deterministic on any
// thread count. Returns the vertices moved.
std::size_t move_onto_cell_normals(TriangleMesh& mesh, const std::vector<Vec3>& seeds,
                                   const std::vector<CellNormal>& cells,
                                   const SurfaceProjector& projector, std::vector<bool> movable);

}  // namespace cvtmesh
