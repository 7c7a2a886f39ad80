// The local feature size near sharp features and boundaries (issue 20 item 1): the width of the
// gap across which another part of the feature curves faces a curve vertex. The poles see a
// smooth surface's medial axis; a strip between two creases, a slot between two boundary
// stretches or a small hole is as narrow as its curves are close, however flat it is.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/sizing.hpp"
#include "features/curve_projector.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_sectors.hpp"
#include "geometry/median.hpp"
#include "geometry/point_tree.hpp"
#include "geometry/unit_vector.hpp"
#include "sizing/small_holes.hpp"

namespace cvtmesh {

namespace {

// Two stretches face each other across a gap when the chord between them makes at least 60°
// with both curves. Two curves meeting at a corner at an angle α only face each other near it
// when α < 60°: a right-angled corner is no narrow place, a 20° wedge is, and so is a closed
// curve, across its width.
constexpr double kFacingCos = 0.5;
// A gap is a narrow place where it goes on along the curve: a gap further along it, the curve
// faces another part within twice the gap (a strip, a slot, a wedge, a small hole). A zigzag
// of a jagged rim faces itself at one corner only, across an edge the output traces as it is.
constexpr double kGoesOn = 2;
// Curve points sampled this finely (as a fraction of the median size) find the stretches near
// a point; the distance itself is to the stretch, exactly.
constexpr double kSamplesPerSize = 8;
constexpr double kMaxSamples = 2e6;
// Two points face each other across a wedge when each is at most this many times as far from its
// tip as the other.
constexpr double kSidesRatio = 2;
// Wedges narrower than this, and only these, narrow to their tips (capped_by_feature_gaps).
constexpr double kWedgeDeg = 60;
// WedgeGaps::traced_narrow: how many sizes at the tip each side must run along its curve (an even
// sizing looks for gaps under half its length: two edges).
constexpr double kTracedSideSizes = 4;

// The nearest point of the curves that faces a point of them, by the segments near it.
class GapFinder {
 public:
  GapFinder(const TriangleMesh& mesh, const Features& features, double step) : step_(step) {
    for (const FeatureCurve& curve : features.curves) {
      const std::size_t n = curve.vertices.size();
      for (std::size_t k = 0; k + 1 < n + (curve.closed ? 1 : 0); ++k) {
        const Vec3 a = mesh.vertices[curve.vertices[k]],
                   b = mesh.vertices[curve.vertices[(k + 1) % n]];
        const auto m = static_cast<std::size_t>(std::max(1.0, std::ceil(distance(a, b) / step)));
        for (std::size_t i = 0; i < m; ++i) {  // each point of the segment within step/2 of one
          samples_.push_back(a + ((i + 0.5) / static_cast<double>(m)) * (b - a));
          sample_segment_.push_back(static_cast<std::uint32_t>(segments_.size()));
        }
        segments_.push_back({a, b});
      }
    }
    tree_.emplace(samples_);
  }

  struct Scratch {
    std::vector<Index> near;
    std::vector<std::uint32_t> segments;
  };

  // Tips of wedges (vertices with a narrow sector between feature edges) whose sides are no gap
  // for operator(); `tips` must outlive the finder.
  void skip_wedges_at(const std::vector<Vec3>& tips) {
    tips_ = &tips;
    if (!tips.empty()) tip_tree_.emplace(tips);
  }

  // The distance from p (on a curve going along `tangent`) to the nearest point of the curves
  // facing it, or `limit` if none is nearer.
  double operator()(const Vec3& p, const Vec3& tangent, double limit, Scratch& s) const {
    const double reach = limit + step_;
    tree_->within(p, reach * reach, s.near);
    s.segments.clear();
    for (const Index k : s.near) s.segments.push_back(sample_segment_[k]);
    std::sort(s.segments.begin(), s.segments.end());
    s.segments.erase(std::unique(s.segments.begin(), s.segments.end()), s.segments.end());
    double best = limit;
    for (const std::uint32_t k : s.segments) {
      const auto& [a, b] = segments_[k];
      const Vec3 ab = b - a;
      const double length2 = dot(ab, ab);
      if (length2 == 0) continue;
      const Vec3 q = a + std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) * ab;
      const double d = distance(p, q);
      // The segments through p itself, and rounding-level distances, are no gap.
      if (!(d < best) || d <= 1e-9 * step_) continue;
      const Vec3 chord = (1 / d) * (q - p);
      if (std::abs(dot(chord, tangent)) > kFacingCos) continue;
      if (std::abs(dot(chord, ab)) > kFacingCos * std::sqrt(length2)) continue;
      if (across_a_wedge(p, q, d, s)) continue;
      best = d;
    }
    return best;
  }

