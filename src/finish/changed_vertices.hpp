// Where the finishing steps add vertices (halved edges) or leave some unused (collapsed edges):
// the region the sweeps after them look at, and the renumbering after them.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

// The vertices within two rings of those from `first_new` on: where halving an edge changes the
// shapes, and the sweeps after it need to look (all over the mesh in every round of
// finish_output's halvings, they took femur.off at 1k, whose stacked sheets leave a hundred bad
// triangles, from 2.3 s to 4.3 s; 3.7 s with only the first round's all over it).
std::vector<bool> around_new_vertices(const TriangleMesh& mesh, std::size_t first_new);

// Halves edge a -> b of triangle t = (a, b, c) at `point`, appended as a vertex: t becomes
// (c, a, m) and (c, m, b); where `d` is not kNoIndex, triangle u = (b, a, d) across the edge
// becomes (b, m, d) and (m, a, d). Orientations are kept. Returns m.
Index halve_edge(TriangleMesh& mesh, std::size_t t, std::size_t u, Index a, Index b, Index c,
                 Index d, const Vec3& point);

// Drops the vertices no triangle uses (repair_mesh), and renumbers the rest in `r`'s vertices
// added and feature edges, and in `flags` (per vertex).
void drop_unused_vertices(RemeshResult& r, std::vector<bool>& flags);

}  // namespace cvtmesh
