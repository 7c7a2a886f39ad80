// A triangle's axis-aligned bounding box, and whether two boxes overlap: the first test of every
// crossing search (geometry/self_crossings, finish/near_triangles, improve_shapes's guarded
// checks).
#pragma once

#include <algorithm>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct TriangleBounds {
  Vec3 lo, hi;
};

inline TriangleBounds bounds_of(const std::vector<Vec3>& points, const Triangle& f) {
  TriangleBounds b{points[f[0]], points[f[0]]};
  for (const Index v : f) {
    const Vec3& p = points[v];
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

inline bool overlap(const TriangleBounds& a, const TriangleBounds& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

}  // namespace cvtmesh
