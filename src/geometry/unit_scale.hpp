// Work on a mesh at about unit size (see size_exponent in cvtmesh/mesh.hpp).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// The points make(m) gives on `mesh` scaled by a power of two to about unit size, scaled back
// (exactly): sampling takes areas and squared distances, which underflow at 2^-600.
template <class Make>
std::vector<Vec3> points_at_unit_scale(const TriangleMesh& mesh, const Make& make) {
  const int exponent = size_exponent(mesh);
  if (exponent == 0) return make(mesh);
  std::vector<Vec3> points = make(scaled_by_power_of_two(mesh, -exponent));
  for (Vec3& p : points) p = scaled_by_power_of_two(p, exponent);
  return points;
}

}  // namespace cvtmesh
