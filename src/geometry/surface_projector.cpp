#include "geometry/surface_projector.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <optional>

#include "geometry/point_tree.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {
// Plain doubles: a nearest point is a construction, rounded whatever the kernel, and the filtered
// box-sphere tests of an exact-predicates kernel only decide which boxes the search opens, a
// rounding's difference at most (spool.off at 5k: the whole remesh 8% faster).
using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
}  // namespace

struct SurfaceProjector::Tree {
  Triangles triangles;
  std::vector<Vec3> normals;
  std::vector<std::size_t> surface_id;  // per triangle, its id in the surface
  AabbTree tree;
  std::vector<Vec3> centroids;  // of `triangles`: the start of a query with no hint
  std::optional<PointTree> nearest_centroid;

  Foot foot(const AabbTree::Point_and_primitive_id& found) const {
    const auto& [point, triangle] = found;
    const auto index = static_cast<std::size_t>(triangle - triangles.begin());
    return {{point.x(), point.y(), point.z()}, normals[index], index};
  }
};

SurfaceProjector::SurfaceProjector(const TriangleMesh& surface) : tree_(std::make_unique<Tree>()) {
  // Degenerate triangles hold no nearest point that a neighbour does not hold too; they are
  // kept only when nothing else is left, with a zero normal.
  tree_->triangles.reserve(surface.triangles.size());
  tree_->normals.reserve(surface.triangles.size());
  for (const bool keep_degenerate : {false, true}) {
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
      const auto [a, b, c] = surface.corners(t);
      const Vec3 n = cross(b - a, c - a);
      const double length = norm(n);
      if (length == 0 && !keep_degenerate) continue;
      tree_->triangles.emplace_back(Kernel::Point_3(a.x, a.y, a.z), Kernel::Point_3(b.x, b.y, b.z),
                                    Kernel::Point_3(c.x, c.y, c.z));
      tree_->normals.push_back(unit_or_zero(n));
      tree_->surface_id.push_back(t);
    }
    if (!tree_->triangles.empty()) break;
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
  // A query without a hint starts from the nearest triangle centroid: a kd-tree over them is
  // faster to build than CGAL's own (accelerate_distance_queries), as fast to query.
  tree_->tree.do_not_accelerate_distance_queries();
  tree_->centroids.reserve(tree_->triangles.size());
  for (const auto& t : tree_->triangles) {
    const auto c = CGAL::centroid(t);
    tree_->centroids.push_back({c.x(), c.y(), c.z()});
  }
  tree_->nearest_centroid.emplace(tree_->centroids);
}

SurfaceProjector::~SurfaceProjector() = default;

SurfaceProjector::Foot SurfaceProjector::nearest(const Vec3& p) const {
  const Index t = (*tree_->nearest_centroid)(p);
  return nearest(p, {tree_->centroids[t], tree_->normals[t], t});
}

SurfaceProjector::Foot SurfaceProjector::nearest(const Vec3& p, const Foot& hint) const {
  const AabbTree::Point_and_primitive_id start{
      Kernel::Point_3(hint.point.x, hint.point.y, hint.point.z),
      tree_->triangles.begin() + static_cast<std::ptrdiff_t>(hint.triangle)};
  return tree_->foot(
      tree_->tree.closest_point_and_primitive(Kernel::Point_3(p.x, p.y, p.z), start));
}

std::size_t SurfaceProjector::surface_triangle(std::size_t triangle) const {
  return tree_->surface_id[triangle];
}

double SurfaceProjector::squared_distance_to(const Vec3& p, std::size_t triangle) const {
  return CGAL::squared_distance(Kernel::Point_3(p.x, p.y, p.z), tree_->triangles[triangle]);
}

}  // namespace cvtmesh
