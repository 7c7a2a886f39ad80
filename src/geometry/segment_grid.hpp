// Which of many segments a point lies on, to a round-off: a hash grid of the segments' boxes, so
// that finding the points of a large mesh on a long polyline costs about a lookup each.
#pragma once

#include <array>
#include <optional>
#include <unordered_map>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SegmentGrid {
 public:
  // Segment i runs from `from[i]` to `to[i]`; a point is on it within `relative` times its length.
  SegmentGrid(std::vector<Vec3> from, std::vector<Vec3> to, double relative);
  struct Hit {
    std::size_t segment;
    double u;  // where: from + u (to - from), in [0, 1]
  };
  // The first segment (by index) that p lies on, if any.
  std::optional<Hit> find(const Vec3& p) const;

 private:
  std::array<long long, 3> cell_of(const Vec3& p) const;
  static std::size_t key(const std::array<long long, 3>& c);

  std::vector<Vec3> from_, to_;
  double relative_, cell_ = 1;
  std::unordered_map<std::size_t, std::vector<std::size_t>> cells_;
};

}  // namespace cvtmesh
