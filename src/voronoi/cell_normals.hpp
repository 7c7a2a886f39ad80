// Each restricted Voronoi cell's centroid and mean normal, for where the output's vertex of a seed
// goes on the surface (finish/cell_normal_points).
#pragma once

#include <vector>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

struct CellNormal {
  Vec3 centroid;  // of the cell's area; the seed where the cell is empty
  Vec3 normal;    // the unit mean of the surface's normal over the cell; zero where none
};

// The cells of `seeds` on `surface`, replaying from `memory` what its last traversal left
// unchanged (after an extraction of the same seeds, all of it). The same values on any thread
// count.
std::vector<CellNormal> cell_normals(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                                     TraversalMemory& memory);

}  // namespace cvtmesh
