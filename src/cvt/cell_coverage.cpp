#include "cvt/cell_coverage.hpp"

#include <algorithm>

#include "voronoi/kept_chunks.hpp"

namespace cvtmesh {

void CellCoverage::for_pieces(const TrianglePieces& pieces) {
  pieces_ = &pieces;
  if (pieces.cuts() != cuts_) {
    cuts_ = pieces.cuts();
    forget_kept_chunks();
  }
}

void CellCoverage::begin(std::size_t chunks) {
  chunks_.assign(chunks, {});
  ball_chunks_.assign(chunks, {});
}

void CellCoverage::begin_kept(std::size_t /*chunks*/, const std::vector<char>& kept) {
  keep_only(kept, chunks_, ball_chunks_);
}

void CellCoverage::polygon(std::size_t chunk, const RvdPolygon& p) {
  chunks_[chunk].push_back({p.seed, p.triangle});
  if (!pieces_->cut(p.triangle)) return;
  ball_chunks_[chunk].push_back({p.triangle, p.seed, bounding_ball(p.vertices)});
}

// Each chunk is kept as it is, sized exactly: joined into one array, they were held twice.
void CellCoverage::chunk_done(std::size_t chunk) {
  chunks_[chunk].shrink_to_fit();
  ball_chunks_[chunk].shrink_to_fit();
}

std::vector<Index> CellCoverage::triangles_of(const std::vector<Index>& cells) const {
  std::vector<Index> out;
  for (const auto& chunk : chunks_)
    for (const auto& [seed, triangle] : chunk)
      if (std::binary_search(cells.begin(), cells.end(), seed)) out.push_back(triangle);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::map<Index, std::vector<Ball>> CellCoverage::balls_of(const std::vector<Index>& cells) const {
  std::map<Index, std::vector<Ball>> out;
  for (const auto& chunk : ball_chunks_)
    for (const BallOn& b : chunk)
      if (std::binary_search(cells.begin(), cells.end(), b.seed)) out[b.triangle].push_back(b.ball);
  return out;
}

}  // namespace cvtmesh
