#include "voronoi/cell_pieces.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "geometry/triangle_sides.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// Where each seed's items start when they are laid out in seed order: offsets[s] to
// offsets[s + 1], from a count per seed (`count[s + 1]` holds seed s's; count[0] is 0).
std::vector<std::size_t> seed_offsets(std::vector<std::size_t> count) {
  std::partial_sum(count.begin(), count.end(), count.begin());
  return count;
}

// Sorts each seed's range of `items` (laid out by `offsets`) by `less`: a cell's few items.
template <class T, class Less>
void sort_each_seed(std::vector<T>& items, const std::vector<std::size_t>& offsets,
                    const Less& less) {
  for (std::size_t s = 0; s + 1 < offsets.size(); ++s)
    std::sort(items.begin() + static_cast<std::ptrdiff_t>(offsets[s]),
              items.begin() + static_cast<std::ptrdiff_t>(offsets[s + 1]), less);
}

}  // namespace

void CellPieceCollector::begin(std::size_t chunks) {
  // Triangle ids take 29 bits of a polygon record (a 2^29-triangle input would need some 350 GB).
  if (surface_.triangles.size() >= (std::size_t{1} << 29))
    throw std::length_error("too many triangles for the cell pieces");
  polygon_chunks_.assign(chunks, {});
  // A cell meets an input edge in one segment (the cell is convex): its polygons on the
  // triangles around the edge all have that segment as a side, and are one piece. Each triangle
  // side's next around its edge (a ring: two sides for an inner edge, one for a boundary edge,
  // more where the input branches) leads to them. Found here, before any polygon is kept: the
  // sorted sides take 24 bytes per side for a moment (igea.ply at 10k: 19 MB at the peak, in
  // end()).
  const std::vector<TriangleSide> sides = sorted_sides(surface_);
  around_.assign(sides.size(), 0);
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j) {
    for (j = i + 1; j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi;)
      ++j;
    for (std::size_t k = i; k < j; ++k) {
      const TriangleSide& next = sides[k + 1 < j ? k + 1 : i];
      around_[3 * sides[k].triangle + sides[k].side] =
          static_cast<std::uint32_t>(3 * next.triangle + next.side);
    }
  }
}

void CellPieceCollector::polygon(std::size_t chunk, const RvdPolygon& p) {
  const auto& v = p.vertices;
  Polygon out{p.seed, p.triangle, 0, 0, {}};
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const double a = triangle_area(v[0].point, v[k].point, v[k + 1].point);
    out.area += a;
    out.moment += (a / 3) * (v[0].point + v[k].point + v[k + 1].point);
  }
  if (!(out.area > 0)) out.moment = v[0].point;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (const int e = input_edge_of_side(v[k], v[(k + 1) % v.size()]); e >= 0) out.sides |= 1u << e;
  polygon_chunks_[chunk].push_back(out);
}

void CellPieceCollector::end() {
  // The chunks are joined into one array, sized exactly, and each chunk is freed as soon as it
  // is copied: at the peak, extraction held every polygon up to three times (issue 22: 264 MB
  // of a 490 MB run on a 500k-triangle torus).
  std::size_t polygon_count = 0;
  Index seeds = 0;
  for (const auto& chunk : polygon_chunks_) {
    polygon_count += chunk.size();
    for (const Polygon& polygon : chunk) seeds = std::max(seeds, polygon.seed + 1);
  }
  std::vector<Polygon> polygons;
  polygons.reserve(polygon_count);
  for (auto& chunk : polygon_chunks_) {
    polygons.insert(polygons.end(), chunk.begin(), chunk.end());
    std::vector<Polygon>().swap(chunk);
  }
  polygon_chunks_.clear();
  // Per seed, its polygons as (triangle, polygon), by triangle: scattered into seed order, then
  // each seed's few sorted. The pieces' lookup (piece_at) later reuses it, polygon → piece.
  std::vector<std::size_t> polygons_of(static_cast<std::size_t>(seeds) + 1, 0);
  for (const Polygon& polygon : polygons) ++polygons_of[polygon.seed + 1];
  piece_offsets_ = seed_offsets(std::move(polygons_of));
  std::vector<std::size_t> next(piece_offsets_.begin(), piece_offsets_.end() - 1);
  piece_of_.resize(polygons.size());
  for (std::size_t p = 0; p < polygons.size(); ++p)
    piece_of_[next[polygons[p].seed]++] = {polygons[p].triangle, p};
  std::vector<std::size_t>().swap(next);
  sort_each_seed(piece_of_, piece_offsets_,
                 [](const PieceOf& a, const PieceOf& b) { return a.triangle < b.triangle; });
  // Polygons of a cell around an input edge are one piece (see begin).
  UnionFind roots(polygons.size());
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const Polygon& polygon = polygons[p];
    for (std::uint32_t e = 0; e < 3; ++e) {
      if (!(polygon.sides & (1u << e))) continue;
      const std::uint32_t side = 3 * polygon.triangle + e;
      for (std::uint32_t other = around_[side]; other != side; other = around_[other])
        if (const PieceOf* q = entry(polygon.seed, other / 3)) roots.unite(p, q->piece);
    }
  }
  std::vector<std::uint32_t>().swap(around_);
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> slot(polygons.size(), kNone);  // root -> index in pieces_
  pieces_.clear();
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const std::size_t r = roots.find(p);
    if (slot[r] == kNone) {
      slot[r] = pieces_.size();
      pieces_.push_back({polygons[p].seed, p, 0, {}, {}, -1});
    }
    CellPiece& piece = pieces_[slot[r]];
    const Polygon& polygon = polygons[p];
    const bool has_area = polygon.area > 0;
    piece.area += polygon.area;
    if (has_area) piece.moment += polygon.moment;
    if (polygon.area > piece.largest_area) {
      piece.largest_area = polygon.area;
      piece.largest_centre = has_area ? (1 / polygon.area) * polygon.moment : polygon.moment;
    }
  }
  std::vector<std::size_t> order(pieces_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const CellPiece &x = pieces_[a], &y = pieces_[b];
    return std::make_tuple(x.seed, -x.area, x.first) < std::make_tuple(y.seed, -y.area, y.first);
  });
  std::vector<std::size_t> rank(order.size());
  std::vector<CellPiece> sorted;
  for (std::size_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = i;
    sorted.push_back(pieces_[order[i]]);
  }
  pieces_ = std::move(sorted);
  // Each seed's (triangle, polygon) becomes (triangle, piece).
  for (PieceOf& of : piece_of_) of.piece = rank[slot[roots.find(of.piece)]];
}

const CellPieceCollector::PieceOf* CellPieceCollector::entry(Index seed, Index triangle) const {
  const PieceOf* begin = piece_of_.data() + piece_offsets_[seed];
  const PieceOf* end = piece_of_.data() + piece_offsets_[seed + 1];
  const PieceOf* at = std::lower_bound(begin, end, triangle,
                                       [](const PieceOf& x, Index t) { return x.triangle < t; });
  return at != end && at->triangle == triangle ? at : nullptr;
}

std::size_t CellPieceCollector::piece_at(Index seed, Index triangle) const {
  return entry(seed, triangle)->piece;
}

}  // namespace cvtmesh
