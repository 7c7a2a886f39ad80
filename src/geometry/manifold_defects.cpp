#include "geometry/manifold_defects.hpp"

#include <algorithm>

#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

bool degenerate(const Triangle& f) {
  return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
}

// One use of an edge by a triangle: the edge's ends (smaller first), whether the triangle runs
// from the smaller to the larger, and the triangle.
struct EdgeUse {
  Index a, b;
  bool forward;
  std::size_t triangle;
};

}  // namespace

ManifoldDefects find_manifold_defects(std::size_t vertices, const std::vector<Triangle>& tris,
                                      const std::vector<bool>& may_bound, bool folds,
                                      const std::vector<bool>& may_branch) {
  auto branches = [&](Index v) { return !may_branch.empty() && may_branch[v]; };
  // The uses in (a, b, triangle) order, by two stable counting sorts (by b, then by a) of the
  // uses as the triangles come: linear in the uses and the vertices (a comparison sort of them was
  // a twentieth of camel.off's remesh at 5k on two threads, run serially after each extraction).
  std::vector<EdgeUse> uses, by_b;
  by_b.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (degenerate(tris[t])) continue;
    for (int k = 0; k < 3; ++k) {
      const Index u = tris[t][k], w = tris[t][(k + 1) % 3];
      by_b.push_back({std::min(u, w), std::max(u, w), u < w, t});
    }
  }
  const auto counting_sort = [&](const std::vector<EdgeUse>& in, Index EdgeUse::*end) {
    std::vector<std::size_t> start(vertices + 1, 0);
    for (const EdgeUse& use : in) ++start[use.*end + 1];
    for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
    std::vector<EdgeUse> out(in.size());
    for (const EdgeUse& use : in) out[start[use.*end]++] = use;
    return out;
  };
  by_b = counting_sort(by_b, &EdgeUse::b);
  uses = counting_sort(by_b, &EdgeUse::a);
  std::vector<EdgeUse>().swap(by_b);

  ManifoldDefects d;
  d.vertex.assign(vertices, false);
  d.triangle.assign(tris.size(), false);
  // Corners (triangle, vertex) joined across the manifold edges they share: a vertex whose
  // corners form several classes has several fans.
  UnionFind fans(3 * tris.size());
  auto corner = [&](std::size_t t, Index v) {
    const Triangle& f = tris[t];
    return 3 * t + static_cast<std::size_t>(f[0] == v ? 0 : f[1] == v ? 1 : 2);
  };
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    const std::size_t count = j - i;
    const bool folded = folds && count == 2 && uses[i].forward == uses[i + 1].forward;
    const bool stray =
        count == 1 && !may_bound.empty() && !(may_bound[uses[i].a] && may_bound[uses[i].b]);
    const bool branching = count >= 3 && !(branches(uses[i].a) && branches(uses[i].b));
    if (branching || folded || stray)
      for (std::size_t k = i; k < j; ++k) d.triangle[uses[k].triangle] = true;
    if (branching) d.vertex[uses[i].a] = d.vertex[uses[i].b] = true;
    d.nonmanifold_edges += branching;
    d.folded_edges += folded;
    d.stray_boundary_edges += stray;
    if (count == 2)
      for (const Index v : {uses[i].a, uses[i].b})
        fans.unite(corner(uses[i].triangle, v), corner(uses[i + 1].triangle, v));
    i = j;
  }
  // A vertex has several fans where its corners are in several classes: each class is named
  // by its root corner, whose triangle then stands for the fan.
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> first_class(vertices, kNone);
  std::vector<bool> several(vertices, false);
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (!degenerate(tris[t]))
      for (int k = 0; k < 3; ++k) {
        const Index v = tris[t][k];
        const std::size_t c = fans.find(3 * t + static_cast<std::size_t>(k));
        if (first_class[v] == kNone)
          first_class[v] = c;
        else if (first_class[v] != c)
          several[v] = true;
      }
  for (std::size_t v = 0; v < vertices; ++v)
    if (several[v] && !branches(static_cast<Index>(v))) {
      ++d.nonmanifold_vertices;
      d.vertex[v] = true;
    }
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (!degenerate(tris[t]))
      for (int k = 0; k < 3; ++k)
        if (several[tris[t][k]] && !branches(tris[t][k]))
          d.triangle[fans.find(3 * t + static_cast<std::size_t>(k)) / 3] = true;
  return d;
}

}  // namespace cvtmesh
