#include "features/curve_lloyd.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace cvtmesh {

namespace {

// One Jacobi step of 1D Lloyd on arc lengths `t` (sorted). The cell of seed i is
// [(t[i-1] + t[i]) / 2, (t[i] + t[i+1]) / 2], so its middle is (t[i-1] + 2 t[i] + t[i+1]) / 4.
// An open curve's neighbours at its ends are its corners, at 0 and `length`; a closed curve's
// wrap around.
std::vector<double> lloyd_step(const std::vector<double>& t, double length, bool closed) {
  const std::size_t n = t.size();
  std::vector<double> next(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double before = i > 0 ? t[i - 1] : closed ? t[n - 1] - length : 0.0;
    const double after = i + 1 < n ? t[i + 1] : closed ? t[0] + length : length;
    next[i] = (before + 2 * t[i] + after) / 4;
  }
  return next;
}

}  // namespace

void relax_curve_seeds(std::vector<Vec3>& seeds, const SeedConstraints& c,
                       const CurveProjector& curves, const CurveSpacing& spacing, int steps) {
  const SeedsAlongCurves along = seeds_along_curves(seeds, c, curves);
  std::set<Vec3> occupied(seeds.begin(), seeds.end());
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto& seeds_on = along[k];
    // A loop of fewer than three has no spacing to even (and place_feature_seeds gives it three).
    if (seeds_on.empty() || (curves.closed(k) && seeds_on.size() < 3)) continue;
    // Lloyd in measured length: even there, the seeds follow the sizes.
    std::vector<double> t;
    for (const auto& [arclength, s] : seeds_on) t.push_back(spacing.length(k, 0, arclength));
    const double whole = spacing.length(k, 0, curves.length(k));
    for (int step = 0; step < steps; ++step) t = lloyd_step(t, whole, curves.closed(k));
    for (std::size_t i = 0; i < t.size(); ++i) {
      Vec3& seed = seeds[seeds_on[i].second];
      const Vec3 p = curves.at(k, spacing.arclength(k, t[i]));
      if (p == seed || !occupied.insert(p).second) continue;
      occupied.erase(seed);
      seed = p;
    }
  }
}

SeedConstraints curve_seeds_held(const SeedConstraints& c, const std::vector<Vec3>& seeds) {
  SeedConstraints held = c;
  for (Index s = 0; s < seeds.size(); ++s)
    if (held.kind[s] == SeedConstraints::Kind::curve) {
      held.kind[s] = SeedConstraints::Kind::corner;
      held.anchor[s] = seeds[s];
    }
  return held;
}

}  // namespace cvtmesh
