#include "geometry/unit_scale.hpp"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

int size_exponent(const TriangleMesh& mesh) {
  const BoundingBox box = bounding_box(mesh);
  // Each extent is a difference of two coordinates: exact under scaling by 2^k, unlike the
  // diagonal, whose squares overflow at 1e200.
  const double extent =
      std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
  return extent > 0 && std::isfinite(extent) ? std::ilogb(extent) : 0;
}

TriangleMesh scaled_by_power_of_two(TriangleMesh mesh, int exponent) {
  for (Vec3& v : mesh.vertices)
    v = {std::ldexp(v.x, exponent), std::ldexp(v.y, exponent), std::ldexp(v.z, exponent)};
  return mesh;
}

}  // namespace cvtmesh
