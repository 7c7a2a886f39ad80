// Feature edges (boundary, non-manifold, sharp, user-given), chained into curves between
// corners (paper §4.3: vertices with other than two feature edges, and sharp turns).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "features/crease_at_scale.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_sectors.hpp"
#include "features/twin_curves.hpp"
#include "geometry/union_find.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {

// A sharp turn of a curve is a corner only if both its curves are at least this many output
// edge lengths long. An edge this short beside edges of one length has angles under
// 2 asin(0.15) = 17° opposite it. The rims of scans' holes are jagged, every other vertex a sharp
// turn a fifth of an edge from the next (lion.off, stanford-bunny.obj at 5k: 5° kept as corners).
constexpr double kShortestTurnCurve = 0.3;
// Between two such turns (a step of a staircase rim) the curve must be longer still: an edge
// under 2 sin(15°) = 0.52 of its neighbours' length faces an angle under 30°, the quality promise
// (stanford-bunny.obj at 5k, its base's holes stepped by 0.3 and 0.5 edges: θmin 16.0° with 36
// corners, 40.2° with 20). A turn next to a junction of curves keeps the shorter bound: that is
// how a CAD part's creases meet (blade.off, a true corner 0.4 edges from a junction at 5k).
constexpr double kShortestStep = 0.55;
// ... unless all the feature curves it is connected to, together, are shorter than this many: the
// rim of a small hole or the outline of a small part, whose corners are its shape.
constexpr double kShortestJaggedNetwork = 2;

// Whether the two triangles' normals (`normal`, per triangle) make an angle above the
// threshold, their orientations made consistent along the edge first (a mesh read as a soup may
// not be oriented).
bool sharp(const TriangleMesh& mesh, const std::vector<Vec3>& normal, const Edge& e, std::size_t t0,
           std::size_t t1, double cos_threshold) {
  const Vec3 n0 = normal[t0];
  Vec3 n1 = normal[t1];
  if (runs_forward(mesh.triangles[t0], e[0], e[1]) == runs_forward(mesh.triangles[t1], e[0], e[1]))
    n1 = -1.0 * n1;
  if (dot(n0, n0) == 0 || dot(n1, n1) == 0) return false;  // no normal: no angle
  return dot(n0, n1) < cos_threshold;
}

// The feature edges around each vertex, as a compressed adjacency list.
struct Adjacency {
  std::vector<std::size_t> start;
  std::vector<Index> other;
  std::size_t degree(Index v) const { return start[v + 1] - start[v]; }
};

Adjacency adjacency(std::size_t vertices, const std::vector<Edge>& edges) {
  Adjacency a;
  a.start.assign(vertices + 1, 0);
  for (const Edge& e : edges) ++a.start[e[0] + 1], ++a.start[e[1] + 1];
  for (std::size_t v = 0; v < vertices; ++v) a.start[v + 1] += a.start[v];
  a.other.resize(2 * edges.size());
  std::vector<std::size_t> fill(a.start.begin(), a.start.end() - 1);
  for (const Edge& e : edges) a.other[fill[e[0]]++] = e[1], a.other[fill[e[1]]++] = e[0];
  for (std::size_t v = 0; v < vertices; ++v)
    std::sort(a.other.begin() + static_cast<std::ptrdiff_t>(a.start[v]),
              a.other.begin() + static_cast<std::ptrdiff_t>(a.start[v + 1]));
  return a;
}

// A vertex with two feature edges where the curve turns by more than the threshold.
bool sharp_turn(const TriangleMesh& mesh, const Adjacency& adj, Index v, double cos_threshold) {
  const Vec3& p = mesh.vertices[v];
  const Vec3 in = p - mesh.vertices[adj.other[adj.start[v]]];
  const Vec3 out = mesh.vertices[adj.other[adj.start[v] + 1]] - p;
  const double lengths = norm(in) * norm(out);
  return lengths > 0 && dot(in, out) < cos_threshold * lengths;
}

double curve_length(const TriangleMesh& mesh, const FeatureCurve& c) {
  double length = 0;
  for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
    length += distance(mesh.vertices[c.vertices[k]], mesh.vertices[c.vertices[k + 1]]);
  if (c.closed) length += distance(mesh.vertices[c.vertices.back()], mesh.vertices[c.vertices[0]]);
  return length;
}

