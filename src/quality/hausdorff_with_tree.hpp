// The Hausdorff distance of cvtmesh/hausdorff.hpp, for a caller that already holds an AABB tree
// of the reference (the remesher does): building it again costs as much as the measurement.
#pragma once

#include "cvtmesh/hausdorff.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

// `to_b` must have been built from `b`, or from the same triangles in another order.
HausdorffReport hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                   const SurfaceProjector& to_b, const HausdorffSettings& settings);

}  // namespace cvtmesh
