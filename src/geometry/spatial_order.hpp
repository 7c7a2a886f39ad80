// An order of points along a Hilbert curve (CGAL's hilbert_sort, median policy): points near in
// the order are near in space. Queries run in this order can start each search from the previous
// answer; it is deterministic (no shuffling).
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Indices of `points`, in Hilbert order.
std::vector<Index> spatial_order(const std::vector<Vec3>& points);

}  // namespace cvtmesh
