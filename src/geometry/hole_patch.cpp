#include "geometry/hole_patch.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>

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

namespace {

// CGAL's search over the loop's 3D Delaunay triangles alone gave a loop whose points lie in a
// plane (a hole in a flat wall) different patches from one call to the next, as the heap went
// (not when built with AddressSanitizer, whose heap hands out addresses in order), so outputs
// differed from run to run; its search over all triangles, which it falls back to, is
// deterministic, and optimal for CGAL's weight, in time cubic in the loop's length. It takes
// loops of up to kMostCubic edges: a loop of 1,305 edges, which the last step opened on a noised
// slab folded through itself, took 30 s, and was patched again each round. Longer loops are split
// in two (split_at) until every part is that short.
constexpr std::size_t kMostCubic = 200;

// Per patch triangle, its corners as places in the loop.
using Places = std::vector<std::array<std::size_t, 3>>;

// Where a loop too long for the cubic search is split: the shortest chord between places half
// the loop apart, (i, i + n/2) with i < n/2 (the first such where two are as short), between
// distinct points. Nothing where every such chord has no length (a loop of repeated points).
std::optional<std::size_t> split_at(const std::vector<Vec3>& p) {
  const std::size_t n = p.size(), half = n / 2;
  std::optional<std::size_t> best;
  double shortest = 0;
  for (std::size_t i = 0; i < half; ++i) {
    const double d = distance(p[i], p[i + half]);
    if (d > 0 && (!best || d < shortest)) best = i, shortest = d;
  }
  return best;
}

// The patch of the loop through `points` (in order; edge k from point k to point k + 1, the last
// back to the first), whose triangle across edge k has its third corner at `third[k]`.
std::optional<Places> patch_places(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& third) {
  const std::size_t n = points.size();
  if (n <= kMostCubic) {
    std::vector<Kernel::Point_3> p, q;
    for (std::size_t k = 0; k < n; ++k) {
      p.emplace_back(points[k].x, points[k].y, points[k].z);
      q.emplace_back(third[k].x, third[k].y, third[k].z);
    }
    std::vector<CGAL::Triple<int, int, int>> patch;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(
        p, q, std::back_inserter(patch),
        CGAL::parameters::use_delaunay_triangulation(false).do_not_use_cubic_algorithm(false));
    if (patch.size() + 2 != n) return std::nullopt;
    Places places;
    for (const auto& [a, b, c] : patch)
      places.push_back(
          {static_cast<std::size_t>(a), static_cast<std::size_t>(b), static_cast<std::size_t>(c)});
    return places;
  }
  // Two loops, each closed by the chord from i to j = i + n/2: the part from i to j, and the part
  // from j round to i. The chord's third corner, which the other part's patch will have, is
  // taken as the mean of that part's other points (it sets the fold CGAL weighs at the chord).
  const std::optional<std::size_t> split = split_at(points);
  if (!split) return std::nullopt;
  const std::size_t i = *split, j = i + n / 2;
  Places places;
  for (const bool first : {true, false}) {
    std::vector<std::size_t> at;  // the part's places in the loop, in order
    for (std::size_t k = first ? i : j;; k = (k + 1) % n) {
      at.push_back(k);
      if (k == (first ? j : i)) break;
    }
    Vec3 across;  // the mean of the other part's points off the chord
    for (std::size_t k = (first ? j + 1 : i + 1) % n; k != (first ? i : j); k = (k + 1) % n)
      across += points[k];
    across = (1.0 / static_cast<double>(n - at.size())) * across;
    std::vector<Vec3> part_points, part_third;
    for (std::size_t k = 0; k < at.size(); ++k) {
      part_points.push_back(points[at[k]]);
      part_third.push_back(k + 1 < at.size() ? third[at[k]] : across);
    }
    const std::optional<Places> part = patch_places(part_points, part_third);
    if (!part) return std::nullopt;
    for (const auto& [a, b, c] : *part) places.push_back({at[a], at[b], at[c]});
  }
  return places;
}

}  // namespace

std::optional<std::vector<Triangle>> hole_patch(const TriangleMesh& mesh, const HoleLoop& loop) {
  std::vector<Vec3> points, third;
  for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
    points.push_back(mesh.vertices[loop.vertices[i]]);
    third.push_back(mesh.vertices[loop.opposite[i]]);
  }
  const std::optional<Places> places = patch_places(points, third);
  if (!places) return std::nullopt;
  std::vector<Triangle> triangles;
  for (const auto& [a, b, c] : *places)
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
