#include "sizing/split_for_sizes.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace cvtmesh {

namespace {

// A safety net: the splits stop after this many added vertices per given triangle (graded sizes
// converge towards the small end within a few halvings of each edge). No corpus mesh meets it; a
// needle whose apex has a tiny size did while midpoints were sized from their edge's ends alone
// (SplitForSizes.ANeedleWithATinySizeAtItsApexIsSplitFewTimes).
constexpr std::size_t kMostPerTriangle = 8;
// Bounds on the work for one triangle: the halvings before its own longest edge is halved, and
// the steps along a longest-edge path (an edge reached at the last step is halved as if it ended
// the path). A triangle far smaller than its neighbours would have them refined down to its size
// first: at a hole 0.1% of an edge across (ChineseDragon-10kv.off), paths thousands of triangles
// long, for minutes. Left unsplit, such a triangle is smaller than a cell anyway.
constexpr int kMostRounds = 32;
constexpr int kLongestPath = 16;

std::uint64_t key_of(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

// Midpoints by the edge they halve, to follow a split edge down to its pieces.
using Midpoints = std::unordered_map<std::uint64_t, Index>;

// Appends to `out` the vertices after `a` along edge (a, b) as split: its midpoints, then b.
void append_pieces(const Midpoints& mid, Index a, Index b, std::vector<Index>& out) {
  const auto it = mid.find(key_of(a, b));
  if (it == mid.end()) {
    out.push_back(b);
    return;
  }
  append_pieces(mid, a, it->second, out);
  append_pieces(mid, it->second, b, out);
}

}  // namespace

std::optional<SplitForSizes> split_for_sizes(const TriangleMesh& mesh,
                                             const std::vector<double>& sizes, double ratio,
                                             double gradation) {
  SplitForSizes out;
  std::vector<double>& size = out.sizes;
  size = sizes;
  std::vector<Triangle>& triangles = out.mesh.triangles;
  // A triangle whose edges are all shorter than an eighth of its smallest size lies within one
  // cell, which no split of it would make follow the sizes better. Where the sizes are not
  // graded (a midpoint graded from the vertex across its edge may lie right by a vertex of a much
  // larger size), halving towards that vertex would never bring the two within the ratio: the
  // camel of the corpus with 166 one-triangle holes made 155,000 midpoints converge on one
  // vertex, down to coincident corners, and its remesh at 9k took 7 minutes.
  constexpr double kFinest = 0.125;
  const auto needs_split = [&](std::size_t t) {
    const Triangle& f = triangles[t];
    const auto [lo, hi] = std::minmax({size[f[0]], size[f[1]], size[f[2]]});
    if (!(hi > ratio * lo)) return false;
    const double reach = kFinest * lo;
    const auto [a, b, c] = out.mesh.corners(t);
    return std::max({distance(a, b), distance(b, c), distance(c, a)}) >= reach;
  };
  out.mesh = mesh;
  std::vector<std::size_t> queue;
  for (std::size_t t = triangles.size(); t-- > 0;)
    if (needs_split(t)) queue.push_back(t);
  if (queue.empty()) return std::nullopt;

  std::vector<std::size_t> parent(triangles.size());  // per triangle, the given one it is part of
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> on_edge;
  on_edge.reserve(triangles.size() * 2);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::vector<std::size_t>& on = on_edge[key_of(triangles[t][k], triangles[t][(k + 1) % 3])];
      if (on.empty() || on.back() != t) on.push_back(t);  // once, even on a degenerate triangle
    }
  const std::size_t most = kMostPerTriangle * mesh.triangles.size();
  // A triangle's longest edge, ties broken by the vertex ids: a strict order along any path.
  const auto longest_of = [&](std::size_t t) {
    const Triangle& f = triangles[t];
    Edge best{};
    double best_length = -1;
    for (int k = 0; k < 3; ++k) {
      const Edge e{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])};
      const double length = distance(out.mesh.vertices[e[0]], out.mesh.vertices[e[1]]);
      if (length > best_length || (length == best_length && e > best)) {
        best = e;
        best_length = length;
      }
    }
    return best;
  };
  // Halves edge (a, b) and every triangle on it; queues the pieces.
  const auto halve = [&](Index a, Index b) {
    const auto it = on_edge.find(key_of(a, b));
    const std::vector<std::size_t> on = std::move(it->second);
    on_edge.erase(it);
    const auto m = static_cast<Index>(out.mesh.vertices.size());
    const Vec3 pa = out.mesh.vertices[a], pb = out.mesh.vertices[b];
    const Vec3 pm = 0.5 * (pa + pb);
    double s = (size[a] + size[b]) / 2;
    if (gradation > 0) {
      // Graded from every vertex it gets an edge to: the ends, and the vertex across the edge
      // in each triangle on it. The midpoint of a needle's long side lies close to the vertex
      // across; bigger than that vertex's size allows, it would make the short new edge need a
      // split, and so on down to nothing.
      s = std::min(s, std::min(size[a], size[b]) + distance(pa, pb) / 2 / gradation);
      for (const std::size_t t : on)
        for (const Index c : triangles[t])
          if (c != a && c != b)
            s = std::min(s, size[c] + distance(pm, out.mesh.vertices[c]) / gradation);
    }
    out.mesh.vertices.push_back(pm);
    size.push_back(s);
    out.halved.push_back({a, b});
    for (const std::size_t t : on) {
      // t = (p, q, c) with {p, q} = {a, b}, in its own orientation; it becomes (p, m, c), and
      // (m, q, c) is added.
      int k = 0;
      while (key_of(triangles[t][k], triangles[t][(k + 1) % 3]) != key_of(a, b)) ++k;
      const Index p = triangles[t][k], q = triangles[t][(k + 1) % 3], c = triangles[t][(k + 2) % 3];
      const std::size_t u = triangles.size();
      triangles[t] = {p, m, c};
      triangles.push_back({m, q, c});
      parent.push_back(parent[t]);
      on_edge[key_of(p, m)].push_back(t);
      on_edge[key_of(m, q)].push_back(u);
      std::vector<std::size_t>& mc = on_edge[key_of(m, c)];
      mc.push_back(t);
      mc.push_back(u);
      std::vector<std::size_t>& qc = on_edge[key_of(q, c)];
      std::replace(qc.begin(), qc.end(), t, u);
      queue.push_back(t);
      queue.push_back(u);
    }
  };
  // Rivara's longest-edge bisection along the longest-edge propagation path (LEPP): a triangle
  // whose sizes differ too much is halved across its longest edge, once that edge is the longest
  // of the triangle beyond it too (else that one is halved first): the pieces shrink towards the
  // small end with their angles bounded below. Halving other edges makes needles, which need
  // many more splits.
  while (!queue.empty() && out.halved.size() < most) {
    const std::size_t t = queue.back();
    queue.pop_back();
    if (!needs_split(t)) continue;
    const Edge own = longest_of(t);
    if (own[0] == own[1]) continue;  // a degenerate triangle: nothing to halve
    for (int round = 0; round < kMostRounds && out.halved.size() < most; ++round) {
      std::size_t at = t;
      Edge e = own;
      for (int step = 0; step < kLongestPath; ++step) {
        const std::vector<std::size_t>& on = on_edge.at(key_of(e[0], e[1]));
        if (on.size() != 2) break;  // a boundary or non-manifold edge ends the path
        const std::size_t beyond = on[0] == at ? on[1] : on[0];
        const Edge next = longest_of(beyond);
        if (next == e) break;
        at = beyond;
        e = next;
      }
      halve(e[0], e[1]);
      if (e == own) break;
    }
  }
  // Children where their parent was: the triangle order stays spatial.
  std::vector<std::size_t> order(triangles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return parent[x] < parent[y]; });
  std::vector<Triangle> sorted(triangles.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = triangles[order[i]];
  triangles = std::move(sorted);
  return out;
}

