// How far an RVD polygon reaches from its cell's seed, for the bounds that decide which seeds
// and which triangles a cell may meet.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

// The largest distance from `point` to a vertex of the polygon plus the vertices' largest error:
// every vertex's exact position lies within it. One square root per polygon, not per vertex (it
// runs after every cut of the RVD's clipping).
inline double reach_from(const Vec3& point, std::span<const RvdVertex> polygon) {
  double d2 = 0, error = 0;
  for (const RvdVertex& v : polygon) {
    d2 = std::max(d2, dot(v.point - point, v.point - point));
    error = std::max(error, v.error);
  }
  return std::sqrt(d2) + std::sqrt(3.0) * error;
}

// The largest squared distance from `seed` to the polygon, rounded up past every vertex's
// error: the polygon is convex, so its farthest point from the seed is a vertex.
inline double squared_reach(const Vec3& seed, std::span<const RvdVertex> polygon) {
  const double r = reach_from(seed, polygon);
  return r * r * (1 + 1e-10);
}

// A ball around a polygon: centred at the mean of its vertices, reaching past every vertex's
// exact position.
struct Ball {
  Vec3 center;
  double radius;
};

inline Ball bounding_ball(std::span<const RvdVertex> polygon) {
  Vec3 center{};
  for (const RvdVertex& v : polygon) center = center + v.point;
  center = (1.0 / static_cast<double>(polygon.size())) * center;
  return {center, reach_from(center, polygon) * (1 + 1e-10)};
}

}  // namespace cvtmesh
