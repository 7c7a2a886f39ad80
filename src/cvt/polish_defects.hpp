// Local Lloyd polishing of the output (paper §2.2's Lloyd step, applied to a few seeds): the
// global optimization stops at an iteration cap with the tessellation nearly, not exactly,
// centroidal, and its few badly shaped triangles sit where two seeds are still too close (a
// 5-7 valence pair). Lloyd steps on the seeds around them, with all others fixed, finish the
// convergence there; each step costs an RVD over only the input triangles those cells cover.
#pragma once

#include <vector>

#include "cvt/cvt_objective.hpp"
#include "cvt/extraction_memory.hpp"

namespace cvtmesh {

struct PolishSettings {
  int rounds = 3;  // rounds of (find defects, Lloyd steps around them); 0: no polishing
  int steps = 10;  // Lloyd steps per round, at most (fewer once the defects are gone)
  // Seeds from this id on do not move: refinement points that topology control puts at details
  // finer than the spacing, which Lloyd steps would pull back out of them.
  std::size_t pinned_from = static_cast<std::size_t>(-1);
  // Seed ids (sorted): only the defects within kAroundRings rings of them in the triangulation
  // are polished; empty: all of them.
  std::vector<Index> around = {};
};

struct PolishedOutput {
  // The restricted Delaunay triangulation of the final seeds, one vertex per piece of each cell
  // (MultiNerveBuilder): the seeds by id, then the cells' far pieces.
  TriangleMesh mesh;
  std::vector<Index> vertex_seed;  // per vertex of `mesh`, the seed whose cell it stands for
  int rounds = 0;                  // rounds that found defects and moved seeds
  std::size_t defects = 0;         // defective triangles found in the first round
};

// Whether the optimizer's output is polished as soon as it is extracted: not under a density.
// There its badly shaped triangles are where the valences change with the size (the 5-7 pairs
// the grading needs), not unconverged seeds: Lloyd steps barely move them (bull.off adaptive at
// 2k: 227 defects, 180 after 30 steps over 1,410 of its 2,000 seeds) and the last step's flips
// and moves mend them on the mesh. Topology control polishes it before it adds seeds
// (mend_topology).
inline bool polished_at_once(const CvtObjective& objective) {
  return objective.density() == nullptr;
}

// Triangulates the seeds (restricted Delaunay, multi-nerve) and, while it has defective triangles,
// rounds are left and the last round did not already move every seed around them, moves the surface
// seeds around them by local Lloyd steps and triangulates again. Moved seeds stay on the
// surface (objective.constrained); feature seeds do not move. The result does not depend on
// the thread count. Each triangulation clips, and collects, only where the last one over
// `surface` with `memory` changed (ExtractionMemory), and leaves its own for the next.
// `polished`, if given, holds the seeds of an output polished before: a defect whose three seeds
// are all there as they were then was polished then, and is not polished again (topology
// control's rounds change a few seeds).
PolishedOutput extract_polished(const TriangleMesh& surface, std::vector<Vec3>& seeds,
                                const CvtObjective& objective, const PolishSettings& settings,
                                ExtractionMemory& memory,
                                const std::vector<Vec3>* polished = nullptr);

}  // namespace cvtmesh
