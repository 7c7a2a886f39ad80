// Groups of points that lie within a tolerance of one another: the copies of one vertex that a
// CAD exporter wrote with different rounding (issue 18: an STL whose coordinates differ by 1e-16
// where they should be equal has cracks along its edges, boundary loops the part never had).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// The tolerance under which two vertices of `points` count as one: 1e-12 of the larger of the
// bounding box's diagonal and the largest coordinate's magnitude (a part far from the origin
// carries the rounding of its coordinates' size). Real geometry is many orders above it, the
// rounding of coordinates computed in double a few orders below.
double near_point_tolerance(const std::vector<Vec3>& points);

// Per point, the least index of its group: points closer than `tolerance` are in one group, and
// groups are closed under that (a chain of near points is one group). Exactly equal points are
// always grouped, also with a tolerance of 0. Deterministic; linear in the points after a sort.
std::vector<Index> near_point_groups(const std::vector<Vec3>& points, double tolerance);

}  // namespace cvtmesh
