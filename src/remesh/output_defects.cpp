#include "remesh/output_defects.hpp"

#include <algorithm>

#include "cvt/cell_islands.hpp"
#include "cvtmesh/rvd.hpp"
#include "geometry/manifold_defects.hpp"
#include "geometry/surface_projector.hpp"
#include "voronoi/dual_triangle.hpp"
#include "voronoi/piece_euler.hpp"

namespace cvtmesh {

namespace {

Triangle rotated_to_smallest(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// Where split cells may cause the defects of `triangles` (in seed ids): the balls around each
// triangle's centroid whose radius is kIslandReach times its longest edge. A thin part's cells,
// split around it, cause defects a few cells along it (camel.off at 2k: its tail's, 0.06 from a
// non-manifold edge that 5 rounds of refinement alone did not mend, 2 edge lengths). Split cells
// farther away are left alone: a cell at a concave crease is often in two pieces with a
// triangulation right all the same, and a seed in every such cell only makes more (3torus.off at
// 2k, adaptive: 74 for 3 defective triangles, 245 seeds added in all against 5).
class DefectBalls {
 public:
  DefectBalls(const std::vector<Vec3>& seeds, const std::vector<Triangle>& triangles) {
    for (const Triangle& t : triangles) {
      const Vec3 &a = seeds[t[0]], &b = seeds[t[1]], &c = seeds[t[2]];
      const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
      balls_.push_back({(1.0 / 3) * (a + b + c), kIslandReach * longest});
    }
  }
  bool contains(const Vec3& p) const {
    return std::any_of(balls_.begin(), balls_.end(),
                       [&](const Ball& b) { return distance(p, b.centre) <= b.radius; });
  }

 private:
  static constexpr double kIslandReach = 4;
  struct Ball {
    Vec3 centre;
    double radius;
  };
  std::vector<Ball> balls_;
};

}  // namespace

OutputDefects find_output_defects(const TriangleMesh& rdt, const std::vector<bool>& may_bound,
                                  bool folds, const std::vector<bool>& may_branch) {
  const ManifoldDefects m =
      find_manifold_defects(rdt.vertices.size(), rdt.triangles, may_bound, folds, may_branch);
  OutputDefects d{
      {}, m.nonmanifold_edges, m.nonmanifold_vertices, m.stray_boundary_edges, m.folded_edges};
  for (std::size_t t = 0; t < rdt.triangles.size(); ++t)
    if (m.triangle[t]) d.triangles.push_back(rdt.triangles[t]);
  return d;
}

DefectSeeds defect_seeds(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                         const std::vector<Triangle>& triangles, bool check_discs,
                         SplitCells split_cells, const SurfaceProjector* crossings,
                         ExtractionMemory& memory) {
  const bool exhaustive = split_cells == SplitCells::at_centroids_everywhere;
  const bool everywhere = split_cells != SplitCells::near_triangles;
  // The cells' pieces and where the Voronoi edges cross the surface are the triangulation's: for
  // the seeds that the last extraction triangulated, as here, the traversal clips nothing and
  // hands the triangulation nothing. Only the pieces' shapes, the first time they are wanted,
  // take every polygon again.
  const RestrictedVoronoiDiagram rvd(surface, seeds, memory.traversal);
  memory.nerve.for_diagram(rvd);
  std::vector<PolygonSink*> sinks{&memory.nerve, &memory.stop};
  // The pieces' shapes (Euler characteristics, farthest vertices), where wanted; once made, kept
  // up by every traversal.
  const bool shaped = check_discs || !exhaustive;
  if (shaped) memory.make_piece_shapes();
  if (memory.piece_shapes) {
    memory.piece_shapes->for_diagram(rvd);
    sinks.push_back(&*memory.piece_shapes);
  }
  rvd.traverse(sinks, memory.traversal);
  const CellPieceCollector& pieces = memory.nerve.pieces();
  DefectSeeds out;
  const DefectBalls at_defects(seeds, triangles);
  const std::vector<PieceShape> shapes =
      shaped ? memory.piece_shapes->shapes(pieces) : std::vector<PieceShape>{};
  // A piece that reaches a crossing of the input's sheets is left alone, as no seed splits it
  // off: the sheets cross within the piece's reach from its seed.
  const auto at_crossing = [&](const Vec3& p, Index seed) {
    return crossings && crossings->distance_to(p) <= distance(p, seeds[seed]);
  };
  for (const CellIsland& island : cell_islands(pieces))
    if ((everywhere || at_defects.contains(island.centroid)) &&
        !at_crossing(island.centroid, island.seed))
      out.islands.push_back(exhaustive ? island.centroid : shapes[island.piece].farthest);
  if (check_discs) {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const CellPiece& piece = pieces.pieces()[i];
      if (shapes[i].euler != 1 && piece.area > 0 && !at_crossing(shapes[i].farthest, piece.seed))
        out.islands.push_back(shapes[i].farthest);
    }
  }
  std::vector<Triangle> wanted = triangles;
  for (Triangle& t : wanted) t = rotated_to_smallest(t);
  std::sort(wanted.begin(), wanted.end());
  std::vector<Vec3>& kept = out.refinement;
  std::vector<double> radius;
  for (const auto& c : memory.nerve.crossings(wanted)) {
    // A crossing at a seed (radius 0) would duplicate it; one near a point kept already adds
    // nothing the other does not.
    if (!(c.radius > 0)) continue;
    bool near = false;
    for (std::size_t k = 0; k < kept.size() && !near; ++k)
      near = distance(kept[k], c.point) < 0.5 * std::max(c.radius, radius[k]);
    if (near) continue;
    kept.push_back(c.point);
    radius.push_back(c.radius);
  }
  return out;
}

}  // namespace cvtmesh
