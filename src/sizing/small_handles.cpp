#include "sizing/small_handles.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <utility>

#include "geometry/point_tree.hpp"
#include "geometry/triangles_around.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// The grid of the first, coarse search, as a share of the radius looked at.
constexpr double kProbeCell = 0.25;
// A vertex is on a handle's throat where its loop is at most this many times the thinnest loop
// within its ball's radius.
constexpr double kThroat = 1.5;
// The most grid cells of the coarse search from the origin along an axis.
constexpr double kFinestCells = 1e9;

// Compressed per-vertex lists: list v is items[first[v]] to items[first[v + 1]].
struct Lists {
  std::vector<std::size_t> first;
  std::vector<Index> items;
  std::span<const Index> of(Index v) const {
    return {items.data() + first[v], items.data() + first[v + 1]};
  }
};

// Per vertex, the other ends of its triangles' edges, sorted, each as often as triangles have the
// edge: a counting sort by vertex, then each short list sorted (in parallel), no sort of all the
// edges.
Lists edge_ends(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  Lists ends;
  ends.first.assign(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (const Index v : t) ends.first[v + 1] += 2;
  for (std::size_t v = 0; v < n; ++v) ends.first[v + 1] += ends.first[v];
  ends.items.resize(ends.first[n]);
  std::vector<std::size_t> next(ends.first.begin(), ends.first.end() - 1);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      ends.items[next[t[k]]++] = t[(k + 1) % 3];
      ends.items[next[t[k]]++] = t[(k + 2) % 3];
    }
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t v) {
    std::sort(ends.items.begin() + static_cast<std::ptrdiff_t>(ends.first[v]),
              ends.items.begin() + static_cast<std::ptrdiff_t>(ends.first[v + 1]));
  });
  return ends;
}

// Per vertex, its neighbours along edges (sorted, each once).
Lists neighbours(const TriangleMesh& mesh) {
  const Lists ends = edge_ends(mesh);
  Lists around;
  around.first.assign(mesh.vertices.size() + 1, 0);
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    const std::span<const Index> all = ends.of(v);
    std::unique_copy(all.begin(), all.end(), std::back_inserter(around.items));
    around.first[v + 1] = around.items.size();
  }
  return around;
}

// One thread's state for growing balls, reset by stamps rather than clears.
struct Scratch {
  std::vector<std::uint32_t> in_ball, reached;
  std::vector<double> distance;
  std::uint32_t stamp = 0;
  std::vector<std::pair<double, Index>> heap;
};

// The radius at which the geodesic ball around `source` (Dijkstra along the edges) stops being a
// disc for good, if it does within `radius`; -1 otherwise. Its Euler characteristic (the
// triangles with every corner in it, their edges and vertices) is 1 while it is a disc; once it
// falls to 0 or below, the ball takes in every vertex it has reached so far (a vertex whose
// neighbours all came in first left a hole that closes then), and the fall counts if it lasts.
double wrap_radius(const TriangleMesh& mesh, const Lists& around,
                   const std::vector<std::vector<Index>>& at, Index source, double radius,
                   Scratch& s) {
  const std::uint32_t stamp = ++s.stamp;
  const auto greater = std::greater<std::pair<double, Index>>();
  s.heap.assign(1, {0.0, source});
  s.reached[source] = stamp;
  s.distance[source] = 0;
  long long euler = 0;
  double wrapped = -1, settled = -1;  // where it fell, and how far it must hold
  while (!s.heap.empty()) {
    std::pop_heap(s.heap.begin(), s.heap.end(), greater);
    const auto [d, w] = s.heap.back();
    s.heap.pop_back();
    if (s.in_ball[w] == stamp || d > s.distance[w]) continue;
    if (wrapped >= 0 && d > settled) return wrapped;
    if (wrapped < 0 && d > radius) return -1;
    s.in_ball[w] = stamp;
    ++euler;
    for (const Index u : around.of(w)) {
      if (s.in_ball[u] == stamp) {
        --euler;
        continue;
      }
      const double to_u = d + distance(mesh.vertices[w], mesh.vertices[u]);
      if (s.reached[u] != stamp || to_u < s.distance[u]) {
        s.reached[u] = stamp;
        s.distance[u] = to_u;
        s.heap.emplace_back(to_u, u);
        std::push_heap(s.heap.begin(), s.heap.end(), greater);
      }
    }
    for (const Index t : at[w]) {
      const Triangle& tri = mesh.triangles[t];
      if (std::all_of(tri.begin(), tri.end(), [&](Index v) { return s.in_ball[v] == stamp; }))
        ++euler;
    }
    if (euler >= 1) {
      wrapped = -1;
    } else if (wrapped < 0) {
      wrapped = d;
      settled = d;
      for (const auto& entry : s.heap) settled = std::max(settled, entry.first);
    }
  }
  return wrapped;  // the whole part taken in, no disc
}

}  // namespace

