// What cvtmesh's own readers (OFF, PLY) return: points and polygons as the file lists them,
// indices already checked against the vertex count.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace cvtmesh {

struct PolygonSoup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<double> vertex_scalar;  // when asked for (read_ply's `with_scalar`)
};

}  // namespace cvtmesh
