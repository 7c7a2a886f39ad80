// How well the output follows the target edge lengths (issue 20): the report's ratios.
#pragma once

#include "cvtmesh/remesh.hpp"
#include "geometry/surface_projector.hpp"
#include "sizing/size_field.hpp"

namespace cvtmesh {

// Over the output's edges, the 5th, 50th and 95th percentiles of length / target, the target
// being the mean of the size field at the surface points nearest to the edge's ends (the
// projector's surface is the field's mesh), or `uniform` without a field.
EdgeLengthRatio edge_length_ratio(const TriangleMesh& output, const SurfaceProjector& projector,
                                  const SizeField* field, double uniform);

}  // namespace cvtmesh
