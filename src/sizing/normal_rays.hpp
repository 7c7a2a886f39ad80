// The local feature size bounded by rays along the vertices' normals (issue 20 item 1): what the
// poles of a sample coarser than a thin part cannot see.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Lowers `lfs` (per vertex of `mesh`) to half the distance from each vertex to the first triangle
// hit by the rays along its unit `normal` (zero: no ray), both ways: the largest ball inside (or
// outside) the surface that touches it at p is centred on the normal, so it cannot reach past the
// hit. A nearest hit at the vertex itself (a vertex of another sheet at the same place) bounds
// nothing.
void bound_by_normal_rays(const TriangleMesh& mesh, const std::vector<Vec3>& normal,
                          std::vector<double>& lfs);

}  // namespace cvtmesh
