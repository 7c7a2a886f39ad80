// The sectors of the surface between feature edges at a vertex, for the rules that ask how
// narrow a wedge between two curves (or a curve and a boundary) really is.
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// At `apex`, the triangles walked round from feature neighbour `from` to the next feature
// neighbour `to`, and the sum of their angles at `apex`: the wedge no output that traces both
// edges can fill with a wider angle. The 3D angle between the two edges is never larger.
struct FeatureSector {
  Index apex, from, to;
  double angle_deg;
};

// Every such sector, both ways round each feature edge, at every vertex with two feature edges
// or more; none for a walk that meets no other feature edge (an open fan's end).
std::vector<FeatureSector> feature_sectors(const TriangleMesh& mesh, const Features& features);

}  // namespace cvtmesh
