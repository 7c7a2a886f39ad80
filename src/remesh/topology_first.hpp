// Topology wins over sharp features and over even sizes (issue 18): a crease that the output
// cannot trace without losing the input's topology is dropped, even edge lengths that cannot
// resolve its thin parts give way to adaptive ones, and the report says so.
#pragma once

#include "remesh/pipeline.hpp"

namespace cvtmesh {

// remesh_unit; and where its output does not keep the input's topology while it traced sharp
// creases (edges kept for their dihedral angle alone: not boundaries, non-manifold or user
// edges), remesh_unit again without them. The second output is taken only if it keeps the
// topology better: with no triangle removed by the last step, or with its holes closed again
// where the first's topology differs. Its `feature_edges_dropped` lists the creases left out.
// Where the output kept still has another topology than the input's and its sizes were even
// (no sizing, no seeds given), remesh_unit again with adaptive sizes at the same count, taken
// on the same terms (`sizes_adapted`). All runs' work is counted.
UnitRemesh remesh_unit_topology_first(const TriangleMesh& input, const RemeshSettings& settings);

}  // namespace cvtmesh
