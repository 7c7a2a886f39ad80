#include "cvt/cvt_objective.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cvtmesh {

void CvtObjective::project(std::vector<Vec3>& seeds) const {
  std::vector<Vec3> feet(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) feet[s] = projector_.nearest(seeds[s]).point;
  std::vector<std::size_t> order(seeds.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto key = [&](std::size_t s) { return std::tie(feet[s].x, feet[s].y, feet[s].z); };
  std::sort(order.begin(), order.end(),
            [&](auto a, auto b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || !(feet[order[k]] == feet[order[k - 1]])) seeds[order[k]] = feet[order[k]];
}

CvtObjective::Evaluation CvtObjective::operator()(std::vector<Vec3>& seeds) {
  if (constrained_) project(seeds);
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
      const Vec3 n = projector_.nearest(seeds[s]).normal;
      e.gradient[s] = e.gradient[s] - dot(e.gradient[s], n) * n;
    }
  }
  return e;
}

}  // namespace cvtmesh
