// The last step of topology control (issue 18): whatever the rounds of seed insertion left, the
// output is made an oriented 2-manifold by removing the triangles at its defects (non-manifold
// edges and vertices, and folds where the input is oriented), repeatedly, until there are none. It
// always terminates (each pass removes triangles) and always succeeds; the price is a hole where a
// defect was, which the report states (validity before topology), unless close_holes can close
// it again.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Returns the triangles removed (none when the mesh was a manifold already). Folds (an edge two
// triangles use the same way) count as defects when `oriented`.
std::vector<Triangle> make_manifold(TriangleMesh& mesh, bool oriented);

}  // namespace cvtmesh
