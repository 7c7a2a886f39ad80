#include "cvt/cell_islands.hpp"

#include "voronoi/cell_pieces.hpp"

namespace cvtmesh {

std::vector<CellIsland> cell_islands(const TriangleMesh& surface, const std::vector<Vec3>& seeds) {
  const RestrictedVoronoiDiagram rvd(surface, seeds);
  CellPieceCollector collector(surface);
  rvd.traverse(collector);
  return cell_islands(collector);
}

std::vector<CellIsland> cell_islands(const CellPieceCollector& collector) {
  // Each cell's pieces come largest first: the others are islands.
  const std::vector<CellPiece>& pieces = collector.pieces();
  std::vector<CellIsland> islands;
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].seed == pieces[i - 1].seed && pieces[i].area > 0)
      islands.push_back(
          {pieces[i].seed, (1 / pieces[i].area) * pieces[i].moment, pieces[i].area, i});
  return islands;
}

}  // namespace cvtmesh
