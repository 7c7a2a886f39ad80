#include "geometry/triangle_sides.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <tuple>

#include "geometry/index_range.hpp"

namespace cvtmesh {

// Sorted by (lo, hi, triangle, side): a counting sort on lo (stable, so each bucket is in triangle
// order), then each bucket, a vertex's few sides, by hi. Linear where one global sort of the
// 3·F sides was the report's largest cost on big inputs.
std::vector<TriangleSide> sorted_sides(std::size_t vertices,
                                       const std::vector<Triangle>& triangles) {
  require_index_range(triangles.size(), "triangles for their sides' list");
  std::vector<std::size_t> start(vertices + 1, 0);
  for (const Triangle& f : triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(f[k], f[(k + 1) % 3]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<TriangleSide> sides(3 * triangles.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& f = triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Index a = f[k], b = f[(k + 1) % 3];
      sides[next[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), static_cast<Index>(t), a < b,
                                       static_cast<std::uint8_t>(k)};
    }
  }
  // The buckets apart, in parallel (each sorted by a strict order: the same on any thread count).
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, start.size() - 1, 4096), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v)
      std::sort(sides.begin() + static_cast<std::ptrdiff_t>(start[v]),
                sides.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
                [](const TriangleSide& x, const TriangleSide& y) {
                  return std::tie(x.hi, x.triangle, x.side) < std::tie(y.hi, y.triangle, y.side);
                });
  });
  return sides;
}

std::vector<TriangleSide> sorted_sides(const TriangleMesh& mesh) {
  return sorted_sides(mesh.vertices.size(), mesh.triangles);
}

}  // namespace cvtmesh
