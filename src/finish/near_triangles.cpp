#include "finish/near_triangles.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/triangle_bounds.hpp"

namespace cvtmesh {

namespace {

// A triangle whose box spans more cells than this is listed apart and looked at always (a long
// sliver of a CAD tessellation would fill a row of cells).
constexpr std::int64_t kMostCells = 27;
// Rebuilt once the triangles rewired since the build are more than this share of all: each is
// looked at in every search.
constexpr std::size_t kRewiredShare = 16;

}  // namespace

bool NearTriangles::stale() const {
  // Past a cell's width of drift, every search opens 27 cells or more.
  return !built_ || drift_ > cell_ || rewired_.size() * kRewiredShare > is_rewired_.size();
}

NearTriangles::Cell NearTriangles::cell_of(const Vec3& p) const {
  const auto at = [&](double x) { return static_cast<std::int64_t>(std::floor(x / cell_)); };
  return {at(p.x), at(p.y), at(p.z)};
}

// 21 bits a coordinate: cells that wrap onto one key only list more triangles together.
std::uint64_t NearTriangles::key(const Cell& c) {
  const auto bits = [](std::int64_t x) { return static_cast<std::uint64_t>(x) & 0x1fffffu; };
  return bits(c.i) << 42 | bits(c.j) << 21 | bits(c.k);
}

void NearTriangles::build(const TriangleMesh& mesh, const std::vector<bool>& gone) {
  const std::size_t n = mesh.triangles.size();
  at_ = mesh.vertices;
  drift_ = 0;
  cells_.clear();
  everywhere_.clear();
  rewired_.clear();
  is_rewired_.assign(n, 0);
  seen_.assign(n, 0);
  stamp_ = 0;
  built_ = true;
  const auto bounds = [&](Index t) { return bounds_of(at_, mesh.triangles[t]); };
  // Cells twice the mean extent of a triangle, as self_crossing_triangles sizes its grid.
  double extent = 0;
  std::size_t counted = 0;
  for (Index t = 0; t < n; ++t) {
    if (gone[t]) continue;
    const TriangleBounds b = bounds(t);
    extent += std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
    ++counted;
  }
  cell_ = extent > 0 ? 2 * extent / static_cast<double>(counted) : 1.0;
  for (Index t = 0; t < n; ++t) {
    if (gone[t]) continue;
    const TriangleBounds box = bounds(t);
    const Cell a = cell_of(box.lo), b = cell_of(box.hi);
    if ((b.i - a.i + 1) * (b.j - a.j + 1) * (b.k - a.k + 1) > kMostCells) {
      everywhere_.push_back(t);
      continue;
    }
    for (std::int64_t i = a.i; i <= b.i; ++i)
      for (std::int64_t j = a.j; j <= b.j; ++j)
        for (std::int64_t k = a.k; k <= b.k; ++k) cells_[key({i, j, k})].push_back(t);
  }
}

void NearTriangles::moved(Index v, const Vec3& to) {
  if (built_) drift_ = std::max(drift_, distance(to, at_[v]));
}

void NearTriangles::rewired(Index t) {
  if (!built_ || is_rewired_[t]) return;
  is_rewired_[t] = 1;
  rewired_.push_back(t);
}

}  // namespace cvtmesh
