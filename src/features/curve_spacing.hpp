// How long the stretches of the feature curves are, measured in the spacing the remesh wants
// there: the measure by which feature seeds are spaced (paper §4.3), evened (curve_lloyd) and
// judged (topology control). Uniform: the arc length itself. With a size field h (issue 20): the
// arc length the stretch would have at the uniform spacing, spacing · ∫ ds / h (h linear along
// each segment), so that curve seeds follow the surface's sizes; with h constant, the same.
#pragma once

#include <vector>

#include "features/curve_projector.hpp"

namespace cvtmesh {

class SizeField;

class CurveSpacing {
 public:
  explicit CurveSpacing(double spacing) : spacing_(spacing) {}
  CurveSpacing(double spacing, const CurveProjector& curves, const Features& features,
               const SizeField& sizes);

  // The uniform spacing: about one seed per this much of length().
  double spacing() const { return spacing_; }
  // The measured length of curve c between arc lengths `from` and `to` (from <= to; on a closed
  // curve either may pass its length, as a link's end does).
  double length(std::size_t c, double from, double to) const { return at(c, to) - at(c, from); }
  // The arc length where the measured length from the start of curve c is `u` (the inverse of
  // length(c, 0, ·)).
  double arclength(std::size_t c, double u) const;

 private:
  double at(std::size_t c, double s) const;  // length(c, 0, s)

  double spacing_;
  const CurveProjector* curves_ = nullptr;     // null when uniform; else its polylines' arc lengths
  std::vector<std::vector<double>> measured_;  // and per curve, per polyline point, length(c, 0, ·)
};

}  // namespace cvtmesh
