#include "finish/split_obtuse_corners.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "features/edge_uses.hpp"
#include "finish/changed_vertices.hpp"
#include "finish/worst_shape.hpp"
#include "geometry/angle.hpp"
#include "geometry/surface_projector.hpp"
#include "quality/narrow_angles.hpp"

namespace cvtmesh {

namespace {

// An angle above this at a boundary corner is split: the CVT's own triangles stay well under it
// (Q 0.6 allows about 105° between two 37.5° angles).
constexpr double kObtuseDeg = 100;
// How far from the halved edge's middle its foot on the surface may lie, in edge lengths.
constexpr double kMostOffset = 0.25;
// Under the bar, one split at most per this many vertices, per call: femur.off at 1k, whose
// stacked sheets leave a hundred obtuse triangles, took 139 halvings (90 vertices more than
// without; collapses took the rest back) and 2 times the time in three rounds without a cap, for
// θmin 17.5° → 20.7°.
constexpr std::size_t kVerticesPerSplit = 100;

// The curve a feature edge (a, b) runs along, by its vertices' supports: the curve of either one
// on a curve (a fixed vertex, a corner, may end several); none where they name two curves or none.
std::optional<std::uint32_t> curve_of(const std::vector<VertexSupport>& supports, Index a,
                                      Index b) {
  const auto on_curve = [&](Index v) -> std::optional<std::uint32_t> {
    if (v < supports.size() && supports[v].kind == VertexSupport::Kind::curve)
      return supports[v].curve;
    return std::nullopt;
  };
  const std::optional<std::uint32_t> ca = on_curve(a), cb = on_curve(b);
  if (ca && cb && *ca != *cb) return std::nullopt;
  return ca ? ca : cb;
}

}  // namespace

std::size_t split_obtuse_corners(TriangleMesh& mesh, const std::vector<Edge>& features,
                                 const SurfaceProjector& surface, ObtuseCorners which,
                                 CurveSplits* along, const std::vector<double>* narrow_at) {
  const std::vector<EdgeUse> uses = edge_uses(mesh);  // sorted by edge
  // Per use, its edge's other use: itself for a boundary edge, none past two uses.
  constexpr std::size_t kNone = ~std::size_t{0};
  std::vector<std::size_t> other(uses.size(), kNone);
  std::vector<bool> boundary(mesh.vertices.size(), false);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i == 1) {
      boundary[uses[i].edge[0]] = boundary[uses[i].edge[1]] = true;
      other[i] = i;
    }
    if (j - i == 2) other[i] = i + 1, other[i + 1] = i;
  });
  // The obtuse corners to split: triangle t = (a, b, c) with the obtuse angle at c, u = (b, a, d)
  // across edge a-b (none for a boundary edge), and t's Q; a feature edge's curve.
  struct Candidate {
    double quality;
    std::size_t t, u;
    Index a, b, c, d;
    std::optional<std::uint32_t> curve;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < uses.size(); ++i) {
    if (other[i] == kNone) continue;
    std::optional<std::uint32_t> curve;
    if (std::binary_search(features.begin(), features.end(), uses[i].edge)) {
      if (!along) continue;
      curve = curve_of(along->supports, uses[i].edge[0], uses[i].edge[1]);
      if (!curve) continue;
    } else if (other[i] == i) {
      continue;  // a boundary edge is a feature edge: the features given do not have it
    }
    const std::size_t t = uses[i].triangle(), u = uses[other[i]].triangle();
    const bool across = other[i] != i;
    if (across && t == u) continue;
    // t from its use of edge a -> b; u must run b -> a.
    const Triangle ft = mesh.triangles[t], fu = mesh.triangles[u];
    const std::size_t k = uses[i].corner % 3, l = uses[other[i]].corner % 3;
    const Index a = ft[k], b = ft[(k + 1) % 3], c = ft[(k + 2) % 3];
    const Index d = across ? fu[(l + 2) % 3] : kNoIndex;
    if (across && (fu[l] != b || fu[(l + 1) % 3] != a || d == c)) continue;
    if (which == ObtuseCorners::at_boundary && !boundary[c]) continue;
    if (narrow_at && narrow_angle_at(ft, *narrow_at) > 0) continue;
    const Vec3& p = mesh.vertices[c];
    if (!(angle_deg(mesh.vertices[a] - p, mesh.vertices[b] - p) > kObtuseDeg)) continue;
    // Q only for obtuse corners: each triangle comes up once per edge, and few are obtuse.
    const double quality = min_shape(p, mesh.vertices[a], mesh.vertices[b]).quality;
    if (which == ObtuseCorners::under_bar && !(quality < kBarQuality)) continue;
    candidates.push_back({quality, t, u, a, b, c, d, curve});
  }
  std::size_t cap = candidates.size();
  if (which == ObtuseCorners::under_bar) {
    // The worst first, and few: each split adds a vertex the count did not ask for.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& x, const Candidate& y) { return x.quality < y.quality; });
    cap = std::max<std::size_t>(1, mesh.vertices.size() / kVerticesPerSplit);
  }
  std::vector<bool> split(mesh.triangles.size(), false);
  std::size_t added = 0;
  std::vector<std::array<Index, 3>> halved;  // feature edges halved: their ends, their middle
  for (const auto& [quality, t, u, a, b, c, d, curve] : candidates) {
    if (added == cap) break;
    if (split[t] || split[u]) continue;
    // The midpoint's foot, unless the nearest surface lies farther than a quarter of the edge:
    // another sheet of a thin part, which the new triangles would reach across. On a feature
    // edge, its foot on the curve, alike.
    const Vec3 middle = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
    const Vec3 foot =
        curve ? along->curves.nearest(*curve, middle).point : surface.nearest(middle).point;
    const double length = distance(mesh.vertices[a], mesh.vertices[b]);
    if (distance(foot, middle) > kMostOffset * length) continue;
    const Index m = halve_edge(mesh, t, u, a, b, c, d, foot);
    split[t] = split[u] = true;
    if (along) {
      std::vector<VertexSupport>& supports = along->supports;
      // The middle of an edge with a guarded end is guarded too (finish/crossing_guard): the
      // triangles around it are those the guard was for (a fandisk_noisy.off with 1% of its
      // triangles removed, at 1.5k: 8 crossing triangles after the sweeps, 13 and 5 guarded
      // where the middles were not, none where they are).
      const bool guarded = std::ranges::any_of(
          std::array{a, b}, [&](Index v) { return v < supports.size() && supports[v].guarded; });
      supports.resize(mesh.vertices.size());
      if (curve) supports[m] = {VertexSupport::Kind::curve, *curve};
      supports[m].guarded = guarded;
    }
    if (curve) halved.push_back({a, b, m});
    ++added;
  }
  if (along && !halved.empty()) {
    std::vector<Edge>& edges = along->feature_edges;
    std::vector<Edge> whole;
    for (const auto& [a, b, m] : halved) whole.push_back(edge_of(a, b));
    std::sort(whole.begin(), whole.end());
    std::erase_if(edges,
                  [&](const Edge& e) { return std::binary_search(whole.begin(), whole.end(), e); });
    for (const auto& [a, b, m] : halved) {
      edges.push_back(edge_of(a, m));
      edges.push_back(edge_of(m, b));
    }
    std::sort(edges.begin(), edges.end());
  }
  return added;
}

}  // namespace cvtmesh
