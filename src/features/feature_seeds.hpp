// Feature seeds (paper §4.3): after the unconstrained RCVT, the seeds nearest to the feature
// curves move onto them, one per corner and evenly spaced along each curve, and stay there.
#pragma once

#include <cstdint>
#include <vector>

#include "features/curve_projector.hpp"

namespace cvtmesh {

// What each seed is bound to during CCVT.
struct SeedConstraints {
  enum class Kind : std::uint8_t { surface, curve, corner };
  std::vector<Kind> kind;            // per seed
  std::vector<std::uint32_t> curve;  // per seed: its curve, for curve seeds
  std::vector<Vec3> anchor;          // per seed: its input corner, for corner seeds
  std::vector<Index> corner_seed;    // per input corner (Features::corners order): its seed

  bool empty() const { return kind.empty(); }
};

// Replaces seeds by feature seeds: each corner, and points at about `spacing` along each curve
// (at least three on a closed loop, two on a curve from a corner back to itself, so no loop
// collapses), each taking the place of the nearest seed not taken yet. The seed count stays
// the same. InvalidArgument when the features need more seeds than there are.
SeedConstraints place_feature_seeds(std::vector<Vec3>& seeds, const TriangleMesh& mesh,
                                    const Features& features, const CurveProjector& curves,
                                    double spacing);

// CVT is indifferent to which seeds cover a curve: a surface seed may end up nearest to a
// stretch of one, where the output would then cut the crease. Each such seed (nearest to a
// sample of a curve, samples `spacing`/8 apart) joins that curve. Returns how many did.
std::size_t snap_stray_seeds(std::vector<Vec3>& seeds, SeedConstraints& c,
                             const CurveProjector& curves, double spacing);

// The feature edges the output must have: consecutive seeds along each curve (corners at the
// ends), as pairs of seed ids, ordered by their projections on the curve.
std::vector<Edge> feature_chains(const std::vector<Vec3>& seeds, const SeedConstraints& c,
                                 const Features& features, const CurveProjector& curves);

}  // namespace cvtmesh
