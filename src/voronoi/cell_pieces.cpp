#include "voronoi/cell_pieces.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

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
  polygon_chunks_.assign(chunks, {});
  side_chunks_.assign(chunks, {});
}

void CellPieceCollector::polygon(std::size_t chunk, const RvdPolygon& p) {
  const auto& v = p.vertices;
  Polygon out{p.seed, p.triangle, 0, {}};
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const double a = triangle_area(v[0].point, v[k].point, v[k + 1].point);
    out.area += a;
    out.moment += (a / 3) * (v[0].point + v[k].point + v[k + 1].point);
  }
  if (!(out.area > 0)) out.moment = v[0].point;
  const Triangle& t = surface_.triangles[p.triangle];
  for (std::size_t k = 0; k < v.size(); ++k) {
    const int e = input_edge_of_side(v[k], v[(k + 1) % v.size()]);
    if (e < 0) continue;
    const Index u = t[e], w = t[(e + 1) % 3];
    side_chunks_[chunk].push_back({p.seed,
                                   {std::min(u, w), std::max(u, w)},
                                   static_cast<Index>(polygon_chunks_[chunk].size())});
  }
  polygon_chunks_[chunk].push_back(out);
}

void CellPieceCollector::end() {
  // The chunks are joined into one array each, sized exactly, and each chunk is freed as soon as
  // it is copied: at the peak, extraction held every polygon up to three times (issue 22: 264 MB
  // of a 490 MB run on a 500k-triangle torus).
  // A cell meets an input edge in one segment (the cell is convex): its polygons on either side
  // of the edge both have that segment as a side, and are one piece. The sides go straight into
  // seed order (a counting sort, stable in traversal order), then each cell's few sides are
  // sorted: sorting them all together was a third of this step.
  std::size_t polygon_count = 0;
  Index seeds = 0;
  for (const auto& chunk : polygon_chunks_) {
    polygon_count += chunk.size();
    for (const Polygon& polygon : chunk) seeds = std::max(seeds, polygon.seed + 1);
  }
  std::vector<std::size_t> sides_of(static_cast<std::size_t>(seeds) + 1, 0);
  for (const auto& chunk : side_chunks_)
    for (const Side& side : chunk) ++sides_of[side.seed + 1];
  const std::vector<std::size_t> side_offsets = seed_offsets(std::move(sides_of));
  std::vector<std::size_t> next(side_offsets.begin(), side_offsets.end() - 1);
  std::vector<Polygon> polygons;
  std::vector<Side> sides(side_offsets.back());
  polygons.reserve(polygon_count);
  for (std::size_t c = 0; c < polygon_chunks_.size(); ++c) {
    for (Side side : side_chunks_[c]) {
      side.polygon += static_cast<Index>(polygons.size());
      sides[next[side.seed]++] = side;
    }
    polygons.insert(polygons.end(), polygon_chunks_[c].begin(), polygon_chunks_[c].end());
    std::vector<Polygon>().swap(polygon_chunks_[c]);
    std::vector<Side>().swap(side_chunks_[c]);
  }
  polygon_chunks_.clear();
  side_chunks_.clear();
  sort_each_seed(sides, side_offsets, [](const Side& a, const Side& b) {
    return std::tie(a.edge, a.polygon) < std::tie(b.edge, b.polygon);
  });
  UnionFind roots(polygons.size());
  for (std::size_t i = 1; i < sides.size(); ++i)
    if (sides[i].seed == sides[i - 1].seed && sides[i].edge == sides[i - 1].edge)
      roots.unite(sides[i].polygon, sides[i - 1].polygon);
  std::vector<Side>().swap(sides);
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
  // Per seed, its polygons' (triangle, piece), by triangle: scattered into seed order, then
  // each seed's few sorted.
  std::vector<std::size_t> polygons_of(static_cast<std::size_t>(seeds) + 1, 0);
  for (const Polygon& polygon : polygons) ++polygons_of[polygon.seed + 1];
  piece_offsets_ = seed_offsets(std::move(polygons_of));
  next.assign(piece_offsets_.begin(), piece_offsets_.end() - 1);
  piece_of_.resize(polygons.size());
  for (std::size_t p = 0; p < polygons.size(); ++p)
    piece_of_[next[polygons[p].seed]++] = {polygons[p].triangle, rank[slot[roots.find(p)]]};
  sort_each_seed(piece_of_, piece_offsets_,
                 [](const PieceOf& a, const PieceOf& b) { return a.triangle < b.triangle; });
}

std::size_t CellPieceCollector::piece_at(Index seed, Index triangle) const {
  const auto begin = piece_of_.begin() + static_cast<std::ptrdiff_t>(piece_offsets_[seed]);
  const auto end = piece_of_.begin() + static_cast<std::ptrdiff_t>(piece_offsets_[seed + 1]);
  return std::lower_bound(begin, end, triangle,
                          [](const PieceOf& x, Index t) { return x.triangle < t; })
      ->piece;
}

}  // namespace cvtmesh
