// The pieces of the restricted Voronoi cells (paper §4.4): a cell meets the surface in one piece
// when the topological ball property holds, in several where it reaches across a thin part, onto
// a nearby sheet or component, or through a self-intersection. Polygons of one cell are one piece
// when they share a stretch of an input edge; the surface's connectivity comes from its vertex
// ids, so sheets that only cross or touch in space stay apart.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cvtmesh/rvd.hpp"
#include "voronoi/side_rings.hpp"

namespace cvtmesh {

// The edge of the input triangle (0-2: edge e joins corners e and (e + 1) % 3) that the side from
// polygon vertex a to the next, b, lies on, or -1 for a side along a bisector: the side lies on an
// input edge when both its ends do.
inline int input_edge_of_side(const RvdVertex& a, const RvdVertex& b) {
  for (const std::int32_t s : a.symbols)
    if (s < 0 && (s == b.symbols[0] || s == b.symbols[1])) return -(s + 1);
  return -1;
}

struct CellPiece {
  Index seed;
  std::size_t first;  // the triangle of its first polygon (in traversal order), for a stable order
  double area;
  Vec3 moment;          // area × centroid
  Vec3 largest_centre;  // the centroid of its largest polygon: a point on the surface
  double largest_area;
};

// Collects one traversal's polygons; after it, each polygon's piece and each cell's pieces,
// largest first. Independent of the thread count (polygons are numbered in chunk order).
class CellPieceCollector : public PolygonSink {
 public:
  // `rings`: the surface's SideRings, if the caller keeps them for several traversals; else
  // each traversal finds its own.
  explicit CellPieceCollector(const TriangleMesh& surface, const SideRings* rings = nullptr)
      : surface_(surface), rings_(rings) {}
  // A collector that keeps its chunks from one traversal to the next with the same memory
  // (PolygonSink::keeps_chunks), and so holds their polygons between traversals.
  struct Keeping {};
  CellPieceCollector(Keeping, const TriangleMesh& surface, const SideRings* rings)
      : surface_(surface), rings_(rings), keeping_(true) {}
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void chunk_done(std::size_t chunk) override;
  void end() override;
  bool keeps_chunks() const override { return keeping_; }
  void begin_kept(std::size_t chunks, const std::vector<char>& kept) override;

  // By seed, then area (largest first), then first polygon.
  const std::vector<CellPiece>& pieces() const { return pieces_; }
  // The index in pieces() of the piece holding the polygon of `seed` on input `triangle` (a cell
  // meets a triangle in at most one polygon: both are convex).
  std::size_t piece_at(Index seed, Index triangle) const;
  // Whether the last traversal kept every chunk (begin_kept): the pieces are as they were.
  bool kept_every_chunk() const { return all_kept_; }

 private:
  struct Polygon {
    Index seed;
    // The input edges (bit e: edge e of the triangle) that the polygon has a side on: 3 bits of
    // the triangle's id, as polygons are most of the collector's memory.
    std::uint32_t triangle : 29, sides : 3;
    double area;
    Vec3 moment;  // area × centroid; for a polygon without area, a vertex of it instead
  };
  const TriangleMesh& surface_;
  const SideRings* rings_;
  bool keeping_ = false;
  bool all_kept_ = false;  // this traversal kept every chunk: the pieces are as they were
  std::optional<SideRings> own_rings_;  // where none were given: from begin() to end()
  std::vector<std::vector<Polygon>> polygon_chunks_;
  std::vector<CellPiece> pieces_;
  // Each polygon's piece (index in pieces_; while end() joins them, its polygon), grouped by seed
  // (from piece_offsets_[seed]), each seed's by triangle: what piece_at searches.
  struct PieceOf {
    Index triangle;
    Index piece;
  };
  std::vector<PieceOf> piece_of_;
  std::vector<std::size_t> piece_offsets_;
  std::vector<std::size_t> first_piece_;  // per seed, where its pieces start in pieces_
  Index seeds_ = 0;                       // the seeds end() found pieces for
  // Of a traversal that keeps chunks: which (empty: none, all came again), and the cells that had
  // a polygon in a chunk that did not.
  std::vector<char> kept_chunks_;
  std::vector<char> changed_;
  // The entry of `seed`'s polygon on `triangle` in piece_of_, or null where it has none.
  const PieceOf* entry(Index seed, Index triangle) const;
};

}  // namespace cvtmesh
