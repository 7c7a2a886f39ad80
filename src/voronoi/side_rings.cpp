#include "voronoi/side_rings.hpp"

#include <limits>
#include <stdexcept>

#include "geometry/triangle_sides.hpp"

namespace cvtmesh {

SideRings::SideRings(const TriangleMesh& surface) {
  if (surface.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3)
    throw std::length_error("too many triangles for their side rings");
  // The sorted sides take 16 bytes per side for a moment (igea.ply: 13 MB).
  const std::vector<TriangleSide> sides = sorted_sides(surface);
  next_.assign(sides.size(), 0);
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j) {
    for (j = i + 1; j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi;)
      ++j;
    for (std::size_t k = i; k < j; ++k) {
      const TriangleSide& next = sides[k + 1 < j ? k + 1 : i];
      next_[3 * sides[k].triangle + sides[k].side] =
          static_cast<std::uint32_t>(3 * next.triangle + next.side);
    }
  }
}

}  // namespace cvtmesh
