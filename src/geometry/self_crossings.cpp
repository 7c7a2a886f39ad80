#include "geometry/self_crossings.hpp"

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>

#include "geometry/triangle_bounds.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

Kernel::Point_3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

double longest_edge(const std::vector<Vec3>& points, const Triangle& t) {
  const Vec3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
  return std::max({distance(a, b), distance(b, c), distance(c, a)});
}

}  // namespace

bool triangles_cross(const TriangleMesh& mesh, const Triangle& a, const Triangle& b) {
  const auto tri = [&](const Triangle& t) {
    return Kernel::Triangle_3(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]),
                              point(mesh.vertices[t[2]]));
  };
  int shared = 0;
  Index common = 0;
  for (const Index u : a)
    if (std::find(b.begin(), b.end(), u) != b.end()) {
      ++shared;
      common = u;
    }
  if (shared >= 2) return false;
  if (shared == 0) return CGAL::do_intersect(tri(a), tri(b));
  const auto opposite = [&](const Triangle& t) {
    std::array<Index, 2> e{};
    int k = 0;
    for (const Index u : t)
      if (u != common) e[k++] = u;
    return Kernel::Segment_3(point(mesh.vertices[e[0]]), point(mesh.vertices[e[1]]));
  };
  return CGAL::do_intersect(opposite(a), tri(b)) || CGAL::do_intersect(opposite(b), tri(a));
}

namespace {

// The pairs of triangles with overlapping boxes, by CGAL's box intersection (a streamed segment
// tree): for meshes whose triangles differ so much in size that a grid would be crowded.
void cross_by_box_tree(const TriangleMesh& mesh, const std::vector<TriangleBounds>& bounds,
                       std::vector<bool>& crossing) {
  std::vector<Box> boxes;
  boxes.reserve(bounds.size());
  for (std::size_t t = 0; t < bounds.size(); ++t) {
    const auto& [lo, hi] = bounds[t];
    boxes.emplace_back(CGAL::Bbox_3(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z), t);
  }
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
      boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
        const std::size_t s = p.info(), t = q.info();
        if ((crossing[s] && crossing[t]) ||
            !triangles_cross(mesh, mesh.triangles[s], mesh.triangles[t]))
          return;
        crossing[s] = crossing[t] = true;
      });
}

// Grid cells per triangle, on average, past which the grid gives way to the box tree (a CAD
// tessellation's long slivers each span many cells of a grid sized to the average triangle).
constexpr double kMostCellsPerTriangle = 8;

}  // namespace

// A uniform grid of cells twice the average triangle's extent: each pair of triangles whose
// boxes overlap is tested once, in the cell holding the low corner of the boxes' overlap; cells
// are looked at in parallel. Twice as fast as CGAL's box intersection on outputs (a 20k-triangle
// remesh: 31 ms against 55), where nearly every pair found shares a vertex, before threads.
std::vector<bool> self_crossing_triangles(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  std::vector<TriangleBounds> bounds(n);
  double extent = 0;
  for (std::size_t t = 0; t < n; ++t) {
    const TriangleBounds& b = bounds[t] = bounds_of(mesh.vertices, mesh.triangles[t]);
    extent += std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
  }
  std::vector<bool> crossing(n, false);
  if (n < 2) return crossing;
  const double cell = extent > 0 ? 2 * extent / static_cast<double>(n) : 1.0;
  const auto at = [&](double x) { return static_cast<std::int64_t>(std::floor(x / cell)); };
  // 21 bits a coordinate: cells that wrap onto one key only make a group larger.
  const auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    const auto bits = [](std::int64_t c) { return static_cast<std::uint64_t>(c) & 0x1fffffu; };
    return bits(i) << 42 | bits(j) << 21 | bits(k);
  };
  double cells = 0;
  for (const TriangleBounds& b : bounds)
    cells += static_cast<double>(at(b.hi.x) - at(b.lo.x) + 1) *
             static_cast<double>(at(b.hi.y) - at(b.lo.y) + 1) *
             static_cast<double>(at(b.hi.z) - at(b.lo.z) + 1);
  if (cells > kMostCellsPerTriangle * static_cast<double>(n)) {
    cross_by_box_tree(mesh, bounds, crossing);
    return crossing;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> in_cell;
  in_cell.reserve(static_cast<std::size_t>(cells));
  for (std::size_t t = 0; t < n; ++t) {
    const auto& [lo, hi] = bounds[t];
    for (auto i = at(lo.x); i <= at(hi.x); ++i)
      for (auto j = at(lo.y); j <= at(hi.y); ++j)
        for (auto k = at(lo.z); k <= at(hi.z); ++k)
          in_cell.push_back({key(i, j, k), static_cast<std::uint32_t>(t)});
  }
  std::sort(in_cell.begin(), in_cell.end());
  std::vector<std::size_t> group{0};
  for (std::size_t e = 1; e <= in_cell.size(); ++e)
    if (e == in_cell.size() || in_cell[e].first != in_cell[e - 1].first) group.push_back(e);
  std::vector<std::uint8_t> flag(n, 0);  // set from several threads: the same value, atomically
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, group.size() - 1, 64), [&](const auto& r) {
    for (std::size_t g = r.begin(); g != r.end(); ++g) {
      const std::uint64_t here = in_cell[group[g]].first;
      for (std::size_t x = group[g]; x < group[g + 1]; ++x)
        for (std::size_t y = x + 1; y < group[g + 1]; ++y) {
          const std::uint32_t s = in_cell[x].second, t = in_cell[y].second;
          const TriangleBounds &p = bounds[s], &q = bounds[t];
          if (s == t || !overlap(p, q) ||
              key(at(std::max(p.lo.x, q.lo.x)), at(std::max(p.lo.y, q.lo.y)),
                  at(std::max(p.lo.z, q.lo.z))) != here)
            continue;
          std::atomic_ref<std::uint8_t> fs(flag[s]), ft(flag[t]);
          if ((fs.load(std::memory_order_relaxed) != 0 &&
               ft.load(std::memory_order_relaxed) != 0) ||
              !triangles_cross(mesh, mesh.triangles[s], mesh.triangles[t]))
            continue;
          fs.store(1, std::memory_order_relaxed);
          ft.store(1, std::memory_order_relaxed);
        }
    }
  });
  for (std::size_t t = 0; t < n; ++t) crossing[t] = flag[t] != 0;
  return crossing;
}

