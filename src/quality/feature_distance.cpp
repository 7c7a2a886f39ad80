// One-sided distance from the input's feature curves to the output's feature edges (issue
// report key feature_hausdorff_*), by an AABB tree over the output segments; and the corners
// the output keeps (corners_out).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cvtmesh/hausdorff.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Segment = Kernel::Segment_3;
using Primitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

FeatureDistance unit_feature_distance(const TriangleMesh& input,
                                      const std::vector<Edge>& input_edges,
                                      const TriangleMesh& output,
                                      const std::vector<Edge>& output_edges) {
  std::vector<Segment> segments;
  for (const Edge& e : output_edges)
    segments.emplace_back(point(output.vertices[e[0]]), point(output.vertices[e[1]]));
  Tree tree(segments.begin(), segments.end());
  tree.accelerate_distance_queries();

  const double step = bounding_box(input).diagonal() / 4000;
  std::vector<std::size_t> first(input_edges.size() + 1, 0);  // samples of edge k start here
  for (std::size_t k = 0; k < input_edges.size(); ++k) {
    const double length =
        distance(input.vertices[input_edges[k][0]], input.vertices[input_edges[k][1]]);
    first[k + 1] = first[k] + 1 + static_cast<std::size_t>(std::ceil(length / step));
  }
  std::vector<double> d(first.back());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, input_edges.size()), [&](const auto& r) {
    for (std::size_t k = r.begin(); k < r.end(); ++k) {
      const Vec3& a = input.vertices[input_edges[k][0]];
      const Vec3& b = input.vertices[input_edges[k][1]];
      const std::size_t n = first[k + 1] - first[k];  // samples at t = i / (n - 1), both ends
      for (std::size_t i = 0; i < n; ++i) {
        const double t = n == 1 ? 0 : static_cast<double>(i) / static_cast<double>(n - 1);
        d[first[k] + i] = std::sqrt(tree.squared_distance(point(a + t * (b - a))));
      }
    }
  });
  FeatureDistance result;
  for (double x : d) result.max = std::max(result.max, x), result.mean += x;
  result.mean /= static_cast<double>(d.size());
  return result;
}

}  // namespace

FeatureDistance feature_distance(const TriangleMesh& input, const std::vector<Edge>& input_edges,
                                 const TriangleMesh& output,
                                 const std::vector<Edge>& output_edges) {
  if (input_edges.empty()) return {};
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (output_edges.empty()) return {kInfinity, kInfinity};
  // As in hausdorff_distance: squared distances at about unit size, whatever the units.
  const int exponent = size_exponent(input);
  if (exponent == 0) return unit_feature_distance(input, input_edges, output, output_edges);
  const FeatureDistance unit =
      unit_feature_distance(scaled_by_power_of_two(input, -exponent), input_edges,
                            scaled_by_power_of_two(output, -exponent), output_edges);
  return {std::ldexp(unit.max, exponent), std::ldexp(unit.mean, exponent)};
}

std::size_t corners_kept(const TriangleMesh& input, const Features& features,
                         const TriangleMesh& output) {
  std::vector<Vec3> at(output.vertices);
  std::sort(at.begin(), at.end());
  return static_cast<std::size_t>(std::count_if(
      features.corners.begin(), features.corners.end(),
      [&](Index c) { return std::binary_search(at.begin(), at.end(), input.vertices[c]); }));
}

}  // namespace cvtmesh
