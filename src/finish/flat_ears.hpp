// Flat ears at the output's boundary: a triangle whose two edges at one vertex are both boundary
// edges, with an angle near 180° there. The restricted Delaunay triangulation makes one where three
// seeds on a nearly straight stretch of boundary have cells that meet on the surface (their dual
// Voronoi vertex lies there, however far the circumcentre); its smallest angle is then a
// degree or two (pig.off, ChineseDragon-10kv.off, mech-holes-shark.off at 5k). Removing it takes
// the ear's vertex off the boundary, which then runs along the chord of the other two: the same
// boundary loop, a manifold as before, the same Euler characteristic (one vertex, two edges and
// one triangle fewer). An ear folded back over the triangle across its chord goes as well: a cell
// in two pieces along a boundary curve gives its far piece a vertex there, which can lie on the
// wrong side of the chord; and so does an ear at such a vertex, which is no seed, from 120°.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// A boundary angle at least this wide (degrees) is flat: a flat ear's, and a flat pair's
// (finish/flat_pairs).
inline constexpr double kFlatBoundaryAngleDeg = 160;

// Removes, until none is left, every ear whose angle at its vertex is at least 160° (120° where
// that vertex is `seedless`: a cell's far piece, no seed), and every ear whose normal turns more
// than 120° from its neighbour's across its third edge (folded back over it), unless that vertex
// is `kept` (corners); and every ear whose vertex lies on top of one of its neighbours (nearer
// than 1e-12 times its third edge: no area), even where that vertex is kept. A flat ear's
// smallest angle is under 10°, and its vertex lies within 0.09 chord lengths of the chord: the
// height |ab||ac| sin θ / |bc| is at most sin 20° (|ab| + |ac|)² / (4 |bc|), and
// |bc| ≥ cos 10° (|ab| + |ac|); a seedless one's is under 30°, its vertex within 0.29 chord
// lengths. A folded ear covers nothing its neighbour does not. The removed vertices are left
// unreferenced. Returns how many ears were removed. Sequential, in triangle order.
std::size_t remove_flat_ears(TriangleMesh& mesh, const std::vector<bool>& kept,
                             const std::vector<bool>& seedless);

}  // namespace cvtmesh
