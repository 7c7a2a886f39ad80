#include "geometry/triangle_sides.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cvtmesh {

// Sorted by (lo, hi, triangle, side): a counting sort on lo (stable, so each bucket is in triangle
// order), then each bucket, a vertex's few sides, by hi. Linear where one global sort of the
// 3·F sides was the report's largest cost on big inputs.
std::vector<TriangleSide> sorted_sides(const TriangleMesh& mesh) {
  std::vector<std::size_t> start(mesh.vertices.size() + 1, 0);
  for (const Triangle& f : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(f[k], f[(k + 1) % 3]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<TriangleSide> sides(3 * mesh.triangles.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Index a = f[k], b = f[(k + 1) % 3];
      sides[next[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), t, a < b,
                                       static_cast<std::uint8_t>(k)};
    }
  }
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    std::sort(sides.begin() + start[v], sides.begin() + start[v + 1],
              [](const TriangleSide& x, const TriangleSide& y) {
                return std::tie(x.hi, x.triangle, x.side) < std::tie(y.hi, y.triangle, y.side);
              });
  return sides;
}

}  // namespace cvtmesh
