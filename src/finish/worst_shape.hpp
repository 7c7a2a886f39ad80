// The worst shape among a few triangles, as the output's last steps judge a change: the worst Q
// and the worst θmin (in units of 60°: both are 1 when equilateral), and the smaller of the two
// as one score.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>

#include "quality/min_shape.hpp"

namespace cvtmesh {

// The quality promise's bar (issue 18 item 6): θmin 30° and Q 0.6, away from narrow input angles.
inline constexpr double kBarAngleDeg = 30, kBarQuality = 0.6;

// Whether a triangle of shape `s` is under the bar.
inline bool under_bar(const MinShape& s) {
  return s.min_angle < kBarAngleDeg || s.quality < kBarQuality;
}

struct WorstShape {
  double quality = 1;
  double angle = 1;

  void add(const Vec3& a, const Vec3& b, const Vec3& c) {
    add_above(a, b, c, -std::numeric_limits<double>::infinity());
  }
  // As add, where the score stays above `bar`. Returns false where it falls to `bar` or under,
  // having measured no more than it must (its Q alone, where that is enough): better_than then
  // fails against any shape of score `bar`, whatever else is added, and the caller drops this one.
  bool add_above(const Vec3& a, const Vec3& b, const Vec3& c, double bar) {
    const std::optional<MinShape> s = min_shape_if_above(a, b, c, bar);
    if (!s) return false;
    quality = std::min(quality, s->quality);
    angle = std::min(angle, s->min_angle / 60);
    return score() > bar;
  }
  void add(const WorstShape& o) {
    quality = std::min(quality, o.quality);
    angle = std::min(angle, o.angle);
  }
  double score() const { return std::min(quality, angle); }
  // Whether this (the triangles a change makes) is better than `o` (those it replaces): a
  // better score, and neither Q nor θmin under both o's and the mesh's worst at the start
  // (`floor`), so that the mesh's own Qmin and θmin never fall below where they were, whichever
  // triangle holds them. (A floor raised as they rise leaves improve_shapes' search less room:
  // on the corpus at 1k it did worse on 3 meshes, better on 1.)
  bool better_than(const WorstShape& o, const WorstShape& floor) const {
    return score() > o.score() && quality >= std::min(o.quality, floor.quality) &&
           angle >= std::min(o.angle, floor.angle);
  }
};

}  // namespace cvtmesh
