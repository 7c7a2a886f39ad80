#include "voronoi/piece_euler.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "voronoi/kept_chunks.hpp"

namespace cvtmesh {

namespace {

enum Kind : std::int64_t { kCorner = 0, kCrossing = 1, kEdge = 2 };

// Input edge e of a triangle joins its corners e and (e + 1) % 3; as a key, its two vertex ids
// with the smaller first.
std::int64_t edge_key(const Triangle& t, int e) {
  const std::int64_t u = t[e], w = t[(e + 1) % 3];
  return std::min(u, w) * (std::int64_t{1} << 32) + std::max(u, w);
}

}  // namespace

void PieceEulerCollector::begin(std::size_t chunks) {
  own_.assign(chunks, {});
  shared_.assign(chunks, {});
}

void PieceEulerCollector::begin_kept(std::size_t /*chunks*/, const std::vector<char>& kept) {
  keep_only(kept, own_, shared_);
}

void PieceEulerCollector::polygon(std::size_t chunk, const RvdPolygon& p) {
  const auto& v = p.vertices;
  const Triangle& t = surface_.triangles[p.triangle];
  Own own{p.seed, p.triangle, 1, static_cast<std::uint32_t>(shared_[chunk].size()), v[0].point, -1};
  auto share = [&](Kind kind, std::int64_t a, std::int64_t b) {
    shared_[chunk].push_back({kind, a, b});
  };
  for (std::size_t k = 0; k < v.size(); ++k) {
    const RvdVertex& a = v[k];
    const double d = distance(a.point, (*seeds_)[p.seed]);
    if (d > own.distance) {
      own.distance = d;
      own.farthest = a.point;
    }
    const auto [s0, s1] = a.symbols;
    if (a.bisector_count() == 2) {
      ++own.euler;
    } else if (a.bisector_count() == 1) {
      const std::int32_t edge = s0 < 0 ? s0 : s1, bisector = s0 < 0 ? s1 : s0;
      share(kCrossing, edge_key(t, -(edge + 1)), bisector);
    } else {
      // The corner the two edges share: edge e ends at corner (e + 1) % 3.
      const int e0 = -(s0 + 1), e1 = -(s1 + 1);
      share(kCorner, t[(e0 + 1) % 3 == e1 ? e1 : e0], 0);
    }
    if (const int e = input_edge_of_side(a, v[(k + 1) % v.size()]); e >= 0)
      share(kEdge, edge_key(t, e), 0);
    else
      --own.euler;
  }
  own_[chunk].push_back(own);
}

std::vector<PieceShape> PieceEulerCollector::shapes(const CellPieceCollector& pieces) const {
  // Each polygon's piece, looked up chunk by chunk in parallel; and where it is, as (chunk,
  // index in the chunk).
  std::vector<std::size_t> first(own_.size() + 1, 0);
  for (std::size_t c = 0; c < own_.size(); ++c) first[c + 1] = first[c] + own_[c].size();
  std::vector<std::size_t> piece_of(first.back());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at(first.back());
  tbb::parallel_for(std::size_t{0}, own_.size(), [&](std::size_t c) {
    for (std::size_t k = 0; k < own_[c].size(); ++k) {
      piece_of[first[c] + k] = pieces.piece_at(own_[c][k].seed, own_[c][k].triangle);
      at[first[c] + k] = {static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(k)};
    }
  });
  std::vector<PieceShape> out(pieces.pieces().size(), {0, {}});
  std::vector<double> farthest(out.size(), -1);
  std::vector<std::size_t> offsets(out.size() + 1, 0);
  for (std::size_t g = 0; g < at.size(); ++g) {
    const Own& o = own_[at[g].first][at[g].second];
    const std::size_t i = piece_of[g];
    out[i].euler += o.euler;
    if (o.distance > farthest[i]) {
      farthest[i] = o.distance;
      out[i].farthest = o.farthest;
    }
    ++offsets[i + 1];
  }
  // Each piece's polygons (a counting sort of their places), then, piece by piece in parallel,
  // the keys its polygons share with one another, each counted once (scattering the keys into
  // piece order instead, serially, was most of this step: 24 bytes a key, written at random).
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_piece(at.size());
  for (std::size_t g = 0; g < at.size(); ++g) by_piece[next[piece_of[g]]++] = at[g];
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size()), [&](const auto& range) {
    std::vector<Key> keys;
    for (std::size_t piece = range.begin(); piece != range.end(); ++piece) {
      keys.clear();
      for (std::size_t g = offsets[piece]; g < offsets[piece + 1]; ++g) {
        const auto [c, k] = by_piece[g];
        const std::size_t end =
            k + 1 < own_[c].size() ? own_[c][k + 1].shared_begin : shared_[c].size();
        keys.insert(keys.end(), shared_[c].begin() + own_[c][k].shared_begin,
                    shared_[c].begin() + static_cast<std::ptrdiff_t>(end));
      }
      std::sort(keys.begin(), keys.end());
      for (auto key = keys.begin(); key != keys.end(); ++key)
        if (key == keys.begin() || *key != key[-1]) out[piece].euler += (*key)[0] == kEdge ? -1 : 1;
    }
  });
  return out;
}

}  // namespace cvtmesh
