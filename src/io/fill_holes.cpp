// Filling an input's small holes, on request (`remesh --fill-holes`): a scan's dropouts that are
// smaller than the output's triangles cost their surroundings many small, badly shaped triangles
// when kept (a bull with 1% of its triangles removed, remeshed to 1.5k: 3.5k vertices, a fifth of
// the triangles under 30°), and users who want them closed, as geogram's vorpalite closes them,
// say so.
#include <cmath>
#include <string>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "geometry/hole_patch.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

double loop_length(const TriangleMesh& mesh, const HoleLoop& loop) {
  double length = 0;
  const std::size_t n = loop.vertices.size();
  for (std::size_t i = 0; i < n; ++i)
    length += distance(mesh.vertices[loop.vertices[i]], mesh.vertices[loop.vertices[(i + 1) % n]]);
  return length;
}

// The area of each vertex's component (by shared vertices), per vertex.
std::vector<double> component_areas(const TriangleMesh& mesh) {
  UnionFind parts(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles) {
    parts.unite(t[0], t[1]);
    parts.unite(t[1], t[2]);
  }
  std::vector<double> area(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    area[parts.find(t[0])] +=
        triangle_area(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  std::vector<double> of_vertex(mesh.vertices.size());
  for (std::size_t v = 0; v < of_vertex.size(); ++v) of_vertex[v] = area[parts.find(v)];
  return of_vertex;
}

}  // namespace

HoleFilling fill_holes(TriangleMesh& mesh, double max_perimeter) {
  if (!(max_perimeter >= 0))
    throw InvalidArgument("the largest hole to fill must be a length of at least 0, not " +
                          std::to_string(max_perimeter));
  HoleFilling report;
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  const std::optional<std::vector<HoleLoop>> loops = hole_loops(mesh, uses);
  if (!loops) {
    report.loops_undefined = true;
    return report;
  }
  const std::vector<double> area = component_areas(mesh);
  std::vector<Triangle> added;
  for (const HoleLoop& loop : *loops) {
    const double length = loop_length(mesh, loop);
    if (!(length < max_perimeter) || !(length < std::sqrt(area[loop.vertices[0]]))) {
      ++report.larger;
      continue;
    }
    // (A lone triangle's loop, which only its copy would close, is a rim: its length is over 4.5
    // times the square root of its area.)
    const std::optional<std::vector<Triangle>> patch = hole_patch(mesh, loop);
    // The patches of different loops share no vertex (repair leaves no vertex on two loops), so
    // each is checked against the mesh as it came.
    if (!patch || reuses_edge(*patch, loop, uses)) {
      ++report.left_open;
      continue;
    }
    added.insert(added.end(), patch->begin(), patch->end());
    ++report.filled;
  }
  report.triangles_added = added.size();
  mesh.triangles.insert(mesh.triangles.end(), added.begin(), added.end());
  return report;
}

}  // namespace cvtmesh
