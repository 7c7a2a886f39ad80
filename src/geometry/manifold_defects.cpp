#include "geometry/manifold_defects.hpp"

#include <algorithm>

#include "geometry/triangle_sides.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

bool degenerate(const Triangle& f) {
  return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
}

}  // namespace

ManifoldDefects find_manifold_defects(std::size_t vertices, const std::vector<Triangle>& tris,
                                      const std::vector<bool>& may_bound, bool folds,
                                      const std::vector<bool>& may_branch) {
  auto branches = [&](Index v) { return !may_branch.empty() && may_branch[v]; };
  // The edges' uses by the triangles, in (edge, triangle) order; none of a degenerate triangle.
  std::vector<TriangleSide> uses = sorted_sides(vertices, tris);
  std::erase_if(uses, [&](const TriangleSide& s) { return degenerate(tris[s.triangle]); });

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
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    const std::size_t count = j - i;
    const bool folded = folds && count == 2 && uses[i].forward == uses[i + 1].forward;
    const bool stray =
        count == 1 && !may_bound.empty() && !(may_bound[uses[i].lo] && may_bound[uses[i].hi]);
    const bool branching = count >= 3 && !(branches(uses[i].lo) && branches(uses[i].hi));
    if (branching || folded || stray)
      for (std::size_t k = i; k < j; ++k) d.triangle[uses[k].triangle] = true;
    if (branching) d.vertex[uses[i].lo] = d.vertex[uses[i].hi] = true;
    d.nonmanifold_edges += branching;
    d.folded_edges += folded;
    d.stray_boundary_edges += stray;
    if (count == 2)
      for (const Index v : {uses[i].lo, uses[i].hi})
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
