// Nearest points on the input surface, and the surface normal there (CGAL AABB tree).
#pragma once

#include <memory>
#include <optional>
#include <span>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SurfaceProjector {
 public:
  // `surface` must have at least one triangle.
  explicit SurfaceProjector(const TriangleMesh& surface);
  ~SurfaceProjector();
  struct Foot {
    Vec3 point;            // the nearest surface point
    Vec3 normal;           // unit normal of the triangle it lies on
    std::size_t triangle;  // that triangle, as numbered inside the projector
  };
  // Thread-safe after construction.
  Foot nearest(const Vec3& p) const;
  // The same, starting the search from a foot found earlier for a point nearby (much faster
  // when the point has moved little, as seeds do between CVT iterations).
  Foot nearest(const Vec3& p, const Foot& hint) const;
  // A triangle (as numbered inside the projector) within reach of p, with p's squared distance
  // to it, if there is one: where the reach is small, far cheaper than `nearest`, as it opens
  // only the boxes within reach and stops at the first such triangle. Given the same reach,
  // there is one exactly where nearest(p) is within reach (up to rounding).
  struct Near {
    double squared;
    std::size_t triangle;
  };
  std::optional<Near> within(const Vec3& p, double squared_reach) const;
  // The same, asking triangle `hint` first (as numbered inside the projector): no search where
  // it is within reach, as a triangle found for a point nearby often is.
  std::optional<Near> within(const Vec3& p, double squared_reach, std::size_t hint) const;
  // The distance from p to the surface.
  double distance_to(const Vec3& p) const { return distance(p, nearest(p).point); }
  // The squared distance from p to one triangle (as numbered inside the projector): an upper
  // bound on the squared distance to the surface, far cheaper than a search.
  double squared_distance_to(const Vec3& p, std::size_t triangle) const;
  // The signed distance t, |t| <= reach, of the surface point p + t·direction nearest to p along
  // the line (direction a unit vector), if the line meets the surface within reach of p; none
  // for a zero direction or a reach that is not positive and finite. Given `facing`, only the
  // triangles whose normal makes less than 90° with it count.
  std::optional<double> along(const Vec3& p, const Vec3& direction, double reach,
                              const Vec3& facing = {}) const;
  // A triangle's id in the surface given, from its id inside the projector.
  std::size_t surface_triangle(std::size_t triangle) const;
  // Each triangle's unit normal, by its id in the surface given, where the projector holds every
  // triangle of it (none without area); empty otherwise. The same as cvtmesh::unit_normals of the
  // surface, bit for bit: a caller that integrates over the surface can share them.
  std::span<const Vec3> unit_normals() const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
