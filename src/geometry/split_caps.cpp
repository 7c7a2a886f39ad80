#include "geometry/split_caps.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 point(const TriangleMesh& mesh, Index v) {
  const Vec3& p = mesh.vertices[v];
  return {p.x, p.y, p.z};
}

Edge undirected(Index a, Index b) {
  return {std::min(a, b), std::max(a, b)};
}

// The corner of cap `t` that lies strictly between the other two (0, 1 or 2); none when two
// corners are at one point (a needle: nothing to split at).
std::optional<int> middle_corner(const TriangleMesh& mesh, const Triangle& t) {
  for (int k = 0; k < 3; ++k)
    if (CGAL::collinear_are_strictly_ordered_along_line(
            point(mesh, t[(k + 1) % 3]), point(mesh, t[k]), point(mesh, t[(k + 2) % 3])))
      return k;
  return std::nullopt;
}

// One pass over the caps, each split against the triangles as the pass found them (a triangle
// changed in this pass waits for the next). Returns how many were split.
std::size_t split_pass(TriangleMesh& mesh) {
  std::vector<std::size_t> caps;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2] && zero_area(mesh, f)) caps.push_back(t);
  }
  if (caps.empty()) return 0;
  std::set<Edge> edges;
  for (const Triangle& f : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(undirected(f[k], f[(k + 1) % 3]));
  // The triangles at each edge of a cap.
  std::map<Edge, std::vector<std::size_t>> triangles_of;
  for (const std::size_t t : caps) {
    const Triangle& f = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) triangles_of[undirected(f[k], f[(k + 1) % 3])];
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (auto at = triangles_of.find(undirected(f[k], f[(k + 1) % 3])); at != triangles_of.end())
        at->second.push_back(t);
  }
  std::vector<bool> changed(mesh.triangles.size(), false);
  std::vector<bool> dropped(mesh.triangles.size(), false);
  std::vector<Triangle> halves;
  std::size_t split = 0;
  for (const std::size_t t : caps) {
    if (changed[t]) continue;
    const Triangle cap = mesh.triangles[t];
    const std::optional<int> m = middle_corner(mesh, cap);
    if (!m) continue;
    const Index c = cap[*m], a = cap[(*m + 1) % 3], b = cap[(*m + 2) % 3];
    const std::vector<std::size_t>& across = triangles_of.at(undirected(a, b));
    if (across.size() != 2) continue;
    const std::size_t other = across[0] == t ? across[1] : across[0];
    if (changed[other] || zero_area(mesh, mesh.triangles[other])) continue;
    // The other triangle as (p, q, d), with p q its side along the cap's long edge, in its own
    // orientation.
    Triangle o = mesh.triangles[other];
    while (!((o[0] == a && o[1] == b) || (o[0] == b && o[1] == a)))
      std::rotate(o.begin(), o.begin() + 1, o.end());
    const Index d = o[2];
    if (d == c || edges.contains(undirected(c, d))) continue;
    mesh.triangles[other] = {o[0], c, d};
    halves.push_back({c, o[1], d});
    edges.insert(undirected(c, d));
    changed[t] = changed[other] = true;
    dropped[t] = true;
    ++split;
  }
  std::size_t n = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!dropped[t]) mesh.triangles[n++] = mesh.triangles[t];
  mesh.triangles.resize(n);
  mesh.triangles.insert(mesh.triangles.end(), halves.begin(), halves.end());
  return split;
}

}  // namespace

bool zero_area(const TriangleMesh& mesh, const Triangle& t) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
         CGAL::collinear(point(mesh, t[0]), point(mesh, t[1]), point(mesh, t[2]));
}

std::size_t split_caps(TriangleMesh& mesh) {
  std::size_t total = 0;
  while (const std::size_t split = split_pass(mesh)) total += split;
  return total;
}

}  // namespace cvtmesh
