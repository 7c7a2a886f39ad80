#include "voronoi/seed_neighbors.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
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
// simplices join over coplanar hull facets the same way.
void add_cospherical_pairs(Delaunay& dt, std::vector<std::pair<Index, Index>>& pairs) {
  const int dim = dt.dimension();
  if (dim < 2) return;
  std::vector<Delaunay::Cell_handle> cells;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = cells.size();
    cells.push_back(c);
  }
  UnionFind groups(cells.size());
  std::vector<std::size_t> group_size(cells.size(), 1);
  for (const Delaunay::Cell_handle c : cells) {
    for (int i = 0; i <= dim; ++i) {
      const Delaunay::Cell_handle other = c->neighbor(i);
      if (other->info() < c->info()) continue;  // each facet once
      const Delaunay::Vertex_handle opposite = other->vertex(other->index(c));
      if (dt.is_infinite(opposite)) continue;
      const CGAL::Bounded_side side = dim == 3 ? dt.side_of_sphere(c, opposite->point())
                                               : dt.side_of_circle(c, 3, opposite->point());
      if (side == CGAL::ON_BOUNDARY) groups.unite(c->info(), other->info());
    }
  }
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

}  // namespace

SeedNeighbors delaunay_neighbors(const std::vector<Vec3>& seeds) {
  if (seeds.empty()) throw InvalidArgument("no seeds");
  reject_bad_seeds(seeds);
  std::vector<std::pair<Kernel::Point_3, Index>> points;
  points.reserve(seeds.size());
  for (Index s = 0; s < seeds.size(); ++s)
    points.emplace_back(Kernel::Point_3(seeds[s].x, seeds[s].y, seeds[s].z), s);
  Delaunay dt(points.begin(), points.end());  // spatially sorted insertion

  // Each Delaunay edge makes its two seeds Voronoi neighbours.
  std::vector<std::pair<Index, Index>> pairs;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    pairs.emplace_back(e->first->vertex(e->second)->info(), e->first->vertex(e->third)->info());
  add_cospherical_pairs(dt, pairs);
  for (auto& [a, b] : pairs)
    if (a > b) std::swap(a, b);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  std::vector<std::size_t> degree(seeds.size(), 0);
  for (const auto& [a, b] : pairs) ++degree[a], ++degree[b];
  SeedNeighbors n;
  n.offsets.assign(seeds.size() + 1, 0);
  std::partial_sum(degree.begin(), degree.end(), n.offsets.begin() + 1);
  n.ids.resize(n.offsets.back());
  std::vector<std::size_t> fill(n.offsets.begin(), n.offsets.end() - 1);
  for (const auto& [a, b] : pairs) {
    n.ids[fill[a]++] = b;
    n.ids[fill[b]++] = a;
  }
  // Nearest first; ties by id, so the order never depends on the triangulation's internals.
  for (Index s = 0; s < seeds.size(); ++s) {
    auto begin = n.ids.begin() + static_cast<std::ptrdiff_t>(n.offsets[s]);
    auto end = n.ids.begin() + static_cast<std::ptrdiff_t>(n.offsets[s + 1]);
    auto d2 = [&](Index t) { return dot(seeds[t] - seeds[s], seeds[t] - seeds[s]); };
    std::sort(begin, end,
              [&](Index a, Index b) { return std::pair(d2(a), a) < std::pair(d2(b), b); });
  }
  return n;
}

}  // namespace cvtmesh
