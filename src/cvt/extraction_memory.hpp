// What one extraction leaves for the next over the same surface (issue 18: polishing and topology
// control work locally): the traversal's memory, and the sinks that keep, from one traversal to
// the next, the chunks that no changed seed reaches (PolygonSink::keeps_chunks). An extraction
// after a few seeds moved, came or went then clips, and collects, only around them; what stays
// global is each sink's end (the cells' pieces, the triangulation).
#pragma once

#include <memory>
#include <optional>

#include "cvt/cell_coverage.hpp"
#include "cvt/interrupt.hpp"
#include "cvtmesh/rvd.hpp"
#include "voronoi/multi_nerve.hpp"
#include "voronoi/piece_euler.hpp"

namespace cvtmesh {

struct ExtractionMemory {
  // `rings`: the surface's SideRings; `interrupt`: the remesh's. All three outlive the memory.
  ExtractionMemory(const TriangleMesh& surface, const SideRings& rings, const Interrupt& interrupt)
      : surface(surface), nerve(CellPieceCollector::Keeping{}, surface, &rings), stop(interrupt) {}
  // With the surface's SideRings found here.
  ExtractionMemory(const TriangleMesh& surface, const Interrupt& interrupt)
      : surface(surface),
        own_rings(std::make_unique<SideRings>(surface)),
        nerve(CellPieceCollector::Keeping{}, surface, own_rings.get()),
        stop(interrupt) {}

  const TriangleMesh& surface;
  std::unique_ptr<const SideRings> own_rings;  // where none were given
  TraversalMemory traversal;
  MultiNerveBuilder nerve;  // the restricted Delaunay triangulation (multi-nerve)
  CellCoverage coverage;    // for polishing's patches
  InterruptSink stop;
  // The shapes of the cells' pieces, for topology control (defect_seeds): made where it first
  // needs them, and kept up from then on by every traversal with the memory, so that no round
  // hands it every polygon again.
  std::optional<PieceEulerCollector> piece_shapes;
  void make_piece_shapes() {
    if (!piece_shapes) piece_shapes.emplace(PieceEulerCollector::Keeping{}, surface);
  }
};

}  // namespace cvtmesh
