// The Euler characteristic of each piece of the restricted Voronoi cells (paper §2, Theorem 1:
// the restricted Delaunay triangulation is homeomorphic to the surface when every cell is a
// disc). A cell in one piece can still fail: around a handle or a hole narrower than the spacing
// it is an annulus (χ 0), and the triangulation closes the handle without showing a defect. The
// count is combinatorial, on the vertices' symbols, so it is exact: a piece's polygons are glued
// along the stretches of input edges they share and at the input corners and edge crossings
// they share.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "voronoi/cell_pieces.hpp"

namespace cvtmesh {

struct PieceShape {
  int euler;      // V - E + F of the piece: 1 for a disc
  Vec3 farthest;  // its vertex farthest from its seed
};

class PieceEulerCollector : public PolygonSink {
 public:
  PieceEulerCollector(const TriangleMesh& surface, const std::vector<Vec3>& seeds)
      : surface_(surface), seeds_(&seeds) {}
  // A collector that keeps its chunks from one traversal of `surface` to the next with the same
  // memory (PolygonSink::keeps_chunks), for topology control's rounds (ExtractionMemory): each
  // traversal's diagram is set first (for_diagram).
  struct Keeping {};
  PieceEulerCollector(Keeping, const TriangleMesh& surface) : surface_(surface), keeping_(true) {}
  void for_diagram(const RestrictedVoronoiDiagram& rvd) { seeds_ = &rvd.seeds(); }
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  bool keeps_chunks() const override { return keeping_; }
  void begin_kept(std::size_t chunks, const std::vector<char>& kept) override;

  // After the traversal, for each piece of `pieces` (collected in the same traversal), in its
  // order. Independent of the thread count.
  std::vector<PieceShape> shapes(const CellPieceCollector& pieces) const;

 private:
  // What one polygon adds on its own: its face, its vertices between two bisectors, its sides
  // along a bisector, none of which another polygon of the cell has; and where its shared keys
  // start in its chunk's (they end where the next polygon's start).
  struct Own {
    Index seed, triangle;
    int euler;
    std::uint32_t shared_begin;
    Vec3 farthest;
    double distance;
  };
  // What a polygon shares with other polygons of the cell: an input corner (+1), a crossing of an
  // input edge and a bisector (+1), a stretch of an input edge (-1). Counted once per piece. Its
  // kind, then input vertex or edge ids and a seed.
  using Key = std::array<std::int64_t, 3>;
  const TriangleMesh& surface_;
  const std::vector<Vec3>* seeds_ = nullptr;
  bool keeping_ = false;
  std::vector<std::vector<Own>> own_;
  std::vector<std::vector<Key>> shared_;
};

}  // namespace cvtmesh