bool has_handles(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  const Lists ends = edge_ends(mesh);
  UnionFind parts(n), loops(n);
  for (const Triangle& t : mesh.triangles) {
    parts.unite(t[0], t[1]);
    parts.unite(t[1], t[2]);
  }
  std::vector<bool> on_boundary(n, false);
  long long vertices = 0, edges = 0, components = 0, boundaries = 0;
  for (Index v = 0; v < n; ++v) {
    const std::span<const Index> all = ends.of(v);
    for (auto i = all.begin(); i != all.end();) {
      const auto j = std::find_if(i, all.end(), [&](Index u) { return u != *i; });
      if (j - i > 2) return false;  // an edge of three or more triangles: no surface there
      if (*i > v) {                 // each edge once, from its lower end
        ++edges;
        if (j - i == 1) {
          loops.unite(v, *i);
          on_boundary[v] = on_boundary[*i] = true;
        }
      }
      i = j;
    }
  }
  for (Index v = 0; v < n; ++v) {
    if (ends.of(v).empty()) continue;  // in no triangle
    ++vertices;
    components += parts.find(v) == v;
    boundaries += on_boundary[v] && loops.find(v) == v;
  }
  // Twice the genus summed over the parts: 2 - χ - b each.
  const long long euler = vertices - edges + static_cast<long long>(mesh.triangles.size());
  return 2 * components - euler - boundaries > 0;
}

std::vector<double> handle_widths(const TriangleMesh& mesh, double reach) {
  const std::size_t n = mesh.vertices.size();
  std::vector<double> width(n, std::numeric_limits<double>::infinity());
  if (!(reach > 0) || !std::isfinite(reach) || !has_handles(mesh)) return width;
  const Lists around = neighbours(mesh);
  const std::vector<std::vector<Index>> at = triangles_around(mesh);
  // A loop around a handle of width w (its throat's diameter, were it round) is πw long; a ball
  // wraps round it at half that radius.
  const double radius = std::numbers::pi / 2 * reach;
  tbb::enumerable_thread_specific<Scratch> scratch([n] {
    Scratch s;
    s.in_ball.assign(n, 0);
    s.reached.assign(n, 0);
    s.distance.assign(n, 0);
    return s;
  });
  // First from one vertex per cell of a grid a quarter of the radius wide (the first by id), out
  // to the radius and a cell's diagonal more: one of them lies that near any loop around a
  // handle, and wraps round it. Then from every vertex within twice the radius of those that
  // wrapped, each to its own loop.
  const double cell = kProbeCell * radius;
  // Cells numbered in 64 bits: none is looked for at a scale a billionth of the mesh's or finer
  // (the remesher's copy is about unit size, and its reach a share of an edge).
  const BoundingBox box = bounding_box(mesh);
  if (!(std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z),
                  std::abs(box.max.x), std::abs(box.max.y), std::abs(box.max.z)}) <
        kFinestCells * cell))
    return width;
  std::map<std::array<std::int64_t, 3>, Index> first_in_cell;
  for (Index v = 0; v < n; ++v) {
    if (around.of(v).empty()) continue;
    const Vec3& p = mesh.vertices[v];
    first_in_cell.try_emplace({static_cast<std::int64_t>(std::floor(p.x / cell)),
                               static_cast<std::int64_t>(std::floor(p.y / cell)),
                               static_cast<std::int64_t>(std::floor(p.z / cell))},
                              v);
  }
  std::vector<Index> probes;
  for (const auto& [key, v] : first_in_cell) probes.push_back(v);
  std::sort(probes.begin(), probes.end());
  std::vector<char> wraps(probes.size(), 0);
  const double probe_radius = radius + std::sqrt(3.0) * cell;
  tbb::parallel_for(std::size_t{0}, probes.size(), [&](std::size_t i) {
    wraps[i] = wrap_radius(mesh, around, at, probes[i], probe_radius, scratch.local()) >= 0;
  });
  std::vector<Vec3> near;
  for (std::size_t i = 0; i < probes.size(); ++i)
    if (wraps[i]) near.push_back(mesh.vertices[probes[i]]);
  if (near.empty()) return width;
  const PointTree tree(near);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t v) {
    if (around.of(static_cast<Index>(v)).empty()) return;
    const Vec3& p = mesh.vertices[v];
    if (distance(p, near[tree(p)]) > 2 * radius) return;
    // The loop through the vertex is about twice the radius where its ball wrapped.
    const double r = wrap_radius(mesh, around, at, static_cast<Index>(v), radius, scratch.local());
    if (r >= 0) width[v] = 2 * r / std::numbers::pi;
  });
  // Only the handle's throat, as only a hole's rim: a vertex whose own loop is much longer than
  // one within its ball's radius (its loop runs to the throat and back) takes its size from the
  // grading instead, which spreads it as the settings ask (that of every vertex's own loop grows
  // a third of the distance, and took femur.off's whole count at 1k).
  std::vector<Index> looped;
  std::vector<Vec3> at_loops;
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(width[v])) looped.push_back(v), at_loops.push_back(mesh.vertices[v]);
  const PointTree loops(at_loops);
  std::vector<double> throat(n, std::numeric_limits<double>::infinity());
  tbb::parallel_for(std::size_t{0}, looped.size(), [&](std::size_t i) {
    const Index v = looped[i];
    const double r = std::numbers::pi / 2 * width[v];
    std::vector<Index> found;
    loops.within(mesh.vertices[v], r * r, found);
    double thinnest = width[v];
    for (const Index j : found) thinnest = std::min(thinnest, width[looped[j]]);
    if (width[v] <= kThroat * thinnest) throat[v] = width[v];
  });
  return throat;
}

}  // namespace cvtmesh
