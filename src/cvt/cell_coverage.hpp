// What local Lloyd steps need of an extraction to build their patch (polish_defects): the input
// triangles each restricted cell covers, and, on the triangles that TrianglePieces cuts, the
// balls around its polygons there.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "cvt/triangle_pieces.hpp"
#include "cvtmesh/rvd.hpp"
#include "voronoi/polygon_reach.hpp"

namespace cvtmesh {

// Keeps its chunks from one traversal to the next with the same memory (PolygonSink::
// keeps_chunks) while the triangles cut stay the same.
class CellCoverage : public PolygonSink {
 public:
  // Before each traversal: the pieces it is for. Where they cut other triangles than the last
  // traversal's, the next traversal hands over every polygon again (the balls are for the cut
  // triangles only, and the cuts depend on the seed count).
  void for_pieces(const TrianglePieces& pieces);

  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& p) override;
  void chunk_done(std::size_t chunk) override;
  bool keeps_chunks() const override { return true; }
  void begin_kept(std::size_t chunks, const std::vector<char>& kept) override;

  // The triangles covered by any of `cells` (sorted), sorted and without repeats. One scan, only
  // in rounds that found defects: most extractions never ask.
  std::vector<Index> triangles_of(const std::vector<Index>& cells) const;
  // Per cut triangle of `cells` (sorted), the balls around their polygons there.
  std::map<Index, std::vector<Ball>> balls_of(const std::vector<Index>& cells) const;

 private:
  struct BallOn {
    Index triangle, seed;
    Ball ball;
  };
  const TrianglePieces* pieces_ = nullptr;
  std::vector<char> cuts_;  // the last traversal's pieces' (TrianglePieces::cuts)
  std::vector<std::vector<std::pair<Index, Index>>> chunks_;  // (seed, triangle)
  std::vector<std::vector<BallOn>> ball_chunks_;
};

}  // namespace cvtmesh
