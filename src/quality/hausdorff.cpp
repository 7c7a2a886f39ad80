#include "cvtmesh/hausdorff.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/errors.hpp"
#include "geometry/area_sampler.hpp"
#include "geometry/spatial_order.hpp"
#include "geometry/surface_projector.hpp"
#include "quality/hausdorff_with_tree.hpp"

namespace cvtmesh {

namespace {

constexpr std::size_t kChunk = 1024;

// Max over samples and vertices; mean and RMS over the area samples (an unbiased estimate of
// the area-weighted mean). Queries run in Morton order, in fixed chunks, each query starting
// from the previous one's foot: nearby points, so a short search. The distances do not depend on
// that order, and the reduction runs serially in sample order: bit-identical for any thread count.
OneSidedDistance one_sided(const TriangleMesh& from, const SurfaceProjector& to,
                           std::size_t samples, std::uint64_t seed) {
  const AreaSampler sampler(from, seed);
  if (!sampler.has_area()) samples = 0;
  std::vector<AreaSampler::Sample> points(samples);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples, 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) points[i] = sampler.sample(i);
  });
  std::vector<Vec3> at(samples);
  for (std::size_t i = 0; i < samples; ++i) at[i] = points[i].point;
  const std::vector<Index> order = spatial_order(at);
  std::vector<double> d2(samples);
  tbb::parallel_for(std::size_t{0}, (samples + kChunk - 1) / kChunk, [&](std::size_t chunk) {
    const std::size_t begin = chunk * kChunk, end = std::min(samples, begin + kChunk);
    SurfaceProjector::Foot foot = to.nearest(points[order[begin]].point);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& p = points[order[k]].point;
      if (k > begin) foot = to.nearest(p, foot);
      d2[order[k]] = dot(foot.point - p, foot.point - p);
    }
  });
  OneSidedDistance r;
  double sum = 0, sum_sq = 0, max_sq = 0;
  for (const double d : d2) max_sq = std::max(max_sq, d), sum += std::sqrt(d), sum_sq += d;
  if (samples > 0) {
    r.mean = sum / static_cast<double>(samples);
    r.rms = std::sqrt(sum_sq / static_cast<double>(samples));
  }
  // The vertices count for the max only. A vertex whose distance to the previous foot's
  // triangle (an upper bound on its distance to the surface) is within the max so far cannot
  // raise it, so it needs no search: on a big input (igea's 270k vertices) most need none. The
  // max is the exact max whatever the order, so it does not depend on the thread count either.
  const std::size_t vertices = from.vertices.size();
  const std::vector<Index> vertex_order = spatial_order(from.vertices);
  std::vector<double> chunk_max((vertices + kChunk - 1) / kChunk, max_sq);
  tbb::parallel_for(std::size_t{0}, chunk_max.size(), [&](std::size_t chunk) {
    const std::size_t begin = chunk * kChunk, end = std::min(vertices, begin + kChunk);
    double& max = chunk_max[chunk];
    SurfaceProjector::Foot foot = to.nearest(from.vertices[vertex_order[begin]]);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& p = from.vertices[vertex_order[k]];
      if (k > begin && to.squared_distance_to(p, foot.triangle) <= max) continue;
      if (k > begin) foot = to.nearest(p, foot);
      max = std::max(max, dot(foot.point - p, foot.point - p));
    }
  });
  for (const double m : chunk_max) max_sq = std::max(max_sq, m);
  r.max = std::sqrt(max_sq);
  return r;
}

}  // namespace

HausdorffReport hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                   const SurfaceProjector& to_b,
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
  const SurfaceProjector to_a(a);
  r.a_to_b = one_sided(a, to_b, r.samples_per_surface, settings.seed);
  r.b_to_a = one_sided(b, to_a, r.samples_per_surface, settings.seed + 1);
  r.max = std::max(r.a_to_b.max, r.b_to_a.max);
  r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
  r.rms = std::max(r.a_to_b.rms, r.b_to_a.rms);
  return r;
}

HausdorffReport scaled_by_power_of_two(HausdorffReport h, int exponent) {
  for (double* d : {&h.a_to_b.max, &h.a_to_b.mean, &h.a_to_b.rms, &h.b_to_a.max, &h.b_to_a.mean,
                    &h.b_to_a.rms, &h.max, &h.mean, &h.rms, &h.reference_diagonal})
    *d = std::ldexp(*d, exponent);
  return h;
}

HausdorffReport hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                   const HausdorffSettings& settings) {
  if (a.triangles.empty() || b.triangles.empty())
    throw InvalidArgument("Hausdorff distance needs two non-empty meshes");
  // At 2^600 squared distances overflow and CGAL's exact fallback fails on the infinities (GMP
  // raised SIGFPE); at 2^-600 they underflow. One exponent for both keeps them comparable.
  const int exponent = std::max(size_exponent(a), size_exponent(b));
  if (exponent == 0) return hausdorff_distance(a, b, SurfaceProjector(b), settings);
  const TriangleMesh unit_a = scaled_by_power_of_two(a, -exponent);
  const TriangleMesh unit_b = scaled_by_power_of_two(b, -exponent);
  return scaled_by_power_of_two(
      hausdorff_distance(unit_a, unit_b, SurfaceProjector(unit_b), settings), exponent);
}

}  // namespace cvtmesh
