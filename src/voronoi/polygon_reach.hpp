// How far an RVD polygon reaches from its cell's seed, for the bounds that decide which seeds
// and which triangles a cell may meet.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

// The largest squared distance from `seed` to the polygon, rounded up past every vertex's
// error: the polygon is convex, so its farthest point from the seed is a vertex.
inline double squared_reach(const Vec3& seed, std::span<const RvdVertex> polygon) {
  double r2 = 0;
  for (const RvdVertex& v : polygon) {
    const double r = norm(v.point - seed) + std::sqrt(3.0) * v.error;
    r2 = std::max(r2, r * r);
  }
  return r2 * (1 + 1e-10);
}

}  // namespace cvtmesh
