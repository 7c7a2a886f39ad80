// Where the restricted Delaunay triangulation fails the topological ball property (paper §2,
// Theorem 1), seen on the triangulation itself: an edge with three or more triangles (a Voronoi
// face meeting the surface in several arcs), a vertex whose triangles form several fans (a cell
// that is not a disc), a boundary edge where the input has none (a Voronoi edge that misses the
// surface where it should cross it), two triangles that use an edge the same way (a fold). A cell
// in several pieces (cell_islands) shows up as some of these, but many of these come from cells
// in one piece, so the triangulation is what topology control checks.
#pragma once

#include <vector>

#include "cvt/extraction_memory.hpp"
#include "cvtmesh/mesh.hpp"
#include "cvtmesh/rvd.hpp"

namespace cvtmesh {
class SurfaceProjector;
}

namespace cvtmesh {

struct OutputDefects {
  std::vector<Triangle> triangles;  // every triangle at a defect, as in the triangulation
  std::size_t nonmanifold_edges = 0, nonmanifold_vertices = 0;
  std::size_t stray_boundary_edges = 0;  // boundary edges with an end not allowed on a boundary
  std::size_t folded_edges = 0;          // edges that two triangles use in the same direction

  bool empty() const { return triangles.empty(); }
};

// The defects of `rdt` (vertices: the seeds, by id). A boundary edge is a defect unless both its
// ends have may_bound set (seeds on the input's boundary curves), an edge of three or more
// triangles unless both have may_branch set (seeds on the input's own non-manifold curves; empty:
// none). Folds count only with `folds` (a non-orientable input has them wherever its output
// closes up).
OutputDefects find_output_defects(const TriangleMesh& rdt, const std::vector<bool>& may_bound,
                                  bool folds = true, const std::vector<bool>& may_branch = {});

// Where topology control adds seeds, from one traversal of the seeds' RVD:
struct DefectSeeds {
  // for the pieces of a cell but its largest (cell_islands), and for each piece that is not a disc
  // (an annulus around a handle or a hole narrower than the spacing, a whole closed component in
  // one cell: PieceEulerCollector), a point that the new seed splits them at
  std::vector<Vec3> islands;
  // refinement points for the defective triangles (Boissonnat-Oudot / Cheng-Dey-Ramos Delaunay
  // refinement, the terminating step the paper's §4.4 points to): the points where each
  // triangle's dual Voronoi edge crosses the surface, the centres of its surface Delaunay balls.
  // Each is farther from every seed than the ball's radius, so inserting it refines the sampling
  // where the ball property fails. Points within half a ball radius of one kept earlier are
  // dropped.
  std::vector<Vec3> refinement;
};
// In traversal order: independent of the thread count. `triangles` are in seed ids. Pieces are
// checked for being discs only with `check_discs` (for a manifold surface: around a non-manifold
// input edge or vertex a piece is no surface, and its count says nothing); a piece that is not
// one gets a seed at its vertex farthest from its seed.
// Split cells get seeds in one of three ways:
// - at_centroids_everywhere, the paper's rule (§4.4): a seed at the centroid of every extra piece;
// - farthest_everywhere or near_triangles: a seed at each extra piece's vertex farthest from its
//   seed, everywhere or only near `triangles`. That vertex is as far from every other seed as
//   from its own, so a seed there keeps the spacing at the piece's reach, as Delaunay refinement
//   does, where a centroid can fall next to the seed and split again; and split cells far from
//   any defect, often right as they are (at concave creases), are left alone. At 2k on the 56
//   shared meshes (--seed 1, 2, 3) this added 1,659, 1,553 and 1,538 seeds where the paper's rule
//   in every round added 2,249, 4,101 and 2,303, and the quality bar of issue 20 was met on 43,
//   41 and 42 meshes against 42, 40 and 42. Where the defects persist, the paper's rule resolves
//   handles far finer than the spacing (femur.off at 1k) that the farthest vertices leave.
// No piece gets a seed where it reaches `crossings` (the input's triangles that cross another;
// null: none) within its reach from its seed.
// `memory` holds what the last extraction of `surface` left (ExtractionMemory), and gets this
// traversal.
enum class SplitCells { near_triangles, farthest_everywhere, at_centroids_everywhere };
DefectSeeds defect_seeds(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                         const std::vector<Triangle>& triangles, bool check_discs,
                         SplitCells split_cells, const SurfaceProjector* crossings,
                         ExtractionMemory& memory);

}  // namespace cvtmesh
