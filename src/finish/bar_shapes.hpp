// How the output's last steps judge a round of changes (finish_output): by the quality promise's
// bar (issue 18 item 6), θmin 30° and Q 0.6 away from the input's narrow angles, and at those, by
// the shapes against the input angle, which must not fall for what the bar cannot see.
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"
#include "finish/worst_shape.hpp"

namespace cvtmesh {

// Away from the input's narrow angles, how many triangles are under the bar (kBarAngleDeg,
// kBarQuality) and the worst Q and θmin; at them, the worst Q and the worst θmin over the input
// angle, up to 1 (where the promise holds; 1 where no triangle is at one); and the worst score over
// all (WorstShape::score).
struct BarShapes {
  std::size_t under = 0;
  WorstShape away;
  double quality_at = 1, ratio_at = 1;
  double worst_all = 1;
  // Triangles of no area to speak of, anywhere (an angle under kFlatDeg): the manifold
  // guarantee (issue 18 item 1) has none, so fewer of them is better before all else.
  std::size_t flat = 0;
};

// An angle under this, in degrees, leaves a triangle no area to speak of.
inline constexpr double kFlatDeg = 1e-3;

// A triangle is at a narrow angle where one of its vertices is within `reach` of it, as the
// report has it (measure_away_from).
BarShapes bar_shapes(const TriangleMesh& mesh, const std::vector<NarrowAngle>& narrow,
                     double reach);

// Whether `a` is shaped better than `b`: fewer flat triangles; else away from narrow angles, fewer
// triangles under the bar, or as many and a better worst Q and θmin; and no worse at narrow
// angles, else (each better in one part) a better worst triangle over all.
bool shaped_better(const BarShapes& a, const BarShapes& b);

// How a round's shapes `a` compare with `b` (the best kept) in the order of the quality promise,
// which the worst triangle keeps or breaks, after fewer flat triangles (better; more: no_better):
// better where its worst Q and θmin away from narrow angles are better than b's (where one is
// better and the other worse, its score), or as good with fewer under the bar, or alike there and
// better at narrow angles; and no worse at them. Where it is better in one part and worse in the
// other, better if its worst triangle over all is, else mixed; no_better where it is better in
// neither. (In that order: the best first.)
enum class Verdict { better, mixed, no_better };
Verdict judge_round(const BarShapes& a, const BarShapes& b);

}  // namespace cvtmesh
