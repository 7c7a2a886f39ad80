// The exact side-of-bisector predicate of the RVD (paper §3.4) and the construction of new RVD
// vertices. Everything is decided on the vertices' symbolic definitions, never on rounded
// coordinates alone: a floating-point filter with certified error bounds first, then exact
// arithmetic (CGAL::Mpzf) when it cannot decide, then a symbolic perturbation for exact ties.
#pragma once

#include <array>
#include <cstddef>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh::predicates {

// What a predicate needs to know beyond the vertex: the input triangle being clipped, all
// seeds, and the seed i whose cell is being computed (bisector symbols are relative to it).
struct ClipFrame {
  std::array<Vec3, 3> corners;  // input triangle q0, q1, q2
  const Vec3* seeds;
  Index cell;
};

struct PredicateCounters {
  std::size_t predicates = 0, exact_fallbacks = 0, perturbed_ties = 0;
};

// True when v is strictly closer to seed frame.cell than to seed j, in the perturbed sense: each
// seed s carries an infinitesimal power-diagram weight ε^(s+1), so exact ties go to the seed of
// lower index and every answer is definite. j must not be one of v's bisector symbols.
bool closer_to_cell(const ClipFrame& frame, const RvdVertex& v, Index j,
                    PredicateCounters& counters);

// The vertex where bisector (cell, j) crosses the polygon edge [a, b], which it separates.
RvdVertex bisector_crossing(const ClipFrame& frame, const RvdVertex& a, const RvdVertex& b,
                            Index j);

// The symbol that consecutive polygon vertices a and b share: the plane of the side between them.
std::int32_t common_symbol(const RvdVertex& a, const RvdVertex& b);

// The RVD vertex at input corner k of the frame's triangle: its symbols name the two edges that
// meet there (edge e joins corners e and e + 1, symbol -e - 1). Inline, as every cell that clips a
// triangle starts from its three corners: called out of line, returning through memory, it was a
// tenth of the clipping's time (perf on BM_CvtPass).
inline RvdVertex corner_vertex(const ClipFrame& frame, int k) {
  return {frame.corners[k], 0.0, {-((k + 2) % 3) - 1, -k - 1}};
}

// The vertex of the frame's triangle and cell with these symbols, as corner_vertex or
// bisector_crossing makes it, bit for bit, except where bisector_crossing finds the formula
// ill-conditioned (its vertex then has an infinite error bound).
RvdVertex vertex_with_symbols(const ClipFrame& frame, std::array<std::int32_t, 2> symbols);

}  // namespace cvtmesh::predicates
