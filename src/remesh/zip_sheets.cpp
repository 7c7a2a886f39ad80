#include "remesh/zip_sheets.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/angle.hpp"
#include "geometry/edge_splitter.hpp"
#include "geometry/polyline_index.hpp"

namespace cvtmesh {

namespace {

// A vertex on a segment, at parameter t (0 at a, 1 at b).
struct OnSegment {
  double t;
  Index vertex;
};

// Splits the triangles on the edge (p, q) at the new vertex x, and the edge among the feature
// edges.
void split_edge(TriangleMesh& mesh, EdgeSplitter& stars, std::vector<Edge>& feature_edges, Index p,
                Index q, Index x) {
  const auto feature = std::find(feature_edges.begin(), feature_edges.end(), edge_of(p, q));
  if (feature != feature_edges.end()) {
    *feature = edge_of(p, x);
    feature_edges.push_back(edge_of(x, q));
  }
  stars.split(mesh, p, q, x);
}

// The chains of `on` (sorted by t) along the output's edges: each runs from a vertex at t = 0 to
// one at t = 1, through vertices of increasing t. None when the vertices on the segment do not
// form such chains.
std::optional<std::vector<std::vector<OnSegment>>> chains_along(const TriangleMesh& mesh,
                                                                const EdgeSplitter& stars,
                                                                const std::vector<OnSegment>& on) {
  std::vector<Index> ids;
  for (const OnSegment& o : on) ids.push_back(o.vertex);
  std::sort(ids.begin(), ids.end());
  const auto place = [&](Index v) -> std::ptrdiff_t {
    const auto at = std::lower_bound(ids.begin(), ids.end(), v);
    return at != ids.end() && *at == v ? at - ids.begin() : -1;
  };
  // Per vertex on the segment (by place in `ids`), its neighbours on it, each once.
  std::vector<std::vector<Index>> next(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (const Index t : stars.around(ids[i]))
      for (const Index w : mesh.triangles[t])
        if (w != ids[i] && place(w) >= 0 && std::ranges::find(next[i], w) == next[i].end())
          next[i].push_back(w);
  std::vector<double> t_of(ids.size());
  for (const OnSegment& o : on) t_of[place(o.vertex)] = o.t;
  std::vector<std::vector<OnSegment>> chains;
  std::size_t visited = 0;
  for (const OnSegment& start : on) {
    // A copy of an end in a fan off the segment (a sheet's other fan there) starts no chain.
    if (start.t != 0 || next[place(start.vertex)].empty()) continue;
    std::vector<OnSegment> chain{start};
    for (Index v = start.vertex; t_of[place(v)] != 1;) {
      // The nearest step forward: a sheet's side that spans the whole stretch (a sliver flap's
      // free side, both its ends on the junction) is no step of the chain along it.
      const std::vector<Index>& n = next[place(v)];
      Index forward = kNoIndex;
      for (const Index w : n)
        if (t_of[place(w)] > t_of[place(v)] &&
            (forward == kNoIndex || t_of[place(w)] < t_of[place(forward)]))
          forward = w;
      if (forward == kNoIndex) return std::nullopt;
      v = forward;
      chain.push_back({t_of[place(v)], v});
      if (chain.size() > ids.size()) return std::nullopt;
    }
    visited += chain.size();
    chains.push_back(std::move(chain));
  }
  // Each vertex on the segment in exactly one chain, but for ends' copies off it.
  const auto off =
      static_cast<std::size_t>(std::count_if(on.begin(), on.end(), [&](const OnSegment& o) {
        return (o.t == 0 || o.t == 1) && next[place(o.vertex)].empty();
      }));
  if (visited + off != ids.size()) return std::nullopt;
  return chains;
}

// The smallest angle of triangle (a, b, c), in degrees.
double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::min({angle_deg(b - a, c - a), angle_deg(c - b, a - b), angle_deg(a - c, b - c)});
}

// Splitting a sheet's side at another's points leaves fans of thin triangles where that sheet
// had no vertex (a sliver flap kept as it is: every point of the surface's junction joined to its
// apex). Edges of the triangles at the points added are flipped where that raises the smaller
// of the two triangles' smallest angles, within a sheet, never a feature edge, while any does.
void flip_around(TriangleMesh& mesh, const std::vector<Edge>& feature_edges,
                 const std::vector<Index>& added) {
  std::vector<Edge> fixed = feature_edges;
  std::sort(fixed.begin(), fixed.end());
  std::vector<bool> near(mesh.vertices.size(), false);
  for (const Index v : added) near[v] = true;
  std::map<Edge, std::vector<std::size_t>> on;  // the edges of the triangles at the points
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (!near[f[0]] && !near[f[1]] && !near[f[2]]) continue;
    for (int k = 0; k < 3; ++k) on[edge_of(f[k], f[(k + 1) % 3])].push_back(t);
  }
  // The triangles at those edges, beyond the ones at the points.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (near[f[0]] || near[f[1]] || near[f[2]]) continue;
    for (int k = 0; k < 3; ++k)
      if (auto at = on.find(edge_of(f[k], f[(k + 1) % 3])); at != on.end()) at->second.push_back(t);
  }
  const auto opposite = [&](std::size_t t, const Edge& e) {
    for (const Index v : mesh.triangles[t])
      if (v != e[0] && v != e[1]) return v;
    return kNoIndex;
  };
  for (int pass = 0; pass < 8; ++pass) {
    bool flipped = false;
    for (auto& [e, ts] : on) {
      if (ts.size() != 2 || std::binary_search(fixed.begin(), fixed.end(), e)) continue;
      const Index r = opposite(ts[0], e), q = opposite(ts[1], e);
      if (r == kNoIndex || q == kNoIndex || r == q || on.contains(edge_of(r, q))) continue;
      const Vec3 &a = mesh.vertices[e[0]], &b = mesh.vertices[e[1]], &pr = mesh.vertices[r],
                 &pq = mesh.vertices[q];
      const double before = std::min(smallest_angle(a, b, pr), smallest_angle(a, b, pq));
      const double after = std::min(smallest_angle(pr, pq, a), smallest_angle(pr, pq, b));
      if (!(after > before + 1e-9)) continue;
      // The new triangles, oriented as the old: (r, q, x) for the end x that followed r.
      const Triangle& first = mesh.triangles[ts[0]];
      int k = 0;
      while (first[k] != r) ++k;
      const Index after_r = first[(k + 1) % 3], before_r = first[(k + 2) % 3];
      const Triangle t0{r, q, before_r}, t1{q, r, after_r};
      const Vec3 n_old = cross(mesh.vertices[first[1]] - mesh.vertices[first[0]],
                               mesh.vertices[first[2]] - mesh.vertices[first[0]]);
      bool folds = false;
      for (const Triangle& t : {t0, t1}) {
        const Vec3 n = cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                             mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        folds = folds || !(dot(n, n_old) > 0);
      }
      if (folds) continue;
      const std::size_t i0 = ts[0], i1 = ts[1];
      mesh.triangles[i0] = t0;
      mesh.triangles[i1] = t1;
      // Update the edge lists: (a, b) goes, (r, q) comes; the sides change triangles.
      const auto retarget = [&](const Edge& side, std::size_t from, std::size_t to) {
        if (auto at = on.find(side); at != on.end())
          std::replace(at->second.begin(), at->second.end(), from, to);
      };
      // i0 now holds before_r's sides with q, i1 after_r's.
      retarget(edge_of(q, before_r), i1, i0);
      retarget(edge_of(r, after_r), i0, i1);
      on[edge_of(r, q)] = {i0, i1};
      ts.clear();  // (a, b) is no edge now
      flipped = true;
    }
    if (!flipped) break;
  }
}

}  // namespace

