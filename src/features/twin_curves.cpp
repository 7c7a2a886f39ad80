#include "features/twin_curves.hpp"

#include <algorithm>
#include <map>

namespace cvtmesh {

namespace {

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

// The largest distance from a vertex of `from` to the polyline `to`.
double farthest_vertex(const TriangleMesh& mesh, const FeatureCurve& from, const FeatureCurve& to) {
  double farthest = 0;
  for (const Index v : from.vertices) {
    double nearest = distance(mesh.vertices[v], mesh.vertices[to.vertices[0]]);
    for (std::size_t k = 0; k + 1 < to.vertices.size(); ++k)
      nearest =
          std::min(nearest, distance_to_segment(mesh.vertices[v], mesh.vertices[to.vertices[k]],
                                                mesh.vertices[to.vertices[k + 1]]));
    farthest = std::max(farthest, nearest);
  }
  return farthest;
}

double length_of(const TriangleMesh& mesh, const FeatureCurve& c) {
  double length = 0;
  for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
    length += distance(mesh.vertices[c.vertices[k]], mesh.vertices[c.vertices[k + 1]]);
  return length;
}

}  // namespace

std::vector<bool> twin_curves(const TriangleMesh& mesh, const std::vector<FeatureCurve>& curves,
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
        const double la = length_of(mesh, curves[a]), lb = length_of(mesh, curves[b]);
        // a goes for b: b stays (not droppable, or shorter, or as long and earlier).
        const bool b_stays = !droppable[b] || lb < la || (lb == la && b < a);
        if (b_stays && farthest_vertex(mesh, curves[a], curves[b]) < 0.5 * scale &&
            farthest_vertex(mesh, curves[b], curves[a]) < 0.5 * scale)
          twin[a] = true;
      }
  return twin;
}

}  // namespace cvtmesh
