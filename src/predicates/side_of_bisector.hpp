// The exact side-of-bisector predicate of the RVD (paper §3.4) and the construction of new RVD
// vertices. Everything is decided on the vertices' symbolic definitions, never on rounded
// coordinates alone: a floating-point filter with certified error bounds first, then exact
// arithmetic (CGAL::Mpzf) when it cannot decide, then a symbolic perturbation for exact ties.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "cvtmesh/rvd.hpp"
#include "predicates/bounded_double.hpp"

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

// Filter 1 of closer_to_cell: the sign of d = J·((v − x_i) + (v − x_j)), J = x_j − x_i, on the
// vertex's rounded position, or 0 when its error bound cannot certify it. A static error bound in
// plain doubles, inline: it decides nearly every predicate of the RVD (BM_CvtPass 2-3% faster than
// with it called out of line). With u the unit roundoff and e the vertex's error per
// coordinate, each term J_c·s_c of the dot product is off by at most 6u·|J_c|(|v_c − x_ic| +
// |v_c − x_jc|) (roundings of J_c, the two differences, their sum, the product and the two
// additions), plus 2e·|J_c| from v itself; 8u instead of 6u covers the rounding of the bound's own
// arithmetic.
inline int rounded_side(const Vec3& xi, const Vec3& xj, const RvdVertex& v) {
  constexpr double u = BoundedDouble::kU;
  const Vec3 J = xj - xi, a = v.point - xi, b = v.point - xj;
  const double d = dot(J, a + b);
  const Vec3 aJ{std::abs(J.x), std::abs(J.y), std::abs(J.z)};
  const double spread = aJ.x * (std::abs(a.x) + std::abs(b.x)) +
                        aJ.y * (std::abs(a.y) + std::abs(b.y)) +
                        aJ.z * (std::abs(a.z) + std::abs(b.z));
  const double bound =
      8 * u * spread + 2 * (1 + 4 * u) * v.error * (aJ.x + aJ.y + aJ.z) + BoundedDouble::kTiny;
  if (d > bound) return 1;
  if (d < -bound) return -1;
  return 0;  // also when d or the bound is not finite
}

// closer_to_cell where rounded_side cannot decide: the symbolic formula in bounded doubles, then
// exact arithmetic, then the perturbation.
bool closer_to_cell_past_filter(const ClipFrame& frame, const RvdVertex& v, Index j,
                                PredicateCounters& counters);

// True when v is strictly closer to seed frame.cell than to seed j, in the perturbed sense: each
// seed s carries an infinitesimal power-diagram weight ε^(s+1), so exact ties go to the seed of
// lower index and every answer is definite. j must not be one of v's bisector symbols.
inline bool closer_to_cell(const ClipFrame& frame, const RvdVertex& v, Index j,
                           PredicateCounters& counters) {
  ++counters.predicates;
  if (const int s = rounded_side(frame.seeds[frame.cell], frame.seeds[j], v); s != 0) return s < 0;
  return closer_to_cell_past_filter(frame, v, j, counters);
}

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
