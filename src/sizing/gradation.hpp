// Grading a size field along a mesh's edges.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// The largest field g <= size with g(v) <= g(u) + |uv| / gradation along every edge uv: sizes
// that change by at most 1/gradation per unit length (Dijkstra from every vertex at once).
// Vertices used by no triangle keep their size.
std::vector<double> graded(const TriangleMesh& mesh, std::vector<double> size, double gradation);

}  // namespace cvtmesh
