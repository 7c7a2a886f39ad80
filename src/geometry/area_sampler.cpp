#include "geometry/area_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/random.hpp"

namespace cvtmesh {

namespace {

std::vector<double> triangle_areas(const TriangleMesh& mesh) {
  std::vector<double> areas(mesh.triangles.size());
  for (std::size_t t = 0; t < areas.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    areas[t] = triangle_area(a, b, c);
  }
  return areas;
}

}  // namespace

AreaSampler::AreaSampler(const TriangleMesh& mesh, std::uint64_t seed)
    : AreaSampler(mesh, seed, triangle_areas(mesh)) {}

AreaSampler::AreaSampler(const TriangleMesh& mesh, std::uint64_t seed,
                         const std::vector<double>& weights)
    : mesh_(mesh), seed_(seed) {
  cumulative_.reserve(weights.size());
  double sum = 0;
  for (const double w : weights) cumulative_.push_back(sum += w);
}

AreaSampler::Sample AreaSampler::sample(std::uint64_t k) const {
  CounterRng rng(seed_, k);
  const double target = rng.uniform() * cumulative_.back();
  const std::size_t t = std::min<std::size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin(),
      cumulative_.size() - 1);
  const auto [a, b, c] = mesh_.corners(t);
  // Uniform point in a triangle: s = √u1 along the median direction, u2 across.
  const double s = std::sqrt(rng.uniform()), u = rng.uniform();
  return {(1 - s) * a + (s * (1 - u)) * b + (s * u) * c, t};
}

}  // namespace cvtmesh
