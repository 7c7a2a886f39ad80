// After the last step (make_manifold) removed triangles at the defects topology control could
// not mend, the holes it opened are closed again where that gives back the input's topology: the
// local re-triangulation issue 18 names beside refinement. It matters where refinement cannot
// converge, as where an input crosses itself: every seed near the crossing line owns a sliver of
// the other sheet, at every spacing, so inserting seeds there only makes smaller defects
// (man.off's interpenetrating fingers).
#pragma once

#include <cstddef>
#include <span>

#include "cvtmesh/mesh.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh {

struct ClosedHoles {
  std::size_t holes = 0, triangles = 0;
};

// A hole here is a boundary loop of `mesh` all of whose edges were shared with a triangle of
// `removed`. Each is triangulated on its own vertices, no vertex added (CGAL's hole filling:
// Liepa's minimum of the largest dihedral angle, then of the area, with the removed
// neighbours' dihedrals counted). The triangles are kept only when every hole is closed and the
// result is a manifold (oriented when `oriented`) with the topology of `input`; otherwise `mesh`
// is left as it was and nothing is reported.
ClosedHoles close_opened_holes(TriangleMesh& mesh, std::span<const Triangle> removed,
                               const TopologyReport& input, bool oriented);

}  // namespace cvtmesh
