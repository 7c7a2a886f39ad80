// Flat pairs at the output's boundary: a vertex on a nearly straight stretch of boundary with two
// triangles, one to each side of an interior edge. Near a corner where a crease meets the boundary,
// the restricted Delaunay triangulation makes one of vertices a few thousandths of an edge apart,
// and its triangles keep angles of a few degrees, which no flip mends (two of their edges are
// boundary edges) and no move either (the vertex on the boundary is held there, its neighbours on
// features). Merging the two into the triangle without the vertex takes it off the boundary, which
// runs along the chord of its two boundary neighbours: the same loop, one vertex, two edges and one
// triangle fewer, so the same Euler characteristic. (beetle-alt.obj of a public test set at 5k:
// θmin 8.7°.)
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Merges, in one pass, each flat pair whose vertex v is not `kept` (corners) and has two
// triangles, (v, a, c) and (v, c, b) with a-v and v-b boundary edges, where the angle a-v-b is at
// least 160°, a-b is no edge yet, one of the two is under the quality bar (kBarAngleDeg,
// kBarQuality), and the merged triangle (a, c, b) faces as both did and is shaped at least as
// well as the worse of them; where a-v and v-b are both in `feature_edges`
// (sorted), a-b replaces them there, and where one of them is, or v-c, the pair stays. A pair next
// to one merged in the same pass waits (none is looked at again). The vertices merged away are left
// unreferenced. Returns how many pairs were merged.
std::size_t merge_flat_pairs(TriangleMesh& mesh, std::vector<Edge>& feature_edges,
                             const std::vector<bool>& kept);

}  // namespace cvtmesh
