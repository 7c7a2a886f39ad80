// Voronoi neighbours of the seeds, from their 3D Delaunay triangulation (CGAL).
#pragma once

#include <span>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Compressed adjacency: the neighbours of seed s are ids[offsets[s] .. offsets[s+1]), sorted by
// distance to s (nearest first), so that clipping can stop at the first bisector too far away.
struct SeedNeighbors {
  std::vector<std::size_t> offsets;
  std::vector<Index> ids;

  std::span<const Index> of(Index s) const {
    return {ids.data() + offsets[s], ids.data() + offsets[s + 1]};
  }
};

// Throws InvalidArgument for a non-finite seed or for identical seeds (naming the first pair).
SeedNeighbors delaunay_neighbors(const std::vector<Vec3>& seeds);

}  // namespace cvtmesh
