#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <tuple>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "geometry/manifold_defects.hpp"
#include "geometry/near_points.hpp"
#include "geometry/orient_triangles.hpp"
#include "geometry/split_caps.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// Keeps the vertices with keep[v], in order, and renumbers the triangles. Returns each vertex's
// new id (kRemovedVertex for those not kept).
std::vector<Index> compact_vertices(TriangleMesh& mesh, const std::vector<bool>& keep) {
  std::vector<Index> new_index(mesh.vertices.size(), kRemovedVertex);
  std::size_t n = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!keep[v]) continue;
    new_index[v] = static_cast<Index>(n);
    mesh.vertices[n++] = mesh.vertices[v];
  }
  mesh.vertices.resize(n);
  for (Triangle& t : mesh.triangles)
    for (Index& v : t) v = new_index[v];
  return new_index;
}

// Vertex ids through two renumberings, `first` then `second`.
void compose(std::vector<Index>& first, const std::vector<Index>& second) {
  for (Index& v : first)
    if (v != kRemovedVertex) v = second[v];
}

// A vertex's star: how many fans its triangles make (joined across its edges of exactly two of
// them), and how many of its edges have three or more; per triangle, the first of its fan.
struct Star {
  std::size_t fans = 0, branching_edges = 0;
  std::vector<std::size_t> fan_of;
};

Star star_of(Index v, const std::vector<Triangle>& around) {
  std::map<Index, std::vector<std::size_t>> at_edge;  // per other end, the triangles
  for (std::size_t i = 0; i < around.size(); ++i)
    for (const Index w : around[i])
      if (w != v) at_edge[w].push_back(i);
  UnionFind fans(around.size());
  Star star;
  for (const auto& [w, triangles] : at_edge) {
    if (triangles.size() == 2) fans.unite(triangles[0], triangles[1]);
    star.branching_edges += triangles.size() > 2;
  }
  for (std::size_t i = 0; i < around.size(); ++i) {
    star.fan_of.push_back(fans.find(i));
    star.fans += star.fan_of.back() == i;
  }
  return star;
}

// Per vertex flagged (its merged vertex is non-manifold in `merged`), whether the merge made it
// so: more fans than the most any of the vertices merged into it (`to`) had in `original`, or
// more edges of three or more triangles than they had together. A group whose vertex was a pinch
// already, merged with copies that only close slits in its fans, stays merged (teapot.obj of a
// public test set: three vertices at one point, one of them a pinch of two fans; kept apart, its
// remesh welded the wrong ones).
std::vector<bool> made_worse(const std::vector<Triangle>& original,
                             const std::vector<Triangle>& merged, const std::vector<Index>& to,
                             const std::vector<bool>& flagged) {
  std::map<Index, std::vector<Triangle>> before, after;  // per vertex merged into a flagged one
  for (const Triangle& t : original)
    for (const Index v : t)
      if (flagged[to[v]]) before[v].push_back(t);
  for (const Triangle& t : merged)
    for (const Index v : t)
      if (flagged[v]) after[v].push_back(t);
  std::map<Index, Star> most;  // per flagged vertex: the most fans of those merged, edges summed
  for (const auto& [v, around] : before) {
    const Star star = star_of(v, around);
    Star& m = most[to[v]];
    m.fans = std::max(m.fans, star.fans);
    m.branching_edges += star.branching_edges;
  }
  std::vector<bool> worse(flagged.size(), false);
  for (const auto& [v, around] : after) {
    const Star star = star_of(v, around), m = most[v];
    worse[v] = star.fans > m.fans || star.branching_edges > m.branching_edges;
  }
  return worse;
}

