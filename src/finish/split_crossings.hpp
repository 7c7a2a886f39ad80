// Where the output still passes through itself once the finishing steps are done, and guarding
// them (finish/crossing_guard) did not help: beside a wall thinner than the spacing, the
// triangles on each side are chords that sag through the other side (couplingdown.off at 100
// vertices: walls about 0.02 thick between its holes, edges 0.15 long, 10 triangles crossing).
// Halving the long edges there, each middle put back on its own side of the wall, shortens the
// chords until none reaches through; the shape sweeps then even out the triangles around, each of
// their changes checked for crossings. Where the triangles that cross span the wall instead (a
// plate thinner than the spacing, whose cells hold both its sides), halving does not help, and
// the output stays as it was.
#pragma once

#include <cstddef>

#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

class InputCrossings;
class SurfaceProjector;

// In up to `rounds` rounds on `result.mesh`: each halves, for every triangle that crosses another
// away from where the input crosses itself (crossings_of_its_own against `input`), its longest
// edge of two triangles, used in opposite directions, that is no feature edge of
// `result.feature_edges`, where the line through its middle along the two triangles' mean normal
// meets a sheet of `surface` facing their way within half the edge's length: that point becomes
// the new vertex, and the two triangles four. The rounds stop once none crosses, or after three
// rounds without fewer. The round with the fewest, swept around its new vertices (improve_shapes,
// guarded; kept where that leaves no more crossing), replaces the output where it has fewer than
// the output had: then `result.output_crossing_triangles` is updated and the vertices added
// returned (else 0). The topology does not change: a halving subdivides two triangles, the
// sweeps keep it. Sequential, in a fixed order.
std::size_t split_crossings(RemeshResult& result, const SurfaceProjector& surface,
                            InputCrossings& input, int rounds);

}  // namespace cvtmesh
