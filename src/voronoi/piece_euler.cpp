#include "voronoi/piece_euler.hpp"

#include <algorithm>
#include <numeric>

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

void PieceEulerCollector::polygon(std::size_t chunk, const RvdPolygon& p) {
  const auto& v = p.vertices;
  const Triangle& t = surface_.triangles[p.triangle];
  Own own{p.seed, p.triangle, 1, v[0].point, -1};
  auto share = [&](Kind kind, std::int64_t a, std::int64_t b) {
    shared_[chunk].push_back({p.seed, p.triangle, {kind, a, b}});
  };
  for (std::size_t k = 0; k < v.size(); ++k) {
    const RvdVertex& a = v[k];
    const double d = distance(a.point, seeds_[p.seed]);
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
  std::vector<PieceShape> out(pieces.pieces().size(), {0, {}});
  std::vector<double> farthest(out.size(), -1);
  for (const auto& chunk : own_)
    for (const Own& o : chunk) {
      const std::size_t i = pieces.piece_at(o.seed, o.triangle);
      out[i].euler += o.euler;
      if (o.distance > farthest[i]) {
        farthest[i] = o.distance;
        out[i].farthest = o.farthest;
      }
    }
  // Each piece's shared keys, counted once: scattered into piece order (a counting sort), then
  // each piece's few sorted (sorting them all together was a twentieth of femur.off at 1k).
  std::vector<std::size_t> piece_of_key, offsets(out.size() + 1, 0);
  for (const auto& chunk : shared_)
    for (const Shared& s : chunk) {
      piece_of_key.push_back(pieces.piece_at(s.seed, s.triangle));
      ++offsets[piece_of_key.back() + 1];
    }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
  std::vector<std::array<std::int64_t, 3>> keys(piece_of_key.size());
  std::size_t k = 0;
  for (const auto& chunk : shared_)
    for (const Shared& s : chunk) keys[next[piece_of_key[k++]]++] = s.key;
  for (std::size_t piece = 0; piece < out.size(); ++piece) {
    const auto begin = keys.begin() + static_cast<std::ptrdiff_t>(offsets[piece]);
    const auto end = keys.begin() + static_cast<std::ptrdiff_t>(offsets[piece + 1]);
    std::sort(begin, end);
    for (auto key = begin; key != end; ++key)
      if (key == begin || *key != key[-1]) out[piece].euler += (*key)[0] == kEdge ? -1 : 1;
  }
  return out;
}

}  // namespace cvtmesh