std::optional<std::vector<std::pair<Index, Index>>> zip_shared_segments(
    TriangleMesh& mesh, std::vector<Edge>& feature_edges, const std::vector<SheetVertices>& sheets,
    const std::vector<SharedSegment>& segments, Index first_key) {
  std::vector<std::pair<Index, Index>> keyed;
  Index key = first_key;
  const auto first_added = static_cast<Index>(mesh.vertices.size());
  EdgeSplitter stars(mesh);
  // Every sheet's vertices on the stretches: at a stretch's end exactly (a corner, shared by the
  // stretches that end there), or inside one to round-off (curve seeds are projections onto the
  // input's edges).
  std::vector<std::vector<Vec3>> polylines;
  for (const SharedSegment& segment : segments) {
    const std::vector<Vec3>& points = segment.points;
    if (points.size() < 2 || points.front() == points.back()) return std::nullopt;
    double length = 0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      length += distance(points[i], points[i + 1]);
    if (!(length > 0)) return std::nullopt;
    polylines.push_back(points);
  }
  const PolylineIndex index(polylines, 1e-9);
  const auto has = [&](std::size_t k, std::size_t sheet) {
    return std::ranges::find(segments[k].sheets, sheet) != segments[k].sheets.end();
  };
  std::vector<std::vector<OnSegment>> on_stretch(segments.size());
  for (std::size_t c = 0; c < sheets.size(); ++c)
    for (Index v = sheets[c].first; v < sheets[c].end; ++v)
      for (const PolylineIndex::At& at : index.find(mesh.vertices[v]))
        if (has(at.polyline, c) && (at.end || (at.t > 0 && at.t < 1)))
          on_stretch[at.polyline].push_back({at.t, v});
  // All chains found first: splitting one stretch's steps never touches another's.
  std::vector<std::vector<std::vector<OnSegment>>> all_chains;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    std::vector<OnSegment>& on = on_stretch[k];
    std::sort(on.begin(), on.end(),
              [](const OnSegment& x, const OnSegment& y) { return x.t < y.t; });
    std::optional<std::vector<std::vector<OnSegment>>> chains = chains_along(mesh, stars, on);
    if (!chains || chains->size() < 2) return std::nullopt;
    all_chains.push_back(std::move(*chains));
  }
  for (std::vector<std::vector<OnSegment>>& chains : all_chains) {
    // The positions inside the segment, from every chain: a chain's own near another's are the
    // same position, the first's (by t), which the others move to along the segment. Near: within
    // a quarter of the shortest step of any chain (so never two of one chain), where one chain's
    // position and another's a little beside it would both go into every chain, with an edge of a
    // hundredth of the others between them (triple_vierbein.obj adaptive at 5k: where one sheet's
    // topology control added seeds on the junction, θmin 0.6°); at least a round-off.
    std::vector<OnSegment> inner;
    for (const auto& chain : chains) inner.insert(inner.end(), chain.begin() + 1, chain.end() - 1);
    std::sort(inner.begin(), inner.end(),
              [](const OnSegment& x, const OnSegment& y) { return x.t < y.t; });
    double step = 1;
    for (const auto& chain : chains)
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        step = std::min(step, chain[i + 1].t - chain[i].t);
    const double near = std::max(0.25 * step, 1e-9);
    std::vector<std::size_t> group_of(inner.size());  // position groups, by t
    std::vector<OnSegment> groups;                    // each group's first
    for (std::size_t i = 0; i < inner.size(); ++i) {
      if (groups.empty() || inner[i].t - groups.back().t > near) groups.push_back(inner[i]);
      group_of[i] = groups.size() - 1;
    }
    const auto group_at = [&](Index v) {
      for (std::size_t i = 0; i < inner.size(); ++i)
        if (inner[i].vertex == v) return group_of[i];
      return groups.size();
    };
    for (const auto& chain : chains) {
      // Each group once in the chain, taken from it or added to it.
      std::vector<Index> at(groups.size(), kNoIndex);
      for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
        const std::size_t g = group_at(chain[i].vertex);
        Index& slot = at[g];
        if (slot != kNoIndex) return std::nullopt;  // two of one chain's vertices coincide
        slot = chain[i].vertex;
        mesh.vertices[slot] = mesh.vertices[groups[g].vertex];
      }
      std::size_t g = 0;
      for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
        Index from = chain[i].vertex;
        const Index to = chain[i + 1].vertex;
        for (; g < groups.size() && groups[g].t < chain[i + 1].t - 1e-9; ++g) {
          if (at[g] != kNoIndex) continue;
          const auto x = static_cast<Index>(mesh.vertices.size());
          const Vec3 position = mesh.vertices[groups[g].vertex];
          mesh.vertices.push_back(position);
          split_edge(mesh, stars, feature_edges, from, to, x);
          at[g] = x;
          from = x;
        }
        if (g < groups.size() && at[g] == to) ++g;
      }
      if (std::ranges::count(at, kNoIndex) > 0) return std::nullopt;  // a position not placed
      for (std::size_t k = 0; k < groups.size(); ++k) keyed.emplace_back(key + k, at[k]);
    }
    key += static_cast<Index>(groups.size());
  }
  std::vector<Index> added;
  for (Index v = first_added; v < mesh.vertices.size(); ++v) added.push_back(v);
  if (!added.empty()) flip_around(mesh, feature_edges, added);
  return keyed;
}

}  // namespace cvtmesh
