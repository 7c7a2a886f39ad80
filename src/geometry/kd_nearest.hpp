// The nearest-point query on a nanoflann kd-tree with 32-bit ids, which PointTree and the surface
// projector's tree of triangle centroids share. Included by their .cpp files only: nanoflann stays
// out of the headers that much of the project includes.
#pragma once

#include <nanoflann.hpp>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// The id of the point of `tree` nearest to p (a nanoflann KDTreeSingleIndexAdaptor over Index).
template <class KdTree>
Index nearest_id(const KdTree& tree, const Vec3& p) {
  Index id = 0;
  double d2 = 0;
  nanoflann::KNNResultSet<double, Index> result(1);
  result.init(&id, &d2);
  const double query[3] = {p.x, p.y, p.z};
  tree.findNeighbors(result, query, nanoflann::SearchParams());
  return id;
}

}  // namespace cvtmesh
