// Output vertices onto the input's creases that the output does not trace (issue 19 item 6, the
// Hausdorff mean). A polyhedral input coarser than the output (a low-poly model remeshed finer, a
// scan's edges that bend by tens of degrees) has creases that no feature detection keeps on an
// organic surface; a triangle across one cuts the crease off, and a vertex a little beside it
// makes the triangles on both sides lean off their faces. On the corpus's coarse meshes most of
// the distance from the input to the output lies within half an edge of such creases (hand.off
// at 5k: 60% of it, on a third of the surface). A vertex there moved onto the crease puts the
// output's triangles back on the faces. (geogram's vorpalite does not project its vertices onto
// the input, and its fit leaves many on creases as well.)
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector;

// Moves each vertex of `output` flagged in `movable` that lies near an edge of `surface` whose
// triangles' normals turn by more than 20° and that is at least as long as the output's mean edge
// (a crease; `features`, which the output traces, are none), within 0.3 of the vertex's shortest
// edge, to the nearest point of the nearest such edge (a CGAL AABB tree's), where that brings its
// triangles nearer the surface (at their centroids and edge midpoints, weighted by area) with
// none of those points farther than the farthest was, keeps each triangle at least as well shaped
// as the worst of them was, or at θmin 40° and Q 0.7 (what the last sweeps aim at), turns none by
// 25° or more, and the crease's triangles face the side the vertex lies on (not the other side of
// a part thinner than the reach). Vertices on an edge with other than two triangles never move; nor
// does the connectivity. One pass over the vertices, in rounds of vertices no two of which are
// neighbours, each round's moves judged at once: deterministic on any thread count. Returns the
// vertices moved.
std::size_t snap_to_creases(TriangleMesh& output, const TriangleMesh& surface,
                            const Features& features, const SurfaceProjector& projector,
                            const std::vector<bool>& movable);

}  // namespace cvtmesh