// Per vertex, the total length of the feature edges connected to it.
std::vector<double> network_lengths(const TriangleMesh& mesh, const std::vector<Edge>& edges) {
  UnionFind sets(mesh.vertices.size());
  for (const Edge& e : edges) sets.unite(e[0], e[1]);
  std::vector<double> length(mesh.vertices.size(), 0);
  for (const Edge& e : edges)
    length[sets.find(e[0])] += distance(mesh.vertices[e[0]], mesh.vertices[e[1]]);
  std::vector<double> result(mesh.vertices.size());
  for (Index v = 0; v < mesh.vertices.size(); ++v) result[v] = length[sets.find(v)];
  return result;
}

// Corners and curves of the feature edges f.edges, with the user's corners among the corners.
// With `scale` > 0, a sharp turn is no corner where one of its curves is shorter than
// kShortestTurnCurve times it, or kShortestStep where that curve ends at another such turn (with
// both ends output vertices, that curve would be an output edge this short), unless its network
// of curves is a small detail (kShortestJaggedNetwork).
void chain(const TriangleMesh& mesh, double cos_threshold, double scale,
           const std::vector<Index>& user_corners, Features& f) {
  const Adjacency adj = adjacency(mesh.vertices.size(), f.edges);
  std::vector<bool> corner(mesh.vertices.size(), false), turn(mesh.vertices.size(), false);
  for (Index v : user_corners) corner[v] = true;
  const std::vector<double> network =
      scale > 0 ? network_lengths(mesh, f.edges) : std::vector<double>{};
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    const std::size_t d = adj.degree(v);
    const bool sharp = !corner[v] && d == 2 && sharp_turn(mesh, adj, v, cos_threshold);
    turn[v] = sharp && scale > 0 && network[v] >= kShortestJaggedNetwork * scale;
    corner[v] = corner[v] || (d > 0 && d != 2) || sharp;
  }
  auto slot = [&](Index from, Index to) {
    const auto first = adj.other.begin() + static_cast<std::ptrdiff_t>(adj.start[from]);
    const auto last = adj.other.begin() + static_cast<std::ptrdiff_t>(adj.start[from + 1]);
    return adj.start[from] + static_cast<std::size_t>(std::lower_bound(first, last, to) - first);
  };
  // Chains: from each corner along each of its edges; what is left are loops without corners.
  auto chain_curves = [&] {
    f.corners.clear();
    f.curves.clear();
    for (Index v = 0; v < mesh.vertices.size(); ++v)
      if (corner[v]) f.corners.push_back(v);
    std::vector<bool> used(adj.other.size(), false);  // per adjacency slot (directed edge)
    auto walk = [&](Index from, Index to) {
      FeatureCurve c;
      c.vertices.push_back(from);
      for (;;) {
        used[slot(from, to)] = used[slot(to, from)] = true;
        if (corner[to]) {
          c.vertices.push_back(to);
          return c;
        }
        if (to == c.vertices.front()) {  // back at the start of a loop
          c.closed = true;
          return c;
        }
        c.vertices.push_back(to);
        const std::size_t s = adj.start[to];
        const Index next = adj.other[s] == from ? adj.other[s + 1] : adj.other[s];
        from = to, to = next;
      }
    };
    for (Index v : f.corners)
      for (std::size_t s = adj.start[v]; s < adj.start[v + 1]; ++s)
        if (!used[s]) f.curves.push_back(walk(v, adj.other[s]));
    for (Index v = 0; v < mesh.vertices.size(); ++v)
      for (std::size_t s = adj.start[v]; s < adj.start[v + 1]; ++s)
        if (!used[s]) f.curves.push_back(walk(v, adj.other[s]));
  };
  // Each pass turns at least one corner into a curve vertex, so this ends.
  for (;;) {
    chain_curves();
    if (scale == 0) return;
    bool changed = false;
    const auto turns = [&](Index v) { return turn[v] && corner[v]; };
    for (const FeatureCurve& c : f.curves) {
      // Measured only where an end may stop being a corner: most curves end elsewhere.
      const Index a = c.vertices.front(), b = c.vertices.back();
      if (c.closed || !(turns(a) || turns(b))) continue;
      const double shortest = turns(a) && turns(b) ? kShortestStep : kShortestTurnCurve;
      if (curve_length(mesh, c) >= shortest * scale) continue;
      for (const Index end : {a, b})
        if (turns(end)) corner[end] = false, changed = true;
    }
    if (!changed) return;
  }
}

