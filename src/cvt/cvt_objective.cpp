#include "cvt/cvt_objective.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cvtmesh {

std::vector<CvtObjective::Tangent> CvtObjective::project(std::vector<Vec3>& seeds) {
  using Kind = SeedConstraints::Kind;
  const bool hinted = hints_.size() == seeds.size();
  hints_.resize(seeds.size());
  std::vector<Vec3> feet(seeds.size());
  std::vector<Tangent> tangents(seeds.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, seeds.size(), 256), [&](const auto& r) {
    for (std::size_t s = r.begin(); s < r.end(); ++s) {
      if (kind(s) == Kind::corner) {
        feet[s] = features_->anchor[s];
        tangents[s] = {{}, Kind::corner};
      } else if (kind(s) == Kind::curve) {
        const CurveProjector::Foot foot = curves_->nearest(features_->curve[s], seeds[s]);
        feet[s] = foot.point;
        tangents[s] = {foot.tangent, Kind::curve};
      } else {
        hints_[s] =
            hinted ? projector_->nearest(seeds[s], hints_[s]) : projector_->nearest(seeds[s]);
        feet[s] = hints_[s].point;
        tangents[s] = {hints_[s].normal, Kind::surface};
      }
    }
  });
  // Seeds move to their feet, except where that would make two seeds coincide: then the one
  // of lower priority (corner seeds first, then by id) keeps its position. Repeated, since a
  // seed kept in place may now coincide with another's foot; it ends, as every round keeps at
  // least one more seed in place and the incoming seeds are distinct.
  std::vector<bool> moves(seeds.size(), true);
  std::vector<std::size_t> order(seeds.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto at = [&](std::size_t s) { return moves[s] ? feet[s] : seeds[s]; };
  auto key = [&](std::size_t s) {
    return std::make_tuple(at(s), tangents[s].kind != Kind::corner, s);
  };
  for (bool changed = true; changed;) {
    changed = false;
    // The keys are distinct (the seed id is one): any sort gives the one order.
    tbb::parallel_sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
    for (std::size_t k = 1; k < order.size(); ++k) {
      const std::size_t a = order[k - 1], b = order[k];
      if (!(at(a) == at(b))) continue;
      moves[moves[b] ? b : a] = false;  // both cannot stay: the incoming seeds are distinct
      changed = true;
    }
  }
  for (std::size_t s = 0; s < seeds.size(); ++s)
    if (moves[s]) seeds[s] = feet[s];
  return tangents;
}

Vec3 CvtObjective::constrained(std::size_t s, const Vec3& p) const {
  switch (kind(s)) {
    case SeedConstraints::Kind::corner:
      return features_->anchor[s];
    case SeedConstraints::Kind::curve:
      return curves_->nearest(features_->curve[s], p).point;
    case SeedConstraints::Kind::surface:
      break;
  }
  return projector_->nearest(p).point;
}

CvtObjective::Evaluation CvtObjective::operator()(std::vector<Vec3>& seeds) {
  const std::vector<Tangent> tangents = projector_ ? project(seeds) : std::vector<Tangent>{};
  interrupt_.check();
  ++evaluations_;
  const RestrictedVoronoiDiagram rvd(surface_, seeds, neighbors_);
  CellIntegrator integrator(
      rvd, density_ ? std::span<const double>(*density_) : std::span<const double>{},
      unit_normals_);
  InterruptSink stop(interrupt_);
  PolygonSink* sinks[] = {&integrator, &stop};
  rvd.traverse(sinks);
  const CellIntegrals& integrals = integrator.result();
  Evaluation e{integrals.total_energy, integrals.gradient(seeds), {}, integrals.mass};
  e.centroids.resize(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s)
    e.centroids[s] = integrals.mass[s] > 0 ? integrals.centroid(static_cast<Index>(s)) : seeds[s];
  if (projector_) {
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      Vec3& g = e.gradient[s];
      const Vec3& d = tangents[s].direction;
      switch (tangents[s].kind) {
        case SeedConstraints::Kind::surface:
          g = g - dot(g, d) * d;
          break;
        case SeedConstraints::Kind::curve:
          g = dot(g, d) * d;
          break;
        case SeedConstraints::Kind::corner:
          g = {};
          break;
      }
    }
  }
  return e;
}

}  // namespace cvtmesh
