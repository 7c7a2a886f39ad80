// How much farther from the input surface the output's last steps may bring a triangle (a flip,
// a vertex move, a vertex of three triangles removed): this much farther, relatively, plus a
// small fraction of the length the change spans, so that chords of a flat region, 0 away, may
// change at all.
#pragma once

namespace cvtmesh {

// The largest distance to the surface allowed after a change that was `before` away and spans
// `length`.
inline double allowed_gap(double before, double length) {
  constexpr double kGapGrowth = 1.1;
  constexpr double kGapFloor = 0.01;
  return kGapGrowth * before + kGapFloor * length;
}

}  // namespace cvtmesh
