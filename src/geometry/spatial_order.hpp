// Orders of points along a Morton (Z-order) curve: points near in the order are near in space,
// so a walk or a search that starts from the previous answer stays short.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Indices of `points` in Morton order of their bounding cube (21 bits per axis), ties broken by
// the coordinates, then the index: the same set of distinct points gives the same order
// whatever order it comes in.
std::vector<Index> spatial_order(const std::vector<Vec3>& points);

}  // namespace cvtmesh