// A crease free at both ends (it rises out of a smooth surface and dies back into it, meeting no
// other feature) is kept only if at least this many output edge lengths long. On the 57 meshes
// of ../shared/data and its corpus, the creases of CAD parts end at corners where they meet other
// creases or boundaries, and the one free crease among them is 72 edge lengths long
// (couplingdown.off at 5k); the free creases of organic models are folds of their polygons, 2 to
// 10 long, whose tracing cost angles (issue 18 item 5: bull.off at 5k 29° against 34° without
// features, plane_holes.obj Qmin 0.41 against 0.52, triceratops.off at 1k 16° against 23°).
constexpr double kFreeCreaseLengths = 8;
// And, whatever the output's scale, at least this fraction of the square root of its component's
// area: a free crease a third of the model across is a designed feature; the folds of an organic
// model's polygons that pass at fine scales are shorter (0.10-0.28 of it: cactus, lion-head,
// triceratops, demosthenes and scorpion at 5k and 10k, each then worse in θmin or Qmin than
// without features; the free creases of CAD parts: fandisk at 1k 0.43, couplingdown 1.09).
constexpr double kFreeCreaseOfModel = 1.0 / 3;

// Whether curve c meets no other feature: open, with one feature edge at each end.
bool free_at_both_ends(const Adjacency& adj, const FeatureCurve& c) {
  return !c.closed && adj.degree(c.vertices.front()) == 1 && adj.degree(c.vertices.back()) == 1;
}

// Whether curve c leaves an end along a boundary edge with a sector of the surface under
// kNarrowAngleDeg between them: the wedge holds no triangle better than that angle, and without
// the crease the boundary alone is kept (a scan's lip fading into a jagged hole rim, lion.off at
// 5k: 8.6°). `sectors` are the feature sectors, sorted by apex; `boundary` the boundary edges,
// sorted.
bool narrow_at_boundary(const std::vector<FeatureSector>& sectors,
                        const std::vector<Edge>& boundary, const FeatureCurve& c) {
  if (c.closed || c.vertices.size() < 2) return false;
  const auto narrow = [&](Index end, Index next) {
    auto s = std::lower_bound(sectors.begin(), sectors.end(), end,
                              [](const FeatureSector& x, Index v) { return x.apex < v; });
    for (; s != sectors.end() && s->apex == end; ++s)
      if (s->from == next && s->angle_deg < kNarrowAngleDeg &&
          std::binary_search(boundary.begin(), boundary.end(), edge_of(end, s->to)))
        return true;
    return false;
  };
  const std::vector<Index>& v = c.vertices;
  return narrow(v.front(), v[1]) || narrow(v.back(), v[v.size() - 2]);
}

std::vector<Edge> edges_of(const FeatureCurve& c) {
  std::vector<Edge> edges;
  for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
    edges.push_back(edge_of(c.vertices[k], c.vertices[k + 1]));
  if (c.closed) edges.push_back(edge_of(c.vertices.back(), c.vertices[0]));
  return edges;
}

// Removes `dropped` (sorted here) from the feature edges.
void drop_edges(std::vector<Edge> dropped, Features& f) {
  std::sort(dropped.begin(), dropped.end());
  std::erase_if(f.edges, [&](const Edge& e) {
    return std::binary_search(dropped.begin(), dropped.end(), e);
  });
}

// After curves went, a piece of a kept network may be left free at both ends: it met the
// network only at a dropped curve. Such a piece is dropped if shorter than this many output edge
// lengths: the fans of well-shaped triangles around its two free ends would cover all of it.
// Measured on the 57 shared meshes: organic folds left so are 2.1-3.6 long (femur.off,
// triceratops.off, ChineseDragon-10kv.off at 10k, scorpion_low_resolution.obj at 1k: each worse
// than --no-features), CAD pieces 4.1-7.5 (anchor.off's at 1k are 7.1; with the 8 lengths of
// other free creases it lost 4 of its 16 corners).
constexpr double kFreePieceLengths = 4;

