// The angle between two vectors, in degrees.
#pragma once

#include <cmath>
#include <numbers>

#include "cvtmesh/vec3.hpp"

namespace cvtmesh {

// atan2 stays accurate for angles near 0° and 180°, where acos of the cosine does not.
inline double angle_deg(const Vec3& u, const Vec3& v) {
  return 180 / std::numbers::pi * std::atan2(norm(cross(u, v)), dot(u, v));
}

}  // namespace cvtmesh
