#include "features/twin_curves.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "features/edge_uses.hpp"

namespace cvtmesh {

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Segment = CGAL::Exact_predicates_inexact_constructions_kernel::Segment_3;

Point point(const Vec3& p) {
  return {p.x, p.y, p.z};
}

// The largest distance from a vertex of `from` to the polyline `to`.
double farthest_vertex(const TriangleMesh& mesh, const FeatureCurve& from, const FeatureCurve& to) {
  double farthest2 = 0;
  for (const Index v : from.vertices) {
    const Point p = point(mesh.vertices[v]);
    double nearest2 = CGAL::squared_distance(p, point(mesh.vertices[to.vertices[0]]));
    for (std::size_t k = 0; k + 1 < to.vertices.size(); ++k)
      nearest2 = std::min(
          nearest2, CGAL::squared_distance(p, Segment(point(mesh.vertices[to.vertices[k]]),
                                                      point(mesh.vertices[to.vertices[k + 1]]))));
    farthest2 = std::max(farthest2, nearest2);
  }
  return std::sqrt(farthest2);
}

}  // namespace

std::vector<bool> twin_curves(const TriangleMesh& mesh, const std::vector<FeatureCurve>& curves,
                              const std::vector<double>& lengths,
                              const std::vector<bool>& droppable, double scale) {
  std::map<Edge, std::vector<std::size_t>> by_ends;  // open curves by their two end corners
  for (std::size_t c = 0; c < curves.size(); ++c)
    if (!curves[c].closed)
      by_ends[edge_of(curves[c].vertices.front(), curves[c].vertices.back())].push_back(c);
  std::vector<bool> twin(curves.size(), false);
  for (const auto& [ends, group] : by_ends)
    for (const std::size_t a : group)
      for (const std::size_t b : group) {
        if (a == b || !droppable[a] || twin[b]) continue;
        // a goes for b: b stays (not droppable, or shorter, or as long and earlier).
        const bool b_stays =
            !droppable[b] || lengths[b] < lengths[a] || (lengths[b] == lengths[a] && b < a);
        if (b_stays && farthest_vertex(mesh, curves[a], curves[b]) < 0.5 * scale &&
            farthest_vertex(mesh, curves[b], curves[a]) < 0.5 * scale)
          twin[a] = true;
      }
  return twin;
}

}  // namespace cvtmesh
