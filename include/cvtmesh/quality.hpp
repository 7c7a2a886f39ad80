// Triangle-quality figures of the paper (§5) and of the usual remeshing comparisons.
#pragma once

#include <cstddef>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Shape of one triangle. Angles in degrees.
struct TriangleShape {
  double quality = 0;    // Q = 6/√3 · A/(p·h): 1 equilateral, 0 degenerate (paper §5)
  double min_angle = 0;  // smallest interior angle
  double max_angle = 0;  // largest interior angle
};

// A triangle with a zero-length edge has Q = 0, smallest angle 0° and largest 180°.
TriangleShape triangle_shape(const Vec3& a, const Vec3& b, const Vec3& c);

struct QualityReport {
  std::size_t triangles = 0;
  double q_min = 0, q_avg = 0;
  double angle_min_deg = 0;       // θmin: the smallest angle of the mesh
  double angle_min_avg_deg = 0;   // θmin_ave: mean over triangles of each one's smallest angle
  double angle_max_deg = 0;       // the largest angle of the mesh
  double pct_angle_below_30 = 0;  // % of triangles whose smallest angle is < 30°
  double edge_length_mean = 0, edge_length_std = 0;  // over distinct undirected edges
};

QualityReport measure_quality(const TriangleMesh& mesh);

// Input angles under this between two feature curves are narrow: no output that traces both
// curves can have a larger angle there (issue 18 item 6).
inline constexpr double kNarrowAngleDeg = 30;

// The quality promise stated as quality meshers state it (Shewchuk's Triangle): over the
// triangles away from the input's narrow angles, and at them, against the input angle.
struct NarrowAngleQuality {
  std::size_t narrow_angles = 0;  // input angles given
  // Triangles with a vertex within half the mean edge length of a narrow angle: at it.
  std::size_t triangles_at = 0;
  double angle_min_away_deg = 0;  // θmin over the others (over all, when none is at one)
  double q_min_away = 0;          // Qmin over the same triangles
  double ratio_at_min = 0;  // over those at one: smallest angle / the input angle; 0 when none
};
// `quality`: measure_quality(mesh), which callers have already.
NarrowAngleQuality measure_away_from(const TriangleMesh& mesh, const QualityReport& quality,
                                     const std::vector<NarrowAngle>& narrow);

}  // namespace cvtmesh
