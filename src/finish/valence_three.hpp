// A vertex with three triangles, inside the surface, caps a triangle split in three: however it
// moves, its triangles' angles at the outer corners share what the three 120°s at it leave
// (θmin 30°, Q 0.5 at best). Topology control leaves such vertices where it adds seeds next to
// others (cow.off at 1k: its worst triangles are all at one, 116° there). Removing the vertex and
// its three triangles for the one they cover keeps the topology (V - 1, E - 3, F - 2) and, where
// that triangle is better shaped and lies close to where the three did, the output.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector;

// Replaces the three triangles of each vertex with `removable` set and three triangles around it
// (a closed fan) with the triangle of its three neighbours when: no triangle of those three
// exists already; its min(Q, θmin / 60°) is above the worst of the three's; the vertex lies
// within a fifth of its longest edge of its plane; and its centroid is about as close to
// `surface` as the three's were. The vertex is left unused. Returns how many were removed.
std::size_t remove_valence_three(TriangleMesh& mesh, const std::vector<bool>& removable,
                                 const SurfaceProjector& surface);

}  // namespace cvtmesh
