// Triangle-quality figures of the paper (§5) and of the usual remeshing comparisons.
#pragma once

#include <cstddef>

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

}  // namespace cvtmesh
