// Scale invariance: see cvtmesh/mesh.hpp.
#include <algorithm>
#include <cmath>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

int size_exponent(const TriangleMesh& mesh) {
  const BoundingBox box = bounding_box(mesh);
  // Each extent is a difference of two coordinates: exact under scaling by 2^k, unlike the
  // diagonal, whose squares overflow at 1e200. Halved first, so that coordinates near the
  // largest double (±1.7e308) do not make it overflow.
  const double half = std::max({box.max.x / 2 - box.min.x / 2, box.max.y / 2 - box.min.y / 2,
                                box.max.z / 2 - box.min.z / 2});
  return half > 0 && std::isfinite(half) ? std::ilogb(half) + 1 : 0;
}

Vec3 scaled_by_power_of_two(const Vec3& p, int exponent) {
  return {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
}

TriangleMesh scaled_by_power_of_two(TriangleMesh mesh, int exponent) {
  for (Vec3& v : mesh.vertices) v = scaled_by_power_of_two(v, exponent);
  return mesh;
}

}  // namespace cvtmesh
