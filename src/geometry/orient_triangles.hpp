// Consistent orientation of a triangle soup: a CAD export or a scan's soup may list some
// triangles clockwise and their neighbours counter-clockwise. The remesher orients each output
// triangle by the input triangle under it, so such an input came out inconsistent, with edges
// used twice the same way, which topology control took for defects (multibody.stl of trimesh's
// test models, a box with one face flipped: 2 components out of 1 at every count).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/triangle_sides.hpp"

namespace cvtmesh {

// The triangles to flip so that each patch of triangles joined by manifold edges (edges of
// exactly two triangles) walks each of its interior edges once each way, keeping the
// orientation of the larger part of the patch's area (on a tie, that of its first triangle).
// A patch that no orientation makes consistent (a Möbius strip) is left as it is. Sorted.
std::vector<std::size_t> triangles_to_flip(const TriangleMesh& mesh);
// The same, from the mesh's sorted_sides, where the caller has them.
std::vector<std::size_t> triangles_to_flip(const TriangleMesh& mesh,
                                           const std::vector<TriangleSide>& sides);

// Flips the given triangles: their corners 1 and 2 swap.
void flip_triangles(TriangleMesh& mesh, const std::vector<std::size_t>& triangles);

// Flips triangles_to_flip(mesh); returns how many.
std::size_t orient_consistently(TriangleMesh& mesh);

}  // namespace cvtmesh
