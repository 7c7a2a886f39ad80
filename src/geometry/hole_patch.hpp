// Triangulating a hole of a mesh on its own boundary vertices: CGAL's hole filling (Liepa: the
// largest dihedral angle, then the area, made smallest, the neighbours' dihedrals counted). Used
// where the output's last step closes the holes it opened (remesh/close_holes) and where an
// input's small holes are filled on request (fill_holes).
#pragma once

#include <optional>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "features/edge_uses.hpp"

namespace cvtmesh {

// A boundary loop (boundary_loops: a triangle closing the hole on three consecutive loop
// vertices a, b, c is (a, b, c)), with each step's third vertex in its triangle.
struct HoleLoop {
  std::vector<Index> vertices;
  std::vector<std::size_t> uses;  // per edge (vertices[i], vertices[i + 1]): its edge use
  std::vector<Index> opposite;    // per edge: the third vertex of its triangle
};

// Every boundary loop of `mesh`, from `uses` = edge_uses(mesh); nothing when a vertex has two
// boundary edges leaving it (a non-manifold vertex, where loops are not defined).
std::optional<std::vector<HoleLoop>> hole_loops(const TriangleMesh& mesh,
                                                const std::vector<EdgeUse>& uses);

// The triangles closing `loop`, oriented as the triangles around it, or nothing when CGAL finds no
// complete triangulation (a loop whose every fan has a degenerate triangle).
std::optional<std::vector<Triangle>> hole_patch(const TriangleMesh& mesh, const HoleLoop& loop);

// Whether a triangle of `patch` has an edge across `loop` (a chord) that the mesh has already
// (`uses`: edge_uses of the mesh, sorted by edge): its two ends joined around the other side of a
// thin part, which the patch would make non-manifold.
bool reuses_edge(const std::vector<Triangle>& patch, const HoleLoop& loop,
                 const std::vector<EdgeUse>& uses);

}  // namespace cvtmesh
