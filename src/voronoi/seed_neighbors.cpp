#include "voronoi/seed_neighbors.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>

#include "cvtmesh/errors.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<std::size_t, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Cell = Delaunay::Cell_handle;
constexpr Index kNoStamp = std::numeric_limits<Index>::max();

void reject_bad_seeds(const std::vector<Vec3>& seeds) {
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const Vec3& p = seeds[s];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidArgument("seed " + std::to_string(s) + " has a non-finite coordinate");
  }
  std::vector<Index> order(seeds.size());
  std::iota(order.begin(), order.end(), Index{0});
  auto key = [&](Index s) { return std::tie(seeds[s].x, seeds[s].y, seeds[s].z); };
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (seeds[order[k]] == seeds[order[k - 1]])
      throw InvalidArgument("seeds " + std::to_string(order[k - 1]) + " and " +
                            std::to_string(order[k]) + " are identical (remove duplicates)");
}

// Where seeds are cospherical (or, in 2D, cocircular), the Delaunay subdivision has cells with
// more than 4 (3) vertices, which CGAL splits into simplices its own way. The RVD's symbolic
// perturbation (by seed index) may split them differently and make any two vertices of such a
// cell neighbours; so every pair of vertices of each degenerate cell is made a neighbour pair.
// The degenerate cells are found as groups of simplices joined across a facet whose opposite
// vertex lies exactly on the neighbouring simplex's circumsphere (exact predicate); infinite
// simplices join over coplanar hull facets the same way. `cells` are all cells, info() = index.
void add_cospherical_pairs(const Delaunay& dt, const std::vector<Cell>& cells,
                           std::vector<std::pair<Index, Index>>& pairs) {
  const int dim = dt.dimension();
  if (dim < 2) return;
  tbb::enumerable_thread_specific<std::vector<std::pair<std::size_t, std::size_t>>> joins;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 1024), [&](const auto& r) {
    auto& local = joins.local();
    for (std::size_t k = r.begin(); k < r.end(); ++k) {
      const Cell c = cells[k];
      for (int i = 0; i <= dim; ++i) {
        const Cell other = c->neighbor(i);
        if (other->info() < c->info()) continue;  // each facet once
        const Delaunay::Vertex_handle opposite = other->vertex(other->index(c));
        if (dt.is_infinite(opposite)) continue;
        const CGAL::Bounded_side side = dim == 3 ? dt.side_of_sphere(c, opposite->point())
                                                 : dt.side_of_circle(c, 3, opposite->point());
        if (side == CGAL::ON_BOUNDARY) local.emplace_back(c->info(), other->info());
      }
    }
  });
  UnionFind groups(cells.size());
  bool any = false;
  for (const auto& local : joins)
    for (const auto& [a, b] : local) groups.unite(a, b), any = true;
  if (!any) return;
  std::map<std::size_t, std::vector<Index>> members;  // only degenerate groups: usually few
  std::vector<std::size_t> cells_in_group(cells.size(), 0);
  for (std::size_t k = 0; k < cells.size(); ++k) ++cells_in_group[groups.find(k)];
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::size_t root = groups.find(k);
    if (cells_in_group[root] < 2) continue;
    for (int i = 0; i <= dim; ++i)
      if (!dt.is_infinite(cells[k]->vertex(i)))
        members[root].push_back(cells[k]->vertex(i)->info());
  }
  for (auto& [root, seeds] : members) {
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    for (std::size_t x = 0; x < seeds.size(); ++x)
      for (std::size_t y = x + 1; y < seeds.size(); ++y) pairs.emplace_back(seeds[x], seeds[y]);
  }
}

// Compressed lists from a list of pairs (each pair once, either order).
SeedNeighbors from_pairs(std::size_t n, const std::vector<std::pair<Index, Index>>& pairs) {
  std::vector<std::size_t> degree(n, 0);
  for (const auto& [a, b] : pairs) ++degree[a], ++degree[b];
  SeedNeighbors lists;
  lists.offsets.assign(n + 1, 0);
  std::partial_sum(degree.begin(), degree.end(), lists.offsets.begin() + 1);
  lists.ids.resize(lists.offsets.back());
  std::vector<std::size_t> fill(lists.offsets.begin(), lists.offsets.end() - 1);
  for (const auto& [a, b] : pairs) {
    lists.ids[fill[a]++] = b;
    lists.ids[fill[b]++] = a;
  }
  return lists;
}

