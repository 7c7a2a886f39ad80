#include "cvtmesh/hausdorff.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/errors.hpp"
#include "geometry/area_sampler.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// Distance queries against one surface, safe to call from many threads once built.
class SurfaceDistance {
 public:
  explicit SurfaceDistance(const TriangleMesh& mesh) {
    triangles_.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto [a, b, c] = mesh.corners(t);
      triangles_.emplace_back(point(a), point(b), point(c));
    }
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.build();
    tree_.accelerate_distance_queries();  // build the search structure now, not in a race later
  }
  double squared(const Vec3& p) const { return tree_.squared_distance(point(p)); }

 private:
  Triangles triangles_;
  Tree tree_;
};

// Max over samples and vertices; mean and RMS over the area samples (an unbiased estimate of
// the area-weighted mean). Reduced serially in sample order: bit-identical for any thread count.
OneSidedDistance one_sided(const TriangleMesh& from, const SurfaceDistance& to, std::size_t samples,
                           std::uint64_t seed) {
  const AreaSampler sampler(from, seed);
  if (!sampler.has_area()) samples = 0;
  std::vector<double> d2(samples + from.vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, d2.size(), 1024), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i)
      d2[i] = to.squared(i < samples ? sampler(i) : from.vertices[i - samples]);
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
  const SurfaceDistance to_a(a), to_b(b);
  r.a_to_b = one_sided(a, to_b, r.samples_per_surface, settings.seed);
  r.b_to_a = one_sided(b, to_a, r.samples_per_surface, settings.seed + 1);
  r.max = std::max(r.a_to_b.max, r.b_to_a.max);
  r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
  r.rms = std::max(r.a_to_b.rms, r.b_to_a.rms);
  return r;
}

}  // namespace cvtmesh
