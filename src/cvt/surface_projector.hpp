// Nearest points on the input surface, and the surface normal there (CGAL AABB tree).
#pragma once

#include <memory>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector {
 public:
  explicit SurfaceProjector(const TriangleMesh& surface);
  ~SurfaceProjector();
  struct Foot {
    Vec3 point;   // the nearest surface point
    Vec3 normal;  // unit normal of the triangle it lies on
  };
  // Thread-safe after construction.
  Foot nearest(const Vec3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
