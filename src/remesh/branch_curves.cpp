#include "remesh/branch_curves.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "geometry/edge_splitter.hpp"
#include "geometry/polyline_index.hpp"

namespace cvtmesh {

namespace {

// A junction vertex where the curve turns by more than this is a corner of every sheet.
constexpr double kJunctionTurnDeg = 20;

// The junction's curves as polylines of input vertices (a closed one ends where it starts).
std::vector<std::vector<Index>> junction_curves(const TriangleMesh& mesh,
                                                const std::vector<Edge>& branch) {
  std::vector<std::vector<Index>> next(mesh.vertices.size());
  for (const Edge& e : branch) {
    next[e[0]].push_back(e[1]);
    next[e[1]].push_back(e[0]);
  }
  std::vector<bool> walked(branch.size(), false);
  const auto take = [&](Index a, Index b) {
    const auto at = std::lower_bound(branch.begin(), branch.end(), edge_of(a, b));
    const auto i = static_cast<std::size_t>(at - branch.begin());
    if (walked[i]) return false;
    walked[i] = true;
    return true;
  };
  const auto is_end = [&](Index v) { return next[v].size() != 2; };
  std::vector<std::vector<Index>> curves;
  const auto walk = [&](Index from, Index to) {
    std::vector<Index> curve{from, to};
    for (Index previous = from, v = to; !is_end(v) && v != from;) {
      const Index w = next[v][0] == previous ? next[v][1] : next[v][0];
      if (!take(v, w)) break;
      curve.push_back(w);
      previous = v;
      v = w;
    }
    curves.push_back(std::move(curve));
  };
  for (Index v = 0; v < next.size(); ++v)
    if (!next[v].empty() && is_end(v))
      for (const Index w : next[v])
        if (take(v, w)) walk(v, w);
  for (const Edge& e : branch)  // closed curves, each from its smallest vertex
    if (take(e[0], e[1])) walk(e[0], e[1]);
  return curves;
}

// The edges of three or more triangles, sorted, and how many triangles each has.
std::pair<std::vector<Edge>, std::vector<std::size_t>> junction_edges(const TriangleMesh& mesh) {
  std::vector<Edge> branch;
  std::vector<std::size_t> count;
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i > 2) {
      branch.push_back(uses[i].edge);
      count.push_back(j - i);
    }
  });
  return {branch, count};
}

}  // namespace

