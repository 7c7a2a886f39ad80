#include "geometry/manifold_defects.hpp"

#include <algorithm>
#include <tuple>

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
  auto key() const { return std::tie(a, b, triangle); }
};

}  // namespace

ManifoldDefects find_manifold_defects(std::size_t vertices, const std::vector<Triangle>& tris,
                                      const std::vector<bool>& may_bound, bool folds,
                                      const std::vector<bool>& may_branch) {
  auto branches = [&](Index v) { return !may_branch.empty() && may_branch[v]; };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (degenerate(tris[t])) continue;
    for (int k = 0; k < 3; ++k) {
      const Index u = tris[t][k], w = tris[t][(k + 1) % 3];
      uses.push_back({std::min(u, w), std::max(u, w), u < w, t});
    }
  }
  std::sort(uses.begin(), uses.end(),
            [](const EdgeUse& x, const EdgeUse& y) { return x.key() < y.key(); });

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
  // Per vertex, its corners' classes: sorted (vertex, class) pairs, then runs per vertex.
  std::vector<std::pair<Index, std::size_t>> classes;
  classes.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (!degenerate(tris[t]))
      for (int k = 0; k < 3; ++k) classes.push_back({tris[t][k], fans.find(3 * t + k)});
  std::sort(classes.begin(), classes.end());
  for (std::size_t i = 0; i < classes.size();) {
    std::size_t j = i;
    bool several = false;
    while (j < classes.size() && classes[j].first == classes[i].first) {
      several = several || classes[j].second != classes[i].second;
      ++j;
    }
    if (several && !branches(classes[i].first)) {
      ++d.nonmanifold_vertices;
      d.vertex[classes[i].first] = true;
      for (std::size_t k = i; k < j; ++k) d.triangle[classes[k].second / 3] = true;
    }
    i = j;
  }
  return d;
}

}  // namespace cvtmesh
