// The last resort for feature links the restricted Delaunay triangulation still misses after
// topology control (paper §4.4): where one edge flip makes the link, flip it, as constrained
// Delaunay meshers recover a segment; where a corner at a boundary tip has no triangle, add the
// one its two links bound. In a wedge between two curves narrower than a triangle,
// no placement of seeds makes every link Delaunay; a flip there costs no more angle than the
// wedge already does.
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// For each edge (a, b) of `links` not in `mesh`: where two triangles (a, c, d) and (d, c, b)
// share edge (c, d) and no other triangle does, they become (a, c, b) and (a, b, d), if both
// new triangles face the way the two old ones do (no fold) and have no angle under
// `min_angle_deg`. Returns, per link, whether a flip made it.
std::vector<bool> flip_in_links(TriangleMesh& mesh, const std::vector<Edge>& links,
                                double min_angle_deg);

// At a sharp tip of a boundary, the Voronoi vertex of the corner seed and the seeds next to it
// on the two curves can fall past the tip's edges, off the surface: the restricted Delaunay
// triangulation then has no triangle at the corner, and the output would lose it
// (mech-holes-shark.off at 3k vertices). For each corner in `corners` that no triangle uses and
// that has exactly two `links` (the missing ones), to a and b: where edge (a, b) has a single
// triangle, and the corner lies on that edge's free side (the new triangle faces the way that
// one does), triangle (a, b, corner) is added. Returns how many were.
std::size_t close_corner_tips(TriangleMesh& mesh, const std::vector<Index>& corners,
                              const std::vector<Edge>& links);

}  // namespace cvtmesh
