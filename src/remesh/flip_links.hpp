// The last resort for feature links the restricted Delaunay triangulation still misses after
// topology control (paper §4.4): where one edge flip makes the link, flip it, as constrained
// Delaunay meshers recover a segment; where a corner at a boundary tip has no triangle, add the
// triangles its links bound. In a wedge between two curves narrower than a triangle,
// no placement of seeds makes every link Delaunay; a flip there costs no more angle than the
// wedge already does. And an edge taken out (take_out_edge), which parts a pinch's output copies
// before their weld (remesh/by_component).
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

// Takes edge e = (a, b) out of `mesh`, so that b is no neighbour of a, where exactly two
// triangles (a, b, c) and (b, a, d) share it: by the flip to (c, a, d) and (d, b, c) (where c-d
// is no edge yet, a and b keep three triangles each, and neither new triangle folds over), or by
// halving it (a vertex m at its middle: (a, m, c), (m, b, c), (b, m, d) and (m, a, d)), whichever
// leaves the larger smallest angle (the middle lies on the chord, a sagitta off the input at
// most). A flip alone left a fan of four triangles around cow.obj's pinch (of a public test set,
// at 1k), one of them 139° wide: θmin 15.6° and Qmin 0.294, where the halving leaves 20.5° and
// 0.488 (it halves the angles across from the edge). Where no flip may be, the pinch was left
// unwelded before. Returns whether the edge went.
bool take_out_edge(TriangleMesh& mesh, const Edge& e);

// At a sharp tip of a boundary, the Voronoi vertex of the corner seed and the seeds next to it
// on the two curves can fall past the tip's edges, off the surface: the restricted Delaunay
// triangulation then has no triangle at the corner, and the output would lose it
// (mech-holes-shark.off at 3k vertices). In a wedge narrower still (under about 15°), no rung
// between seeds on its two sides has a Voronoi vertex on the surface for several spacings: the
// output stops where the wedge is wide enough, and its tip is cut off (a sliver of a triangle,
// 7° at its tip, lost both tips at 500 vertices). For each corner in `corners` that no triangle
// uses and that has exactly two `links` (the missing ones): each side's chain of missing links,
// from the corner to the first vertex with triangles, and the boundary across the wedge between
// those two vertices (at most 3 edges) bound the triangles added, a zipper between the chains,
// where they fold nowhere against the boundary's triangle and make no edge the mesh has. Returns
// how many triangles were added.
std::size_t close_corner_wedges(TriangleMesh& mesh, const std::vector<Index>& corners,
                                const std::vector<Edge>& links);

}  // namespace cvtmesh
