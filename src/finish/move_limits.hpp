// What the finishing steps that move output vertices aim at, and how far they may turn a triangle:
// shared, so that no step undoes what another aims at.
#pragma once

namespace cvtmesh {

// The shape the sweeps aim at (improve_shapes), a little above what a converged CVT gives on a
// smooth surface (θmin about 35-38°, Q about 0.65): below it, a triangle is worth improving, and
// changes stop where they no longer help. A snap onto a crease may take a triangle down to it.
constexpr double kAimAngleDeg = 40;
constexpr double kAimQuality = 0.7;

// How far a fit or a snap may turn a triangle (cosine of 25°): it shifts the output along the
// surface, it does not fold it.
constexpr double kMaxShiftTurnCos = 0.906;

}  // namespace cvtmesh