// Splits the vertices that `worse` marks, each into one per fan of its triangles in `merged`
// (joined across its edges of exactly two triangles): the vertices merged into it (`to`) whose
// triangles (`source`: per triangle of `merged`, its index in `original`) lie in one fan go
// together, into the first of them in file order. In a triangle soup, where each copy of a vertex
// has one triangle, two parts that touch at a point get a vertex each there, and the copies around
// it stay merged (keeping them all apart left the triangles there unstitched, so that their
// neighbours' stars split in turn, until nothing of a soup of diplodocus.off merged). Where one
// fan holds them all, they are kept apart, each its own vertex.
void split_by_fans(const std::vector<Triangle>& original, const std::vector<Triangle>& merged,
                   const std::vector<std::size_t>& source, const std::vector<bool>& worse,
                   std::vector<Index>& to) {
  std::map<Index, std::vector<std::size_t>> star;  // per vertex to split, its triangles
  for (std::size_t k = 0; k < merged.size(); ++k)
    for (const Index v : merged[k])
      if (worse[v]) star[v].push_back(k);
  std::map<Index, std::vector<Index>> merged_into;  // per vertex to split, in file order
  for (std::size_t v = 0; v < to.size(); ++v)
    if (worse[to[v]]) merged_into[to[v]].push_back(static_cast<Index>(v));
  for (auto& [v, copies] : merged_into) {
    const std::vector<std::size_t>& around = star[v];
    std::vector<Triangle> triangles;
    for (const std::size_t k : around) triangles.push_back(merged[k]);
    const Star fans = star_of(v, triangles);
    UnionFind together(copies.size());
    std::map<std::size_t, std::size_t> fan_copy;  // per fan, a copy of its triangles
    for (std::size_t i = 0; i < around.size(); ++i) {
      const Triangle& m = merged[around[i]];
      const auto corner = std::find(m.begin(), m.end(), v) - m.begin();
      const Index copy = original[source[around[i]]][corner];
      const std::size_t c = std::lower_bound(copies.begin(), copies.end(), copy) - copies.begin();
      const auto [at, first] = fan_copy.try_emplace(fans.fan_of[i], c);
      if (!first) together.unite(c, at->second);
    }
    std::vector<Index> first_of(copies.size(), kRemovedVertex);  // per class root
    std::size_t classes = 0;
    for (std::size_t c = 0; c < copies.size(); ++c)
      if (Index& f = first_of[together.find(c)]; f == kRemovedVertex) f = copies[c], ++classes;
    for (std::size_t c = 0; c < copies.size(); ++c)
      to[copies[c]] = classes > 1 ? first_of[together.find(c)] : copies[c];
  }
}

// Merges vertices with equal coordinates, or within near_point_tolerance of one another, where
// that stitches the mesh, as CGAL's stitch_borders does: a group whose merge would leave a
// non-manifold edge or vertex there is split by fans (split_by_fans: two parts that touch at a
// point or along an edge are not welded; issue 18, diplodocus.off). Groups are merged all at
// once, then those at a defect that the merge made are split, until none is. Returns the vertices
// merged; `nearly_equal` counts those of them not exactly at their group's first vertex,
// `kept_apart` the vertices that a group was split into, less one each; `new_id`: each vertex's
// id after the merge.
std::size_t merge_duplicate_vertices(TriangleMesh& mesh, std::size_t& nearly_equal,
                                     std::size_t& kept_apart, std::vector<Index>& new_id) {
  const auto& p = mesh.vertices;
  // Each group maps to its first vertex in file order, whose position it takes.
  const std::vector<Index> representative = near_point_groups(p, near_point_tolerance(p));
  std::vector<std::size_t> group_size(p.size(), 0);
  for (const Index r : representative) ++group_size[r];
  kept_apart = nearly_equal = 0;
  if (std::none_of(group_size.begin(), group_size.end(), [](std::size_t n) { return n > 1; }))
    return 0;
  std::vector<Index> to(p.size());  // per vertex, the vertex it merges into (itself: none)
  for (std::size_t v = 0; v < p.size(); ++v) to[v] = representative[v];
  for (;;) {
    std::vector<Triangle> merged;
    std::vector<std::size_t> source;  // per merged triangle, its index in the mesh
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      Triangle m = mesh.triangles[t];
      for (Index& v : m) v = to[v];
      // A triangle with two nearly equal corners collapses; the repair drops it.
      if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2]) continue;
      merged.push_back(m);
      source.push_back(t);
    }
    // Boundary edges and folds are allowed: only a non-manifold edge or vertex splits a group,
    // and only one that the merge made worse than the group's own vertices were.
    const std::vector<bool> bad = find_manifold_defects(p.size(), merged, {}, false).vertex;
    std::vector<std::size_t> merged_count(p.size(), 0);
    for (const Index t : to) ++merged_count[t];
    std::vector<bool> flagged(p.size(), false);
    bool any_flagged = false;
    for (std::size_t v = 0; v < p.size(); ++v)
      any_flagged |= flagged[v] = bad[v] && to[v] == v && merged_count[v] > 1;
    if (!any_flagged) break;  // the usual case: no merge made a defect
    std::vector<bool> worse = made_worse(mesh.triangles, merged, to, flagged);
    if (std::none_of(worse.begin(), worse.end(), [](bool w) { return w; })) break;
    // No two neighbours split at once: where two merged vertices share an edge of four
    // triangles, splitting either mends both, and splitting both opens a slit between them
    // (each splits the four into other pairs). The first in file order is split, the other
    // judged again once it is.
    std::map<Index, std::vector<Index>> neighbours;  // of the vertices to split
    for (const Triangle& t : merged)
      for (const Index v : t)
        if (worse[v]) neighbours[v].insert(neighbours[v].end(), t.begin(), t.end());
    std::vector<bool> beside(p.size(), false);  // a neighbour of a vertex split this time
    for (const auto& [v, around] : neighbours) {
      if (beside[v]) {
        worse[v] = false;
        continue;
      }
      for (const Index w : around) beside[w] = true;
    }
    split_by_fans(mesh.triangles, merged, source, worse, to);
  }
  std::vector<bool> keep(p.size(), true);
  std::size_t count = 0;
  for (std::size_t v = 0; v < p.size(); ++v)
    if (to[v] != v) {
      keep[v] = false, ++count;
      nearly_equal += p[to[v]] != p[v];
    } else if (representative[v] != v) {
      ++kept_apart;  // the first vertex of a part its group was split into, not the group's
    }
  if (count == 0) return 0;
  for (Triangle& t : mesh.triangles)
    for (Index& v : t) v = to[v];
  const std::vector<Index> compacted = compact_vertices(mesh, keep);
  for (std::size_t v = 0; v < new_id.size(); ++v) new_id[v] = compacted[to[v]];
  return count;
}

