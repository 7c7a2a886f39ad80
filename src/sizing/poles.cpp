#include "sizing/poles.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <utility>

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::size_t, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<std::size_t, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay =
    CGAL::Delaunay_triangulation_3<Kernel,
                                   CGAL::Triangulation_data_structure_3<VertexBase, CellBase>>;

Vec3 vec(const Kernel::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}

// A cell's circumcentre. Rounded arithmetic puts that of a sliver (four nearly coplanar points,
// as on a finely tessellated sphere, whose points are all cospherical) anywhere: when the four
// distances from the rounded centre disagree, it is constructed exactly.
Vec3 circumcentre(const Delaunay::Cell_handle& c) {
  const Vec3 centre = vec(CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                                             c->vertex(2)->point(), c->vertex(3)->point()));
  double lo = INFINITY, hi = 0;
  for (int i = 0; i < 4; ++i) {
    const double d = distance(centre, vec(c->vertex(i)->point()));
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  if (std::isfinite(hi) && hi - lo <= 1e-9 * hi) return centre;
  ExactKernel::Point_3 p[4];
  for (int i = 0; i < 4; ++i) {
    const Kernel::Point_3& q = c->vertex(i)->point();
    p[i] = ExactKernel::Point_3(q.x(), q.y(), q.z());
  }
  const ExactKernel::Point_3 exact = CGAL::circumcenter(p[0], p[1], p[2], p[3]);
  return {CGAL::to_double(exact.x()), CGAL::to_double(exact.y()), CGAL::to_double(exact.z())};
}

}  // namespace

std::vector<Vec3> sample_poles(const std::vector<SurfaceSample>& samples) {
  std::vector<std::pair<Kernel::Point_3, std::size_t>> points;
  points.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3& p = samples[i].point;
    points.emplace_back(Kernel::Point_3(p.x, p.y, p.z), i);
  }
  Delaunay delaunay(points.begin(), points.end());  // spatially sorted inside
  if (delaunay.dimension() < 3) return {};          // coplanar samples: no Voronoi vertex at all
  std::vector<Vec3> centres;
  for (auto c = delaunay.finite_cells_begin(); c != delaunay.finite_cells_end(); ++c) {
    c->info() = centres.size();
    centres.push_back(circumcentre(c));
  }
  Vec3 centroid;
  for (const SurfaceSample& s : samples) centroid += s.point;
  centroid = (1.0 / static_cast<double>(samples.size())) * centroid;

  // Per sample, the farthest Voronoi vertex (circumcentre of an incident cell) on each side.
  std::vector<Vec3> pole;
  std::vector<Delaunay::Cell_handle> cells;
  for (auto v = delaunay.finite_vertices_begin(); v != delaunay.finite_vertices_end(); ++v) {
    const SurfaceSample& s = samples[v->info()];
    cells.clear();
    delaunay.incident_cells(v, std::back_inserter(cells));
    double far[2] = {0, 0};  // squared distances, along +normal and -normal
    Vec3 at[2];
    bool on_hull = false;
    for (const Delaunay::Cell_handle& c : cells) {
      if (delaunay.is_infinite(c)) {
        on_hull = true;
        continue;
      }
      const Vec3 d = centres[c->info()] - s.point;
      const int side = dot(d, s.normal) < 0;
      const double d2 = dot(d, d);
      if (d2 > far[side]) far[side] = d2, at[side] = centres[c->info()];
    }
    // The hull is convex: from a point on it, its inside (the samples' centroid) lies opposite
    // the outer side, whose pole is at infinity.
    const int outer = on_hull ? dot(s.point - centroid, s.normal) < 0 : -1;
    for (int side = 0; side < 2; ++side)
      if (far[side] > 0 && side != outer) pole.push_back(at[side]);
  }
  return pole;
}

}  // namespace cvtmesh
