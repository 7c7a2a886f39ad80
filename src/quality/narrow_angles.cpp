// The quality promise as quality meshers state it (Shewchuk's Triangle; Cheng, Dey and
// Shewchuk): bounds hold away from the input's narrow angles, and at one, relative to it.
#include <algorithm>
#include <limits>

#include "cvtmesh/quality.hpp"
#include "geometry/point_tree.hpp"
#include "quality/narrow_angles.hpp"

namespace cvtmesh {

std::vector<double> narrow_angle_at_vertices(const TriangleMesh& mesh,
                                             const std::vector<NarrowAngle>& narrow,
                                             double radius) {
  std::vector<double> angle_at(mesh.vertices.size(), 0);
  if (narrow.empty() || mesh.vertices.empty()) return angle_at;
  const PointTree tree(mesh.vertices);
  std::vector<Index> near;
  for (const NarrowAngle& a : narrow) {
    tree.within(a.at, radius * radius, near);
    for (Index v : near)
      angle_at[v] = angle_at[v] == 0 ? a.angle_deg : std::min(angle_at[v], a.angle_deg);
  }
  return angle_at;
}

NarrowAngleQuality measure_away_from(const TriangleMesh& mesh, const QualityReport& quality,
                                     const std::vector<NarrowAngle>& narrow) {
  NarrowAngleQuality out;
  out.narrow_angles = narrow.size();
  out.angle_min_away_deg = quality.angle_min_deg;
  out.q_min_away = quality.q_min;
  if (narrow.empty() || mesh.triangles.empty()) return out;
  // A vertex within half an edge of a narrow angle stands for it: exactly there in an output
  // that keeps its corners, the nearest vertex in one that does not.
  const std::vector<double> angle_at =
      narrow_angle_at_vertices(mesh, narrow, 0.5 * quality.edge_length_mean);
  double away = 180, q_away = 1, ratio = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles) {
    const TriangleShape shape =
        triangle_shape(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    const double theta = shape.min_angle;
    const double input = narrow_angle_at(t, angle_at);
    if (input == 0) {
      away = std::min(away, theta);
      q_away = std::min(q_away, shape.quality);
    } else {
      ++out.triangles_at;
      ratio = std::min(ratio, theta / input);
    }
  }
  out.angle_min_away_deg = away;
  out.q_min_away = q_away;
  out.ratio_at_min = out.triangles_at > 0 ? ratio : 0;
  return out;
}

}  // namespace cvtmesh
