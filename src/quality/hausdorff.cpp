#include "cvtmesh/hausdorff.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cvtmesh/errors.hpp"
#include "features/edge_uses.hpp"
#include "geometry/even_samples.hpp"
#include "geometry/spatial_order.hpp"
#include "geometry/surface_projector.hpp"
#include "quality/hausdorff_with_tree.hpp"

namespace cvtmesh {

namespace {

constexpr std::size_t kChunk = 1024;

// Each point's squared distance to the surface. Queries run in Morton order, in fixed chunks,
// each starting from the previous one's foot: nearby points, so a short search. A point equal to
// the one before it in that order takes its distance. The distances do not depend on the order:
// the same on any thread count.
std::vector<double> squared_distances(const std::vector<Vec3>& points, const SurfaceProjector& to) {
  const std::vector<Index> order = spatial_order(points);
  std::vector<double> d2(points.size());
  tbb::parallel_for(std::size_t{0}, (points.size() + kChunk - 1) / kChunk, [&](std::size_t chunk) {
    const std::size_t begin = chunk * kChunk, end = std::min(points.size(), begin + kChunk);
    SurfaceProjector::Foot foot = to.nearest(points[order[begin]]);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& p = points[order[k]];
      if (k > begin && p == points[order[k - 1]]) {
        d2[order[k]] = d2[order[k - 1]];
        continue;
      }
      if (k > begin) foot = to.nearest(p, foot);
      d2[order[k]] = dot(foot.point - p, foot.point - p);
    }
  });
  return d2;
}

// Max over samples, vertices and edge midpoints; mean and RMS over the area samples, spread evenly
// (even_area_samples: an unbiased estimate of the area-weighted mean, closer than independent
// samples). The reductions run serially in sample order: bit-identical for any thread count.
OneSidedDistance one_sided(const TriangleMesh& from, const SurfaceProjector& to, std::size_t count,
                           std::uint64_t seed) {
  const std::vector<double> d2 = squared_distances(even_area_samples(from, count, seed), to);
  const std::size_t samples = d2.size();
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
  // Each vertex keeps that bound, or its distance, and the triangle it is measured to, for the
  // next pass.
  const std::size_t vertices = from.vertices.size();
  const std::vector<Index> vertex_order = spatial_order(from.vertices);
  std::vector<double> reach(vertices);  // the distance bound, squared
  std::vector<std::size_t> reach_triangle(vertices);
  std::vector<double> chunk_max((vertices + kChunk - 1) / kChunk, max_sq);
  tbb::parallel_for(std::size_t{0}, chunk_max.size(), [&](std::size_t chunk) {
    const std::size_t begin = chunk * kChunk, end = std::min(vertices, begin + kChunk);
    double& max = chunk_max[chunk];
    SurfaceProjector::Foot foot = to.nearest(from.vertices[vertex_order[begin]]);
    for (std::size_t k = begin; k < end; ++k) {
      const Index v = vertex_order[k];
      const Vec3& p = from.vertices[v];
      const double above = to.squared_distance_to(p, foot.triangle);
      reach[v] = above;
      reach_triangle[v] = foot.triangle;
      if (k > begin && above <= max) continue;
      // Nor does one with some triangle within the max: a search that opens only the boxes
      // within it, and stops at the first.
      if (k > begin) {
        if (const auto near = to.within(p, max)) {
          reach[v] = near->squared;
          reach_triangle[v] = near->triangle;
          continue;
        }
        foot = to.nearest(p, foot);
      }
      const double squared = dot(foot.point - p, foot.point - p);
      reach[v] = squared;
      reach_triangle[v] = foot.triangle;
      max = std::max(max, squared);
    }
  });
  for (const double m : chunk_max) max_sq = std::max(max_sq, m);
  // Then the edges' midpoints, for the max too: where the max lies along an edge, as along a
  // crease that the other surface rounds off, samples seldom land on it. A midpoint whose
  // distance cannot exceed the max needs no search: on a dense surface, nearly all. Its bounds:
  // an end's bound plus half the edge (a distance to a surface changes no faster than the point
  // moves), then the larger of the two ends' distances to the triangle an end is measured to (the
  // distance to a triangle, a convex set, is convex along the edge), then a triangle within the
  // max (SurfaceProjector::within). Those left are searched as the samples are. (The bounds
  // alone left every output edge open on corpus/bear.off at 5k, and 57% of the input's, 77k
  // searches where the samples take 16k.)
  const std::size_t triangles = from.triangles.size();
  std::vector<std::uint8_t> open(3 * triangles);
  tbb::parallel_for(std::size_t{0}, triangles, [&](std::size_t t) {
    const Triangle& f = from.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Index v = f[k], w = f[(k + 1) % 3];
      const Vec3 &p = from.vertices[v], &q = from.vertices[w];
      const double most = std::sqrt(std::min(reach[v], reach[w])) + 0.5 * distance(p, q);
      open[3 * t + k] =
          most * most > max_sq &&
          std::min(std::max(reach[v], to.squared_distance_to(q, reach_triangle[v])),
                   std::max(reach[w], to.squared_distance_to(p, reach_triangle[w]))) > max_sq;
    }
  });
  // The bounds are the same from both triangles of an edge: each open edge is asked once, by its
  // ends in order.
  std::vector<Edge> edges;
  for (std::size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k)
      if (open[3 * t + k])
        edges.push_back(edge_of(from.triangles[t][k], from.triangles[t][(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const auto midpoint = [&](const Edge& e) {
    return 0.5 * (from.vertices[e[0]] + from.vertices[e[1]]);
  };
  std::vector<std::uint8_t> near(edges.size());
  tbb::parallel_for(std::size_t{0}, edges.size(), [&](std::size_t i) {
    near[i] = to.within(midpoint(edges[i]), max_sq).has_value();
  });
  std::vector<Vec3> midpoints;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (!near[i]) midpoints.push_back(midpoint(edges[i]));
  for (const double d : squared_distances(midpoints, to)) max_sq = std::max(max_sq, d);
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
