#include "geometry/triangle_sides.hpp"

#include <tuple>

#include "geometry/sort_by_edge.hpp"

namespace cvtmesh {

std::vector<TriangleSide> sorted_sides(std::size_t vertices,
                                       const std::vector<Triangle>& triangles) {
  return sorted_by_edge<TriangleSide>(
      vertices, triangles,
      [&](Index lo, Index hi, std::size_t t, int k) {
        return TriangleSide{lo, hi, static_cast<Index>(t), triangles[t][k] == lo && lo != hi,
                            static_cast<std::uint8_t>(k)};
      },
      [](const TriangleSide& x, const TriangleSide& y) {
        return std::tie(x.hi, x.triangle, x.side) < std::tie(y.hi, y.triangle, y.side);
      });
}

std::vector<TriangleSide> sorted_sides(const TriangleMesh& mesh) {
  return sorted_sides(mesh.vertices.size(), mesh.triangles);
}

}  // namespace cvtmesh
