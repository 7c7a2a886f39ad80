#include "geometry/near_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>

#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// Cells a thousand tolerances wide: near points share a cell, except the few within a tolerance
// of a cell's side, which also look in the cells next to them.
constexpr double kCellsPerTolerance = 1000;

using Cell = std::array<std::int64_t, 3>;

}  // namespace

double near_point_tolerance(const std::vector<Vec3>& points) {
  if (points.empty()) return 0;
  Vec3 lo = points[0], hi = points[0];
  double largest = 0;
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const double tolerance = 1e-12 * std::max(distance(lo, hi), largest);
  return std::isfinite(tolerance) ? tolerance : 0;
}

std::vector<Index> near_point_groups(const std::vector<Vec3>& points, double tolerance) {
  const std::size_t n = points.size();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  UnionFind groups(n);
  if (!(tolerance > 0)) {
    // Equal points only: adjacent once sorted.
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return points[a] < points[b]; });
    for (std::size_t k = 1; k < n; ++k)
      if (points[order[k]] == points[order[k - 1]]) groups.unite(order[k], order[k - 1]);
  } else {
    const double width = kCellsPerTolerance * tolerance;
    const auto cell_of = [&](double x, double y, double z) {
      return Cell{static_cast<std::int64_t>(std::floor(x / width)),
                  static_cast<std::int64_t>(std::floor(y / width)),
                  static_cast<std::int64_t>(std::floor(z / width))};
    };
    std::vector<Cell> cell(n);
    for (std::size_t v = 0; v < n; ++v) cell[v] = cell_of(points[v].x, points[v].y, points[v].z);
    // By cell, then equal points together.
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
      return std::tie(cell[a], points[a], a) < std::tie(cell[b], points[b], b);
    });
    struct ByCell {
      const std::vector<Cell>& cell;
      bool operator()(Index v, const Cell& c) const { return cell[v] < c; }
      bool operator()(const Cell& c, Index v) const { return c < cell[v]; }
    };
    // Each point is compared with the distinct points after it in its cell, and, within a
    // tolerance of the cell's sides, with those of the cells there; equal points join the first
    // of their run and are compared no further (an STL soup repeats each point many times).
    std::vector<Index> distinct;  // of the current cell
    for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
      const Cell& c = cell[order[begin]];
      distinct.clear();
      for (end = begin; end < n && cell[order[end]] == c; ++end)
        if (end > begin && points[order[end]] == points[order[end - 1]])
          groups.unite(order[end], order[end - 1]);
        else
          distinct.push_back(order[end]);
      for (std::size_t a = 0; a < distinct.size(); ++a) {
        const Vec3& p = points[distinct[a]];
        for (std::size_t b = a + 1; b < distinct.size(); ++b)
          if (distance(p, points[distinct[b]]) <= tolerance) groups.unite(distinct[a], distinct[b]);
        const Cell low = cell_of(p.x - tolerance, p.y - tolerance, p.z - tolerance);
        const Cell high = cell_of(p.x + tolerance, p.y + tolerance, p.z + tolerance);
        if (low == c && high == c) continue;
        for (std::int64_t x = low[0]; x <= high[0]; ++x)
          for (std::int64_t y = low[1]; y <= high[1]; ++y)
            for (std::int64_t z = low[2]; z <= high[2]; ++z) {
              if (Cell{x, y, z} == c) continue;
              const auto [first, last] =
                  std::equal_range(order.begin(), order.end(), Cell{x, y, z}, ByCell{cell});
              for (auto it = first; it != last; ++it)
                if (distance(p, points[*it]) <= tolerance) groups.unite(distinct[a], *it);
            }
      }
    }
  }
  // Each group named by its least index.
  std::vector<Index> least(n, kNoIndex), group(n);
  for (std::size_t v = 0; v < n; ++v) {
    Index& first = least[groups.find(v)];
    if (first == kNoIndex) first = static_cast<Index>(v);
    group[v] = first;
  }
  return group;
}

}  // namespace cvtmesh
