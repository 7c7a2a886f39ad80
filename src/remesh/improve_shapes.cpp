#include "remesh/improve_shapes.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "cvtmesh/quality.hpp"
#include "geometry/angle.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// A little above what a converged CVT gives on a smooth surface (θmin about 35-38°, Q about
// 0.65): below it, a triangle is worth improving; changes stop where they no longer help.
constexpr double kMinAngleDeg = 40;
constexpr double kMinQuality = 0.7;
// An edge is flipped only between triangles whose normals differ by at most 20°: across a
// sharper fold, the new diagonal would leave the surface.
const double kFlatCos = std::cos(20 * M_PI / 180);
// A change may turn no triangle it touches by more than 30°: more would fold the surface over.
const double kTurnCos = std::cos(30 * M_PI / 180);

// Below this Q, a triangle's normal says little about the surface.
constexpr double kSliver = 0.1;
// A change may bring its triangles this much farther from the surface, relatively, plus this
// fraction of the length it moves or flips across (so that chords of a flat region, 0 away, may
// change at all).
constexpr double kGapGrowth = 1.1;
constexpr double kGapFloor = 0.01;
// A vertex whose angles sum to more than this far from 360° is a tip or a saddle of the
// surface at the output's scale: moving it would uncover the tip (on bunny.off at 1k vertices,
// its ear's tip came 0.4% of the diagonal farther from the output; with this, 0.1%).
constexpr double kTipDefectDeg = 10;

// One figure for a triangle's shape: Q and θmin/60° are both 1 when equilateral; the smaller
// one says how far from that it is.
double score(const Vec3& a, const Vec3& b, const Vec3& c) {
  const TriangleShape s = triangle_shape(a, b, c);
  return std::min(s.quality, s.min_angle / 60);
}

bool badly_shaped(const Vec3& a, const Vec3& b, const Vec3& c) {
  const TriangleShape s = triangle_shape(a, b, c);
  return s.min_angle < kMinAngleDeg || s.quality < kMinQuality;
}

// Whether a unit_or_zero vector has no direction.
bool no_direction(const Vec3& n) {
  return n == Vec3{};
}

double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  using Point = Kernel::Point_3;
  return std::sqrt(CGAL::squared_distance(
      Point(p.x, p.y, p.z),
      Kernel::Triangle_3(Point(a.x, a.y, a.z), Point(b.x, b.y, b.z), Point(c.x, c.y, c.z))));
}

