// Feature seeds (paper §4.3): after the unconstrained RCVT, the seeds nearest to the feature
// curves move onto them, one per corner and evenly spaced along each curve, and stay there.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cvtmesh/errors.hpp"
#include "features/curve_projector.hpp"
#include "features/curve_spacing.hpp"

namespace cvtmesh {

// The features need `needed` seeds of their own, and the count leaves fewer: sizes graded down
// to small holes put far more seeds on their loops than the even spacing that the count was
// checked against (remesh/by_component).
struct FeaturesNeedMoreSeeds : InvalidArgument {
  FeaturesNeedMoreSeeds(const std::string& message, std::size_t needed_seeds)
      : InvalidArgument(message), needed(needed_seeds) {}
  std::size_t needed;
};

// What each seed is bound to during CCVT.
struct SeedConstraints {
  enum class Kind : std::uint8_t { surface, curve, corner };
  std::vector<Kind> kind;            // per seed
  std::vector<std::uint32_t> curve;  // per seed: its curve, for curve seeds
  std::vector<Vec3> anchor;          // per seed: its input corner, for corner seeds
  std::vector<Index> corner_seed;    // per input corner (Features::corners order): its seed

  bool empty() const { return kind.empty(); }
  // The constraints of one more seed, at the end.
  void append(Kind k, std::uint32_t on_curve = 0, const Vec3& at_corner = {}) {
    kind.push_back(k);
    curve.push_back(on_curve);
    anchor.push_back(at_corner);
  }
};

// Replaces seeds by feature seeds: each corner, and points about a spacing apart (as `spacing`
// measures length) along each curve (at least three on a closed loop, two on a curve from a corner
// back to itself, so no loop collapses), each taking the place of the nearest seed not taken yet.
// The seed count stays the same. FeaturesNeedMoreSeeds when they need more seeds than there are.
SeedConstraints place_feature_seeds(std::vector<Vec3>& seeds, const TriangleMesh& mesh,
                                    const Features& features, const CurveProjector& curves,
                                    const CurveSpacing& spacing);

// How many feature seeds place_feature_seeds wants for these features at this spacing (at
// most: where curves overlap in space, it wants a point once); it needs more seeds than that.
std::size_t feature_seed_count(const Features& features, const CurveProjector& curves,
                               const CurveSpacing& spacing);

// CVT is indifferent to which seeds cover a curve: a surface seed may end up nearest to a
// stretch of one, where the output would then cut the crease. Each such seed (nearest to a
// sample of a curve, samples an eighth of a spacing apart) joins that curve. Returns how
// many did.
std::size_t snap_stray_seeds(std::vector<Vec3>& seeds, SeedConstraints& c,
                             const CurveProjector& curves, const CurveSpacing& spacing);

// Per curve, its curve seeds as (arc length of their projection, seed id), by arc length.
using SeedsAlongCurves = std::vector<std::vector<std::pair<double, Index>>>;
SeedsAlongCurves seeds_along_curves(const std::vector<Vec3>& seeds, const SeedConstraints& c,
                                    const CurveProjector& curves);

// A feature edge the output must have: seeds consecutive along a curve (corners at the ends),
// ordered by their projections on it, and the stretch of the curve between them.
struct FeatureLink {
  Edge seeds;  // seed ids, the smaller first
  std::uint32_t curve;
  double from, to;  // arc lengths, from < to; past the length on a closed curve's last link
};
std::vector<FeatureLink> feature_links(const std::vector<Vec3>& seeds, const SeedConstraints& c,
                                       const Features& features, const CurveProjector& curves);

// The output misses a link where a third cell covers part of its stretch, cutting the curve
// there. For each such link whose stretch a surface seed owns in part, that seed (the one
// nearest to the stretch's middle, if several) joins the curve at the middle. A link cut only by
// feature seeds of other curves (in a narrow wedge between two curves, or a saw of corners)
// gets a new curve seed at its middle instead, if it is at least 0.9 spacings long and
// each half's middle is then nearer to the half's ends than to any other seed (so the restricted
// Delaunay triangulation has both halves); other links stay as they are. Returns how many seeds
// joined or came in.
std::size_t mend_missing_links(std::vector<Vec3>& seeds, SeedConstraints& c,
                               const std::vector<FeatureLink>& missing,
                               const CurveProjector& curves, const CurveSpacing& spacing);

}  // namespace cvtmesh