// The vertices of each finite simplex, `dim + 1` per simplex in a flat array (read many times
// below: contiguous, unlike CGAL's cells), and the simplices around each seed, as compressed
// lists of positions in that array.
struct Simplices {
  std::vector<Index> vertices;
  SeedNeighbors around;
};

Simplices finite_simplices(const Delaunay& dt, std::size_t n) {
  const int dim = dt.dimension();
  Simplices s;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
    if (!dt.is_infinite(c))
      for (int i = 0; i <= dim; ++i) s.vertices.push_back(c->vertex(i)->info());
  std::vector<std::size_t> degree(n, 0);
  for (Index v : s.vertices) ++degree[v];
  s.around.offsets.assign(n + 1, 0);
  std::partial_sum(degree.begin(), degree.end(), s.around.offsets.begin() + 1);
  s.around.ids.resize(s.around.offsets.back());
  std::vector<std::size_t> fill(s.around.offsets.begin(), s.around.offsets.end() - 1);
  for (std::size_t k = 0; k < s.vertices.size(); ++k)
    s.around.ids[fill[s.vertices[k]]++] = static_cast<Index>(k - k % (dim + 1));
  return s;
}

}  // namespace

SeedNeighbors delaunay_neighbors(const std::vector<Vec3>& seeds) {
  if (seeds.empty()) throw InvalidArgument("no seeds");
  reject_bad_seeds(seeds);
  std::vector<std::pair<Kernel::Point_3, Index>> points;
  points.reserve(seeds.size());
  for (Index s = 0; s < seeds.size(); ++s)
    points.emplace_back(Kernel::Point_3(seeds[s].x, seeds[s].y, seeds[s].z), s);
  Delaunay dt(points.begin(), points.end());  // spatially sorted insertion

  std::vector<Cell> cells;
  cells.reserve(dt.number_of_cells());
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = cells.size();
    cells.push_back(c);
  }
  std::vector<std::pair<Index, Index>> extra;
  const int dim = dt.dimension();
  if (dim < 1) return from_pairs(seeds.size(), extra);  // a single seed
  add_cospherical_pairs(dt, cells, extra);
  const SeedNeighbors cospherical = from_pairs(seeds.size(), extra);
  const Simplices simplices = finite_simplices(dt, seeds.size());
  const SeedNeighbors& around = simplices.around;

  // Per seed, in parallel: the other vertices of its simplices, each once (a stamp per seed
  // and thread), and its cospherical partners; then nearest first, ties by id, so that the
  // order never depends on the triangulation's internals. Written to a scratch list with
  // room for dim entries per simplex, then compacted.
  std::vector<std::size_t> kept(seeds.size());
  std::vector<Index> scratch(dim * around.ids.size() + cospherical.ids.size());
  auto room = [&](Index s) { return dim * around.offsets[s] + cospherical.offsets[s]; };
  struct Local {
    std::vector<Index> stamp;
    std::vector<std::pair<double, Index>> keyed;
  };
  tbb::enumerable_thread_specific<Local> locals([&] {
    return Local{std::vector<Index>(seeds.size(), kNoStamp), {}};
  });
  tbb::parallel_for(
      tbb::blocked_range<Index>(0, static_cast<Index>(seeds.size()), 256), [&](const auto& r) {
        Local& local = locals.local();
        for (Index s = r.begin(); s < r.end(); ++s) {
          local.keyed.clear();
          auto add = [&](Index t) {
            if (t == s || local.stamp[t] == s) return;
            local.stamp[t] = s;
            local.keyed.emplace_back(dot(seeds[t] - seeds[s], seeds[t] - seeds[s]), t);
          };
          for (Index t : cospherical.of(s)) add(t);
          for (Index first : around.of(s))
            for (int i = 0; i <= dim; ++i) add(simplices.vertices[first + i]);
          std::sort(local.keyed.begin(), local.keyed.end());
          Index* const out = scratch.data() + room(s);
          for (std::size_t k = 0; k < local.keyed.size(); ++k) out[k] = local.keyed[k].second;
          kept[s] = local.keyed.size();
        }
      });
  SeedNeighbors n;
  n.offsets.assign(seeds.size() + 1, 0);
  std::partial_sum(kept.begin(), kept.end(), n.offsets.begin() + 1);
  n.ids.resize(n.offsets.back());
  for (Index s = 0; s < seeds.size(); ++s)
    std::copy_n(scratch.begin() + static_cast<std::ptrdiff_t>(room(s)), kept[s],
                n.ids.begin() + static_cast<std::ptrdiff_t>(n.offsets[s]));
  return n;
}

}  // namespace cvtmesh
