#include "finish/shape_floors.hpp"

#include <algorithm>

#include "finish/move_limits.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

std::vector<MinShape> shape_floors(const TriangleMesh& mesh) {
  std::vector<MinShape> floor(mesh.triangles.size());
  MinShape worst{1, 180};
  for (std::size_t t = 0; t < floor.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    floor[t] = min_shape(a, b, c);
    worst = {std::min(worst.quality, floor[t].quality),
             std::min(worst.min_angle, floor[t].min_angle)};
  }
  const MinShape aim{std::max(kAimQuality, worst.quality), std::max(kAimAngleDeg, worst.min_angle)};
  for (MinShape& f : floor)
    f = {std::min(f.quality, aim.quality), std::min(f.min_angle, aim.min_angle)};
  return floor;
}

bool keeps_shape(const TriangleMesh& mesh, std::size_t t, const MinShape& floor,
                 const Vec3& before) {
  const auto [a, b, c] = mesh.corners(t);
  const MinShape s = min_shape(a, b, c);
  return s.min_angle >= floor.min_angle && s.quality >= floor.quality &&
         dot(unit_normal(a, b, c), before) >= kMaxShiftTurnCos;
}

}  // namespace cvtmesh
