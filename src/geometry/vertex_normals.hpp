// Per-vertex normals of a triangle mesh.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

// Each vertex's unit normal, the mean of its triangles' weighted by area; zero where they cancel
// (or where the vertex has no triangle).
inline std::vector<Vec3> unit_vertex_normals(const TriangleMesh& mesh) {
  std::vector<Vec3> normal(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const Vec3 n = cross(b - a, c - a);  // twice the area: the weight
    for (const Index v : mesh.triangles[t]) normal[v] += n;
  }
  for (Vec3& n : normal) n = unit_or_zero(n);
  return normal;
}

}  // namespace cvtmesh