std::size_t remove_degenerate_triangles(TriangleMesh& mesh) {
  const std::size_t before = mesh.triangles.size();
  std::erase_if(mesh.triangles, [&](const Triangle& t) { return zero_area(mesh, t); });
  return before - mesh.triangles.size();
}

// The non-manifold edges and vertices of `mesh`.
std::size_t nonmanifold_elements(const TriangleMesh& mesh) {
  const ManifoldDefects d = find_manifold_defects(mesh.vertices.size(), mesh.triangles, {}, true);
  return d.nonmanifold_edges + d.nonmanifold_vertices;
}

// The zero-area triangles out: caps split out (split_caps), then the others dropped; but all
// dropped where splitting would leave more non-manifold edges and vertices (degtri_sliding.off
// of CGAL's data, two parts joined only by a strip of zero-area triangles: split, they would
// touch at a vertex). Sets how many were split out and dropped.
void remove_zero_area_triangles(TriangleMesh& mesh, std::size_t& split, std::size_t& dropped) {
  split = 0;
  // Collinear corners, all distinct: a cap, or three corners at one point.
  const bool caps =
      std::any_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const Triangle& t) {
        return t[0] != t[1] && t[1] != t[2] && t[0] != t[2] && zero_area(mesh, t);
      });
  if (caps) {
    TriangleMesh capped = mesh;
    split = split_caps(capped);
    if (split > 0) {
      const std::size_t rest = remove_degenerate_triangles(capped);
      TriangleMesh all_dropped = mesh;
      remove_degenerate_triangles(all_dropped);
      if (nonmanifold_elements(capped) <= nonmanifold_elements(all_dropped)) {
        mesh = std::move(capped);
        dropped = rest;
        return;
      }
      split = 0;
    }
  }
  dropped = remove_degenerate_triangles(mesh);
}

std::size_t remove_unreferenced_vertices(TriangleMesh& mesh, std::vector<Index>& new_id) {
  const std::vector<bool> used = used_vertices(mesh);
  const std::size_t unused = std::count(used.begin(), used.end(), false);
  if (unused > 0) compose(new_id, compact_vertices(mesh, used));
  return unused;
}

}  // namespace

std::size_t remove_duplicate_triangles(TriangleMesh& mesh) {
  // Each triangle's sorted corners: copies of a triangle have the same. Bucketed by the smallest
  // (a counting sort, stable: each bucket in file order), then each bucket, a vertex's few
  // triangles, sorted by the rest and the index: copies end up adjacent, the first in file order
  // first. Linear where one sort of all triangles was a tenth of repairing a 270k-triangle scan.
  const std::size_t nt = mesh.triangles.size();
  std::vector<Triangle> key(mesh.triangles);
  std::size_t ids = 0;  // past the largest vertex id
  for (Triangle& k : key) {
    std::sort(k.begin(), k.end());
    ids = std::max(ids, std::size_t{k[2]} + 1);
  }
  std::vector<std::size_t> start(ids + 1, 0);
  for (const Triangle& k : key) ++start[k[0] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::size_t> order(nt), next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t) order[next[key[t][0]]++] = t;
  std::vector<bool> keep(nt, true);
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto begin = order.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto end = order.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    if (end - begin < 2) continue;
    std::sort(begin, end, [&](std::size_t a, std::size_t b) {
      return std::tie(key[a][1], key[a][2], a) < std::tie(key[b][1], key[b][2], b);
    });
    for (auto i = begin + 1; i != end; ++i)
      if (key[*i] == key[*(i - 1)]) keep[*i] = false;
  }
  std::size_t n = 0;
  for (std::size_t t = 0; t < nt; ++t)
    if (keep[t]) mesh.triangles[n++] = mesh.triangles[t];
  const std::size_t removed = nt - n;
  mesh.triangles.resize(n);
  return removed;
}