 private:
  // Whether p and q, d apart, lie on the two sides of a wedge at one of tips_: about as far from
  // its tip, which is further from both than they are from each other (the sides make an angle
  // of about 60° or less there).
  bool across_a_wedge(const Vec3& p, const Vec3& q, double d, Scratch& s) const {
    if (!tip_tree_) return false;
    // Sides at an angle of α are d = 2 r sin(α/2) apart at r from the tip: r ≤ 64 d for α ≥ 1°.
    constexpr double kReach = 64;
    tip_tree_->within(p, (kReach * d) * (kReach * d), s.near);
    for (const Index k : s.near) {
      const double rp = distance(p, (*tips_)[k]), rq = distance(q, (*tips_)[k]);
      if (rp <= kSidesRatio * rq && rq <= kSidesRatio * rp && d < std::max(rp, rq)) return true;
    }
    return false;
  }

  double step_;
  std::vector<Vec3> samples_;
  std::vector<std::uint32_t> sample_segment_;
  std::vector<std::pair<Vec3, Vec3>> segments_;
  std::optional<PointTree> tree_;
  const std::vector<Vec3>* tips_ = nullptr;
  std::optional<PointTree> tip_tree_;
};

// How far each side of a sector runs along its curve from the apex, when the apex is an end of
// that curve (a corner, which the output keeps as a vertex); 0 when the curve goes on through the
// apex (a curve folding back where detection found no corner is not kept as a tip: lion.off at
// 1k, an 8° fold of a crease, graded: θmin 40.3° → 36.0°, the output's fold as round as before).
class SideLengths {
 public:
  SideLengths(const Features& features, const CurveProjector& curves) {
    for (std::size_t c = 0; c < features.curves.size(); ++c) {
      const std::vector<Index>& on = features.curves[c].vertices;
      const std::size_t n = on.size();
      if (curves.closed(c) || n < 2) continue;
      const double length = curves.length(c);
      ends_.push_back({ordered(on[0], on[1]), on[0], length});
      ends_.push_back({ordered(on[n - 1], on[n - 2]), on[n - 1], length});
    }
    std::sort(ends_.begin(), ends_.end(), [](const End& a, const End& b) {
      return std::tie(a.edge, a.apex) < std::tie(b.edge, b.apex);
    });
  }

  // Along the curve from `apex` through its feature neighbour `next`.
  double operator()(Index apex, Index next) const {
    const Edge edge = ordered(apex, next);
    const auto it = std::lower_bound(
        ends_.begin(), ends_.end(), std::pair{edge, apex}, [](const End& e, const auto& key) {
          return std::tie(e.edge, e.apex) < std::tie(key.first, key.second);
        });
    return it != ends_.end() && it->edge == edge && it->apex == apex ? it->length : 0;
  }

 private:
  static Edge ordered(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }
  struct End {
    Edge edge;      // the curve's first or last segment
    Index apex;     // the curve's end on it
    double length;  // the curve's
  };
  std::vector<End> ends_;
};

// The tips of the wedges whose sides are no gap (GapFinder::skip_wedges_at): every vertex with a
// sector under kWedgeDeg that `wedges` does not narrow.
std::vector<Vec3> tips_left(const TriangleMesh& mesh, const Features& features,
                            const CurveProjector& curves, const std::vector<double>& sizes,
                            WedgeGaps wedges) {
  std::vector<Vec3> tips;
  if (wedges == WedgeGaps::all) return tips;
  const SideLengths side(features, curves);
  // The sectors come by apex; an apex is left if any of its sectors under kWedgeDeg is not traced.
  Index last = kNoIndex;
  for (const FeatureSector& s : feature_sectors(mesh, features)) {
    if (!(s.angle_deg < kWedgeDeg) || s.apex == last) continue;
    const double least = kTracedSideSizes * sizes[s.apex];
    const bool traced = s.angle_deg < kNarrowAngleDeg && side(s.apex, s.from) >= least &&
                        side(s.apex, s.to) >= least;
    if (!traced) tips.push_back(mesh.vertices[last = s.apex]);
  }
  return tips;
}

}  // namespace

