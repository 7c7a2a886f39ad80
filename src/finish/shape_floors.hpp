// How far the finishing steps that move many vertices at once (finish/fit_surface,
// finish/cell_normal_points) may take each triangle: the floors their undo_moves_unless keeps.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

// Per triangle, the shape a move may not take it below: its own, where that is under the aim of
// the sweeps (finish/move_limits.hpp) or under the mesh's worst, else the higher of those two.
// θmin and Qmin never fall, nor does a triangle under the aim get worse. Held to the worst
// triangle alone, the fit's moves took the others down to it where one was far worse, at an
// input's narrow angle or a part thinner than the edges (lion.off at 5k, an 8° input angle and a
// 13.7° triangle there: θmin away from it 39.4° -> 34.1°; femur.off at 5k 37.8° -> 34.6°).
std::vector<MinShape> shape_floors(const TriangleMesh& mesh);

// Whether triangle t, as it is now, is at or above `floor` and turned less than kMaxShiftTurnCos
// from `before` (its unit normal before the moves).
bool keeps_shape(const TriangleMesh& mesh, std::size_t t, const MinShape& floor,
                 const Vec3& before);

}  // namespace cvtmesh
