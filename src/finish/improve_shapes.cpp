#include "finish/improve_shapes.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <span>

#include "features/curve_projector.hpp"
#include "features/edge_uses.hpp"
#include "finish/move_limits.hpp"
#include "finish/near_triangles.hpp"
#include "finish/surface_gap.hpp"
#include "finish/worst_shape.hpp"
#include "geometry/angle.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/triangle_bounds.hpp"
#include "geometry/triangles_around.hpp"
#include "geometry/unit_vector.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// An edge is flipped only where the two triangles' normals and the new two's are within 40° of
// the pair's: across a sharper fold, the new diagonal would leave the surface (the gap test below
// checks that it does not). 40° rather than 20°: on a curved part of the surface a chord and the
// diagonal across it fold by more than 20°, and the worst triangles of corpus/cow.off at 1k and
// couplingdown.off at 5k were such pairs (θmin 24.6° → 30.2°, Qmin 0.508 → 0.543); on the other
// shared meshes at 1k and 5k no θmin or Qmin changed, and the Hausdorff max rose by 0.09% of
// the diagonal at most (ChineseDragon-10kv at 1k).
const double kFlatCos = std::cos(40 * M_PI / 180);
// A change may turn no triangle it touches by more than 30°: more would fold the surface over.
const double kTurnCos = std::cos(30 * M_PI / 180);

// Below this Q, a triangle's normal says little about the surface.
constexpr double kSliver = 0.1;
// A vertex whose angles sum to more than this far from 360° is a tip or a saddle of the
// surface at the output's scale: moving it would uncover the tip (on bunny.off at 1k vertices,
// with no such rule, its ear's tip came 0.4% of the diagonal farther from the output). 20°
// rather than 10°: on the shared meshes at 1k, θmin or Qmin rose on 12 (bull 20.2° → 36.8°,
// scorpion 19.1° → 33.3°, thin parts whose every vertex bends more than 10°) and fell on none;
// the Hausdorff max rose by 0.13% of the diagonal at most (lion-head), the mean by 0.005%.
// 30° rather than 20° (at 9dfb642, 56 meshes): θmin or Qmin rose on 11 at 1k (bull 30.6° →
// 37.3°, triceratops 22.9° → 32.7°, demosthenes 33.3° → 39.4°), 6 at 5k (man 20.9° → 24.9°,
// femur 5.2° → 7.1°) and 7 at 10k (ALSTOM_TEST4 16.0° → 19.2°, man 22.8° → 26.4°); they fell
// on cow at 1k (30.2° → 29.7°), fandisk at 1k (Qmin 0.668 → 0.650), fandisk_noisy at 5k (40.0°
// → 31.3°, another local optimum), demosthenes at 5k (37.7° → 37.3°) and ChineseDragon-10kv at
// 10k (6.1° → 5.6°); the Hausdorff max rose by 0.12% of the diagonal at most (tripod, 1k).
// A saddle (a defect under -30°) uncovers no tip: it is held only until the rest has done what
// it can, then a second pass lets it move. On the 57 shared meshes at 1k, 5k and 10k, θmin or
// Qmin rose on 31 runs (scorpion_low_resolution at 5k 27.9° → 37.2°, two saddles beside a tip
// holding a 28° triangle; man at 1k 20.4° → 32.5°, femur at 10k 17.5° → 27.4°) and fell by
// 0.1° or 0.001 on 2; the Hausdorff max rose by 0.21% of the diagonal at most (couplingdown,
// 1k). Saddles free from the start did as well on most but led triceratops at 1k to another
// local optimum (35.0° → 19.0°: its horn's tip, held, left worse by its neighbours' moves).
constexpr double kTipDefectDeg = 30;
// The search for a better place (a compass search: steps in fixed directions, halved when none
// helps) starts a quarter of the vertex's mean edge length away and stops below 1/32 of it.
constexpr double kFirstStep = 0.25;
constexpr double kLastStep = 1.0 / 32;
// At most this many steps or halvings: each step makes the star strictly better, but its
// places are not on a finite grid, so only a cap bounds their number.
constexpr int kMaxSearchSteps = 64;
// Directions tried on the surface: this many, evenly spread in the star's tangent plane.
constexpr int kDirections = 8;
// The search runs only while the star's worst Q or θmin / 60° is under this.
constexpr double kSearchBelow = 0.7;

// The sweeps and balancing rounds stop (after the one under way) once the vertices' searches
// for a better place reach this many per vertex: on the 57 shared meshes at 1k, 5k and 10k and
// adaptive at 2k, a call took 13.4 at most (couplingdown.off at 1k); a blade of slivers with
// 155 sliver holes, whose output keeps hundreds of badly shaped triangles, took 35-64 in each
// of its dozens of calls (over 200 s at 300 vertices, grown to 2.1k for its holes).
constexpr double kSearchesPerVertex = 24;

// One vertex in this many at most is taken away by collapses, so that the output keeps the
// count asked for within 1%: where every triangle is a little under the bar above (a grid of
// right triangles, 35°), each collapse could otherwise find one better and take it.
constexpr std::size_t kCollapsesPer = 100;

// A start gap not measured yet (gaps are distances, never negative).
constexpr double kNotMeasured = -1;

