#include "features/curve_projector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/unit_vector.hpp"

namespace cvtmesh {

CurveProjector::CurveProjector(const TriangleMesh& mesh, const Features& features) {
  for (const FeatureCurve& c : features.curves) {
    Polyline p{{}, {0.0}, c.closed};
    for (Index v : c.vertices) p.points.push_back(mesh.vertices[v]);
    if (c.closed) p.points.push_back(p.points.front());
    for (std::size_t k = 1; k < p.points.size(); ++k)
      p.arclength.push_back(p.arclength.back() + distance(p.points[k - 1], p.points[k]));
    curves_.push_back(std::move(p));
  }
}

CurveProjector::Foot CurveProjector::nearest(std::size_t c, const Vec3& p) const {
  const Polyline& line = curves_[c];
  Foot best{line.points.front(), {}, 0};
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
    const Vec3 &a = line.points[k], &b = line.points[k + 1];
    const Vec3 ab = b - a;
    const double length2 = dot(ab, ab);
    if (length2 == 0) continue;
    const double t = std::clamp(dot(p - a, ab) / length2, 0.0, 1.0);
    const Vec3 q = a + t * ab;
    const double d2 = dot(p - q, p - q);
    if (d2 < best_d2) {
      best_d2 = d2;
      const double length = std::sqrt(length2);
      best = {q, (1 / length) * ab, line.arclength[k] + t * length};
    }
  }
  if (!line.closed) {
    // A hair off the corners: far below any edge length, far above rounding.
    const double margin = 1e-6 * line.arclength.back();
    const double s = std::clamp(best.arclength, margin, line.arclength.back() - margin);
    if (s != best.arclength) best = {at(c, s), best.tangent, s};
  }
  return best;
}

std::size_t CurveProjector::segment_at(std::size_t c, double& s) const {
  const Polyline& line = curves_[c];
  const double total = line.arclength.back();
  if (line.closed) s = std::fmod(std::fmod(s, total) + total, total);
  s = std::clamp(s, 0.0, total);
  return std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(line.arclength.begin(), line.arclength.end(), s) -
                               line.arclength.begin()),
      line.points.size() - 1);
}

Vec3 CurveProjector::at(std::size_t c, double s) const {
  const Polyline& line = curves_[c];
  const std::size_t k = segment_at(c, s);
  const double s0 = line.arclength[k - 1], s1 = line.arclength[k];
  const double t = s1 > s0 ? (s - s0) / (s1 - s0) : 0;
  return line.points[k - 1] + t * (line.points[k] - line.points[k - 1]);
}

Vec3 CurveProjector::direction(std::size_t c, double s) const {
  const Polyline& line = curves_[c];
  const std::size_t k = segment_at(c, s);
  return unit_or_zero(line.points[k] - line.points[k - 1]);
}

}  // namespace cvtmesh
