// Zero-area "caps" removed without opening the surface. A cap is a triangle whose three corners
// lie on a line with one strictly between the other two: what stitches a T-junction shut in CAD
// tessellations and game assets. Dropping it leaves a slit, a boundary loop the surface never
// had (ogre.obj of a public test set: each earring, closed, came out a tube with two open ends).
// Instead, the triangle across the cap's long edge is split at the middle corner and the cap
// dropped: every edge keeps its two triangles, and the surface its topology.
#pragma once

#include <cstddef>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// Whether triangle t of `mesh` has zero area: a repeated corner, or collinear corners (exact).
bool zero_area(const TriangleMesh& mesh, const Triangle& t);

// Splits out every cap whose long edge has exactly one other triangle, not itself of zero area,
// whose third corner is not joined to the cap's middle corner already (the split would make
// that edge one of three triangles); repeats while that splits more (caps side by side along an
// edge). Caps it cannot split stay, as do the other zero-area triangles. The halves of a split
// triangle take its place and its orientation: the triangle count stays. Exact
// predicates; deterministic. Returns how many caps were split out.
std::size_t split_caps(TriangleMesh& mesh);

}  // namespace cvtmesh
