#include "voronoi/cell_pieces.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>
#include <tuple>

#include "geometry/index_range.hpp"
#include "geometry/union_find.hpp"
#include "voronoi/kept_chunks.hpp"

namespace cvtmesh {

namespace {

// Where each seed's items start when they are laid out in seed order: offsets[s] to
// offsets[s + 1], from a count per seed (`count[s + 1]` holds seed s's; count[0] is 0).
std::vector<std::size_t> seed_offsets(std::vector<std::size_t> count) {
  std::partial_sum(count.begin(), count.end(), count.begin());
  return count;
}

// Sorts each seed's range of `items` (laid out by `offsets`) by `less`: a cell's few items, the
// cells in parallel.
template <class T, class Less>
void sort_each_seed(std::vector<T>& items, const std::vector<std::size_t>& offsets,
                    const Less& less) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, offsets.size() - 1), [&](const auto& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s)
      std::sort(items.begin() + static_cast<std::ptrdiff_t>(offsets[s]),
                items.begin() + static_cast<std::ptrdiff_t>(offsets[s + 1]), less);
  });
}

}  // namespace

void CellPieceCollector::begin(std::size_t chunks) {
  // Triangle ids take 29 bits of a polygon record (a 2^29-triangle input would need some 350 GB).
  if (surface_.triangles.size() >= (std::size_t{1} << 29))
    throw std::length_error("too many triangles for the cell pieces");
  // A cell meets an input edge in one segment (the cell is convex): its polygons on the
  // triangles around the edge all have that segment as a side, and are one piece. Each triangle
  // side's next around its edge leads to them (SideRings), found before any polygon is kept.
  if (!rings_) own_rings_.emplace(surface_);
  polygon_chunks_.assign(chunks, {});
  all_kept_ = false;
}

