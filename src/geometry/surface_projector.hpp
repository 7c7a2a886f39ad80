// Nearest points on the input surface, and the surface normal there (CGAL AABB tree).
#pragma once

#include <memory>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector {
 public:
  // `surface` must have at least one triangle.
  explicit SurfaceProjector(const TriangleMesh& surface);
  ~SurfaceProjector();
  struct Foot {
    Vec3 point;   // the nearest surface point
    Vec3 normal;  // unit normal of the triangle it lies on
  };
  // Thread-safe after construction.
  Foot nearest(const Vec3& p) const;
  double squared_distance(const Vec3& p) const {
    const Vec3 d = nearest(p).point - p;
    return dot(d, d);
  }

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
