// Where the finishing steps make the output pass through itself: their flips and moves, each
// judged by the triangles it touches, can fold a triangle through another where the surface
// turns sharply within a ring (spool.off at 5k, beside a concave crease: 4 crossing triangles
// after the sweeps, 8 after the fit, from an extraction with none). There the steps are run
// again with the extraction's vertices around the crossings guarded (VertexSupport::guarded):
// each flip, move or collapse there is checked for crossings, and no other step moves them.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <vector>

#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

class InputCrossings;

// The finishing steps on `result` (its mesh the extraction), with the vertices at the points
// given guarded.
using FinishSteps = std::function<void(RemeshResult&, const std::set<Vec3>&)>;

// Runs `finish` on `result`; then, where its output has crossing triangles of its own (away from
// where `input` crosses itself, if it does: crossings_of_its_own) away from the crossings of its
// own that the extraction it started from had, up to `attempts` times, runs it again on the
// extraction with the vertices around them guarded (points_near_crossings, `reach` times the
// attempt's number; an attempt whose guard adds no vertex is passed over), each run kept where
// it leaves fewer such and no more of its own in all (one that does not is passed over for the
// next, wider one). Where some of those left are at the extraction's own crossings, the same again
// around all of them (unless each is a triangle of the extraction, left as it was), kept where
// that leaves fewer of its own in all, the attempts stopping at one that does not. Not where the
// extraction does not keep the topology of the input (keeps_topology against
// `result.input_topology`): that output is no valid one however it is finished
// (remesh/topology_first tries again), and each attempt costs a run of the steps. Sets
// `result.output_crossing_triangles` and `result.vertices_guarded`. Where a guarded run was kept
// and crossings are left, returns the first, unguarded output: a mend that comes after (halving
// chords through thin walls, finish/split_crossings) may do better on it (couplingdown.off at
// 100: a wide guard leaves 7 crossing triangles that no halving mends, and the halving mends all
// 10 of the unguarded output's).
std::optional<RemeshResult> finish_uncrossed(RemeshResult& result, InputCrossings& input,
                                             const FinishSteps& finish, int attempts, double reach);

// The vertices of `unfinished` (the extraction the finishing steps started from) within `reach`
// times the longest edge of a `crossing` triangle of `finished` of its centroid, by position:
// those to guard.
std::set<Vec3> points_near_crossings(const TriangleMesh& unfinished, const TriangleMesh& finished,
                                     const std::vector<Triangle>& crossing, double reach);

}  // namespace cvtmesh