// `sizes` lowered on each boundary loop shorter than 2π times them to its length over 2π: about
// six edges around a hole, whatever its shape. The facing rule misses the smallest holes, which
// are triangles (no two sides of an equilateral one face each other), and a hole a few edges
// round with edges of the even length around it gets slivers (lion.off at 1k, a hole 1.9 edges
// round: θmin 18.8° at length over π, 40.3° at length over 2π).
void cap_at_small_holes(const TriangleMesh& mesh, std::vector<double>& sizes) {
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  // None at a vertex with two boundary edges leaving it, where loops are not defined (repair
  // leaves none: it keeps such a vertex as one copy per fan).
  const std::optional<std::vector<BoundaryLoop>> loops = boundary_loops(mesh, uses);
  if (!loops) return;
  for (const BoundaryLoop& loop : *loops) {
    // Summed along the triangles' orientation (the loop backwards), from its smallest vertex.
    const std::size_t n = loop.vertices.size();
    double length = 0;
    for (std::size_t i = n; i > 0; --i)
      length += distance(mesh.vertices[loop.vertices[i % n]], mesh.vertices[loop.vertices[i - 1]]);
    const double width = length / (2 * std::numbers::pi);
    for (const Index v : loop.vertices) sizes[v] = std::min(sizes[v], width);
  }
}

std::vector<double> capped_by_feature_gaps(const TriangleMesh& mesh, const Features& features,
                                           std::vector<double> sizes, WedgeGaps wedges) {
  const CurveProjector curves(mesh, features);
  // Each curve vertex (a corner once per curve it ends), with its curve and place on it.
  struct Place {
    std::size_t curve, index;
    Index v;
  };
  std::vector<Place> places;
  std::vector<double> limits;
  double total = 0;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    total += curves.length(c);
    for (std::size_t i = 0; i < features.curves[c].vertices.size(); ++i) {
      const Index v = features.curves[c].vertices[i];
      if (!(sizes[v] > 0) || !std::isfinite(sizes[v])) continue;
      places.push_back({c, i, v});
      limits.push_back(sizes[v]);
    }
  }
  if (places.empty() || !(total > 0)) return sizes;
  GapFinder gap_at(mesh, features,
                   std::max(median_of(std::move(limits)) / kSamplesPerSize, total / kMaxSamples));
  const std::vector<Vec3> tips = tips_left(mesh, features, curves, sizes, wedges);
  gap_at.skip_wedges_at(tips);

  // Per place, the narrowest gap under its size that goes on: each alone, in parallel, then
  // lowered into `sizes` in order (the same whatever the thread count).
  std::vector<double> gap(places.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, places.size()), [&](const auto& range) {
    GapFinder::Scratch scratch;
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const auto [c, i, v] = places[k];
      const std::vector<Index>& on = features.curves[c].vertices;
      const std::size_t n = on.size();
      const bool closed = curves.closed(c);
      const double limit = sizes[v], u = curves.arclengths(c)[i], length = curves.length(c);
      // The direction of the curve through the vertex (one-sided at an end).
      const Vec3 prev = mesh.vertices[!closed && i == 0 ? v : on[(i + n - 1) % n]];
      const Vec3 next = mesh.vertices[!closed && i + 1 == n ? v : on[(i + 1) % n]];
      const Vec3 tangent = unit_or_zero(next - prev);
      gap[k] = limit;
      if (dot(tangent, tangent) == 0) continue;  // no direction to face across
      const double g = gap_at(mesh.vertices[v], tangent, limit, scratch);
      if (!(g < limit)) continue;
      // Probes about a gap further on, both ways, no further than halfway to an end.
      for (const double way : {-1.0, 1.0}) {
        const double room = closed ? length / 2 : way > 0 ? length - u : u;
        const double along = std::min(g, room / 2);
        if (!(along > 0)) continue;
        const double probe = u + way * along;
        if (gap_at(curves.at(c, probe), curves.direction(c, probe), kGoesOn * g, scratch) <
            kGoesOn * g) {
          gap[k] = g;
          break;
        }
      }
    }
  });
  for (std::size_t k = 0; k < places.size(); ++k)
    sizes[places[k].v] = std::min(sizes[places[k].v], gap[k]);
  cap_at_small_holes(mesh, sizes);
  return sizes;
}

}  // namespace cvtmesh
