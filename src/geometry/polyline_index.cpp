#include "geometry/polyline_index.hpp"

#include <utility>

namespace cvtmesh {

namespace {

// The grid's segments, each polyline's steps in order.
std::pair<std::vector<Vec3>, std::vector<Vec3>> steps_of(
    const std::vector<std::vector<Vec3>>& polylines) {
  std::vector<Vec3> from, to;
  for (const std::vector<Vec3>& points : polylines)
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      from.push_back(points[i]);
      to.push_back(points[i + 1]);
    }
  return {std::move(from), std::move(to)};
}

}  // namespace

PolylineIndex::PolylineIndex(const std::vector<std::vector<Vec3>>& polylines, double relative)
    : grid_([&] {
        auto [from, to] = steps_of(polylines);
        return SegmentGrid(std::move(from), std::move(to), relative);
      }()) {
  arcs_.resize(polylines.size());
  for (std::size_t k = 0; k < polylines.size(); ++k) {
    const std::vector<Vec3>& points = polylines[k];
    if (points.empty()) continue;
    ends_[points.front()].push_back({k, 0.0, true});
    ends_[points.back()].push_back({k, 1.0, true});
    arcs_[k] = {0};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      arcs_[k].push_back(arcs_[k].back() + distance(points[i], points[i + 1]));
      piece_.emplace_back(k, i);
    }
  }
}

std::vector<PolylineIndex::At> PolylineIndex::find(const Vec3& p) const {
  if (const auto at = ends_.find(p); at != ends_.end()) return at->second;
  const std::optional<SegmentGrid::Hit> hit = grid_.find(p);
  if (!hit) return {};
  const auto [k, i] = piece_[hit->segment];
  const std::vector<double>& arc = arcs_[k];
  return {{k, (arc[i] + hit->u * (arc[i + 1] - arc[i])) / arc.back(), false}};
}

}  // namespace cvtmesh
