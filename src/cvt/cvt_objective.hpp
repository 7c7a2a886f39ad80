// The CVT energy F and its gradient as a function of the seeds (paper eq. 3 and 5), one RVD
// per evaluation. Restricted CVT: seeds free in 3D. Constrained CVT: F is evaluated at the
// seeds' nearest surface points and the gradient projected on the tangent planes there (eq. 7);
// with features, curve seeds on their curve with the gradient along its tangent, and corner
// seeds fixed (zero gradient) while their cells still count in F (§4.3).
#pragma once

#include <span>
#include <vector>

#include "cvt/interrupt.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "features/feature_seeds.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

class CvtObjective {
 public:
  // Restricted CVT without a projector; constrained CVT with one. Evaluations check
  // `interrupt` (a cancel throws Cancelled, even during an RVD pass). `density`: ρ per surface
  // vertex (eq. 1), null or empty for ρ = 1.
  CvtObjective(const TriangleMesh& surface, const SurfaceProjector* projector,
               const SeedConstraints* features = nullptr, const CurveProjector* curves = nullptr,
               const Interrupt* interrupt = nullptr, const std::vector<double>* density = nullptr)
      : surface_(surface),
        projector_(projector),
        features_(features),
        curves_(curves),
        interrupt_(interrupt ? *interrupt : kNever),
        density_(density && !density->empty() ? density : nullptr) {
    // The projector's, where it has them: the same values, held once (48 MB on a 2M-triangle
    // input).
    unit_normals_ = projector ? projector->unit_normals() : std::span<const Vec3>{};
    if (unit_normals_.empty()) {
      own_unit_normals_ = unit_normals(surface);
      unit_normals_ = own_unit_normals_;
    }
  }

  // Not copied: unit_normals_ may point into own_unit_normals_.
  CvtObjective(const CvtObjective&) = delete;
  CvtObjective& operator=(const CvtObjective&) = delete;

  struct Evaluation {
    double energy;
    std::vector<Vec3> gradient;
    std::vector<Vec3> centroids;  // restricted centroids (the seed itself where its cell is empty)
    std::vector<double> masses;   // ∫ρ over each cell (0 where it is empty)
  };
  // `seeds` are replaced by the points actually evaluated (projected, when constrained).
  Evaluation operator()(std::vector<Vec3>& seeds);
  int evaluations() const { return evaluations_; }
  // What stops the work done with this objective (the optimization, polishing, topology control).
  const Interrupt& interrupt() const { return interrupt_; }
  // ρ per surface vertex; null for ρ = 1.
  const std::vector<double>* density() const { return density_; }

  // Constrained CVT only. Moves each seed to its nearest surface point (curve seeds: curve point;
  // corner seeds: their corner) and returns, per seed, how to constrain its gradient. A seed that
  // would land on a point another seed already occupies (possible at convex corners) stays where it
  // is, so seeds stay distinct; corner seeds win such ties. Each surface search starts from the
  // previous foot.
  struct Tangent {
    Vec3 direction;  // surface: the normal; curve: the tangent
    SeedConstraints::Kind kind;
  };
  std::vector<Tangent> project(std::vector<Vec3>& seeds);

  // Constrained CVT only. Where seed s goes when moved to p: the nearest point of its curve, or
  // of the surface; a corner seed stays on its corner. Thread-safe.
  Vec3 constrained(std::size_t s, const Vec3& p) const;

  // What seed s is bound to.
  SeedConstraints::Kind kind(std::size_t s) const {
    return features_ && !features_->empty() ? features_->kind[s] : SeedConstraints::Kind::surface;
  }

 private:
  const TriangleMesh& surface_;
  const SurfaceProjector* projector_;
  const SeedConstraints* features_;
  const CurveProjector* curves_;
  static inline const Interrupt kNever;
  const Interrupt& interrupt_;
  const std::vector<double>* density_;
  int evaluations_ = 0;
  std::vector<SurfaceProjector::Foot> hints_;  // the feet of the last projection
  NeighborCache neighbors_;                    // the seeds' nearest seeds, step to step
  std::span<const Vec3> unit_normals_;         // the surface's, for every evaluation
  std::vector<Vec3> own_unit_normals_;         // those, where the projector does not hold them
};

}  // namespace cvtmesh
