// Topology wins over sharp features (issue 18): a crease that the output cannot trace without
// losing the input's topology is dropped, and the report says so.
#pragma once

#include "remesh/pipeline.hpp"

namespace cvtmesh {

// remesh_unit; and where its output does not keep the input's topology while it traced sharp
// creases (edges kept for their dihedral angle alone: not boundaries, non-manifold or user
// edges), remesh_unit again without them. The second output is taken only if it keeps the
// topology better: with no triangle removed by the last step, or with its holes closed again
// where the first's topology differs. Its `feature_edges_dropped` lists the creases left out.
// Both runs' work is counted.
UnitRemesh remesh_unit_topology_first(const TriangleMesh& input, const RemeshSettings& settings);

}  // namespace cvtmesh