// Drops those pieces, if of sharp edges only, and chains the rest again (turns at `scale`, as
// creases at the output's scale are).
template <class SharpOnly>
void drop_short_free_creases(const TriangleMesh& mesh, const FeatureSettings& settings,
                             double cos_threshold, const SharpOnly& sharp_only, Features& f) {
  const Adjacency adj = adjacency(mesh.vertices.size(), f.edges);
  std::vector<Edge> dropped;
  for (const FeatureCurve& c : f.curves) {
    if (!free_at_both_ends(adj, c) || curve_length(mesh, c) >= kFreePieceLengths * settings.scale)
      continue;
    const std::vector<Edge> edges = edges_of(c);
    if (std::all_of(edges.begin(), edges.end(), sharp_only))
      dropped.insert(dropped.end(), edges.begin(), edges.end());
  }
  if (dropped.empty()) return;
  drop_edges(std::move(dropped), f);
  chain(mesh, cos_threshold, settings.scale, settings.user_corners, f);
}

}  // namespace

Features detect_features(const TriangleMesh& mesh, const FeatureSettings& settings) {
  if (settings.sharp_edges && !(settings.angle_deg >= 0 && settings.angle_deg <= 180))
    throw InvalidArgument("the feature angle must be between 0 and 180 degrees");
  const double cos_threshold = std::cos(settings.angle_deg * std::numbers::pi / 180);
  Features f;
  std::vector<Edge> sharp_edges;     // kept for being sharp, and for nothing else
  std::vector<Edge> boundary_edges;  // both sorted, as `uses` is
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  // Each triangle's normal is read across each of its edges: found once each, in parallel
  // (three times each, serially, they were half of this step on igea.ply).
  const std::vector<Vec3> normal = settings.sharp_edges ? unit_normals(mesh) : std::vector<Vec3>{};
  for_each_edge(uses, [&](std::size_t k, std::size_t end) {
    const std::size_t count = end - k;
    if (count != 2) {
      f.edges.push_back(uses[k].edge);
      if (count == 1) boundary_edges.push_back(uses[k].edge);
    } else if (settings.sharp_edges && sharp(mesh, normal, uses[k].edge, uses[k].triangle(),
                                             uses[k + 1].triangle(), cos_threshold)) {
      f.edges.push_back(uses[k].edge);
      sharp_edges.push_back(uses[k].edge);
    }
  });
  for (const Edge& given : settings.user_edges) {
    const auto n = mesh.vertices.size();
    if (given[0] >= n || given[1] >= n)
      throw InvalidArgument("feature edge " + std::to_string(given[0]) + " " +
                            std::to_string(given[1]) + ": vertex id out of range (the mesh has " +
                            std::to_string(n) + " vertices)");
    const Edge e = edge_of(given[0], given[1]);
    const auto used = std::lower_bound(uses.begin(), uses.end(), e,
                                       [](const EdgeUse& u, const Edge& x) { return u.edge < x; });
    if (used == uses.end() || used->edge != e)
      throw InvalidArgument("feature edge " + std::to_string(given[0]) + " " +
                            std::to_string(given[1]) + " is not an edge of the mesh");
    f.edges.push_back(e);
    std::erase(sharp_edges, e);
  }
  for (Index v : settings.user_corners)
    if (v >= mesh.vertices.size())
      throw InvalidArgument("corner " + std::to_string(v) +
                            ": vertex id out of range (the mesh has " +
                            std::to_string(mesh.vertices.size()) + " vertices)");
  auto sharp_only = [&](const Edge& e) {
    return std::binary_search(sharp_edges.begin(), sharp_edges.end(), e);
  };
  std::sort(f.edges.begin(), f.edges.end());
  f.edges.erase(std::unique(f.edges.begin(), f.edges.end()), f.edges.end());

  // As creases at the output's scale, only in the default mode (a forced angle forces both).
  const double turn_scale = settings.creases_at_scale ? settings.scale : 0;
  chain(mesh, cos_threshold, turn_scale, settings.user_corners, f);
  if (settings.scale > 0) {
    // Curves of sharp edges only that are no features at the output's scale go, and the rest is
    // chained again: a corner of a dropped curve may be an ordinary curve vertex now.
    const CreaseScale creases(mesh, uses, f.edges);
    const Adjacency adj = adjacency(mesh.vertices.size(), f.edges);
    std::vector<double> lengths;
    for (const FeatureCurve& c : f.curves) lengths.push_back(curve_length(mesh, c));
    // The model a free crease belongs to: its connected component, whose area's square root
    // measures it. Found on the first free crease that asks (most inputs have none: a walk over
    // every triangle saved).
    std::optional<UnionFind> parts;
    std::vector<double> part_area;
    const auto model_size = [&](const FeatureCurve& c) {
      if (!parts) {
        parts.emplace(mesh.vertices.size());
        for (const Triangle& t : mesh.triangles) parts->unite(t[0], t[1]), parts->unite(t[0], t[2]);
        part_area.assign(mesh.vertices.size(), 0);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
          const auto [p, q, r] = mesh.corners(t);
          part_area[parts->find(mesh.triangles[t][0])] += triangle_area(p, q, r);
        }
      }
      return std::sqrt(part_area[parts->find(c.vertices.front())]);
    };
    auto feature_at_scale = [&](std::size_t c) {
      const double length = lengths[c];
      if (length < 2 * settings.scale) return false;
      if (!settings.creases_at_scale) return true;
      const bool long_if_free = !free_at_both_ends(adj, f.curves[c]) ||
                                (length >= kFreeCreaseLengths * settings.scale &&
                                 length >= kFreeCreaseOfModel * model_size(f.curves[c]));
      return long_if_free && creases.is_crease(f.curves[c], settings.scale, settings.angle_deg);
    };
    std::vector<std::vector<Edge>> curve_edges;
    std::vector<bool> droppable;  // per curve: of sharp edges only
    for (const FeatureCurve& c : f.curves) {
      curve_edges.push_back(edges_of(c));
      droppable.push_back(
          std::all_of(curve_edges.back().begin(), curve_edges.back().end(), sharp_only));
    }
    const std::vector<bool> twin =
        settings.creases_at_scale ? twin_curves(mesh, f.curves, lengths, droppable, settings.scale)
                                  : std::vector<bool>(f.curves.size(), false);
    // Whether the input is smooth around a network of connected curves is voted on by the
    // network as a whole: the creases of a polyhedron or a CAD part are kept or dropped together
    // (tripod.off at 1k, each curve voting alone, kept 9 of its 22 folds: θmin 1.9° under what
    // none gave, 3.6° under all).
    UnionFind networks(mesh.vertices.size());
    for (const Edge& e : f.edges) networks.unite(e[0], e[1]);
    std::vector<CreaseScale::Votes> smooth(mesh.vertices.size());  // per network root
    if (settings.creases_at_scale)
      for (std::size_t c = 0; c < f.curves.size(); ++c)
        if (droppable[c]) {
          const CreaseScale::Votes v = creases.smooth_around(f.curves[c], settings.angle_deg);
          CreaseScale::Votes& total = smooth[networks.find(f.curves[c].vertices[0])];
          total.smooth += v.smooth;
          total.measured += v.measured;
        }
    auto rough_around = [&](std::size_t c) {
      const CreaseScale::Votes& v = smooth[networks.find(f.curves[c].vertices[0])];
      return 2 * v.smooth < v.measured;
    };
    // Only a surface with a boundary has a crease to drop for meeting it narrowly; with no
    // sectors (none, or not at scale) narrow_at_boundary drops nothing.
    const std::vector<FeatureSector> sectors = settings.creases_at_scale && !boundary_edges.empty()
                                                   ? feature_sectors(mesh, f)
                                                   : std::vector<FeatureSector>{};
    std::vector<Edge> dropped;
    for (std::size_t c = 0; c < f.curves.size(); ++c)
      if (droppable[c] && (twin[c] || rough_around(c) || !feature_at_scale(c) ||
                           narrow_at_boundary(sectors, boundary_edges, f.curves[c])))
        dropped.insert(dropped.end(), curve_edges[c].begin(), curve_edges[c].end());
    if (!dropped.empty()) {
      drop_edges(std::move(dropped), f);
      chain(mesh, cos_threshold, turn_scale, settings.user_corners, f);
      if (settings.creases_at_scale)
        drop_short_free_creases(mesh, settings, cos_threshold, sharp_only, f);
    }
  }
  return f;
}

}  // namespace cvtmesh
