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
#include <utility>

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

// The entry of `seed` on `triangle` in `entries` (each seed's from offsets[seed], by triangle),
// or null where it has none.
template <class Entry>
const Entry* entry_on(const std::vector<Entry>& entries, const std::vector<std::size_t>& offsets,
                      Index seed, Index triangle) {
  const Entry* begin = entries.data() + offsets[seed];
  const Entry* end = entries.data() + offsets[seed + 1];
  const Entry* at = std::lower_bound(begin, end, triangle,
                                     [](const Entry& x, Index t) { return x.triangle < t; });
  return at != end && at->triangle == triangle ? at : nullptr;
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
  kept_chunks_.clear();
}

void CellPieceCollector::begin_kept(std::size_t /*chunks*/, const std::vector<char>& kept) {
  all_kept_ = all_kept(kept);
  if (all_kept_) return;
  if (!rings_) own_rings_.emplace(surface_);
  // The cells with a polygon in a chunk that changes (end() joins them again).
  changed_.assign(seeds_, 0);
  for (std::size_t c = 0; c < kept.size(); ++c)
    if (!kept[c])
      for (const Polygon& polygon : polygon_chunks_[c]) changed_[polygon.seed] = 1;
  kept_chunks_ = kept;
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
  std::size_t polygon_count = 0;
  Index seeds = 0;
  for (auto& chunk : polygon_chunks_) {
    chunk.shrink_to_fit();  // where the traversal did not say the chunk was done
    polygon_count += chunk.size();
    for (const Polygon& polygon : chunk) seeds = std::max(seeds, polygon.seed + 1);
  }
  // Polygon and piece ids take 32 bits (2^32 polygons would need some 170 GB).
  require_index_range(polygon_count, "polygons for the cell pieces");
  // The cells joined again: all, or, after a traversal that kept chunks (begin_kept), those with
  // a polygon in a chunk that changed, then or now. A cell's pieces depend on its polygons alone,
  // so the others' are as the last end() found them (issue 18: topology control's and
  // polishing's extractions work locally; igea.ply at 10k on one thread: this step took 0.1 s
  // of each extraction).
  std::vector<char> again(seeds, 1);
  if (!kept_chunks_.empty()) {
    for (Index s = 0; s < std::min<Index>(seeds, seeds_); ++s) again[s] = changed_[s];
    for (std::size_t c = 0; c < polygon_chunks_.size(); ++c)
      if (!kept_chunks_[c])
        for (const Polygon& polygon : polygon_chunks_[c]) again[polygon.seed] = 1;
  }
  // Their polygons stay in their chunks, numbered in chunk order through an array of pointers:
  // joining them into one array held every polygon twice at the peak (issue 22: extraction was
  // 264 MB of a 490 MB run on a 500k-triangle torus).
  std::vector<const Polygon*> polygons;
  if (kept_chunks_.empty()) polygons.reserve(polygon_count);
  std::vector<std::size_t> polygons_of(static_cast<std::size_t>(seeds) + 1, 0);
  for (const auto& chunk : polygon_chunks_)
    for (const Polygon& polygon : chunk)
      if (again[polygon.seed]) {
        polygons.push_back(&polygon);
        ++polygons_of[polygon.seed + 1];
      }
  // Per cell, its polygons as (triangle, polygon), by triangle: scattered into seed order, then
  // each seed's few sorted.
  const std::vector<std::size_t> offsets = seed_offsets(std::move(polygons_of));
  std::vector<PieceOf> joined(polygons.size());
  {
    std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
    for (Index p = 0; p < polygons.size(); ++p)
      joined[next[polygons[p]->seed]++] = {polygons[p]->triangle, p};
  }
  sort_each_seed(joined, offsets,
                 [](const PieceOf& a, const PieceOf& b) { return a.triangle < b.triangle; });
  // Polygons of a cell around an input edge are one piece (see begin). A cell's polygons meet
  // only each other, so the cells are joined and summed on their own, in parallel; each cell's
  // polygons come in traversal order (by triangle, as the chunks hold them), so its pieces' sums
  // and first polygons do not depend on the thread count.
  UnionFind roots(polygons.size());  // each cell's sets apart from the others'
  // Per root polygon, its piece's index among its seed's: first in the order their first
  // polygons come, then sorted by area (largest first), then first polygon.
  constexpr Index kNone = std::numeric_limits<Index>::max();
  std::vector<Index> rank(polygons.size(), kNone);
  // Per cell joined, its piece count (at seed + 1): the cells are joined first, then their pieces
  // summed in place (a vector of pieces per seed took 40 MB, in 3.5 million allocations, for
  // igea.ply at 500k seeds).
  std::vector<std::size_t> pieces_of(static_cast<std::size_t>(seeds) + 1, 0);
  const SideRings& rings = rings_ ? *rings_ : *own_rings_;
  tbb::parallel_for(tbb::blocked_range<Index>(0, seeds), [&](const auto& range) {
    for (Index seed = range.begin(); seed != range.end(); ++seed) {
      if (!again[seed]) continue;
      const std::size_t begin = offsets[seed], end = offsets[seed + 1];
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t p = joined[i].piece;
        const Polygon& polygon = *polygons[p];
        for (std::uint32_t e = 0; e < 3; ++e) {
          if (!(polygon.sides & (1u << e))) continue;
          const std::uint32_t side = 3 * polygon.triangle + e;
          for (std::uint32_t other = rings.next(side); other != side; other = rings.next(other))
            if (const PieceOf* q = entry_on(joined, offsets, seed, other / 3))
              roots.unite(p, q->piece);
        }
      }
      Index count = 0;
      for (std::size_t i = begin; i < end; ++i)
        if (Index& r = rank[roots.find(joined[i].piece)]; r == kNone) r = count++;
      pieces_of[seed + 1] = count;
    }
  });
  own_rings_.reset();
  const std::vector<std::size_t> first_joined = seed_offsets(std::move(pieces_of));
  std::vector<CellPiece> fresh(first_joined[seeds]);
  // Every cell joined again (a first traversal, or changes all over): the arrays as they are
  // are the result, with no copy into place.
  const bool all_again = std::all_of(again.begin(), again.end(), [](char a) { return a != 0; });
  tbb::parallel_for(tbb::blocked_range<Index>(0, seeds), [&](const auto& range) {
    constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
    for (Index seed = range.begin(); seed != range.end(); ++seed) {
      if (!again[seed]) continue;
      const auto pieces =
          std::span(fresh).subspan(first_joined[seed], first_joined[seed + 1] - first_joined[seed]);
      for (CellPiece& piece : pieces) piece = {seed, kUnset, 0, {}, {}, -1};
      const std::size_t begin = offsets[seed], end = offsets[seed + 1];
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t p = joined[i].piece;
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
      for (Index k = 0; k < pieces.size(); ++k) {
        rank[roots.find(pieces[k].first)] = k;
        pieces[k].first = polygons[pieces[k].first]->triangle;  // see CellPiece::first
      }
      // Each entry's piece, as its index among its seed's (in pieces_, where all are joined).
      const auto base = static_cast<Index>(all_again ? first_joined[seed] : 0);
      for (std::size_t i = begin; i < end; ++i)
        joined[i].piece = base + rank[roots.find(joined[i].piece)];
    }
  });
  seeds_ = seeds;
  if (all_again) {
    piece_of_ = std::move(joined);
    piece_offsets_ = offsets;
    pieces_ = std::move(fresh);
    first_piece_ = first_joined;
    if (!keeping_) polygon_chunks_.clear();
    return;
  }
  // All cells in seed order: those joined again from above, the others as they were.
  const std::vector<PieceOf> old_of = std::exchange(piece_of_, {});
  const std::vector<std::size_t> old_offsets = std::exchange(piece_offsets_, {});
  const std::vector<CellPiece> old_pieces = std::exchange(pieces_, {});
  const std::vector<std::size_t> old_first = std::exchange(first_piece_, {});
  std::vector<std::size_t> entries(static_cast<std::size_t>(seeds) + 1, 0);
  std::vector<std::size_t> pieces_per(static_cast<std::size_t>(seeds) + 1, 0);
  for (Index s = 0; s < seeds; ++s) {
    entries[s + 1] = again[s] ? offsets[s + 1] - offsets[s] : old_offsets[s + 1] - old_offsets[s];
    pieces_per[s + 1] =
        again[s] ? first_joined[s + 1] - first_joined[s] : old_first[s + 1] - old_first[s];
  }
  piece_offsets_ = seed_offsets(std::move(entries));
  first_piece_ = seed_offsets(std::move(pieces_per));
  piece_of_.resize(piece_offsets_[seeds]);
  pieces_.resize(first_piece_[seeds]);
  tbb::parallel_for(tbb::blocked_range<Index>(0, seeds), [&](const auto& range) {
    for (Index s = range.begin(); s != range.end(); ++s) {
      const auto at = static_cast<Index>(first_piece_[s]);
      if (again[s]) {
        std::copy(fresh.begin() + static_cast<std::ptrdiff_t>(first_joined[s]),
                  fresh.begin() + static_cast<std::ptrdiff_t>(first_joined[s + 1]),
                  pieces_.begin() + static_cast<std::ptrdiff_t>(at));
        for (std::size_t i = offsets[s]; i < offsets[s + 1]; ++i)
          piece_of_[piece_offsets_[s] + i - offsets[s]] = {joined[i].triangle,
                                                           at + joined[i].piece};
      } else {
        std::copy(old_pieces.begin() + static_cast<std::ptrdiff_t>(old_first[s]),
                  old_pieces.begin() + static_cast<std::ptrdiff_t>(old_first[s + 1]),
                  pieces_.begin() + static_cast<std::ptrdiff_t>(at));
        const auto shift = static_cast<Index>(old_first[s]);
        for (std::size_t i = old_offsets[s]; i < old_offsets[s + 1]; ++i)
          piece_of_[piece_offsets_[s] + i - old_offsets[s]] = {old_of[i].triangle,
                                                               at + old_of[i].piece - shift};
      }
    }
  });
  if (!keeping_) polygon_chunks_.clear();
}

const CellPieceCollector::PieceOf* CellPieceCollector::entry(Index seed, Index triangle) const {
  return entry_on(piece_of_, piece_offsets_, seed, triangle);
}

std::size_t CellPieceCollector::piece_at(Index seed, Index triangle) const {
  return entry(seed, triangle)->piece;
}

}  // namespace cvtmesh
