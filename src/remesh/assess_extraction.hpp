// The check at the heart of topology control (paper §2, Theorem 1; §4.4): an extraction,
// finished as it would be returned, and where it fails the topological ball property: the
// feature links it cuts (a curve's 1D cell crossed by a third cell), the triangles at its
// defects (output_defects), and whether its topology is the input's, as it is or after the last
// step.
#pragma once

#include <tuple>
#include <vector>

#include "features/feature_seeds.hpp"
#include "remesh/output_defects.hpp"

namespace cvtmesh {

struct MendContext;
class InputCrossings;

// Where output boundary edges, and output edges of three or more triangles, may run: along the
// input's own boundary (edges of one triangle) and non-manifold edges (three or more), which its
// output keeps (issue 18). Per feature curve, whether it runs along such edges (a curve never
// leaves the edges it was traced along, so its first edge tells), and per input vertex, whether
// such an edge ends there.
struct SpecialEdges {
  std::vector<bool> boundary_curve, boundary_vertex, branch_curve, branch_vertex;
};

// From the input alone: found once for all the rounds. Empty vectors where the input has no
// boundary and no non-manifold edge (none is read then).
SpecialEdges special_edges(const MendContext& m);

// An extraction, finished as it would be returned, and what it lacks: the links it cuts that
// no well-shaped flip makes (left to the seeds), and whether its topology is the surface's.
// Finished means: the cut links flipped in where one edge flip makes them with no angle under
// 30°; the links still missing then flipped in with none under 15°; and corners left without a
// triangle at a boundary tip given theirs (close_corner_wedges).
struct Assessment {
  TriangleMesh finished;  // all the flips made, and the tips closed
  std::vector<FeatureLink> missing;
  bool topology_kept = true;
  OutputDefects defects;  // of `finished`, if its topology is not kept
  // Its topology kept, or given back by the last step (finish_manifold on a copy).
  bool rescued = true;
  // Where its topology is kept: its triangles that cross another away from where the input
  // crosses itself, if it does (crossings_of_its_own), once the folds that the finishing steps mend
  // before any sweep are mended (assess). Sheets closer than the spacing, or a tube narrower than
  // it, can give the input's topology with triangles that pass through each other (couplingdown.off
  // at 1k: 79 triangles in the narrow holes of its rim, in the first round that kept its topology).
  std::vector<Triangle> crossing;
  std::size_t links_flipped = 0, tips_closed = 0;
  // Better outputs compare greater: the input's topology, then fewer triangles at defects
  // (non-manifold edges and vertices, stray boundary edges, folds), then fewer crossing triangles
  // of its own, then more corners, then fewer
  // links missing, then the better worst triangle (Qmin: a seed that mends a link is worth it only
  // if it leaves better triangles than a flip).
  std::tuple<bool, std::ptrdiff_t, std::ptrdiff_t, std::size_t, std::ptrdiff_t, double> score;
};

// The extraction `rdt` of `seeds` (its vertices: the seeds by id, then the cells' far pieces).
// `crossings`: where the input crosses itself, searched once needed.
Assessment assess(const MendContext& m, const SpecialEdges& special, const TriangleMesh& rdt,
                  const std::vector<Vec3>& seeds, const SeedConstraints& constraints,
                  InputCrossings& crossings);

}  // namespace cvtmesh
