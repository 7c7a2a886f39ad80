// How far apart points spread evenly over a surface are.
#pragma once

#include <cmath>
#include <cstddef>

namespace cvtmesh {

// The edge length of N points spread evenly over area A as the vertices of equilateral
// triangles (about two triangles per vertex: A / N = √3/2 h²).
inline double edge_length_for(double area, std::size_t n) {
  return std::sqrt(area / (std::sqrt(3.0) / 2 * static_cast<double>(n)));
}

}  // namespace cvtmesh
