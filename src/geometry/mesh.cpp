#include "cvtmesh/mesh.hpp"

#include <algorithm>
#include <limits>

namespace cvtmesh {

BoundingBox bounding_box(const TriangleMesh& mesh) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  BoundingBox box{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const Triangle& t : mesh.triangles) {
    for (Index v : t) {
      const Vec3& p = mesh.vertices[v];
      box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
      box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
  }
  if (mesh.triangles.empty()) box = {};
  return box;
}

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * norm(cross(b - a, c - a));
}

std::vector<bool> used_vertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const Triangle& t : mesh.triangles)
    for (const Index v : t) used[v] = true;
  return used;
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    area += triangle_area(a, b, c);
  }
  return area;
}

}  // namespace cvtmesh
