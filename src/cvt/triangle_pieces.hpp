// Input triangles far larger than the cells, cut into small pieces for local Lloyd steps
// (polish_defects): a local RVD over a whole CAD facet gives the facet's far parts, which no
// local seed's cell reaches in the full diagram, to the local cells, whose polygons then stretch
// across the facet and are clipped by every local seed within their reach (corpus/spool.off at
// 10k: each local step clipped 942 of its 1,294 facets, 661k predicates, more than a full RVD of
// all 10k seeds). Only the pieces that the local cells reach go into the patch.
#pragma once

#include <span>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "voronoi/polygon_reach.hpp"

namespace cvtmesh {

class TrianglePieces {
 public:
  // Triangles of `surface` with an edge longer than 8 `spacing` are cut, into pieces at most 4
  // `spacing` long.
  TrianglePieces(const TriangleMesh& surface, double spacing);

  bool cut(Index t) const { return cut_[t] != 0; }
  // Per triangle, whether it is cut.
  const std::vector<char>& cuts() const { return cut_; }

  // Appends to `patch` the pieces of triangle t that meet one of `balls` (around the polygons of
  // the cells that the pieces are for: bounding_ball), in t's orientation,
  // with new vertices; and, when `rho` (per vertex of the surface) is given, their density,
  // linear over t, to `density`.
  void add_pieces(Index t, std::span<const Ball> balls, const std::vector<double>* rho,
                  TriangleMesh& patch, std::vector<double>& density) const;

 private:
  const TriangleMesh& surface_;
  std::vector<char> cut_;  // per triangle
  double piece_length_;
};

}  // namespace cvtmesh
