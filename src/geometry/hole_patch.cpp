#include "geometry/hole_patch.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>

namespace cvtmesh {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

std::optional<std::vector<HoleLoop>> hole_loops(const TriangleMesh& mesh,
                                                const std::vector<EdgeUse>& uses) {
  const std::optional<std::vector<BoundaryLoop>> boundary = boundary_loops(mesh, uses);
  if (!boundary) return std::nullopt;
  std::vector<HoleLoop> loops;
  for (const BoundaryLoop& b : *boundary) {
    HoleLoop loop{b.vertices, b.uses, {}};
    for (const std::size_t i : b.uses)
      loop.opposite.push_back(mesh.triangles[uses[i].triangle()][(uses[i].corner + 2) % 3]);
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::optional<std::vector<Triangle>> hole_patch(const TriangleMesh& mesh, const HoleLoop& loop) {
  std::vector<Kernel::Point_3> points, third;
  for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[loop.vertices[i]];
    const Vec3& q = mesh.vertices[loop.opposite[i]];
    points.emplace_back(p.x, p.y, p.z);
    third.emplace_back(q.x, q.y, q.z);
  }
  std::vector<CGAL::Triple<int, int, int>> patch;
  // CGAL's search over the loop's 3D Delaunay triangles alone gave a loop whose points lie in a
  // plane (a hole in a flat wall) different patches from one call to the next, as the heap went
  // (not when built with AddressSanitizer, whose heap hands out addresses in order), so outputs
  // differed from run to run; its search over all triangles, which it falls back to, is
  // deterministic, and optimal for CGAL's weight, in time cubic in the loop's length. It takes
  // loops of up to kMostCubic edges: a loop of 1,305 edges, which the last step opened on a noised
  // slab folded through itself, took 30 s, and was patched again each round. Longer loops get the
  // Delaunay search: where it fails, the last step closes the loop with a fan (remesh/close_holes),
  // and fill_holes leaves it open.
  constexpr std::size_t kMostCubic = 200;
  const bool cubic = points.size() <= kMostCubic;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(
      points, third, std::back_inserter(patch),
      CGAL::parameters::use_delaunay_triangulation(!cubic).do_not_use_cubic_algorithm(!cubic));
  if (patch.size() + 2 != loop.vertices.size()) return std::nullopt;
  std::vector<Triangle> triangles;
  for (const auto& [a, b, c] : patch)
    triangles.push_back({loop.vertices[a], loop.vertices[b], loop.vertices[c]});
  return triangles;
}

bool reuses_edge(const std::vector<Triangle>& patch, const HoleLoop& loop,
                 const std::vector<EdgeUse>& uses) {
  const auto in_mesh = [&](const Edge& e) {
    const auto at = std::lower_bound(uses.begin(), uses.end(), e,
                                     [](const EdgeUse& u, const Edge& x) { return u.edge < x; });
    return at != uses.end() && at->edge == e;
  };
  const std::size_t n = loop.vertices.size();
  for (const Triangle& t : patch)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const std::size_t i =
          std::find(loop.vertices.begin(), loop.vertices.end(), a) - loop.vertices.begin();
      const bool loop_edge = loop.vertices[(i + 1) % n] == b || loop.vertices[(i + n - 1) % n] == b;
      if (!loop_edge && in_mesh(edge_of(a, b))) return true;
    }
  return false;
}

}  // namespace cvtmesh
