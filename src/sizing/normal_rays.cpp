// Rays along the normals, cast in a CGAL AABB tree over the triangles. Poles see thin parts too
// where the vertices sample the surface finely, but not on a part whose triangles are longer than
// it is thick: camel.off's tail, 0.014 thick under input edges of 0.0195, had pole distances up
// to 1.8 times t/2, and its adaptive lengths then spanned it (at 2k, topology control added 31-39
// seeds there; 3-5 with the bound). The outward ray finds gaps between sheets likewise.
#include "sizing/normal_rays.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <limits>

namespace cvtmesh {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& p) {
  return {p.x, p.y, p.z};
}

Vec3 vec(const Kernel::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

void bound_by_normal_rays(const TriangleMesh& mesh, const std::vector<Vec3>& normal,
                          std::vector<double>& lfs) {
  Triangles triangles;
  triangles.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    triangles.emplace_back(point(a), point(b), point(c));
  }
  const Tree tree(triangles.begin(), triangles.end());
  tbb::parallel_for(std::size_t{0}, lfs.size(), [&](std::size_t v) {
    const Vec3& n = normal[v];
    if (!(dot(n, n) > 0)) return;
    const Vec3& p = mesh.vertices[v];
    std::vector<Triangles::const_iterator> crossed;
    for (const double side : {-1.0, 1.0}) {
      // Only a hit nearer than 2·lfs can lower it, so the tree is asked for the triangles that
      // meet the segment of that length (a ray's query visits every box along the ray: on
      // diplodocus at 2k that was a third of the lfs time); the hit points are the ray's.
      const Vec3 end = p + (2 * lfs[v] * side) * n;
      const Kernel::Ray_3 ray(point(p), Kernel::Vector_3(side * n.x, side * n.y, side * n.z));
      crossed.clear();
      tree.all_intersected_primitives(Kernel::Segment_3(point(p), point(end)),
                                      std::back_inserter(crossed));
      // The nearest hit: where the ray runs along a triangle's plane, the nearer end of that
      // stretch (a surface point on the ray bounds the ball all the same).
      double nearest = std::numeric_limits<double>::infinity();
      for (const Triangles::const_iterator it : crossed) {
        const Triangle& f = mesh.triangles[static_cast<std::size_t>(it - triangles.begin())];
        if (f[0] == v || f[1] == v || f[2] == v) continue;  // its own, which every ray touches
        const auto hit = CGAL::intersection(ray, *it);
        if (!hit) continue;
        if (const Kernel::Point_3* q = boost::get<Kernel::Point_3>(&*hit))
          nearest = std::min(nearest, distance(p, vec(*q)));
        else if (const Kernel::Segment_3* e = boost::get<Kernel::Segment_3>(&*hit))
          nearest =
              std::min({nearest, distance(p, vec(e->source())), distance(p, vec(e->target()))});
      }
      // A nearest hit at p itself (a vertex of another sheet at the same place) bounds nothing.
      if (nearest > 0 && nearest < 2 * lfs[v]) lfs[v] = nearest / 2;
    }
  });
}

}  // namespace cvtmesh
