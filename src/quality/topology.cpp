#include "cvtmesh/topology.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "geometry/triangle_sides.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// The corner of triangle t at vertex v, as an index into 3·t + k.
std::size_t corner(const TriangleMesh& mesh, std::size_t t, Index v) {
  const Triangle& f = mesh.triangles[t];
  return 3 * t + (f[0] == v ? 0 : (f[1] == v ? 1 : 2));
}

}  // namespace

TopologyReport analyze_topology(const TriangleMesh& mesh) {
  TopologyReport r;
  const std::size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  r.triangles = nt;

  std::vector<bool> used(nv, false);
  UnionFind vertex_sets(nv);
  for (const Triangle& f : mesh.triangles) {
    for (Index v : f) used[v] = true;
    vertex_sets.unite(f[0], f[1]);
    vertex_sets.unite(f[0], f[2]);
  }
  r.vertices = std::count(used.begin(), used.end(), true);
  r.unreferenced_vertices = nv - r.vertices;

  // Walk the edges: boundary and non-manifold counts, boundary graph, fans around vertices
  // (corners joined across an edge they share), and orientation parity across manifold edges.
  const std::vector<TriangleSide> sides = sorted_sides(mesh);
  UnionFind boundary_sets(nv), fans(3 * nt), parity(2 * nt);  // parity: 2t = as is, 2t+1 = flipped
  std::vector<bool> on_boundary(nv, false);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    const std::size_t count = j - i;
    ++r.edges;
    if (count == 1) {
      ++r.boundary_edges;
      boundary_sets.unite(sides[i].lo, sides[i].hi);
      on_boundary[sides[i].lo] = on_boundary[sides[i].hi] = true;
    } else if (count > 2) {
      ++r.nonmanifold_edges;
    }
    for (std::size_t k = i + 1; k < j; ++k) {
      for (Index v : {sides[i].lo, sides[i].hi})
        fans.unite(corner(mesh, sides[i].triangle, v), corner(mesh, sides[k].triangle, v));
    }
    if (count == 2) {
      const std::size_t s = sides[i].triangle, t = sides[i + 1].triangle;
      // Consistent orientation walks a shared edge once each way; same way means one is flipped.
      const bool same_way = sides[i].forward == sides[i + 1].forward;
      if (same_way) r.consistently_oriented = false;
      parity.unite(2 * s, 2 * t + (same_way ? 1 : 0));
      parity.unite(2 * s + 1, 2 * t + (same_way ? 0 : 1));
    }
    i = j;
  }
  for (std::size_t t = 0; t < nt; ++t)
    if (parity.find(2 * t) == parity.find(2 * t + 1)) r.orientable = false;

  // Per-vertex fan count: a vertex is manifold when all its corners lie in one fan.
  std::vector<std::size_t> first_fan(nv, SIZE_MAX);
  std::vector<bool> nonmanifold_vertex(nv, false);
  for (std::size_t c = 0; c < 3 * nt; ++c) {
    const Index v = mesh.triangles[c / 3][c % 3];
    const std::size_t fan = fans.find(c);
    if (first_fan[v] == SIZE_MAX)
      first_fan[v] = fan;
    else if (first_fan[v] != fan)
      nonmanifold_vertex[v] = true;
  }
  r.nonmanifold_vertices = std::count(nonmanifold_vertex.begin(), nonmanifold_vertex.end(), true);

  // Components, and per component V, E, F and boundary loops for the genus.
  struct Counts {
    long long v = 0, e = 0, f = 0, loops = 0;
  };
  std::vector<Counts> per_root(nv);  // indexed by each component's union-find root
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    Counts& c = per_root[vertex_sets.find(v)];
    ++c.v;
    if (on_boundary[v] && boundary_sets.find(v) == v) ++c.loops;
  }
  for (const Triangle& f : mesh.triangles) ++per_root[vertex_sets.find(f[0])].f;
  for (std::size_t i = 0; i < sides.size(); ++i)
    if (i == 0 || sides[i].lo != sides[i - 1].lo || sides[i].hi != sides[i - 1].hi)
      ++per_root[vertex_sets.find(sides[i].lo)].e;

  long long genus = 0;
  for (const Counts& c : per_root) {
    if (c.v == 0) continue;
    ++r.components;
    r.boundary_loops += c.loops;
    genus += 2 - (c.v - c.e + c.f) - c.loops;
  }
  r.euler_characteristic = static_cast<long long>(r.vertices) - static_cast<long long>(r.edges) +
                           static_cast<long long>(r.triangles);
  if (r.is_manifold() && r.orientable) r.genus = genus / 2;
  return r;
}

bool same_topology(const TopologyReport& a, const TopologyReport& b) {
  return a.components == b.components && a.euler_characteristic == b.euler_characteristic &&
         a.boundary_loops == b.boundary_loops;
}

bool keeps_topology(const TopologyReport& out, const TopologyReport& in) {
  return same_topology(out, in) && (out.is_manifold() || !in.is_manifold());
}

}  // namespace cvtmesh
