// Unit vectors and triangle normals, with the zero vector standing for "no direction" (a
// degenerate triangle, normals that cancel).
#pragma once

#include "cvtmesh/vec3.hpp"

namespace cvtmesh {

// v scaled to length 1; the zero vector when v has no length (or its length is not finite).
inline Vec3 unit_or_zero(const Vec3& v) {
  const double length = norm(v);
  return length > 0 ? (1 / length) * v : Vec3{};
}

// The unit normal of triangle (a, b, c), by the right-hand rule; zero when it is degenerate.
inline Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  return unit_or_zero(cross(b - a, c - a));
}

}  // namespace cvtmesh
