// The output's last touch (issue 18, item 6): the restricted Delaunay triangulation of seeds that
// an iteration cap stopped short of a centroidal tessellation, or that topology control added at
// details finer than the spacing, has a few badly shaped triangles left. Around them, this step
// flips edges between nearly coplanar triangles and moves vertices towards the centre of their
// star, back onto the input surface, as tangential relaxation does in CGAL's and pmp-library's
// remeshers. Neither changes the triangulation's topology (a flip never makes an edge that is
// there already, a move changes no connectivity), so a manifold stays a manifold with the same
// Euler characteristic and boundary loops, and a change is kept only when the worst triangle it
// touches gets better.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

class SurfaceProjector;

struct ShapeImprovement {
  std::size_t flips = 0;  // edges flipped
  std::size_t moves = 0;  // vertex moves kept
};

// Improves the triangles of `mesh` with θmin under 35° or Q under 0.65 (what a converged CVT
// gives on a smooth surface), in `sweeps` sweeps at most. `fixed` (per vertex) marks vertices that
// must not move (features, corners); vertices on boundary or non-manifold edges, and tips and
// saddles of the surface (angle defect over 10°), never move.
// `feature_edges` (sorted) never flip, and of the others only those with exactly two triangles,
// which use them in opposite directions. Each change keeps the triangles it touches about as close
// to the surface as they were. Moved
// vertices go to their nearest point on `surface`. Sequential, in a fixed order: the result does
// not depend on the thread count.
ShapeImprovement improve_shapes(TriangleMesh& mesh, const SurfaceProjector& surface,
                                std::vector<bool> fixed, const std::vector<Edge>& feature_edges,
                                int sweeps);

}  // namespace cvtmesh
