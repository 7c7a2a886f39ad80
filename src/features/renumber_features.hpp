// Features of a mesh, expressed in the vertex ids of a renumbered copy of it (the remesher works
// on the spatially sorted input, and reports features in the caller's ids).
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// `new_id[v]`: the id in the copy of vertex v. Edges and corners come out sorted; curves keep
// their order and direction.
Features renumbered(const Features& features, const std::vector<Index>& new_id);

}  // namespace cvtmesh
