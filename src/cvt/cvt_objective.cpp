#include "cvt/cvt_objective.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cvtmesh {

std::vector<Vec3> CvtObjective::project(std::vector<Vec3>& seeds) {
  const bool hinted = hints_.size() == seeds.size();
  hints_.resize(seeds.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, seeds.size(), 256), [&](const auto& r) {
    for (std::size_t s = r.begin(); s < r.end(); ++s)
      hints_[s] = hinted ? projector_.nearest(seeds[s], hints_[s]) : projector_.nearest(seeds[s]);
  });
  std::vector<Vec3> feet(seeds.size()), normals(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    feet[s] = hints_[s].point;
    normals[s] = hints_[s].normal;
  }
  std::vector<std::size_t> order(seeds.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto key = [&](std::size_t s) { return std::tie(feet[s].x, feet[s].y, feet[s].z); };
  std::sort(order.begin(), order.end(),
            [&](auto a, auto b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || !(feet[order[k]] == feet[order[k - 1]])) seeds[order[k]] = feet[order[k]];
  return normals;
}

CvtObjective::Evaluation CvtObjective::operator()(std::vector<Vec3>& seeds) {
  const std::vector<Vec3> normals = constrained_ ? project(seeds) : std::vector<Vec3>{};
  ++evaluations_;
  const RestrictedVoronoiDiagram rvd(surface_, seeds);
  CellIntegrator integrator(rvd);
  rvd.traverse(integrator);
  const CellIntegrals& integrals = integrator.result();
  Evaluation e{integrals.total_energy, integrals.gradient(seeds), {}};
  e.centroids.resize(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s)
    e.centroids[s] = integrals.mass[s] > 0 ? integrals.centroid(static_cast<Index>(s)) : seeds[s];
  if (constrained_) {
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      const Vec3& n = normals[s];
      e.gradient[s] = e.gradient[s] - dot(e.gradient[s], n) * n;
    }
  }
  return e;
}

}  // namespace cvtmesh
