// The triangle mesh every cvtmesh module works on: an indexed triangle soup.
// No connectivity is stored; modules that need it (topology, features) derive it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cvtmesh/vec3.hpp"

namespace cvtmesh {

using Index = std::uint32_t;
// No vertex, seed or component: an unset or absent index.
inline constexpr Index kNoIndex = ~Index{0};
using Triangle = std::array<Index, 3>;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;

  std::array<Vec3, 3> corners(std::size_t t) const {
    const Triangle& f = triangles[t];
    return {vertices[f[0]], vertices[f[1]], vertices[f[2]]};
  }
};

struct BoundingBox {
  Vec3 min, max;
  double diagonal() const { return distance(min, max); }
};

// Bounding box of the vertices used by at least one triangle.
BoundingBox bounding_box(const TriangleMesh& mesh);

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c);
double surface_area(const TriangleMesh& mesh);
// Per vertex, whether a triangle uses it.
std::vector<bool> used_vertices(const TriangleMesh& mesh);

// The same surface with its vertices in Morton order, and its triangles in the Morton order of
// their centroids, each turned (orientation kept) to start at its smallest vertex id. The RVD's
// walks go from each vertex's cell to the next's and from triangle to triangle: on a file in no
// spatial order, an RVD pass is up to 10x slower (igea shuffled). A permutation of the same
// vertices and triangles gives the same sorted mesh (unless two vertices coincide).
struct SpatiallySorted {
  TriangleMesh mesh;
  std::vector<Index> new_id;  // per vertex id of the given mesh, its id in `mesh`
};
SpatiallySorted spatially_sorted(const TriangleMesh& mesh);

// Scale invariance (issue 22): cvtmesh works on a mesh scaled by a power of two to about unit
// size. Multiplying by a power of two is exact in floating point (barring subnormals), so
// corners keep their coordinates bit for bit through the scaling and back, and a shape in
// nanometres or in light years is handled as the same shape in metres: areas and squared
// distances neither underflow nor overflow.
//
// The exponent e of the mesh's largest bounding-box extent (over the vertices its triangles
// use): that extent is in [2^e, 2^(e+1)). 0 for a mesh without extent.
int size_exponent(const TriangleMesh& mesh);
// `mesh` (a point) with every coordinate multiplied by 2^exponent.
TriangleMesh scaled_by_power_of_two(TriangleMesh mesh, int exponent);
Vec3 scaled_by_power_of_two(const Vec3& p, int exponent);

}  // namespace cvtmesh
