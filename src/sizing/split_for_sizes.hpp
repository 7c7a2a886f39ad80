// The remesher's copy of the input, its triangles split where the target edge lengths change
// faster than one triangle can carry. The CVT's density is linear over each input triangle (paper
// §4.2): a triangle with a tiny length at one corner (a hole far smaller than the edges around
// it) and the even length at the others would be dense all over, and take most of the seeds.
// Split, each triangle's lengths stay within a small factor, as a graded field needs.
#pragma once

#include <optional>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct SplitForSizes {
  TriangleMesh mesh;  // the same surface: the given vertices first, then the edges' midpoints
  // Per added vertex (the k-th is mesh vertex given.vertices.size() + k): the edge it halves.
  std::vector<Edge> halved;
  std::vector<double> sizes;  // per vertex of `mesh`
};

// `mesh` with every edge whose two ends' `sizes` differ by more than `ratio` halved, again
// and again (down to an eighth of the smaller size, no further), each triangle on it split in two
// (the mesh stays conforming and keeps its orientation and topology); a midpoint's size is the mean
// of its ends', or, with `gradation` > 0, the smaller of that and the smaller end's size plus half
// the edge's length over it (the graded size there). Children keep their parent's place in the
// triangle order (which is spatial). None when no edge needs it. `ratio` > 1; `sizes` > 0 on used
// vertices.
std::optional<SplitForSizes> split_for_sizes(const TriangleMesh& mesh,
                                             const std::vector<double>& sizes, double ratio,
                                             double gradation);

// `features` of the given mesh, on the split mesh: each halved feature edge replaced by its
// halves, each curve through them.
Features split_features(const Features& features, const SplitForSizes& split,
                        std::size_t given_vertices);

}  // namespace cvtmesh
