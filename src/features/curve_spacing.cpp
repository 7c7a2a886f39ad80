#include "features/curve_spacing.hpp"

#include <algorithm>
#include <cmath>

#include "sizing/size_field.hpp"

namespace cvtmesh {

namespace {

// Linear interpolation of y at x over the sorted table xs (clamped to its ends).
double interpolated(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) -
                                                 xs.begin());  // xs[k-1] <= x < xs[k]
  const double span = xs[k] - xs[k - 1];
  const double t = span > 0 ? (x - xs[k - 1]) / span : 0;
  return ys[k - 1] + t * (ys[k] - ys[k - 1]);
}

}  // namespace

CurveSpacing::CurveSpacing(double spacing, const CurveProjector& curves, const Features& features,
                           const SizeField& sizes)
    : spacing_(spacing), curves_(&curves) {
  for (std::size_t c = 0; c < curves.size(); ++c) {
    std::vector<Index> polyline = features.curves[c].vertices;
    if (curves.closed(c)) polyline.push_back(polyline.front());
    std::vector<double> steps = sizes.steps_along(polyline);
    for (double& u : steps) u *= spacing;
    measured_.push_back(std::move(steps));
  }
}

double CurveSpacing::at(std::size_t c, double s) const {
  if (!curves_) return s;
  // A closed curve's arc lengths past its end wrap around (once, for a link's end).
  const double whole = curves_->length(c);
  const double laps = s > whole && whole > 0 ? std::floor(s / whole) : 0;
  return laps * measured_[c].back() +
         interpolated(curves_->arclengths(c), measured_[c], s - laps * whole);
}

double CurveSpacing::arclength(std::size_t c, double u) const {
  if (!curves_) return u;
  const double whole = measured_[c].back();
  const double laps = u > whole && whole > 0 ? std::floor(u / whole) : 0;
  return laps * curves_->length(c) +
         interpolated(measured_[c], curves_->arclengths(c), u - laps * whole);
}

}  // namespace cvtmesh
