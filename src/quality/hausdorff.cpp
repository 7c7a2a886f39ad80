#include "cvtmesh/hausdorff.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cvtmesh/errors.hpp"
#include "geometry/area_sampler.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

namespace {

// Max over samples and vertices; mean and RMS over the area samples (an unbiased estimate of
// the area-weighted mean). Queries run in the order of the triangles the samples lie on, in
// fixed chunks, each query starting from the previous one's foot: nearby points, so a short
// search. The distances do not depend on that order, and the reduction runs serially in sample
// order: bit-identical for any thread count.
OneSidedDistance one_sided(const TriangleMesh& from, const SurfaceProjector& to,
                           std::size_t samples, std::uint64_t seed) {
  const AreaSampler sampler(from, seed);
  if (!sampler.has_area()) samples = 0;
  const std::size_t total = samples + from.vertices.size();
  std::vector<AreaSampler::Sample> points(total);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i)
      points[i] =
          i < samples ? sampler.sample(i) : AreaSampler::Sample{from.vertices[i - samples], 0};
  });
  std::vector<std::size_t> order(total);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(
      order.begin(), order.begin() + static_cast<std::ptrdiff_t>(samples),
      [&](std::size_t a, std::size_t b) { return points[a].triangle < points[b].triangle; });
  std::vector<double> d2(total);
  constexpr std::size_t kChunk = 1024;
  tbb::parallel_for(std::size_t{0}, (total + kChunk - 1) / kChunk, [&](std::size_t chunk) {
    const std::size_t begin = chunk * kChunk, end = std::min(total, begin + kChunk);
    SurfaceProjector::Foot foot = to.nearest(points[order[begin]].point);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& p = points[order[k]].point;
      if (k > begin) foot = to.nearest(p, foot);
      d2[order[k]] = dot(foot.point - p, foot.point - p);
    }
  });
  OneSidedDistance r;
  double sum = 0, sum_sq = 0;
  for (std::size_t i = 0; i < d2.size(); ++i) {
    r.max = std::max(r.max, d2[i]);
    if (i < samples) sum += std::sqrt(d2[i]), sum_sq += d2[i];
  }
  r.max = std::sqrt(r.max);
  if (samples > 0) {
    r.mean = sum / static_cast<double>(samples);
    r.rms = std::sqrt(sum_sq / static_cast<double>(samples));
  }
  return r;
}

}  // namespace

HausdorffReport hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                   const HausdorffSettings& settings) {
  if (a.triangles.empty() || b.triangles.empty())
    throw InvalidArgument("Hausdorff distance needs two non-empty meshes");
  HausdorffReport r;
  r.samples_per_surface = settings.samples;
  if (r.samples_per_surface == 0) {
    const std::size_t dense = 2 * std::max(a.triangles.size(), b.triangles.size());
    r.samples_per_surface = std::clamp<std::size_t>(dense, 200'000, 1'000'000);
  }
  r.reference_diagonal = bounding_box(b).diagonal();
  const SurfaceProjector to_a(a), to_b(b);
  r.a_to_b = one_sided(a, to_b, r.samples_per_surface, settings.seed);
  r.b_to_a = one_sided(b, to_a, r.samples_per_surface, settings.seed + 1);
  r.max = std::max(r.a_to_b.max, r.b_to_a.max);
  r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
  r.rms = std::max(r.a_to_b.rms, r.b_to_a.rms);
  return r;
}

}  // namespace cvtmesh
