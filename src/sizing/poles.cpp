#include "sizing/poles.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <tbb/parallel_for.h>

#include <array>
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
  // The cells' circumcentres and the samples' poles are computed in parallel, each into its own
  // slot, and gathered in the triangulation's order: the same poles on any thread count.
  std::vector<Delaunay::Cell_handle> finite_cells;
  for (auto c = delaunay.finite_cells_begin(); c != delaunay.finite_cells_end(); ++c) {
    c->info() = finite_cells.size();
    finite_cells.push_back(c);
  }
  std::vector<Vec3> centres(finite_cells.size());
  tbb::parallel_for(std::size_t{0}, finite_cells.size(),
                    [&](std::size_t k) { centres[k] = circumcentre(finite_cells[k]); });
  Vec3 centroid;
  for (const SurfaceSample& s : samples) centroid += s.point;
  centroid = (1.0 / static_cast<double>(samples.size())) * centroid;

  // Per sample, the farthest Voronoi vertex (circumcentre of an incident cell) on each side.
  // The cells around each vertex are listed first, serially: CGAL's incident_cells marks the
  // cells it visits, so concurrent calls would see each other's marks.
  std::vector<Delaunay::Vertex_handle> vertices;
  std::vector<std::size_t> slot(samples.size());
  for (auto v = delaunay.finite_vertices_begin(); v != delaunay.finite_vertices_end(); ++v) {
    slot[v->info()] = vertices.size();
    vertices.push_back(v);
  }
  std::vector<std::size_t> first(vertices.size() + 1, 0);
  std::vector<char> on_hull(vertices.size(), 0);
  for (auto c = delaunay.all_cells_begin(); c != delaunay.all_cells_end(); ++c)
    for (int i = 0; i < 4; ++i) {
      if (delaunay.is_infinite(c->vertex(i))) continue;
      const std::size_t k = slot[c->vertex(i)->info()];
      if (delaunay.is_infinite(c))
        on_hull[k] = 1;
      else
        ++first[k + 1];
    }
  for (std::size_t k = 0; k < vertices.size(); ++k) first[k + 1] += first[k];
  std::vector<std::size_t> around(first.back()), next(first.begin(), first.end() - 1);
  for (const Delaunay::Cell_handle& c : finite_cells)
    for (int i = 0; i < 4; ++i) around[next[slot[c->vertex(i)->info()]]++] = c->info();

  std::vector<std::array<Vec3, 2>> at(vertices.size());
  std::vector<std::array<bool, 2>> found(vertices.size(), {false, false});
  tbb::parallel_for(std::size_t{0}, vertices.size(), [&](std::size_t k) {
    const SurfaceSample& s = samples[vertices[k]->info()];
    double far[2] = {0, 0};  // squared distances, along +normal and -normal
    for (std::size_t i = first[k]; i < first[k + 1]; ++i) {
      const Vec3 d = centres[around[i]] - s.point;
      const int side = dot(d, s.normal) < 0;
      const double d2 = dot(d, d);
      if (d2 > far[side]) far[side] = d2, at[k][side] = centres[around[i]];
    }
    // The hull is convex: from a point on it, its inside (the samples' centroid) lies opposite
    // the outer side, whose pole is at infinity.
    const int outer = on_hull[k] ? dot(s.point - centroid, s.normal) < 0 : -1;
    for (int side = 0; side < 2; ++side) found[k][side] = far[side] > 0 && side != outer;
  });
  std::vector<Vec3> pole;
  for (std::size_t k = 0; k < vertices.size(); ++k)
    for (int side = 0; side < 2; ++side)
      if (found[k][side]) pole.push_back(at[k][side]);
  return pole;
}

}  // namespace cvtmesh
