// The edges of a triangle soup as the features module walks them: each triangle's three edges,
// sorted, so that the triangles of an edge are neighbours in the list (a soup read from a file
// has no other connectivity).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

inline Edge edge_of(Index a, Index b) {
  return a < b ? Edge{a, b} : Edge{b, a};
}

// Whether triangle t runs along edge (a, b) from a to b.
bool runs_forward(const Triangle& t, Index a, Index b);

struct EdgeUse {
  Edge edge;
  std::size_t corner;  // 3 t + k: triangle t's edge k, (t[k], t[k+1])
  std::size_t triangle() const { return corner / 3; }
};

// Every triangle's three edges, sorted by edge, then corner; with `keep`, only the uses of the
// edges it accepts (an edge's uses all, or none).
std::vector<EdgeUse> edge_uses(const TriangleMesh& mesh,
                               const std::function<bool(const Edge&)>& keep = {});

// Calls visit(i, j) for each edge's run of uses, uses[i] to uses[j - 1] (j - i triangles have
// it), in order.
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {
    for (j = i + 1; j < uses.size() && uses[j].edge == uses[i].edge; ++j) {
    }
    visit(i, j);
  }
}

// Per vertex of `mesh`, whether it lies on an edge with other than two triangles (a boundary or
// a non-manifold edge): where the finishing steps move no vertex.
std::vector<bool> on_edges_not_of_two(const TriangleMesh& mesh);

// The distinct edges of a mesh, each with the smaller vertex id first, sorted.
std::vector<Edge> sorted_edges(const TriangleMesh& mesh);

// A boundary loop walked against its triangles' orientation: each step (vertices[i],
// vertices[i + 1]) runs the other way in its triangle, so that a triangle closing the hole on
// three consecutive loop vertices a, b, c is (a, b, c). `uses[i]` is that step's edge use (an
// index into the `uses` the loops were found in).
struct BoundaryLoop {
  std::vector<Index> vertices;
  std::vector<std::size_t> uses;
};
// The boundary loops of `mesh` (edges of one triangle), from `uses` = edge_uses(mesh), each
// starting at its smallest vertex id, in that order; none when a vertex has two boundary edges
// leaving it (a non-manifold vertex), or when the boundary edges do not close into loops (they
// meet edges of three or more triangles): there loops are not defined.
std::optional<std::vector<BoundaryLoop>> boundary_loops(const TriangleMesh& mesh,
                                                        const std::vector<EdgeUse>& uses);

}  // namespace cvtmesh
