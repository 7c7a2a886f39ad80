// How many target edge lengths fit along the feature curves: the measure by which feature seeds
// are spaced (paper §4.3), evened (curve_lloyd) and judged (topology control). Uniform: arc
// length over the spacing. With a size field h (issue 20): ∫ ds / h, h linear along each
// segment, so that curve seeds follow the same sizes as the surface's.
#pragma once

#include <vector>

#include "features/curve_projector.hpp"

namespace cvtmesh {

class SizeField;

class CurveSpacing {
 public:
  explicit CurveSpacing(double spacing) : spacing_(spacing) {}
  CurveSpacing(const CurveProjector& curves, const Features& features, const SizeField& sizes);

  // Target lengths along curve c between arc lengths `from` and `to` (from <= to; on a closed
  // curve either may pass its length, as a link's end does).
  double steps(std::size_t c, double from, double to) const { return at(c, to) - at(c, from); }
  // The arc length `u` target lengths from the start of curve c (inverse of steps(c, 0, ·)).
  double arclength(std::size_t c, double u) const;

 private:
  double at(std::size_t c, double s) const;  // steps(c, 0, s)

  double spacing_ = 0;                      // uniform when > 0
  const CurveProjector* curves_ = nullptr;  // with a size field: its polylines' arc lengths
  std::vector<std::vector<double>> steps_;  // and, per curve, per polyline point, its steps
};

}  // namespace cvtmesh
