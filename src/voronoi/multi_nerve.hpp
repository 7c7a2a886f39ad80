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
      : rvd_(&rvd), pieces_(rvd.surface(), rings) {}
  // A builder that keeps its chunks from one traversal of `surface` to the next with the same
  // memory (PolygonSink::keeps_chunks), for extractions that follow one another (ExtractionMemory):
  // each traversal's diagram is set first (for_diagram).
  MultiNerveBuilder(CellPieceCollector::Keeping keeping, const TriangleMesh& surface,
                    const SideRings* rings)
      : pieces_(keeping, surface, rings) {}
  // Before each traversal: its diagram, which outlives the traversal and the calls after it.
  void for_diagram(const RestrictedVoronoiDiagram& rvd) { rvd_ = &rvd; }
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void chunk_done(std::size_t chunk) override;
  void end() override;
  bool keeps_chunks() const override { return pieces_.keeps_chunks(); }
  void begin_kept(std::size_t chunks, const std::vector<char>& kept) override;
  // The cells' pieces, as end() found them.
  const CellPieceCollector& pieces() const { return pieces_; }
  // Of a builder that keeps chunks, after end(): where the dual Voronoi edges of `wanted`
  // (sorted triangles of seed ids, each rotated to start at its smallest) cross the surface, in
  // traversal order, each with its distance to the seeds (its Delaunay ball's radius).
  struct Crossing {
    Vec3 point;
    double radius;
  };
  std::vector<Crossing> crossings(const std::vector<Triangle>& wanted) const;
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
    Vec3 point;      // where it crosses it
  };
  const RestrictedVoronoiDiagram* rvd_ = nullptr;
  CellPieceCollector pieces_;
  std::vector<std::vector<Found>> chunks_;
  // Per chunk, (seed, triangle) of the polygons with an input corner at their seed.
  std::vector<std::vector<std::pair<Index, Index>>> at_seed_;
  TriangleMesh result_;
  std::vector<Index> vertex_seed_;
  std::vector<Vec3> seeds_at_end_;  // of a builder that keeps chunks: the last end()'s seeds
};

}  // namespace cvtmesh