// Where vertex `v` sits in triangle `t`: 0, 1 or 2.
int slot(const Triangle& t, Index v) {
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

class ShapeImprover {
 public:
  ShapeImprover(TriangleMesh& mesh, const SurfaceProjector& surface, std::vector<bool> fixed,
                const std::vector<Edge>& features)
      : mesh_(mesh),
        surface_(surface),
        fixed_(std::move(fixed)),
        features_(features),
        start_(mesh.vertices),
        around_(mesh.vertices.size()) {
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      for (Index v : mesh_.triangles[t]) around_[v].push_back(t);
    for (Index v = 0; v < mesh_.vertices.size(); ++v) {
      // A tip of the surface (a vertex whose triangles' angles fall far short of 360°, or
      // exceed it, at a saddle) stays: moved, it would uncover the tip.
      if (!fixed_[v] && (!interior(v) || std::abs(angle_defect(v)) > kTipDefectDeg))
        fixed_[v] = true;
      start_gap_.push_back(fixed_[v] ? 0 : gap_around(v));  // only moves need it
    }
  }

  // One sweep: flips at the badly shaped triangles, then moves of their vertices and their
  // neighbours. Returns whether anything changed.
  bool sweep(ShapeImprovement& done) {
    bool changed = false;
    for (Index t = 0; t < mesh_.triangles.size(); ++t) {
      if (!bad(t)) continue;
      for (int i = 0; i < 3; ++i) {
        const Triangle& f = mesh_.triangles[t];
        if (try_flip(t, f[i], f[(i + 1) % 3])) {
          ++done.flips;
          changed = true;
          break;  // t is another triangle now
        }
      }
    }
    std::vector<Index> candidates;
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      if (bad(t))
        for (Index v : mesh_.triangles[t])
          for (Index s : around_[v])
            candidates.insert(candidates.end(), mesh_.triangles[s].begin(),
                              mesh_.triangles[s].end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (Index v : candidates)
      if (!fixed_[v] && try_move(v)) {
        ++done.moves;
        changed = true;
      }
    return changed;
  }

 private:
  bool bad(Index t) const {
    const auto [a, b, c] = mesh_.corners(t);
    return badly_shaped(a, b, c);
  }

  // Whether every edge at `v` has exactly two triangles, which use it in opposite directions: a
  // vertex inside an oriented surface, away from boundaries and non-manifold edges.
  bool interior(Index v) const {
    std::vector<std::pair<Index, int>> uses;  // (other end, +1 out of v / -1 into v)
    for (Index t : around_[v]) {
      const Triangle& f = mesh_.triangles[t];
      const int i = slot(f, v);
      uses.push_back({f[(i + 1) % 3], +1});
      uses.push_back({f[(i + 2) % 3], -1});
    }
    std::sort(uses.begin(), uses.end());
    if (uses.size() < 6 || uses.size() % 2 != 0) return false;
    for (std::size_t k = 0; k < uses.size(); k += 2)
      if (uses[k].first != uses[k + 1].first || uses[k].second + uses[k + 1].second != 0 ||
          (k + 2 < uses.size() && uses[k + 2].first == uses[k].first))
        return false;
    return true;
  }

  // The triangles with both `a` and `b`.
  std::vector<Index> sharing(Index a, Index b) const {
    std::vector<Index> out;
    for (Index t : around_[a])
      if (std::ranges::find(mesh_.triangles[t], b) != mesh_.triangles[t].end()) out.push_back(t);
    return out;
  }

  // 360° less the angles of its triangles at `v`, in degrees: the discrete Gaussian curvature.
  double angle_defect(Index v) const {
    double sum = 0;
    for (Index t : around_[v]) {
      const Triangle& f = mesh_.triangles[t];
      const int i = slot(f, v);
      const Vec3& p = mesh_.vertices[v];
      sum += angle_deg(mesh_.vertices[f[(i + 1) % 3]] - p, mesh_.vertices[f[(i + 2) % 3]] - p);
    }
    return 360 - sum;
  }

  // How far the surface is from the triangles at `v` (their centroids), at most.
  double gap_around(Index v) const {
    double gap = 0;
    for (Index t : around_[v]) gap = std::max(gap, gap_at(centroid(t)));
    return gap;
  }
  // How far `p` is from the triangles at `v`.
  double distance_to_star(const Vec3& p, Index v) const {
    double d = std::numeric_limits<double>::infinity();
    for (Index t : around_[v]) {
      const auto [a, b, c] = mesh_.corners(t);
      d = std::min(d, distance_to_triangle(p, a, b, c));
    }
    return d;
  }
  double gap_at(const Vec3& p) const { return distance(p, surface_.nearest(p).point); }
  Vec3 centroid(Index t) const {
    const auto [a, b, c] = mesh_.corners(t);
    return (1.0 / 3) * (a + b + c);
  }

  // Flips edge a→b of triangle t1 = (a, b, c) with its neighbour t2 = (b, a, d) into (c, a, d)
  // and (d, b, c), when that makes the worse of the two better.
  bool try_flip(Index t1, Index a, Index b) {
    if (std::binary_search(features_.begin(), features_.end(),
                           Edge{std::min(a, b), std::max(a, b)}))
      return false;
    if (around_[a].size() < 2 || around_[b].size() < 2) return false;
    const std::vector<Index> both = sharing(a, b);
    if (both.size() != 2) return false;
    const Index t2 = both[0] == t1 ? both[1] : both[0];
    const Triangle f1 = mesh_.triangles[t1], f2 = mesh_.triangles[t2];
    const Index c = f1[(slot(f1, b) + 1) % 3];
    const int ib = slot(f2, b);
    if (f2[(ib + 1) % 3] != a) return false;  // the two use a-b the same way: not oriented
    const Index d = f2[(ib + 2) % 3];
    if (c == d || !sharing(c, d).empty()) return false;
    const std::vector<Vec3>& p = mesh_.vertices;
    // The pair's plane, weighted by area (a sliver's normal says little), must hold both new
    // triangles and every old one that is not a sliver.
    const Vec3 n = unit_or_zero(cross(p[b] - p[a], p[c] - p[a]) + cross(p[a] - p[b], p[d] - p[b]));
    const double before = std::min(score(p[a], p[b], p[c]), score(p[b], p[a], p[d]));
    const double after = std::min(score(p[c], p[a], p[d]), score(p[d], p[b], p[c]));
    if (!(after > before)) return false;
    const std::array<std::array<Index, 3>, 4> planar{{{a, b, c}, {b, a, d}, {c, a, d}, {d, b, c}}};
    for (int k = 0; k < 4; ++k) {
      const auto [u, v, w] = planar[k];
      const Vec3 m = unit_normal(p[u], p[v], p[w]);
      if (k < 2 && triangle_shape(p[u], p[v], p[w]).quality < kSliver) continue;
      if (no_direction(m) || no_direction(n) || dot(m, n) < kFlatCos) return false;
    }
    // The new diagonal stays about as close to the surface as the old one.
    if (gap_at(0.5 * (p[c] + p[d])) >
        kGapGrowth * gap_at(0.5 * (p[a] + p[b])) + kGapFloor * distance(p[c], p[d]))
      return false;
    mesh_.triangles[t1] = {c, a, d};
    mesh_.triangles[t2] = {d, b, c};
    std::erase(around_[a], t2);
    std::erase(around_[b], t1);
    around_[c].push_back(t2);
    around_[d].push_back(t1);
    return true;
  }

  // Moves `v` to the nearest surface point to the mean of its neighbours (or, failing that,
  // halfway there), when that makes the worst triangle of its star better.
  bool try_move(Index v) {
    std::vector<Vec3>& p = mesh_.vertices;
    Vec3 sum{};
    for (Index t : around_[v]) {
      const Triangle& f = mesh_.triangles[t];
      sum += p[f[(slot(f, v) + 1) % 3]];  // each neighbour once: it follows v in one triangle
    }
    const Vec3 from = p[v];
    const Vec3 centre = (1.0 / static_cast<double>(around_[v].size())) * sum;
    double before = 1;
    std::vector<Vec3> normals;
    for (Index t : around_[v]) {
      const auto [a, b, c] = mesh_.corners(t);
      before = std::min(before, score(a, b, c));
      const Vec3 n = unit_normal(a, b, c);
      if (no_direction(n)) return false;
      normals.push_back(n);
    }
    for (const double step : {1.0, 0.5}) {
      p[v] = surface_.nearest(from + step * (centre - from)).point;
      double after = 1;
      bool folds = false;
      for (std::size_t k = 0; k < around_[v].size() && !folds; ++k) {
        const auto [a, b, c] = mesh_.corners(around_[v][k]);
        after = std::min(after, score(a, b, c));
        const Vec3 n = unit_normal(a, b, c);
        folds = no_direction(n) || dot(n, normals[k]) < kTurnCos;
      }
      // Its triangles stay about as close to the surface as they were at the start, and near
      // the surface point where it was then (else smoothing would shrink every convex tip). The
      // bounds are those of the start, so that moves after moves cannot drift away.
      const double allowed = kGapGrowth * start_gap_[v] + kGapFloor * distance(start_[v], p[v]);
      if (!folds && after > before && gap_around(v) <= allowed &&
          distance_to_star(start_[v], v) <= allowed)
        return true;
    }
    p[v] = from;
    return false;
  }

  TriangleMesh& mesh_;
  const SurfaceProjector& surface_;
  std::vector<bool> fixed_;
  const std::vector<Edge>& features_;
  const std::vector<Vec3> start_;           // the vertices where they were
  std::vector<double> start_gap_;           // per vertex, gap_around it then
  std::vector<std::vector<Index>> around_;  // per vertex, its triangles
};

}  // namespace

ShapeImprovement improve_shapes(TriangleMesh& mesh, const SurfaceProjector& surface,
                                std::vector<bool> fixed, const std::vector<Edge>& feature_edges,
                                int sweeps) {
  ShapeImprovement done;
  fixed.resize(mesh.vertices.size(), false);
  ShapeImprover improver(mesh, surface, std::move(fixed), feature_edges);
  for (int k = 0; k < sweeps && improver.sweep(done); ++k) {
  }
  return done;
}

}  // namespace cvtmesh