std::unique_ptr<SurfaceProjector> crossing_surface(const std::vector<Vec3>& points,
                                                   std::vector<Triangle> crossing) {
  if (crossing.empty()) return nullptr;
  return std::make_unique<SurfaceProjector>(TriangleMesh{points, std::move(crossing)});
}

const SurfaceProjector* InputCrossings::get() {
  if (!searched_) {
    const std::vector<bool> flags = self_crossing_triangles(surface_);
    std::vector<Triangle> crossing;
    for (std::size_t t = 0; t < flags.size(); ++t)
      if (flags[t]) crossing.push_back(surface_.triangles[t]);
    count_ = crossing.size();
    found_ = crossing_surface(surface_.vertices, std::move(crossing));
    searched_ = true;
  }
  return found_.get();
}

bool at_crossing(const SurfaceProjector& crossings, const std::vector<Vec3>& points,
                 const Triangle& t) {
  const Vec3 centre = (1.0 / 3) * (points[t[0]] + points[t[1]] + points[t[2]]);
  return crossings.distance_to(centre) <= longest_edge(points, t);
}

std::vector<Triangle> crossings_of_its_own(const TriangleMesh& output, InputCrossings& input) {
  const std::vector<bool> crossing = self_crossing_triangles(output);
  std::vector<Triangle> own;
  if (std::none_of(crossing.begin(), crossing.end(), [](bool c) { return c; })) return own;
  const SurfaceProjector* at = input.get();
  // The longest edge of the triangles at each vertex: a triangle near the input's crossings is
  // at them if the ball round its centroid that reaches as far as the triangles around it do
  // meets them. A small triangle beside larger ones is off the surface as they are, and crosses
  // where they would (a noisy mask_cone.off at 1.5k, after the sweeps: a triangle a tenth of an
  // edge long, two of its lengths from the input's crossings).
  std::vector<double> reach;
  if (at) {
    reach.assign(output.vertices.size(), 0.0);
    for (const Triangle& t : output.triangles) {
      const double longest = longest_edge(output.vertices, t);
      for (const Index v : t) reach[v] = std::max(reach[v], longest);
    }
  }
  for (std::size_t t = 0; t < crossing.size(); ++t) {
    if (!crossing[t]) continue;
    const Triangle& tri = output.triangles[t];
    const Vec3 centre =
        (1.0 / 3) * (output.vertices[tri[0]] + output.vertices[tri[1]] + output.vertices[tri[2]]);
    if (!at || at->distance_to(centre) > std::max({reach[tri[0]], reach[tri[1]], reach[tri[2]]}))
      own.push_back(tri);
  }
  return own;
}

}  // namespace cvtmesh
