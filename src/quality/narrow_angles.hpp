// Which output vertices stand for the input's narrow angles (issue 18 item 6): the quality
// promise holds the triangles there to their input angle, not to θmin 30° and Q 0.6, and so do
// the output's own last steps.
#pragma once

#include <algorithm>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Per vertex of `mesh`, the narrowest input angle of `narrow` within `radius` of it (degrees), or
// 0 where there is none: a triangle with such a vertex is at that angle.
std::vector<double> narrow_angle_at_vertices(const TriangleMesh& mesh,
                                             const std::vector<NarrowAngle>& narrow, double radius);

// The narrowest input angle at triangle t's vertices (`angle_at`: narrow_angle_at_vertices), or 0
// where none of them is at one.
inline double narrow_angle_at(const Triangle& t, const std::vector<double>& angle_at) {
  double input = 0;
  for (const Index v : t)
    if (angle_at[v] > 0) input = input == 0 ? angle_at[v] : std::min(input, angle_at[v]);
  return input;
}

}  // namespace cvtmesh
