#include "geometry/segment_grid.hpp"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

SegmentGrid::SegmentGrid(std::vector<Vec3> from, std::vector<Vec3> to, double relative)
    : from_(std::move(from)), to_(std::move(to)), relative_(relative) {
  double total = 0;
  for (std::size_t i = 0; i < from_.size(); ++i) total += distance(from_[i], to_[i]);
  // Cells about as long as the mean segment: each segment in a few, each cell with a few.
  if (!from_.empty() && total > 0) cell_ = total / static_cast<double>(from_.size());
  for (std::size_t i = 0; i < from_.size(); ++i) {
    const double length = distance(from_[i], to_[i]), slack = relative_ * length;
    // A long segment in pieces about a cell long, each in the cells of its box: a diagonal box
    // many cells wide would fill the cube of its width.
    const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(length / cell_)));
    for (std::size_t k = 0; k < pieces; ++k) {
      const Vec3 d = to_[i] - from_[i];
      const Vec3 p0 = from_[i] + (static_cast<double>(k) / static_cast<double>(pieces)) * d;
      const Vec3 p1 = from_[i] + (static_cast<double>(k + 1) / static_cast<double>(pieces)) * d;
      const Vec3 low{std::min(p0.x, p1.x) - slack, std::min(p0.y, p1.y) - slack,
                     std::min(p0.z, p1.z) - slack};
      const Vec3 high{std::max(p0.x, p1.x) + slack, std::max(p0.y, p1.y) + slack,
                      std::max(p0.z, p1.z) + slack};
      const std::array<long long, 3> a = cell_of(low), b = cell_of(high);
      for (long long x = a[0]; x <= b[0]; ++x)
        for (long long y = a[1]; y <= b[1]; ++y)
          for (long long z = a[2]; z <= b[2]; ++z) {
            std::vector<std::size_t>& in = cells_[key({x, y, z})];
            if (in.empty() || in.back() != i) in.push_back(i);
          }
    }
  }
}

std::array<long long, 3> SegmentGrid::cell_of(const Vec3& p) const {
  return {static_cast<long long>(std::floor(p.x / cell_)),
          static_cast<long long>(std::floor(p.y / cell_)),
          static_cast<long long>(std::floor(p.z / cell_))};
}

std::size_t SegmentGrid::key(const std::array<long long, 3>& c) {
  // Hash collisions only add candidates, each checked exactly.
  return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
}

std::optional<SegmentGrid::Hit> SegmentGrid::find(const Vec3& p) const {
  const auto at = cells_.find(key(cell_of(p)));
  if (at == cells_.end()) return std::nullopt;
  std::optional<Hit> best;
  for (const std::size_t i : at->second) {
    if (best && i > best->segment) continue;
    const Vec3 d = to_[i] - from_[i];
    const double length2 = dot(d, d);
    if (!(length2 > 0)) continue;
    const double u = std::clamp(dot(p - from_[i], d) / length2, 0.0, 1.0);
    if (distance(p, from_[i] + u * d) <= relative_ * std::sqrt(length2)) best = Hit{i, u};
  }
  return best;
}

}  // namespace cvtmesh
