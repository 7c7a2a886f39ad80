#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cvtmesh/quality.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

namespace {

// What both shape functions measure: the edge lengths, twice the area and Q. One cross product
// for the area and all the angles (its norm is twice the area at every corner).
struct Measured {
  double la, lb, lc, twice_area, quality;
};

bool has_zero_edge(const Measured& m) {
  return m.la == 0 || m.lb == 0 || m.lc == 0;
}

Measured measured(const Vec3& a, const Vec3& b, const Vec3& c) {
  Measured m{distance(b, c), distance(c, a), distance(a, b), 0, 0};
  if (has_zero_edge(m)) return m;
  m.twice_area = norm(cross(b - a, c - a));
  const double half_perimeter = 0.5 * (m.la + m.lb + m.lc);
  // Paper §5: Q_t = 6/√3 · A/(p·h).
  m.quality = 3.0 / std::sqrt(3.0) * m.twice_area / (half_perimeter * std::max({m.la, m.lb, m.lc}));
  return m;
}

// The angle in degrees at the corner facing the edge of length l, one of m's. Measured only at
// the corners facing the shortest and the longest edge, where the smallest and the largest
// angle are: shape improvement measures shapes by the million.
double angle_facing(const Measured& m, double l, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto angle_at = [&](const Vec3& p, const Vec3& u, const Vec3& v) {
    return 180 / std::numbers::pi * std::atan2(m.twice_area, dot(u - p, v - p));
  };
  return l == m.la ? angle_at(a, b, c) : l == m.lb ? angle_at(b, c, a) : angle_at(c, a, b);
}

}  // namespace

TriangleShape triangle_shape(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Measured m = measured(a, b, c);
  if (has_zero_edge(m)) return {0, 0, 180};
  return {m.quality, angle_facing(m, std::min({m.la, m.lb, m.lc}), a, b, c),
          angle_facing(m, std::max({m.la, m.lb, m.lc}), a, b, c)};
}

MinShape min_shape(const Vec3& a, const Vec3& b, const Vec3& c) {
  return *min_shape_if_above(a, b, c, -std::numeric_limits<double>::infinity());
}

std::optional<MinShape> min_shape_if_above(const Vec3& a, const Vec3& b, const Vec3& c,
                                           double quality_bar) {
  const Measured m = measured(a, b, c);
  if (has_zero_edge(m)) return quality_bar < 0 ? std::optional(MinShape{0, 0}) : std::nullopt;
  if (m.quality <= quality_bar) return std::nullopt;
  return MinShape{m.quality, angle_facing(m, std::min({m.la, m.lb, m.lc}), a, b, c)};
}

QualityReport measure_quality(const TriangleMesh& given) {
  // Measured at about unit size, exactly scaled (issue 22): the areas of a mesh in nanometres
  // would underflow. Shapes do not depend on the scale; edge lengths are scaled back.
  const int exponent = size_exponent(given);
  TriangleMesh unit;
  if (exponent != 0) unit = scaled_by_power_of_two(given, -exponent);
  const TriangleMesh& mesh = exponent != 0 ? unit : given;
  QualityReport r;
  r.triangles = mesh.triangles.size();
  if (r.triangles == 0) return r;
  r.q_min = r.angle_min_deg = std::numeric_limits<double>::infinity();
  double q_sum = 0, min_angle_sum = 0;
  std::size_t below_30 = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const TriangleShape s = triangle_shape(a, b, c);
    r.q_min = std::min(r.q_min, s.quality);
    r.angle_min_deg = std::min(r.angle_min_deg, s.min_angle);
    r.angle_max_deg = std::max(r.angle_max_deg, s.max_angle);
    q_sum += s.quality;
    min_angle_sum += s.min_angle;
    if (s.min_angle < 30) ++below_30;
  }
  const double n = static_cast<double>(r.triangles);
  r.q_avg = q_sum / n;
  r.angle_min_avg_deg = min_angle_sum / n;
  r.pct_angle_below_30 = 100.0 * static_cast<double>(below_30) / n;

  // Distinct undirected edges, each counted once however many triangles share it.
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& f : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(f[k], f[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  double sum = 0;
  for (const auto& [u, v] : edges)
    sum += lengths.emplace_back(distance(mesh.vertices[u], mesh.vertices[v]));
  r.edge_length_mean = sum / static_cast<double>(lengths.size());
  // Population standard deviation, two-pass to avoid cancellation on near-uniform meshes.
  double sum_sq = 0;
  for (double l : lengths) sum_sq += (l - r.edge_length_mean) * (l - r.edge_length_mean);
  r.edge_length_std = std::sqrt(sum_sq / static_cast<double>(lengths.size()));
  r.edge_length_mean = std::ldexp(r.edge_length_mean, exponent);
  r.edge_length_std = std::ldexp(r.edge_length_std, exponent);
  return r;
}

}  // namespace cvtmesh