void CellPieceCollector::begin_kept(std::size_t /*chunks*/, const std::vector<char>& kept) {
  all_kept_ = std::all_of(kept.begin(), kept.end(), [](char k) { return k != 0; });
  if (!rings_ && !all_kept_) own_rings_.emplace(surface_);
  keep_only(kept, polygon_chunks_);
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

void CellPieceCollector::chunk_done(std::size_t chunk) {
  // Sized exactly once complete: vectors grown by doubling held half as much again as their
  // polygons (igea.ply at 10k seeds: 25 MB for 17 MB of polygons).
  polygon_chunks_[chunk].shrink_to_fit();
}

void CellPieceCollector::end() {
  if (all_kept_) return;  // the same polygons as when the pieces were found
  // The polygons stay in their chunks, numbered in chunk order through an array of pointers:
  // joining them into one array held every polygon twice at the peak (issue 22: extraction was
  // 264 MB of a 490 MB run on a 500k-triangle torus).
  std::size_t polygon_count = 0;
  Index seeds = 0;
  for (auto& chunk : polygon_chunks_) {
    chunk.shrink_to_fit();  // where the traversal did not say the chunk was done
    polygon_count += chunk.size();
    for (const Polygon& polygon : chunk) seeds = std::max(seeds, polygon.seed + 1);
  }
  // Polygon and piece ids take 32 bits (2^32 polygons would need some 170 GB).
  require_index_range(polygon_count, "polygons for the cell pieces");
  std::vector<const Polygon*> polygons;
  polygons.reserve(polygon_count);
  for (const auto& chunk : polygon_chunks_)
    for (const Polygon& polygon : chunk) polygons.push_back(&polygon);
  // Per seed, its polygons as (triangle, polygon), by triangle: scattered into seed order, then
  // each seed's few sorted. The pieces' lookup (piece_at) later reuses it, polygon → piece.
  std::vector<std::size_t> polygons_of(static_cast<std::size_t>(seeds) + 1, 0);
  for (const Polygon* polygon : polygons) ++polygons_of[polygon->seed + 1];
  piece_offsets_ = seed_offsets(std::move(polygons_of));
  std::vector<std::size_t> next(piece_offsets_.begin(), piece_offsets_.end() - 1);
  piece_of_.resize(polygons.size());
  for (Index p = 0; p < polygons.size(); ++p)
    piece_of_[next[polygons[p]->seed]++] = {polygons[p]->triangle, p};
  std::vector<std::size_t>().swap(next);
  sort_each_seed(piece_of_, piece_offsets_,
                 [](const PieceOf& a, const PieceOf& b) { return a.triangle < b.triangle; });
  // Polygons of a cell around an input edge are one piece (see begin). A cell's polygons meet
  // only each other, so the cells are joined and summed on their own, in parallel; each cell's
  // polygons come in traversal order (by triangle, as the chunks hold them), so its pieces' sums
  // and first polygons do not depend on the thread count. (igea.ply at 10k: 430k polygons, this
  // step 0.08 s of each extraction's 0.11 s of serial work.)
  UnionFind roots(polygons.size());  // each cell's sets apart from the others'
  // Per root polygon, its piece's index among its seed's: first in the order their first
  // polygons come, then sorted by area (largest first), then first polygon.
  constexpr Index kNone = std::numeric_limits<Index>::max();
  std::vector<Index> rank(polygons.size(), kNone);
  // Per seed, its piece count (at seed + 1): the cells are joined first, then their pieces
  // summed in place in pieces_ (a vector of pieces per seed took 40 MB, in 3.5 million
  // allocations, for igea.ply at 500k seeds).
  std::vector<std::size_t> pieces_of(static_cast<std::size_t>(seeds) + 1, 0);
  const SideRings& rings = rings_ ? *rings_ : *own_rings_;
  tbb::parallel_for(tbb::blocked_range<Index>(0, seeds), [&](const auto& range) {
    for (Index seed = range.begin(); seed != range.end(); ++seed) {
      const std::size_t begin = piece_offsets_[seed], end = piece_offsets_[seed + 1];
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t p = piece_of_[i].piece;
        const Polygon& polygon = *polygons[p];
        for (std::uint32_t e = 0; e < 3; ++e) {
          if (!(polygon.sides & (1u << e))) continue;
          const std::uint32_t side = 3 * polygon.triangle + e;
          for (std::uint32_t other = rings.next(side); other != side; other = rings.next(other))
            if (const PieceOf* q = entry(seed, other / 3)) roots.unite(p, q->piece);
        }
      }
      Index count = 0;
      for (std::size_t i = begin; i < end; ++i)
        if (Index& r = rank[roots.find(piece_of_[i].piece)]; r == kNone) r = count++;
      pieces_of[seed + 1] = count;
    }
  });
  own_rings_.reset();
  const std::vector<std::size_t> first_piece = seed_offsets(std::move(pieces_of));
  pieces_.resize(first_piece[seeds]);
  tbb::parallel_for(tbb::blocked_range<Index>(0, seeds), [&](const auto& range) {
    constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
    for (Index seed = range.begin(); seed != range.end(); ++seed) {
      const auto pieces =
          std::span(pieces_).subspan(first_piece[seed], first_piece[seed + 1] - first_piece[seed]);
      for (CellPiece& piece : pieces) piece = {seed, kUnset, 0, {}, {}, -1};
      const std::size_t begin = piece_offsets_[seed], end = piece_offsets_[seed + 1];
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t p = piece_of_[i].piece;
        CellPiece& piece = pieces[rank[roots.find(p)]];
        if (piece.first == kUnset) piece.first = p;
        const Polygon& polygon = *polygons[p];
        const bool has_area = polygon.area > 0;
        piece.area += polygon.area;
        if (has_area) piece.moment += polygon.moment;
        if (polygon.area > piece.largest_area) {
          piece.largest_area = polygon.area;
          piece.largest_centre = has_area ? (1 / polygon.area) * polygon.moment : polygon.moment;
        }
      }
      std::sort(pieces.begin(), pieces.end(), [](const CellPiece& x, const CellPiece& y) {
        return std::make_tuple(-x.area, x.first) < std::make_tuple(-y.area, y.first);
      });
      for (Index k = 0; k < pieces.size(); ++k) rank[roots.find(pieces[k].first)] = k;
      // Each of the seed's entries becomes its piece's index in pieces_ (the first pass, which
      // read them with entry, is over).
      for (std::size_t i = begin; i < end; ++i)
        piece_of_[i].piece =
            static_cast<Index>(first_piece[seed]) + rank[roots.find(piece_of_[i].piece)];
    }
  });
  polygons = {};
  if (!keeping_) polygon_chunks_.clear();
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