std::string RepairReport::summary() const {
  std::string s;
  auto add = [&](std::size_t n, const char* what) {
    if (n == 0) return;
    if (!s.empty()) s += ", ";
    s += std::to_string(n) + " " + what;
  };
  add(duplicate_vertices_merged, "duplicate vertices merged");
  if (nearly_equal_vertices_merged > 0)
    s += " (" + std::to_string(nearly_equal_vertices_merged) +
         " of them nearly equal: within 1e-12 of the model's size)";
  add(duplicate_vertices_kept_apart,
      "duplicate vertices kept apart (merging them would make the mesh non-manifold)");
  add(caps_split,
      "zero-area triangles split out (the triangle across each one's long edge split at its "
      "middle corner: no slit opened)");
  add(degenerate_triangles_removed, "zero-area triangles removed");
  add(duplicate_triangles_removed, "duplicate triangles removed");
  add(unreferenced_vertices_removed, "unreferenced vertices removed");
  add(triangles_flipped, "triangles flipped to agree with their neighbours");
  return s;
}

RepairReport repair_mesh(TriangleMesh& mesh, std::vector<Index>* new_id) {
  RepairReport r;
  std::vector<Index> ids(mesh.vertices.size());
  std::iota(ids.begin(), ids.end(), Index{0});
  r.duplicate_vertices_merged = merge_duplicate_vertices(mesh, r.nearly_equal_vertices_merged,
                                                         r.duplicate_vertices_kept_apart, ids);
  remove_zero_area_triangles(mesh, r.caps_split, r.degenerate_triangles_removed);
  r.duplicate_triangles_removed = remove_duplicate_triangles(mesh);
  r.unreferenced_vertices_removed = remove_unreferenced_vertices(mesh, ids);
  r.triangles_flipped = orient_consistently(mesh);
  if (new_id) *new_id = std::move(ids);
  return r;
}

std::vector<Edge> edges_after_repair(const std::vector<Edge>& edges,
                                     const std::vector<Index>& new_id) {
  std::vector<Edge> renumbered;
  renumbered.reserve(edges.size());
  for (const Edge& e : edges) {
    const auto name = [&] { return std::to_string(e[0]) + " " + std::to_string(e[1]); };
    if (e[0] >= new_id.size() || e[1] >= new_id.size())
      throw InvalidArgument("feature edge " + name() + ": vertex id out of range (the mesh has " +
                            std::to_string(new_id.size()) + " vertices)");
    const Index a = new_id[e[0]], b = new_id[e[1]];
    if (a == kRemovedVertex || b == kRemovedVertex)
      throw InvalidArgument("feature edge " + name() +
                            ": not an edge of the mesh (a vertex of it is in "
                            "no triangle of non-zero area)");
    if (a == b)
      throw InvalidArgument("feature edge " + name() + ": its two vertices are at the same point");
    renumbered.push_back({std::min(a, b), std::max(a, b)});
  }
  return renumbered;
}

std::vector<double> values_after_repair(const std::vector<double>& values,
                                        const std::vector<Index>& new_id,
                                        std::size_t repaired_vertex_count) {
  if (values.size() != new_id.size())
    throw InvalidArgument(std::to_string(values.size()) + " values for a mesh of " +
                          std::to_string(new_id.size()) + " vertices");
  std::vector<double> out(repaired_vertex_count, 0);
  std::vector<bool> seen(repaired_vertex_count, false);
  for (std::size_t v = 0; v < values.size(); ++v) {
    const Index to = new_id[v];
    if (to == kRemovedVertex) continue;
    out[to] = seen[to] ? std::min(out[to], values[v]) : values[v];
    seen[to] = true;
  }
  return out;
}

RepairReport diagnose_repairs(const TriangleMesh& mesh) {
  TriangleMesh copy = mesh;
  return repair_mesh(copy);
}

}  // namespace cvtmesh
