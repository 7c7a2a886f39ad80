// The counting sort behind the lists of a mesh's triangle sides (sorted_sides, edge_uses): one
// item per side, sorted by its edge's smaller end, then within each end by the larger end and the
// side's corner. Linear where one comparison sort of the 3·F sides was the report's largest cost
// on big inputs; one pass straight into the caller's item type, as a copy from one list into
// another was as costly as the sort (igea.ply's 270k triangles, its edges walked four times a
// remesh).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/index_range.hpp"

namespace cvtmesh {

// `make(lo, hi, t, k)`: the item of triangle t's side k, from corner k to k + 1, whose ends are
// lo < hi (or equal, for a degenerate side); `before(x, y)`: whether x comes before y among the
// items of one smaller end (by the larger end, then the corner: a strict order, so that the
// result is the same on any thread count); `keep(lo, hi)`: whether the edge's sides are listed.
// A counting sort on lo (stable: each bucket in corner order), then each bucket, a vertex's few
// sides, sorted on its own, in parallel.
template <class Item, class Make, class Before, class Keep>
std::vector<Item> sorted_by_edge(std::size_t vertices, const std::vector<Triangle>& triangles,
                                 const Make& make, const Before& before, const Keep& keep) {
  require_index_range(triangles.size(), "triangles for their sides' list");
  // Calls side(lo, hi, t, k) for each side kept, in triangle order.
  const auto for_each_side = [&](const auto& side) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const Triangle& f = triangles[t];
      for (int k = 0; k < 3; ++k) {
        const Index lo = std::min(f[k], f[(k + 1) % 3]), hi = std::max(f[k], f[(k + 1) % 3]);
        if (keep(lo, hi)) side(lo, hi, t, k);
      }
    }
  };
  std::vector<std::size_t> start(vertices + 1, 0);
  for_each_side([&](Index lo, Index, std::size_t, int) { ++start[lo + 1]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Item> items(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for_each_side(
      [&](Index lo, Index hi, std::size_t t, int k) { items[next[lo]++] = make(lo, hi, t, k); });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 4096), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v)
      std::sort(items.begin() + static_cast<std::ptrdiff_t>(start[v]),
                items.begin() + static_cast<std::ptrdiff_t>(start[v + 1]), before);
  });
  return items;
}

// Every side listed.
template <class Item, class Make, class Before>
std::vector<Item> sorted_by_edge(std::size_t vertices, const std::vector<Triangle>& triangles,
                                 const Make& make, const Before& before) {
  return sorted_by_edge<Item>(vertices, triangles, make, before, [](Index, Index) { return true; });
}

}  // namespace cvtmesh
