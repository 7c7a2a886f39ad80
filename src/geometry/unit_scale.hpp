// Scale invariance (issue 22): a mesh is worked on scaled by a power of two to about unit size.
// Multiplying by a power of two is exact in floating point (barring subnormals), so corners keep
// their coordinates bit for bit through the scaling and back, and a mesh in nanometres or in
// light years is remeshed as the same shape in metres would be: areas and squared distances
// neither underflow nor overflow.
#pragma once

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// The exponent e of the mesh's largest bounding-box extent (over the vertices its triangles
// use): that extent is in [2^e, 2^(e+1)). 0 for a mesh without extent.
int size_exponent(const TriangleMesh& mesh);

// `mesh` with every coordinate multiplied by 2^exponent.
TriangleMesh scaled_by_power_of_two(TriangleMesh mesh, int exponent);

}  // namespace cvtmesh
