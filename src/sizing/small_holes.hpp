// The cap that a hole far smaller than the lengths around it puts on them (sizing/feature_gaps).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// `sizes` (per vertex of `mesh`) lowered on each boundary loop shorter than 2π times them to its
// length over 2π: about six edges around a hole, whatever its shape.
void cap_at_small_holes(const TriangleMesh& mesh, std::vector<double>& sizes);

}  // namespace cvtmesh