Features split_features(const Features& features, const SplitForSizes& split,
                        std::size_t given_vertices) {
  Midpoints mid;
  for (std::size_t k = 0; k < split.halved.size(); ++k)
    mid[key_of(split.halved[k][0], split.halved[k][1])] = static_cast<Index>(given_vertices + k);
  Features out;
  out.corners = features.corners;
  std::vector<Index> path;
  for (const Edge& e : features.edges) {
    path.assign(1, e[0]);
    append_pieces(mid, e[0], e[1], path);
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
      out.edges.push_back({std::min(path[k], path[k + 1]), std::max(path[k], path[k + 1])});
  }
  std::sort(out.edges.begin(), out.edges.end());
  for (const FeatureCurve& curve : features.curves) {
    FeatureCurve& c = out.curves.emplace_back();
    c.closed = curve.closed;
    const std::vector<Index>& v = curve.vertices;
    if (v.empty()) continue;
    c.vertices.push_back(v[0]);
    for (std::size_t k = 0; k + 1 < v.size(); ++k) append_pieces(mid, v[k], v[k + 1], c.vertices);
    if (curve.closed && v.size() > 1) {
      append_pieces(mid, v.back(), v[0], c.vertices);
      c.vertices.pop_back();  // the first again
    }
  }
  return out;
}

}  // namespace cvtmesh
