// The restricted Delaunay triangulation with one vertex per piece of each restricted cell (the
// "multi-nerve": the nerve of the cover of the surface by the cells' connected pieces, as
// geogram's RDT_MULTINERVE). Where every cell is one piece it is the ordinary restricted Delaunay
// triangulation. Where a cell reaches across a thin part, onto a nearby sheet or component, or
// through a self-intersection, its far pieces become vertices of their own, so the triangles of
// each sheet use only vertices of that sheet, and no triangle joins two sheets or components.
#pragma once

#include <utility>
#include <vector>

#include "voronoi/cell_pieces.hpp"

namespace cvtmesh {

class MultiNerveBuilder : public PolygonSink {
 public:
  // `rings`: the surface's, as CellPieceCollector takes them.
  explicit MultiNerveBuilder(const RestrictedVoronoiDiagram& rvd, const SideRings* rings = nullptr)
      : rvd_(rvd), pieces_(rvd.surface(), rings) {}
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void chunk_done(std::size_t chunk) override;
  void end() override;
  // Vertices: the seeds, by id (each for its cell's largest piece), then one per other piece at
  // the centroid of that piece's largest polygon (at the seed, where it and the first both reach
  // it: sheets touching there), in CellPieceCollector order. Triangles oriented like the input
  // facets, each once.
  const TriangleMesh& result() const { return result_; }
  // The seed each vertex of result() stands for (the identity on the seeds).
  const std::vector<Index>& vertex_seed() const { return vertex_seed_; }

 private:
  struct Found {
    Triangle seeds;
    Index triangle;  // the input triangle the dual Voronoi edge crosses
  };
  const RestrictedVoronoiDiagram& rvd_;
  CellPieceCollector pieces_;
  std::vector<std::vector<Found>> chunks_;
  // Per chunk, (seed, triangle) of the polygons with an input corner at their seed.
  std::vector<std::vector<std::pair<Index, Index>>> at_seed_;
  TriangleMesh result_;
  std::vector<Index> vertex_seed_;
};

}  // namespace cvtmesh
