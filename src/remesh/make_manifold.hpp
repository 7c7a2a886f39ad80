// The last step of topology control (issue 18): whatever the rounds of seed insertion left, the
// output is made an oriented 2-manifold by removing the triangles at its defects (non-manifold
// edges and vertices, and folds where the input is oriented), repeatedly, until there are none. It
// always terminates (each pass removes triangles) and always succeeds; the price is a hole where a
// defect was, which the report states (validity before topology).
#pragma once

#include <cstddef>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Returns how many triangles were removed (0 when the mesh was a manifold already). Folds
// (an edge two triangles use the same way) count as defects when `oriented`.
std::size_t make_manifold(TriangleMesh& mesh, bool oriented);

}  // namespace cvtmesh
