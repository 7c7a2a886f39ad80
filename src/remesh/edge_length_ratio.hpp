// How well the output follows the target edge lengths (issue 20): the report's ratios.
#pragma once

#include "cvtmesh/remesh.hpp"
#include "geometry/surface_projector.hpp"
#include "sizing/size_field.hpp"

namespace cvtmesh {

// Per output edge, length / target, the target being the mean of the size field at the surface
// points nearest to the edge's ends (the projector's surface is the field's mesh), or `uniform`
// without a field.
std::vector<double> edge_length_ratios(const TriangleMesh& output,
                                       const SurfaceProjector& projector, const SizeField* field,
                                       double uniform);

// Their 5th, 50th and 95th percentiles.
EdgeLengthRatio ratio_percentiles(std::vector<double> ratios);

}  // namespace cvtmesh
