// A triangle's Q and smallest angle alone: triangle_shape without the largest angle, so one
// arctangent rather than two, for the output's last steps, which judge shapes by the million
// (on corpus/femur.off at 1k, arctangents were a tenth of the run).
#pragma once

#include <optional>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct MinShape {
  double quality = 0;    // as TriangleShape::quality
  double min_angle = 0;  // as TriangleShape::min_angle, in degrees
};

MinShape min_shape(const Vec3& a, const Vec3& b, const Vec3& c);

// min_shape where Q is above `quality_bar`; nothing where it is not, found before the arctangent
// (the costly part): a search for a better place rejects many by Q alone.
std::optional<MinShape> min_shape_if_above(const Vec3& a, const Vec3& b, const Vec3& c,
                                           double quality_bar);

}  // namespace cvtmesh