BranchCurves resample_branch_curves(const TriangleMesh& mesh, double spacing) {
  BranchCurves r;
  r.mesh = mesh;
  r.corner.assign(mesh.vertices.size(), false);
  r.on_curve.assign(mesh.vertices.size(), false);
  const std::pair<std::vector<Edge>, std::vector<std::size_t>> edges = junction_edges(mesh);
  const std::vector<Edge>& branch = edges.first;
  const std::vector<std::size_t>& count = edges.second;
  if (branch.empty()) return r;
  const auto triangles_on = [&](Index a, Index b) {
    return count[std::lower_bound(branch.begin(), branch.end(), edge_of(a, b)) - branch.begin()];
  };
  // Per input edge split: the points on it, as t from its smaller end.
  std::map<Edge, std::vector<double>> on_edge;
  for (const std::vector<Index>& curve : junction_curves(mesh, branch)) {
    for (const Index v : curve) r.on_curve[v] = true;
    r.corner[curve.front()] = r.corner[curve.back()] = true;
    // Corners also where the curve turns (a sheet's own feature detection may see a corner
    // there) or where sheets join or leave it: every sheet has a vertex there.
    for (std::size_t i = 1; i + 1 < curve.size(); ++i) {
      const Vec3& p = mesh.vertices[curve[i]];
      const Vec3 in = p - mesh.vertices[curve[i - 1]], out = mesh.vertices[curve[i + 1]] - p;
      if (dot(in, out) <
              std::cos(kJunctionTurnDeg * std::numbers::pi / 180) * norm(in) * norm(out) ||
          triangles_on(curve[i - 1], curve[i]) != triangles_on(curve[i], curve[i + 1]))
        r.corner[curve[i]] = true;
    }
    // Each stretch between corners resampled evenly, its ends kept.
    for (std::size_t first = 0; first + 1 < curve.size();) {
      std::size_t last = first + 1;
      while (last + 1 < curve.size() && !r.corner[curve[last]]) ++last;
      std::vector<double> arc{0};
      for (std::size_t i = first; i < last; ++i)
        arc.push_back(arc.back() + distance(mesh.vertices[curve[i]], mesh.vertices[curve[i + 1]]));
      const double length = arc.back();
      const bool closed = curve[first] == curve[last];
      const auto steps = std::max<std::size_t>(
          closed ? 3 : 1, static_cast<std::size_t>(std::lround(length / spacing)));
      const double step = length / static_cast<double>(steps);
      std::size_t i = 0;  // the stretch's edge (curve[first + i], curve[first + i + 1])
      for (std::size_t k = 1; k < steps; ++k) {
        const double at = step * static_cast<double>(k);
        while (i + 2 < arc.size() && arc[i + 1] <= at) ++i;
        const Index a = curve[first + i], b = curve[first + i + 1];
        if (at - arc[i] < 1e-3 * step) {
          r.corner[a] = true;
        } else if (arc[i + 1] - at < 1e-3 * step) {
          r.corner[b] = true;
        } else {
          const double u = (at - arc[i]) / (arc[i + 1] - arc[i]);
          on_edge[edge_of(a, b)].push_back(a < b ? u : 1 - u);
        }
      }
      first = last;
    }
  }
  EdgeSplitter splitter(r.mesh);
  for (auto& [e, ts] : on_edge) {
    std::sort(ts.begin(), ts.end());
    const Vec3 a = mesh.vertices[e[0]], d = mesh.vertices[e[1]] - a;
    std::vector<Index> piece{e[0]};
    for (const double t : ts) {
      const auto x = static_cast<Index>(r.mesh.vertices.size());
      r.mesh.vertices.push_back(a + t * d);
      r.corner.push_back(true);
      r.on_curve.push_back(true);
      r.added.push_back({e[0], e[1], t});
      splitter.split(r.mesh, piece.back(), e[1], x);
      piece.push_back(x);
    }
    piece.push_back(e[1]);
    r.split.push_back(e);
    r.pieces.push_back(std::move(piece));
  }
  // The stretches between corners, on the junction as split.
  const std::vector<Edge> split_branch = junction_edges(r.mesh).first;
  for (const std::vector<Index>& curve : junction_curves(r.mesh, split_branch))
    for (std::size_t first = 0; first + 1 < curve.size();) {
      std::size_t last = first + 1;
      while (last + 1 < curve.size() && !r.corner[curve[last]]) ++last;
      r.stretches.emplace_back(curve.begin() + static_cast<std::ptrdiff_t>(first),
                               curve.begin() + static_cast<std::ptrdiff_t>(last) + 1);
      first = last;
    }
  return r;
}

std::size_t edges_off_junction(const TriangleMesh& output, const BranchCurves& junction) {
  std::vector<std::vector<Vec3>> polylines;
  for (const std::vector<Index>& stretch : junction.stretches) {
    polylines.emplace_back();
    for (const Index v : stretch) polylines.back().push_back(junction.mesh.vertices[v]);
  }
  const PolylineIndex index(polylines, 1e-9);
  const auto stretches_at = [&](const Vec3& p) {
    std::vector<std::size_t> found;
    for (const PolylineIndex::At& at : index.find(p)) found.push_back(at.polyline);
    return found;
  };
  const std::vector<Edge> edges = junction_edges(output).first;
  return static_cast<std::size_t>(std::count_if(edges.begin(), edges.end(), [&](const Edge& e) {
    const Vec3 &p = output.vertices[e[0]], &q = output.vertices[e[1]];
    const std::vector<std::size_t> a = stretches_at(p), b = stretches_at(q);
    if (std::ranges::any_of(a, [&](std::size_t k) { return std::ranges::count(b, k) > 0; }))
      return false;
    // Ends on two stretches: along the junction only where it runs straight on between them.
    return a.empty() || b.empty() || stretches_at(0.5 * (p + q)).empty();
  }));
}

}  // namespace cvtmesh
