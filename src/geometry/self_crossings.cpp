#include "geometry/self_crossings.hpp"

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

Kernel::Point_3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// Whether triangles `a` and `b` intersect other than at the vertices they share: none shared, by
// the exact triangle test; one, whether the edge of either opposite it meets the other; two or
// three (an edge, a duplicate), never.
bool cross(const TriangleMesh& mesh, const Triangle& a, const Triangle& b) {
  const auto tri = [&](const Triangle& t) {
    return Kernel::Triangle_3(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]),
                              point(mesh.vertices[t[2]]));
  };
  int shared = 0;
  Index common = 0;
  for (const Index u : a)
    if (std::find(b.begin(), b.end(), u) != b.end()) {
      ++shared;
      common = u;
    }
  if (shared >= 2) return false;
  if (shared == 0) return CGAL::do_intersect(tri(a), tri(b));
  const auto opposite = [&](const Triangle& t) {
    std::array<Index, 2> e{};
    int k = 0;
    for (const Index u : t)
      if (u != common) e[k++] = u;
    return Kernel::Segment_3(point(mesh.vertices[e[0]]), point(mesh.vertices[e[1]]));
  };
  return CGAL::do_intersect(opposite(a), tri(b)) || CGAL::do_intersect(opposite(b), tri(a));
}

}  // namespace

std::vector<bool> self_crossing_triangles(const TriangleMesh& mesh) {
  std::vector<Box> boxes;
  boxes.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    boxes.emplace_back(CGAL::Bbox_3(std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}),
                                    std::min({a.z, b.z, c.z}), std::max({a.x, b.x, c.x}),
                                    std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})),
                       t);
  }
  std::vector<bool> crossing(mesh.triangles.size(), false);
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
      boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
        const std::size_t s = p.info(), t = q.info();
        if ((crossing[s] && crossing[t]) || !cross(mesh, mesh.triangles[s], mesh.triangles[t]))
          return;
        crossing[s] = crossing[t] = true;
      });
  return crossing;
}

std::unique_ptr<SurfaceProjector> crossing_surface(const TriangleMesh& mesh,
                                                   const std::vector<bool>& crossing) {
  TriangleMesh part{mesh.vertices, {}};
  for (std::size_t t = 0; t < crossing.size(); ++t)
    if (crossing[t]) part.triangles.push_back(mesh.triangles[t]);
  if (part.triangles.empty()) return nullptr;
  return std::make_unique<SurfaceProjector>(part);
}

}  // namespace cvtmesh
