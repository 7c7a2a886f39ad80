// The last resort for feature links the restricted Delaunay triangulation still misses after
// topology control (paper §4.4): where one edge flip makes the link, flip it, as constrained
// Delaunay meshers recover a segment. In a wedge between two curves narrower than a triangle,
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

}  // namespace cvtmesh
