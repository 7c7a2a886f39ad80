// The cap that a handle far thinner than the lengths around it puts on them, as a small hole's
// does (sizing/small_holes.hpp): a tunnel through a part, or a bridge over it, whose loop around
// is a few edges long at most. The restricted Delaunay triangulation closes such a handle
// without a defect to show where (femur.off: two handles 0.004 round, under a fifth of the edge
// length at 1k-10k), and topology control's rounds then add hundreds of seeds before it opens
// again; sizes that narrow there from the start give the handle its cells at once.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Whether a part of `mesh` has handles (genus above 0; boundary loops count as the holes they
// are), found from its edges alone (no orientation, no pinch check): the cheap test before
// handle_widths. False with an edge of three or more triangles.
bool has_handles(const TriangleMesh& mesh);

// Per vertex of `mesh` on a handle's throat, the handle's width: its shortest loop around the
// handle through the vertex, over π (a round tunnel's diameter, the gap across it), where that
// is under `reach`; infinite elsewhere. The loop is where the vertex's geodesic ball (Dijkstra
// along the edges) first stops being a disc and stays so: a tunnel's ball wraps round it and
// meets itself, an annulus from then on, while a ball that only passes a vertex on both sides
// closes again within an edge. Every vertex alone, in parallel: the same on any thread count.
// All infinite on a mesh without handles (has_handles), where no ball wraps round anything but a
// hole, which small_holes caps.
std::vector<double> handle_widths(const TriangleMesh& mesh, double reach);

}  // namespace cvtmesh
