// Nearest points on the feature curves, by arc length: where CCVT keeps its feature seeds
// (paper §4.3: each feature seed is projected on its curve after every step).
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

class CurveProjector {
 public:
  CurveProjector(const TriangleMesh& mesh, const Features& features);

  struct Foot {
    Vec3 point;
    Vec3 tangent;      // unit direction of the curve there
    double arclength;  // from the curve's first vertex
  };
  // The nearest point of curve c to p. On an open curve it is kept a hair away from both ends,
  // which are corners with seeds of their own, so two seeds never coincide.
  Foot nearest(std::size_t c, const Vec3& p) const;
  // The point at arc length s along curve c (taken modulo the length on a closed curve).
  Vec3 at(std::size_t c, double s) const;
  // The unit direction of curve c at arc length s (of the segment there).
  Vec3 direction(std::size_t c, double s) const;
  double length(std::size_t c) const { return curves_[c].arclength.back(); }
  // The arc length at each vertex of curve c's polyline (a closed curve's first one again last).
  const std::vector<double>& arclengths(std::size_t c) const { return curves_[c].arclength; }
  bool closed(std::size_t c) const { return curves_[c].closed; }
  std::size_t size() const { return curves_.size(); }

 private:
  struct Polyline {
    std::vector<Vec3> points;  // closed curves repeat the first point at the end
    std::vector<double> arclength;
    bool closed;
  };
  // The index k of the segment (points k-1, k) of curve c at arc length s, after taking s
  // modulo a closed curve's length and into range.
  std::size_t segment_at(std::size_t c, double& s) const;

  std::vector<Polyline> curves_;
};

}  // namespace cvtmesh
