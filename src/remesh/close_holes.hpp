// After the last step (make_manifold) removed triangles at the defects topology control could
// not mend, the holes it opened are closed again where that gives back the input's topology: the
// local re-triangulation issue 18 names beside refinement. It matters where refinement cannot
// converge, as where an input crosses itself: every seed near the crossing line owns a sliver of
// the other sheet, at every spacing, so inserting seeds there only makes smaller defects
// (man.off's interpenetrating fingers).
#pragma once

#include <cstddef>
#include <functional>
#include <span>

#include "cvtmesh/mesh.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh {

struct ClosedHoles {
  std::size_t holes = 0, triangles = 0;
  std::size_t vertices = 0;        // added at the centres of holes closed by a fan
  std::size_t lone_triangles = 0;  // of a closed input's output, removed (see below)
};

// A hole here is a boundary loop of `mesh` all of whose edges were shared with a triangle of
// `removed`; for a closed `input`, any boundary loop. Each is triangulated on its own vertices
// (CGAL's hole filling: Liepa's minimum of the largest dihedral angle, then of the area, with the
// kept neighbours' dihedrals counted), or, where that would use an edge the mesh has already, by
// a fan around a new vertex at `onto_surface` of the loop's centroid. The triangles are kept when
// every hole is closed and the result is a manifold (oriented when `oriented`) with the topology
// of `input`. Otherwise, for a closed input, each hole whose patch leaves a manifold is closed,
// whatever the topology then (the output of a closed input is closed), and a lone triangle, which
// only its own copy would close, is removed; for an open one, `mesh` is left as it was and
// nothing is reported.
ClosedHoles close_opened_holes(TriangleMesh& mesh, std::span<const Triangle> removed,
                               const TopologyReport& input, bool oriented,
                               const std::function<Vec3(const Vec3&)>& onto_surface);

}  // namespace cvtmesh