bool badly_shaped(const Vec3& a, const Vec3& b, const Vec3& c) {
  const MinShape s = min_shape(a, b, c);
  return s.min_angle < kAimAngleDeg || s.quality < kAimQuality;
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

// The score (as WorstShape's, 1 at best) of a triangle at a narrow input angle whose smallest
// angle is `ratio` times that angle: 1 from the input angle up (no triangle there can do better),
// that of a triangle at the bar elsewhere (θmin 30°) at 0.9 of it, the promise's bound for such
// triangles (issue 18 item 6), and nothing from 0.8 down.
double at_narrow_score(double ratio) {
  return std::clamp(0.5 + 5 * (ratio - 0.9), 0.0, 1.0);
}

// The shape of a vertex's star: one closed disc (inside the surface), one half-disc (on a
// boundary), or anything else (a pinch, a non-manifold edge, opposite orientations).
enum class Star { disc, half_disc, other };

class ShapeImprover {
 public:
  ShapeImprover(TriangleMesh& mesh, const SurfaceProjector& surface, const CurveProjector* curves,
                std::vector<VertexSupport> support, std::vector<Edge>& features,
                const std::vector<double>& narrow_at, std::vector<bool> active)
      : mesh_(mesh),
        surface_(surface),
        curves_(curves),
        support_(std::move(support)),
        features_(features),
        narrow_at_(narrow_at),
        active_(std::move(active)),
        start_(mesh.vertices),
        gone_(mesh.triangles.size(), false),
        collapse_budget_(mesh.vertices.size() / kCollapsesPer),
        floor_(mesh_shape()),
        around_(triangles_around(mesh)),
        changed_at_(mesh.vertices.size(), 0),
        stuck_at_(mesh.vertices.size(), 0),
        balance_failed_at_(mesh.triangles.size(), 0),
        visited_(mesh.vertices.size(), 0) {
    support_.resize(mesh_.vertices.size());
    // A gap costs projections, and most vertices never move: each is measured when first needed,
    // or before its triangles first change (on bunny.off at 5k, all of them were half the cost
    // of this step).
    start_gap_.assign(mesh_.vertices.size(), kNotMeasured);
    failed_gap_at_.assign(mesh_.vertices.size(), kNoIndex);
    near_surface_.assign(mesh_.triangles.size(), kNotFound);
    // A held saddle's gap is measured as a movable vertex's: it moves in the second pass.
    for (Index v = 0; v < mesh_.vertices.size(); ++v) {
      const Hold why = v < active_.size() && !active_[v] ? Hold::fixed : hold(v);
      if (why == Hold::none) continue;
      if (why == Hold::saddle)
        saddles_.push_back(v);
      else
        start_gap_[v] = 0;
      support_[v].kind = VertexSupport::Kind::fixed;
    }
  }

  // Lets the saddles held at the start move from now on (see kTipDefectDeg).
  void free_saddles() {
    for (Index v : saddles_) {
      support_[v].kind = VertexSupport::Kind::surface;
      changed(v);  // their neighbours' moves may find better places now
    }
  }

  // One sweep: flips at the badly shaped triangles, then moves of their vertices and their
  // neighbours. Returns whether anything changed.
  bool sweep(ShapeImprovement& done) {
    bool changed = false;
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      if (!gone_[t] && bad(t) &&
          flip_an_edge(t, [&](Index a, Index b) { return try_flip(t, a, b); })) {
        ++done.flips;
        changed = true;
      }
    // The vertices of the bad triangles and their neighbours, in order: marked, as they come in
    // dozens of times each (sorting them all was a twentieth of a remesh that keeps thousands of
    // bad triangles, a scan with hundreds of small holes).
    std::vector<bool> wanted(mesh_.vertices.size(), false);
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      if (!gone_[t] && bad(t))
        for (Index v : mesh_.triangles[t])
          for (Index s : around_[v])
            for (Index w : mesh_.triangles[s]) wanted[w] = true;
    std::vector<Index> candidates;
    for (Index v = 0; v < wanted.size(); ++v)
      if (wanted[v]) candidates.push_back(v);
    for (Index v : candidates)
      if (support_[v].kind != VertexSupport::Kind::fixed && try_move(v)) {
        ++done.moves;
        changed = true;
      }
    return changed;
  }

  // Once sweeps change nothing: balancing flips at the badly shaped triangles, worst first, with
  // the mesh's worst Q and θmin as they are now as the floor that no change, here or in the
  // sweeps after, may go under. Returns whether anything changed.
  bool balance(ShapeImprovement& done) {
    const WorstShape was = floor_;
    floor_ = mesh_shape();
    // A higher floor lets fewer changes through: a vertex stuck under the old one stays stuck.
    if (floor_.quality < was.quality || floor_.angle < was.angle) floor_at_ = ++clock_;
    std::vector<std::pair<double, Index>> worst_first;
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      if (!gone_[t] && bad(t)) worst_first.push_back({worst_of(std::array{t}).score(), t});
    std::sort(worst_first.begin(), worst_first.end());
    bool changed = false;
    for (const auto& worst : worst_first) {
      const Index t = worst.second;
      const auto balancing = [&](Index a, Index b) { return try_balancing_flip(t, a, b, done); };
      if (gone_[t] || !bad(t) || balance_stuck(t)) continue;
      if (flip_an_edge(t, balancing)) {
        ++done.flips;
        changed = true;
      } else if (try_collapse(t, done)) {
        ++done.collapses;
        changed = true;
      } else {
        balance_failed_at_[t] = ++clock_;
      }
    }
    return changed;
  }

  std::size_t searches() const { return searches_; }
  // Whether the searches reached their budget (kSearchesPerVertex).
  bool spent() const {
    return static_cast<double>(searches_) >=
           kSearchesPerVertex * static_cast<double>(mesh_.vertices.size());
  }

  // Drops the triangles that collapses took away (their vertices stay, unused).
  void finish() { erase_marked_triangles(mesh_, gone_); }

 private:
  // Tries `try_one(a, b)` on the edges a→b of triangle t in turn, until one flips.
  template <class TryOne>
  bool flip_an_edge(Index t, const TryOne& try_one) {
    for (int i = 0; i < 3; ++i) {
      const Triangle f = mesh_.triangles[t];
      if (try_one(f[i], f[(i + 1) % 3])) return true;  // t is another triangle now
    }
    return false;
  }

  // The worst shape of the triangles `ts`, where its score is above `bar`; nothing where it is
  // not, found at the first triangle that puts it there (the searches below judge places by the
  // thousand, and many places are no better than the best found: WorstShape::better_than asks
  // for a higher score). The same shape as measuring them all, bit for bit, where one is
  // returned.
  template <class Triangles>
  std::optional<WorstShape> worst_of_above(const Triangles& ts, double bar) const {
    WorstShape worst;
    for (Index t : ts) {
      const auto [a, b, c] = mesh_.corners(t);
      double input = 0;  // the narrowest input angle of a tip the triangle is at, if any
      for (const Index v : mesh_.triangles[t])
        if (v < narrow_at_.size() && narrow_at_[v] > 0)
          input = input > 0 ? std::min(input, narrow_at_[v]) : narrow_at_[v];
      if (input > 0) {
        worst.add(WorstShape{1, at_narrow_score(min_shape(a, b, c).min_angle / input)});
        if (!(worst.score() > bar)) return std::nullopt;
      } else if (!worst.add_above(a, b, c, bar)) {
        return std::nullopt;
      }
    }
    if (!(worst.score() > bar)) return std::nullopt;  // no triangle: score 1
    return worst;
  }
  // The worst shape of the triangles `ts`; of the whole mesh; of the triangles at `v`.
  template <class Triangles>
  WorstShape worst_of(const Triangles& ts) const {
    return *worst_of_above(ts, -std::numeric_limits<double>::infinity());
  }
  WorstShape mesh_shape() const {
    WorstShape worst;
    for (Index t = 0; t < mesh_.triangles.size(); ++t)
      if (!gone_[t]) worst.add(worst_of(std::array{t}));
    return worst;
  }
  WorstShape star_shape(Index v) const { return worst_of(around_[v]); }
  // Whether the triangles at `v` are better than `o` (WorstShape::better_than); if so, their shape
  // goes into `shape`.
  bool star_better_than(Index v, const WorstShape& o, WorstShape& shape) const {
    const std::optional<WorstShape> s = worst_of_above(around_[v], o.score());
    if (!s || !s->better_than(o, floor_)) return false;
    shape = *s;
    return true;
  }

  bool bad(Index t) const {
    if (!active_.empty() && std::none_of(mesh_.triangles[t].begin(), mesh_.triangles[t].end(),
                                         [&](Index v) { return v < active_.size() && active_[v]; }))
      return false;
    const auto [a, b, c] = mesh_.corners(t);
    return badly_shaped(a, b, c);
  }

  // Walks round `v` from triangle to triangle across shared edges: whether its triangles make
  // one disc or one half-disc, consistently oriented. A half-disc's two boundary neighbours go
  // in `ends`.
  Star star(Index v, std::array<Index, 2>& ends) const {
    const std::vector<Index>& ts = around_[v];
    if (ts.size() < 2) return Star::other;
    // Triangle ts[k], going round v, runs from neighbour out to neighbour in. Looked up sorted,
    // as a hole's fan may give one vertex thousands of triangles (the last step's, where a
    // widely self-crossing input left a loop of 1,600 edges: by pairs, 58% of a 300 s run).
    std::vector<std::array<Index, 2>>& steps = star_steps_;
    std::vector<std::pair<Index, std::size_t>>& by_out = star_by_out_;
    std::vector<Index>& ins = star_ins_;
    steps.resize(ts.size());
    by_out.clear();
    ins.clear();
    for (std::size_t k = 0; k < ts.size(); ++k) {
      const Triangle& f = mesh_.triangles[ts[k]];
      const int i = slot(f, v);
      steps[k] = {f[(i + 1) % 3], f[(i + 2) % 3]};
      by_out.push_back({steps[k][0], k});
      ins.push_back(steps[k][1]);
    }
    std::sort(by_out.begin(), by_out.end());
    std::sort(ins.begin(), ins.end());
    const auto after = [&](std::size_t k) {  // the triangle that starts where k ends, if just one
      const Index x = steps[k][1];
      const auto lo = std::lower_bound(by_out.begin(), by_out.end(), std::pair{x, std::size_t{0}});
      const auto hi = std::upper_bound(lo, by_out.end(), std::pair{x, ts.size()});
      return hi - lo == 1 ? std::optional<std::size_t>{lo->second} : std::nullopt;
    };
    std::size_t first = 0, starts = 0;
    for (std::size_t k = 0; k < ts.size(); ++k)
      if (!std::binary_search(ins.begin(), ins.end(), steps[k][0])) {
        first = k;
        ++starts;
      }
    if (starts > 1) return Star::other;
    std::size_t seen = 1;
    std::size_t k = first;
    for (std::optional<std::size_t> next = after(k); next && *next != first; next = after(k)) {
      k = *next;
      if (++seen > ts.size()) return Star::other;
    }
    if (seen != ts.size()) return Star::other;
    if (starts == 0)
      return steps[k][1] == steps[first][0] && ts.size() >= 3 ? Star::disc : Star::other;
    ends = {steps[first][0], steps[k][1]};
    return Star::half_disc;
  }

  // Why `v` may not move at all, if it may not. It may if it is a surface vertex inside the
  // surface that is no tip (moved, a tip would be uncovered), or a curve vertex with one or two
  // feature edges inside the surface, or between its two on a boundary. A surface vertex inside
  // the surface that only the saddle side of the tip rule holds is told apart.
  enum class Hold { none, saddle, fixed };
  Hold hold(Index v) const {
    std::array<Index, 2> ends{};
    switch (support_[v].kind) {
      case VertexSupport::Kind::fixed:
        return Hold::fixed;
      case VertexSupport::Kind::surface: {
        if (star(v, ends) != Star::disc) return Hold::fixed;
        const double defect = angle_defect(v);
        if (std::abs(defect) <= kTipDefectDeg) return Hold::none;
        return defect < -kTipDefectDeg ? Hold::saddle : Hold::fixed;
      }
      case VertexSupport::Kind::curve: {
        std::vector<Index> along;  // its neighbours across feature edges
        for (Index t : around_[v])
          for (Index w : mesh_.triangles[t])
            if (w != v && is_feature(v, w)) along.push_back(w);
        std::sort(along.begin(), along.end());
        along.erase(std::unique(along.begin(), along.end()), along.end());
        // One feature edge when the link to its other neighbour along the curve was not traced:
        // it may still slide, and the edge it has stays a chord of the curve.
        if (along.empty() || along.size() > 2 || curves_ == nullptr) return Hold::fixed;
        const Star kind = star(v, ends);
        std::sort(ends.begin(), ends.end());
        return kind == Star::disc || (kind == Star::half_disc && std::ranges::equal(ends, along))
                   ? Hold::none
                   : Hold::fixed;
      }
    }
    return Hold::fixed;
  }

  bool is_feature(Index a, Index b) const {
    return std::binary_search(features_.begin(), features_.end(), edge_of(a, b));
  }

  static Index other_end(const Edge& e, Index v) { return e[0] == v ? e[1] : e[0]; }

  // Takes the feature edges `gone` (there) out of the sorted list and puts `added` in.
  void replace_features(const std::vector<Edge>& gone, const std::vector<Edge>& added) {
    for (const Edge& e : gone)
      features_.erase(std::lower_bound(features_.begin(), features_.end(), e));
    for (const Edge& e : added)
      features_.insert(std::lower_bound(features_.begin(), features_.end(), e), e);
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

  // Whether the surface is within `allowed` of every triangle at `v` (of their centroids). Asked
  // first of the triangle that failed last at `v`: the places a compass search tries for a vertex
  // mostly fail at the same triangle (on corpus/ChineseDragon-10kv.off at 1k, two in three places
  // failed, and these searches were a sixth of the run).
  bool gaps_within(Index v, double allowed) const {
    Index& first = failed_gap_at_[v];
    const auto fails = [&](Index t) {
      if (gap_within(t, allowed)) return false;
      first = t;
      return true;
    };
    const std::vector<Index>& ts = around_[v];
    const bool known = std::ranges::find(ts, first) != ts.end();
    if (known && fails(first)) return false;
    return std::ranges::none_of(ts, [&](Index t) { return !(known && t == first) && fails(t); });
  }
  // How far the surface was from the triangles at `v` (their centroids) at the start, at most: from
  // v's triangles, which are those of the start until a flip or collapse changes them (each
  // measures the gaps of the vertices whose triangles it changes first), with their vertices where
  // they were then.
  double start_gap(Index v) const {
    double& gap = start_gap_[v];
    if (gap == kNotMeasured) {
      gap = 0;
      for (Index t : around_[v]) {
        const Triangle& f = mesh_.triangles[t];
        gap = std::max(gap, gap_at((1.0 / 3) * (start_[f[0]] + start_[f[1]] + start_[f[2]])));
      }
    }
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
  double gap_at(const Vec3& p) const { return surface_.distance_to(p); }
  // Whether gap_at(p) <= allowed, by a search that opens only the boxes within `allowed` of p
  // and stops at the first triangle there (SurfaceProjector::within): on
  // corpus/ChineseDragon-10kv.off at 1k, nearest-point searches were half of this step.
  bool gap_within(const Vec3& p, double allowed) const {
    return surface_.within(p, allowed * allowed).has_value();
  }
  // The same for triangle t's centroid, asking first the surface triangle found within reach of
  // it last: the places a search tries move t a little, and that triangle is mostly within reach
  // again.
  bool gap_within(Index t, double allowed) const {
    std::size_t& last = near_surface_[t];
    const std::optional<SurfaceProjector::Near> near =
        last == kNotFound ? surface_.within(centroid(t), allowed * allowed)
                          : surface_.within(centroid(t), allowed * allowed, last);
    if (near) last = near->triangle;
    return near.has_value();
  }
  Vec3 centroid(Index t) const {
    const auto [a, b, c] = mesh_.corners(t);
    return (1.0 / 3) * (a + b + c);
  }

  // The quad of a flip of edge a→b of triangle t1 = (a, b, c) with its neighbour t2 = (b, a, d),
  // when the flip is possible: an edge of two triangles that use it in opposite directions, no
  // feature, and no edge c-d yet.
  struct Quad {
    Index t1, t2, a, b, c, d;
  };
  std::optional<Quad> flippable(Index t1, Index a, Index b) const {
    if (is_feature(a, b)) return {};
    if (around_[a].size() < 2 || around_[b].size() < 2) return {};
    const std::vector<Index> both = sharing(a, b);
    if (both.size() != 2) return {};
    const Index t2 = both[0] == t1 ? both[1] : both[0];
    const Triangle f1 = mesh_.triangles[t1], f2 = mesh_.triangles[t2];
    const Index c = f1[(slot(f1, b) + 1) % 3];
    const int ib = slot(f2, b);
    if (f2[(ib + 1) % 3] != a) return {};  // the two use a-b the same way: not oriented
    const Index d = f2[(ib + 2) % 3];
    if (c == d || !sharing(c, d).empty()) return {};
    return Quad{t1, t2, a, b, c, d};
  }

  // Whether the flipped quad stays on the surface: the pair's plane, weighted by area (a sliver's
  // normal says little), holds both new triangles and every old one that is not a sliver, and
  // the new diagonal is about as close to the surface as the old one.
  bool flip_keeps_surface(const Quad& q) const {
    const std::vector<Vec3>& p = mesh_.vertices;
    const auto [t1, t2, a, b, c, d] = q;
    const Vec3 n = unit_or_zero(cross(p[b] - p[a], p[c] - p[a]) + cross(p[a] - p[b], p[d] - p[b]));
    const std::array<std::array<Index, 3>, 4> planar{{{a, b, c}, {b, a, d}, {c, a, d}, {d, b, c}}};
    for (int k = 0; k < 4; ++k) {
      const auto [u, v, w] = planar[k];
      const Vec3 m = unit_normal(p[u], p[v], p[w]);
      if (k < 2 && min_shape(p[u], p[v], p[w]).quality < kSliver) continue;
      if (no_direction(m) || no_direction(n) || dot(m, n) < kFlatCos) return false;
    }
    return gap_within(0.5 * (p[c] + p[d]),
                      allowed_gap(gap_at(0.5 * (p[a] + p[b])), distance(p[c], p[d])));
  }

  void flip(const Quad& q) {
    const auto [t1, t2, a, b, c, d] = q;
    for (const Index v : {a, b, c, d})
      start_gap(v);  // measured while their triangles are the start's
    mesh_.triangles[t1] = {c, a, d};
    mesh_.triangles[t2] = {d, b, c};
    near_.rewired(t1);
    near_.rewired(t2);
    for (const Index v : {a, b, c, d}) changed(v);
    std::erase(around_[a], t2);
    std::erase(around_[b], t1);
    around_[c].push_back(t2);
    around_[d].push_back(t1);
  }

  // Flips edge a→b of triangle t1 into (c, a, d) and (d, b, c), when that makes the worse of the
  // two better.
  bool try_flip(Index t1, Index a, Index b) {
    const std::optional<Quad> q = flippable(t1, a, b);
    if (!q) return false;
    const std::vector<Vec3>& p = mesh_.vertices;
    const Index c = q->c, d = q->d;
    WorstShape before, after;
    before.add(p[a], p[b], p[c]);
    before.add(p[b], p[a], p[d]);
    after.add(p[c], p[a], p[d]);
    after.add(p[d], p[b], p[c]);
    if (!after.better_than(before, floor_) || !flip_keeps_surface(*q)) return false;
    if (flip_crosses(*q)) return false;
    flip(*q);
    return true;
  }

  // Whether flipping quad `q` would pass a triangle through another, where one of its vertices
  // is guarded.
  bool flip_crosses(const Quad& q) {
    const auto [t1, t2, a, b, c, d] = q;
    if (std::ranges::none_of(std::array{a, b, c, d}, [&](Index v) { return support_[v].guarded; }))
      return false;
    const Triangle f1 = mesh_.triangles[t1], f2 = mesh_.triangles[t2];
    mesh_.triangles[t1] = {c, a, d};
    mesh_.triangles[t2] = {d, b, c};
    const bool crosses = crosses_another(std::array{t1, t2});
    mesh_.triangles[t1] = f1;
    mesh_.triangles[t2] = f2;
    return crosses;
  }

  // Whether a triangle of `changed` passes through another (triangles_cross). Any triangle may,
  // as sheets far apart along the mesh can be close in space (a plate a tenth of an edge thick,
  // its two faces nine rings apart): those whose boxes overlap are found in space (near_, built
  // at the first check: only guarded vertices ask, and only where the finishing steps made
  // crossings). A grid built during a check sees `changed` as it is tried: they count as
  // rewired, since the try is undone.
  template <class Triangles>
  bool crosses_another(const Triangles& changed) const {
    if (near_.stale()) {
      near_.build(mesh_, gone_);
      for (const Index t : changed) near_.rewired(t);
    }
    bool crosses = false;
    for (const Index t : changed) {
      const TriangleBounds bounds = bounds_of(mesh_.vertices, mesh_.triangles[t]);
      near_.for_each_near(bounds.lo, bounds.hi, [&](Index s) {
        if (crosses || gone_[s] || std::ranges::find(changed, s) != changed.end() ||
            !overlap(bounds_of(mesh_.vertices, mesh_.triangles[s]), bounds))
          return;
        crosses = triangles_cross(mesh_, mesh_.triangles[t], mesh_.triangles[s]);
      });
      if (crosses) return true;
    }
    // Nor through one another: the triangles of a star that share only its vertex fold through
    // each other where the star no longer projects onto a disc (a fuzzed handle.off with 23
    // one-triangle holes, at 300: every vertex there guarded, two triangles of one star still
    // crossed after the sweeps). Their boxes all hold that vertex: no box test first.
    for (auto t = changed.begin(); t != changed.end(); ++t)
      for (auto s = std::next(t); s != changed.end(); ++s)
        if (triangles_cross(mesh_, mesh_.triangles[*t], mesh_.triangles[*s])) return true;
    return false;
  }

  // A flip that try_flip would not take, since its own two triangles are no better at once: one
  // that brings the valences of a, b, c and d nearer 6 (a vertex of valence 4 beside ones of 7
  // and 8 holds an angle near 100° however it moves; on a boundary, 3 triangles rather than 6:
  // mech-holes-shark at 1k, 22.5° → 26.7°), followed by moves of the four and their
  // neighbours. Kept when the worst triangle at the vertices moved is better; else undone. On the
  // 56 shared meshes at 1k, 5k and 10k vertices, θmin or Qmin rose on 26 runs (3torus at 5k:
  // 26.4° → 33.6°, Qmin 0.459 → 0.627; lion-head at 5k: Qmin 0.613 → 0.659; cow at 1k: 29.7°
  // → 33.2°) and fell on one (bull at 1k: Qmin 0.700 → 0.644 at the same θmin, 37.3°: the
  // valence-three removal that followed took a vertex away before, and finds none now); the
  // Hausdorff max rose by 0.007% of the diagonal at most.
  // The moves kept with it count in `done`.
  bool try_balancing_flip(Index t1, Index a, Index b, ShapeImprovement& done) {
    const std::optional<Quad> q = flippable(t1, a, b);
    if (!q) return false;
    const Index c = q->c, d = q->d;
    std::array<Index, 2> ends{};
    const std::array<Index, 4> quad{a, b, c, d};
    // Squared distances of the triangle counts from 6 inside the surface, 3 on a boundary.
    double off_before = 0, off_after = 0;
    for (int k = 0; k < 4; ++k) {
      const Index v = quad[k];
      const Star kind = star(v, ends);
      if (kind == Star::other) return false;
      const double ideal = kind == Star::disc ? 6 : 3;
      const double valence = static_cast<double>(around_[v].size());
      off_before += (valence - ideal) * (valence - ideal);
      const double flipped = valence + (k < 2 ? -1 : 1);
      off_after += (flipped - ideal) * (flipped - ideal);
    }
    if (off_after >= off_before || !flip_keeps_surface(*q) || flip_crosses(*q)) return false;
    // The quad's vertices and their neighbours move: the four alone often cannot even out the
    // angles that the new valences ask for.
    const Region region = region_at(quad);
    const Stamps saved = stamps_of(region.vertices);
    const Triangle f1 = mesh_.triangles[q->t1], f2 = mesh_.triangles[q->t2];
    std::array<std::vector<Index>, 4> stars;
    for (int k = 0; k < 4; ++k) stars[k] = around_[quad[k]];
    flip(*q);
    if (settled(region, quad, done)) return true;
    for (int k = 0; k < 4; ++k) around_[quad[k]] = std::move(stars[k]);
    mesh_.triangles[q->t1] = f1;
    mesh_.triangles[q->t2] = f2;
    near_.rewired(q->t1);
    near_.rewired(q->t2);
    put_back(saved);
    return false;
  }

  // What a change at the vertices `core` and the moves after it touch: the vertices of the
  // triangles at `core` (sorted, but for `left_out`, which the change takes away), where they
  // are, and the worst triangle of all their stars (left_out's too).
  struct Region {
    std::vector<Index> vertices;
    std::vector<Vec3> from;
    WorstShape before;
  };
  Region region_at(std::span<const Index> core, Index left_out = kNoIndex) const {
    Region r{ring(core), {}, {}};
    for (Index v : r.vertices) r.before.add(star_shape(v));
    std::erase(r.vertices, left_out);
    for (Index v : r.vertices) r.from.push_back(mesh_.vertices[v]);
    return r;
  }

  // After a change at `core`: moves `core`, the region's vertices, then `core` again, and keeps
  // them (counted in `done`) when the region's worst triangle is better than before; else puts
  // the region's vertices back (the caller undoes its change).
  bool settled(const Region& r, std::span<const Index> core, ShapeImprovement& done) {
    std::size_t moves = 0;
    const auto move = [&](Index v) {
      moves += support_[v].kind != VertexSupport::Kind::fixed && try_move(v);
    };
    for (Index v : core) move(v);
    for (Index v : r.vertices) move(v);
    for (Index v : core) move(v);
    WorstShape after;
    const bool better = std::ranges::all_of(r.vertices, [&](Index v) {
      const std::optional<WorstShape> s = worst_of_above(around_[v], r.before.score());
      if (s) after.add(*s);
      return s && after.score() > r.before.score();
    });
    if (better && after.better_than(r.before, floor_)) {
      done.moves += moves;
      return true;
    }
    for (std::size_t k = 0; k < r.vertices.size(); ++k) {
      mesh_.vertices[r.vertices[k]] = r.from[k];
      near_.moved(r.vertices[k], r.from[k]);
    }
    return false;
  }

  // The vertices of the triangles at `core`, sorted (`core` among them, where it has triangles).
  std::vector<Index> ring(std::span<const Index> core) const {
    std::vector<Index> out;
    for (Index v : core)
      for (Index t : around_[v])
        out.insert(out.end(), mesh_.triangles[t].begin(), mesh_.triangles[t].end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // The neighbours of `v`, sorted.
  std::vector<Index> neighbours(Index v) const {
    std::vector<Index> out = ring(std::array{v});
    std::erase(out, v);
    return out;
  }

  // Whether vertex `x` may be merged into its neighbour `y` (edge x-y collapsed, its two
  // triangles gone) with the topology kept: x's star a disc, x-y an edge of two triangles whose
  // third vertices c and d are the only neighbours x and y share (the link condition), and c and
  // d left with three triangles or more. A surface vertex has no feature edge; a curve vertex
  // goes along its curve, into a vertex of the same curve or a corner: its other feature edge
  // then runs from y.
  bool collapsible(Index x, Index y) const {
    std::array<Index, 2> ends{};
    if (support_[x].kind == VertexSupport::Kind::fixed || star(x, ends) != Star::disc) return false;
    const std::vector<Index> both = sharing(x, y);
    if (both.size() != 2) return false;
    const std::vector<Index> nx = neighbours(x), ny = neighbours(y);
    const auto along = std::ranges::count_if(nx, [&](Index w) { return is_feature(x, w); });
    if (support_[x].kind == VertexSupport::Kind::surface && along != 0) return false;
    if (support_[x].kind == VertexSupport::Kind::curve &&
        (along != 2 || !is_feature(x, y) ||
         (support_[y].kind != VertexSupport::Kind::fixed &&
          (support_[y].kind != VertexSupport::Kind::curve ||
           support_[y].curve != support_[x].curve))))
      return false;
    std::vector<Index> common;
    std::ranges::set_intersection(nx, ny, std::back_inserter(common));
    if (common.size() != 2) return false;
    // Where x has three triangles, its third becomes y, c, d: that triangle must not be there
    // already (a tetrahedron, or one closed over a non-manifold edge c-d).
    const auto has_both = [&](Index t) {
      const Triangle& f = mesh_.triangles[t];
      return std::ranges::find(f, common[0]) != f.end() &&
             std::ranges::find(f, common[1]) != f.end();
    };
    if (std::ranges::any_of(around_[y], has_both)) return false;
    for (Index t : both)
      for (Index w : mesh_.triangles[t])
        if (w != x && w != y && around_[w].size() <= 3) return false;
    return true;
  }

  // A change that neither flips nor moves can make where a region has a vertex too many: the
  // shortest edge of bad triangle t collapses, one end merged into the other, followed by moves
  // around it as after a balancing flip. Kept when the worst triangle of the region is better
  // (V - 1, E - 3, F - 2: the topology is kept); else undone. The moves kept with it count in
  // `done`. On the 57 shared meshes at 1k, 5k and 10k, θmin or Qmin rose on 31 runs (blade at 5k
  // 34.0° → 40.2°, couplingdown at 5k Qmin 0.546 → 0.598) and fell on one (femur at 1k, 4.4° →
  // 4.2°, another local optimum).
  bool try_collapse(Index t, ShapeImprovement& done) {
    if (done.collapses >= collapse_budget_) return false;
    const Triangle f = mesh_.triangles[t];
    std::vector<Vec3>& p = mesh_.vertices;
    int shortest = 0;
    for (int i = 1; i < 3; ++i)
      if (distance(p[f[i]], p[f[(i + 1) % 3]]) < distance(p[f[shortest]], p[f[(shortest + 1) % 3]]))
        shortest = i;
    const Index a = f[shortest], b = f[(shortest + 1) % 3];
    for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      if (collapsible(x, y) && try_collapse(x, y, done)) return true;
    }
    return false;
  }

  bool try_collapse(Index x, Index y, ShapeImprovement& done) {
    const std::vector<Index> neighbours_before = neighbours(x);
    const Region region = region_at(std::array{x, y}, x);
    std::vector<Index> touched = region.vertices;
    touched.push_back(x);
    const Stamps saved = stamps_of(touched);
    // Saved for an undo: the triangles at x, the stars that change.
    const std::vector<Index> at_x = around_[x];
    std::vector<Triangle> old_triangles;
    std::vector<Vec3> normals;
    for (Index s : at_x) {
      old_triangles.push_back(mesh_.triangles[s]);
      const auto [u, v, w] = mesh_.corners(s);
      normals.push_back(unit_normal(u, v, w));
    }
    std::vector<std::pair<Index, std::vector<Index>>> stars;
    for (Index s : at_x)
      for (Index w : mesh_.triangles[s]) {
        stars.push_back({w, around_[w]});
        start_gap(w);  // measured while its triangles are the start's
      }
    const double spanned = distance(mesh_.vertices[x], mesh_.vertices[y]);
    // The collapse: triangles with both x and y go, the others at x take y instead.
    for (std::size_t k = 0; k < at_x.size(); ++k) {
      const Index s = at_x[k];
      Triangle& tri = mesh_.triangles[s];
      near_.rewired(s);
      for (Index w : tri) changed(w);
      if (std::ranges::find(tri, y) != tri.end()) {
        gone_[s] = true;
        for (Index w : tri) std::erase(around_[w], s);
      } else {
        tri[slot(tri, x)] = y;
        around_[y].push_back(s);
      }
    }
    around_[x].clear();
    // Along a curve, x's two feature edges x-y and x-z give way to y-z.
    std::vector<Edge> along_x, along_y;
    if (support_[x].kind == VertexSupport::Kind::curve) {
      for (Index z : neighbours_before)
        if (is_feature(x, z)) along_x.push_back(edge_of(x, z));
      const Index z =
          along_x[0] == edge_of(x, y) ? other_end(along_x[1], x) : other_end(along_x[0], x);
      if (!is_feature(y, z)) along_y.push_back(edge_of(y, z));
      replace_features(along_x, along_y);
    }
    // No triangle that stays may fold over, nor leave the surface.
    bool kept = gaps_within(y, allowed_gap(std::max(start_gap(x), start_gap(y)), spanned));
    for (std::size_t k = 0; kept && k < at_x.size(); ++k) {
      if (gone_[at_x[k]]) continue;
      const auto [u, v, w] = mesh_.corners(at_x[k]);
      const Vec3 n = unit_normal(u, v, w);
      kept = !no_direction(n) && dot(n, normals[k]) >= kTurnCos;
    }
    if (kept && (support_[x].guarded || support_[y].guarded)) kept = !crosses_another(around_[y]);
    if (kept && settled(region, std::array{y}, done)) return true;
    for (std::size_t k = 0; k < at_x.size(); ++k) {
      mesh_.triangles[at_x[k]] = old_triangles[k];
      gone_[at_x[k]] = false;
      near_.rewired(at_x[k]);
    }
    for (auto& [w, star] : stars) around_[w] = std::move(star);
    around_[x] = at_x;
    replace_features(along_y, along_x);
    put_back(saved);
    return false;
  }

  // Moves `v` where the worst triangle of its star is better: first to the nearest surface point
  // to the mean of its neighbours (or halfway there), as tangential relaxation does; then, while
  // that star is still badly shaped, by a compass search for its best place on the surface (or
  // along its curve). Returns whether it moved.
  bool try_move(Index v) {
    if (stuck(v)) return false;
    ++searches_;
    std::vector<Vec3>& p = mesh_.vertices;
    const Vec3 from = p[v];
    std::vector<Vec3> normals;
    for (Index t : around_[v]) {
      const auto [a, b, c] = mesh_.corners(t);
      normals.push_back(unit_normal(a, b, c));
      if (no_direction(normals.back())) return false;
    }
    const WorstShape before = star_shape(v);
    WorstShape best = before;
    // Whether v may stand at q: none of its triangles folded or taken off the surface, nor,
    // guarded, passing through another.
    const auto allowed_at = [&](const Vec3& q) {
      p[v] = q;
      const bool allowed =
          keeps_surface(v, normals) && !(support_[v].guarded && crosses_another(around_[v]));
      p[v] = from;
      return allowed;
    };
    // Where v would do better than `best`, and may stand.
    const auto better_at = [&](const Vec3& q) {
      p[v] = q;
      WorstShape now;
      const bool better = star_better_than(v, best, now);
      p[v] = from;
      if (!better || !allowed_at(q)) return false;
      best = now;
      return true;
    };
    // Whether v's triangles alone would do better with v at q: cheap, no projection.
    const auto promising = [&](const Vec3& q) {
      p[v] = q;
      WorstShape now;
      const bool better = star_better_than(v, best, now);
      p[v] = from;
      return better;
    };
    Vec3 at = from;
    if (support_[v].kind == VertexSupport::Kind::surface) {
      Vec3 sum{};
      for (Index t : around_[v]) {
        const Triangle& f = mesh_.triangles[t];
        sum += p[f[(slot(f, v) + 1) % 3]];  // each neighbour once: it follows v in one triangle
      }
      const Vec3 centre = (1.0 / static_cast<double>(around_[v].size())) * sum;
      for (const double step : {1.0, 0.5}) {
        const Vec3 q = surface_.nearest(from + step * (centre - from)).point;
        if (better_at(q)) {
          at = q;
          break;
        }
      }
    }
    if (best.score() < kSearchBelow) at = searched_from(v, at, better_at, promising, allowed_at);
    // It moves when it found a better place (better_than asks for a higher score), or onto its
    // curve.
    if (at == from) {
      stuck_at_[v] = ++clock_;
      return false;
    }
    p[v] = at;
    near_.moved(v, at);
    changed(v);
    return true;
  }

  // A vertex's position or its triangles changed: the moves of it and its neighbours that found
  // nothing better may find something now.
  void changed(Index v) { changed_at_[v] = ++clock_; }

  // Whether balancing at triangle t failed since when nothing it reads changed: the positions and
  // triangles of the vertices three rings out from t's (its flips' and collapses' regions, and
  // their moves' stars), and the floor. (The collapse budget only shrinks.) Walked breadth
  // first, each vertex once (marked with this search's stamp), stopping at the first that
  // changed: three sorted rings per triangle made the sorts a tenth of this step where many
  // badly shaped triangles stay (a scan with dropouts beside slivers).
  bool balance_stuck(Index t) const {
    const std::uint64_t at = balance_failed_at_[t];
    if (!failed_under_this_floor(at)) return false;
    ++visit_;
    reach_.clear();
    const auto reached_unchanged = [&](Index v) {
      if (visited_[v] == visit_) return true;
      visited_[v] = visit_;
      reach_.push_back(v);
      return changed_at_[v] < at;
    };
    for (const Index v : mesh_.triangles[t])
      if (!reached_unchanged(v)) return false;
    for (std::size_t ring = 0, begin = 0; ring < 3; ++ring) {
      const std::size_t end = reach_.size();
      for (std::size_t i = begin; i < end; ++i)
        for (const Index s : around_[reach_[i]])
          for (const Index w : mesh_.triangles[s])
            if (!reached_unchanged(w)) return false;
      begin = end;
    }
    return true;
  }

  // The stamps of some vertices, put back where a change is undone: the mesh is then exactly as
  // it was, and the vertices stuck before it are stuck again (without, each balancing attempt
  // that failed made every sweep after it search its whole region again).
  struct Stamps {
    std::vector<Index> vertices;
    std::vector<std::uint64_t> changed_at, stuck_at;
  };
  Stamps stamps_of(const std::vector<Index>& vertices) const {
    Stamps s{vertices, {}, {}};
    for (Index v : vertices) {
      s.changed_at.push_back(changed_at_[v]);
      s.stuck_at.push_back(stuck_at_[v]);
    }
    return s;
  }
  void put_back(const Stamps& s) {
    for (std::size_t k = 0; k < s.vertices.size(); ++k) {
      changed_at_[s.vertices[k]] = s.changed_at[k];
      stuck_at_[s.vertices[k]] = s.stuck_at[k];
    }
  }

  // Whether try_move(v) found no better place for v since when nothing it reads changed: v's
  // position and triangles, its neighbours' positions, and the floor. It would find none again
  // (it is deterministic); such repeated searches, each projecting dozens of points, were a
  // quarter of this step's on an output that keeps badly shaped triangles (femur.off at 1k).
  bool stuck(Index v) const {
    const std::uint64_t at = stuck_at_[v];
    return failed_under_this_floor(at) && std::ranges::all_of(around_[v], [&](Index t) {
             return unchanged_since(at, mesh_.triangles[t]);  // v and its neighbours
           });
  }

  // The two halves of stuck() and balance_stuck(): a search that failed at clock `at` (0: never)
  // under the floor as it is now, and none of the vertices it read changed since.
  bool failed_under_this_floor(std::uint64_t at) const { return at != 0 && at >= floor_at_; }
  template <class Vertices>
  bool unchanged_since(std::uint64_t at, const Vertices& read) const {
    return std::ranges::all_of(read, [&](Index w) { return changed_at_[w] < at; });
  }

  // The compass search of try_move, from `at`: returns the best place found. On the surface, a
  // step is projected (the search's main cost) only when it looks better in the tangent plane.
  // Along a curve, from its point nearest to `at`, where v goes even if no step is better, as
  // long as `allowed_at` lets it stand there.
  template <class BetterAt, class Promising, class AllowedAt>
  Vec3 searched_from(Index v, Vec3 at, const BetterAt& better_at, const Promising& promising,
                     const AllowedAt& allowed_at) const {
    const double size = mean_edge_length(v);
    if (support_[v].kind == VertexSupport::Kind::curve) {
      const std::size_t c = support_[v].curve;
      double s = curves_->nearest(c, at).arclength;
      double step = kFirstStep * size;
      bool found = false;
      for (int k = 0; k < kMaxSearchSteps && step >= kLastStep * size; ++k) {
        const double to = better_at(curves_->at(c, s + step))   ? s + step
                          : better_at(curves_->at(c, s - step)) ? s - step
                                                                : s;
        if (to == s) step /= 2;
        found |= to != s;
        s = to;
      }
      // A step found is checked; the curve's point nearest to v is not, and v may be off its
      // curve (a guarded vertex of a fuzzed blobby_3cc.off, a thirtieth of an edge off its
      // crease, went there through the sheet beside it).
      const Vec3 onto = curves_->at(c, s);
      return found || onto == at || allowed_at(onto) ? onto : at;
    }
    Vec3 normal{};
    for (Index t : around_[v]) {
      const auto [a, b, c] = mesh_.corners(t);
      normal += cross(b - a, c - a);
    }
    const Vec3 n = unit_or_zero(normal);
    const Vec3 u =
        unit_or_zero(std::abs(n.x) < 0.9 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0}));
    const Vec3 w = cross(n, u);
    if (no_direction(u)) return at;
    double step = kFirstStep * size;
    // Each step's projections start from the foot of the place it starts from: nearby.
    std::optional<SurfaceProjector::Foot> from;
    for (int k = 0; k < kMaxSearchSteps && step >= kLastStep * size; ++k) {
      std::optional<SurfaceProjector::Foot> next;
      for (int d = 0; d < kDirections; ++d) {
        const double angle = 2 * M_PI * d / kDirections;
        const Vec3 in_plane = at + step * (std::cos(angle) * u + std::sin(angle) * w);
        if (!promising(in_plane)) continue;
        if (!from) from = surface_.nearest(at);
        const SurfaceProjector::Foot q = surface_.nearest(in_plane, *from);
        // better_at raised the bar: the last one found is the best
        if (better_at(q.point)) next = q;
      }
      if (next) {
        at = next->point;
        from = next;
      } else {
        step /= 2;
      }
    }
    return at;
  }

  double mean_edge_length(Index v) const {
    double sum = 0;
    for (Index t : around_[v]) {
      const Triangle& f = mesh_.triangles[t];
      sum += distance(mesh_.vertices[v], mesh_.vertices[f[(slot(f, v) + 1) % 3]]);
    }
    return sum / static_cast<double>(around_[v].size());
  }

  // Whether, with `v` where it is now, no triangle at it turned by more than kTurnCos from its
  // `normals` (folded), its triangles are about as close to the surface as they were at the start,
  // and near the surface point where it was then (else smoothing would shrink every convex tip).
  // The bounds are those of the start, so that moves after moves cannot drift away.
  bool keeps_surface(Index v, const std::vector<Vec3>& normals) const {
    for (std::size_t k = 0; k < around_[v].size(); ++k) {
      const auto [a, b, c] = mesh_.corners(around_[v][k]);
      const Vec3 n = unit_normal(a, b, c);
      if (no_direction(n) || dot(n, normals[k]) < kTurnCos) return false;
    }
    const double allowed = allowed_gap(start_gap(v), distance(start_[v], mesh_.vertices[v]));
    return distance_to_star(start_[v], v) <= allowed && gaps_within(v, allowed);
  }

  TriangleMesh& mesh_;
  const SurfaceProjector& surface_;
  const CurveProjector* curves_;
  std::vector<VertexSupport> support_;
  std::vector<Edge>& features_;               // sorted; a collapse along a curve renames one
  const std::vector<double>& narrow_at_;      // per vertex: the narrow tip it traces, if any
  const std::vector<bool> active_;            // per vertex: whether it may change (empty: all)
  const std::vector<Vec3> start_;             // the vertices where they were
  mutable std::vector<double> start_gap_;     // per vertex, start_gap once measured
  mutable std::vector<Index> failed_gap_at_;  // per vertex, the triangle gaps_within last failed at
  // Per triangle, the surface triangle gap_within last found within reach of it (kNotFound: none).
  static constexpr std::size_t kNotFound = ~std::size_t{0};
  mutable std::vector<std::size_t> near_surface_;
  std::vector<bool> gone_;      // per triangle: taken away by a collapse
  mutable NearTriangles near_;  // for crosses_another
  std::size_t collapse_budget_;
  WorstShape floor_;  // the mesh's worst Q and θmin at the start, then where balance() began
  std::vector<std::vector<Index>> around_;  // per vertex, its triangles
  // The clock of stuck(): counts changes. Per vertex, when its position or triangles last
  // changed, and when try_move last found it no better place (0: never); when the floor was set.
  std::uint64_t clock_ = 0;
  std::vector<std::uint64_t> changed_at_, stuck_at_;
  std::vector<std::uint64_t> balance_failed_at_;  // per triangle: when balancing there failed
  // balance_stuck's search (the vertex count never changes here: a collapse leaves its vertex
  // unused): per vertex, the stamp of the last search that reached it; the vertices reached.
  mutable std::vector<std::uint64_t> visited_;
  mutable std::uint64_t visit_ = 0;
  mutable std::vector<Index> reach_;
  std::uint64_t floor_at_ = 0;
  std::vector<Index> saddles_;  // held by the tip rule at the start for their negative defect
  std::size_t searches_ = 0;    // try_move calls that searched (not stuck)
  // star()'s scratch: per triangle its step (the neighbours it leaves from and reaches), the steps
  // by the neighbour they leave from, and the neighbours they reach.
  mutable std::vector<std::array<Index, 2>> star_steps_;
  mutable std::vector<std::pair<Index, std::size_t>> star_by_out_;
  mutable std::vector<Index> star_ins_;
};

}  // namespace

ShapeImprovement improve_shapes(TriangleMesh& mesh, const SurfaceProjector& surface,
                                const CurveProjector* curves, std::vector<VertexSupport> support,
                                std::vector<Edge>& feature_edges, int sweeps,
                                const std::vector<double>& narrow_at, std::vector<bool> active) {
  ShapeImprovement done;
  if (sweeps <= 0) return done;  // nothing to set up for
  ShapeImprover improver(mesh, surface, curves, std::move(support), feature_edges, narrow_at,
                         std::move(active));
  const auto improve = [&] {
    for (int k = 0; k < sweeps && !improver.spent() && improver.sweep(done); ++k) {
    }
    for (int round = 0; round < sweeps && !improver.spent() && improver.balance(done); ++round)
      for (int k = 0; k < sweeps && !improver.spent() && improver.sweep(done); ++k) {
      }
  };
  improve();
  improver.free_saddles();
  improve();
  improver.finish();
  done.searches = improver.searches();
  return done;
}

}  // namespace cvtmesh
