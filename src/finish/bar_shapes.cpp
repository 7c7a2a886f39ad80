#include "finish/bar_shapes.hpp"

#include <algorithm>

#include "quality/min_shape.hpp"
#include "quality/narrow_angles.hpp"

namespace cvtmesh {

namespace {

// Shapes a round-off apart are alike.
constexpr double kRoundOff = 1e-9;

// How `a` is shaped against `b` in two parts, away from narrow angles (`away`: -1, 0 or 1 as `a`
// is worse, alike or better there) and at them (Q and θmin over the input angle, each a round-off
// apart counted alike): better where it is no worse in either and better in one, no_better where
// it is better in neither. A change the bar cannot see must not cost the triangles at a narrow
// angle (fandisk.off at 5k: a round that took one triangle away from under the bar cost Qmin at
// its 19.4° angle 0.415 -> 0.355). Where each is better in one part, better if its worst triangle
// over all is (lion.off at 1k: a split that costs the worst away 0.69 -> 0.67 takes the one at its
// tip from Q 0.47 to 0.67), else mixed.
template <typename CompareAway>
Verdict judged(const BarShapes& a, const BarShapes& b, CompareAway away) {
  // Validity first: a halving whose midpoint's foot lands on a line through the obtuse corner
  // makes a triangle of no area, which the sweeps cannot mend at a boundary, yet it took more
  // triangles from under the bar than any other (teapot.obj of a public test set, noised, at 9k:
  // θmin 0°).
  if (a.flat != b.flat) return a.flat < b.flat ? Verdict::better : Verdict::no_better;
  const int by_away = away(a, b);
  const bool at_no_worse =
      a.quality_at >= b.quality_at - kRoundOff && a.ratio_at >= b.ratio_at - kRoundOff;
  const bool at_no_better =
      a.quality_at <= b.quality_at + kRoundOff && a.ratio_at <= b.ratio_at + kRoundOff;
  if (by_away >= 0 && at_no_worse)
    return by_away > 0 || !at_no_better ? Verdict::better : Verdict::no_better;
  if (by_away <= 0 && at_no_better) return Verdict::no_better;
  return a.worst_all > b.worst_all + kRoundOff ? Verdict::better : Verdict::mixed;
}

// -1, 0 or 1 as x is less than y, within `slack` of it or greater (a count exactly; shapes a
// round-off apart count alike).
template <typename T>
int sign_of(T x, T y, T slack = T{0}) {
  return x > y + slack ? 1 : x < y - slack ? -1 : 0;
}

// -1, 0 or 1 as the worst shapes `x` away from narrow angles are worse, alike or better than `y`:
// where Q and θmin are each no worse and one better, better; where one is better and the other
// worse, by the score (mech-holes-shark.off adaptive at 2k: a round that kept the worst θmin,
// and so the score, took Qmin from 0.514 to 0.435). A round-off apart counts alike.
int compare_away(const WorstShape& x, const WorstShape& y) {
  const int q = sign_of(x.quality, y.quality, kRoundOff);
  const int angle = sign_of(x.angle, y.angle, kRoundOff);
  if (q * angle >= 0) return q != 0 ? q : angle;
  return sign_of(x.score(), y.score(), kRoundOff);
}

}  // namespace

BarShapes bar_shapes(const TriangleMesh& m, const std::vector<NarrowAngle>& narrow, double reach) {
  const std::vector<double> angle_at = narrow_angle_at_vertices(m, narrow, reach);
  BarShapes shapes;
  WorstShape all;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto [p, q, r] = m.corners(t);
    const MinShape s = min_shape(p, q, r);
    const double input = narrow_angle_at(m.triangles[t], angle_at);
    all.add(WorstShape{s.quality, s.min_angle / 60});
    shapes.flat += s.min_angle < kFlatDeg;
    if (input > 0) {
      shapes.quality_at = std::min(shapes.quality_at, s.quality);
      shapes.ratio_at = std::min(shapes.ratio_at, s.min_angle / input);
      continue;
    }
    shapes.under += under_bar(s);
    shapes.away.add(WorstShape{s.quality, s.min_angle / 60});
  }
  shapes.worst_all = all.score();
  return shapes;
}

bool shaped_better(const BarShapes& a, const BarShapes& b) {
  return judged(a, b, [](const BarShapes& x, const BarShapes& y) {
           return x.under != y.under ? sign_of(y.under, x.under) : compare_away(x.away, y.away);
         }) == Verdict::better;
}

// The worst triangle first: fewer under the bar first let man.off at 1k, --seed 2, fall from 30.6°
// to 28.6°; both at once, fewer and a better worst, kept it from 20.1° → 34.9° adaptive at 2k.
Verdict judge_round(const BarShapes& a, const BarShapes& b) {
  return judged(a, b, [](const BarShapes& x, const BarShapes& y) {
    const int away = compare_away(x.away, y.away);
    return away != 0 ? away : sign_of(y.under, x.under);
  });
}

}  // namespace cvtmesh
