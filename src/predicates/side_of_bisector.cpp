// Derivation (translated so that the cell's seed x_i is the origin: Q = q − x_i, J = x_j − x_i,
// K = x_k − x_i, L = x_l − x_i). With power-diagram weights w_s, the side of v is the sign of
//   d = π_i(v) − π_j(v) = 2 v·J − J·J − w_i + w_j,         d < 0: v is closer to x_i,
// and bisector (i, k) is the plane 2 v·K = K·K + w_i − w_k.
//   A, v = q:                      d = J·(2Q − J) + (w_j − w_i).
//   B, v = [q1 q2] ∩ bisector k:   v = Q1 + t (Q2 − Q1), t = (N + w_i − w_k)/D,
//        N = K·K − 2 Q1·K, D = 2 (Q2 − Q1)·K, E = 2 (Q2 − Q1)·J:
//        D·d = [2 (Q1·J) D + N E − (J·J) D] + (w_i − w_k) E + (w_j − w_i) D.
//   C, v = facet ∩ bisectors k, l: rows r0 = 2K, r1 = 2L, r2 = n (facet normal),
//        b = (K·K, L·L, n·Q0), D = det(r0, r1, r2), G = 2J, u_r = det(rows, row r ← G):
//        D·d = [Σ b_r u_r − (J·J) D] + (w_i − w_k) u0 + (w_i − w_l) u1 + (w_j − w_i) D.
// The bracket is the unperturbed value (degree 2, 4 over 2, 6 over 4 in the inputs, paper §3.4).
// With w_s = ε^(s+1), when it is exactly zero the sign is that of the coefficient of the
// lowest-index seed whose coefficient is not zero (the coefficient of w_j is ±D ≠ 0, so one is).
#include "predicates/side_of_bisector.hpp"

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "predicates/bounded_double.hpp"

namespace cvtmesh::predicates {

namespace {

template <class NT>
struct V {
  NT x, y, z;
};

template <class NT>
V<NT> diff(const Vec3& a, const Vec3& b) {
  return {NT(a.x) - NT(b.x), NT(a.y) - NT(b.y), NT(a.z) - NT(b.z)};
}
template <class NT>
V<NT> operator-(const V<NT>& a, const V<NT>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class NT>
V<NT> operator+(const V<NT>& a, const V<NT>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class NT>
V<NT> scaled(const NT& s, const V<NT>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class NT>
NT dot(const V<NT>& a, const V<NT>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class NT>
V<NT> cross(const V<NT>& a, const V<NT>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class NT>
NT det(const V<NT>& a, const V<NT>& b, const V<NT>& c) {
  return dot(a, cross(b, c));
}

// Which planes define a vertex, decoded from its two symbols.
struct Definition {
  int bisectors;       // 0: type A, 1: B, 2: C
  int corner = -1;     // A: the input corner
  int edge = -1;       // B: the input edge, from corner edge to corner edge+1
  Index k = 0, l = 0;  // B: k; C: k and l
};

int edge_of(std::int32_t symbol) {
  return -symbol - 1;
}

Definition define(const RvdVertex& v) {
  const auto [s0, s1] = v.symbols;
  if (s0 < 0 && s1 < 0) {
    const int e0 = edge_of(s0), e1 = edge_of(s1);
    return {0, (e0 + 1) % 3 == e1 ? e1 : e0};
  }
  if (s0 >= 0 && s1 >= 0) return {2, -1, -1, static_cast<Index>(s0), static_cast<Index>(s1)};
  return {1, -1, edge_of(std::min(s0, s1)), static_cast<Index>(std::max(s0, s1))};
}

// The unperturbed value of D·d and the denominator D (1 for type A), and the coefficients of
// the perturbation weights, as (seed, coefficient) pairs.
template <class NT>
struct Expansion {
  NT value, denominator;
  std::array<std::pair<Index, NT>, 4> weights;
  int weight_count = 0;
};

template <class NT>
Expansion<NT> expand(const ClipFrame& f, const Definition& def, Index j) {
  const Vec3& xi = f.seeds[f.cell];
  const V<NT> J = diff<NT>(f.seeds[j], xi);
  const NT JJ = dot(J, J);
  Expansion<NT> e;
  if (def.bisectors == 0) {
    const V<NT> Q = diff<NT>(f.corners[def.corner], xi);
    e.value = dot(J, Q + Q - J);
    e.denominator = NT(1);
    e.weights = {{{f.cell, NT(-1)}, {j, NT(1)}}};
    e.weight_count = 2;
  } else if (def.bisectors == 1) {
    const V<NT> Q1 = diff<NT>(f.corners[def.edge], xi);
    const V<NT> Q2 = diff<NT>(f.corners[(def.edge + 1) % 3], xi);
    const V<NT> K = diff<NT>(f.seeds[def.k], xi);
    const V<NT> edge = Q2 - Q1;
    const NT two(2);
    const NT N = dot(K, K) - two * dot(Q1, K);
    const NT D = two * dot(edge, K);
    const NT E = two * dot(edge, J);
    e.value = two * dot(Q1, J) * D + N * E - JJ * D;
    e.denominator = D;
    e.weights = {{{f.cell, E - D}, {def.k, NT(0) - E}, {j, D}}};
    e.weight_count = 3;
  } else {
    const V<NT> K = diff<NT>(f.seeds[def.k], xi);
    const V<NT> L = diff<NT>(f.seeds[def.l], xi);
    const V<NT> n =
        cross(diff<NT>(f.corners[1], f.corners[0]), diff<NT>(f.corners[2], f.corners[0]));
    const V<NT> Q0 = diff<NT>(f.corners[0], xi);
    const NT two(2);
    const V<NT> r0 = scaled(two, K), r1 = scaled(two, L), G = scaled(two, J);
    const NT D = det(r0, r1, n);
    const NT u0 = det(G, r1, n), u1 = det(r0, G, n), u2 = det(r0, r1, G);
    e.value = dot(K, K) * u0 + dot(L, L) * u1 + dot(n, Q0) * u2 - JJ * D;
    e.denominator = D;
    e.weights = {{{f.cell, u0 + u1 - D}, {def.k, NT(0) - u0}, {def.l, NT(0) - u1}, {j, D}}};
    e.weight_count = 4;
  }
  return e;
}

int sign_of(const CGAL::Mpzf& x) {
  return static_cast<int>(x.sign());
}

// Exact sign of d, with ties broken by the perturbation.
int exact_side(const ClipFrame& f, const Definition& def, Index j, PredicateCounters& counters) {
  ++counters.exact_fallbacks;
  Expansion<CGAL::Mpzf> e = expand<CGAL::Mpzf>(f, def, j);
  const int denominator = sign_of(e.denominator);
  assert(denominator != 0);
  if (const int s = sign_of(e.value); s != 0) return s * denominator;
  ++counters.perturbed_ties;
  // The nonzero coefficient of the lowest seed index decides.
  int decider = -1;
  for (int w = 0; w < e.weight_count; ++w)
    if (sign_of(e.weights[w].second) != 0 &&
        (decider < 0 || e.weights[w].first < e.weights[decider].first))
      decider = w;
  if (decider >= 0) return sign_of(e.weights[decider].second) * denominator;
  assert(false && "perturbation left a tie");
  return 1;
}

// Coordinatewise absolute value, for the static error bounds below.
Vec3 abs(const Vec3& w) {
  return {std::abs(w.x), std::abs(w.y), std::abs(w.z)};
}

}  // namespace

bool closer_to_cell_past_filter(const ClipFrame& f, const RvdVertex& v, Index j,
                                PredicateCounters& counters) {
  // Filter 2: the symbolic formula in bounded doubles.
  const Definition def = define(v);
  if (def.bisectors > 0) {
    const Expansion<BoundedDouble> e = expand<BoundedDouble>(f, def, j);
    const int num = e.value.certain_sign(), den = e.denominator.certain_sign();
    if (num != 0 && den != 0) return num * den < 0;
  }
  return exact_side(f, def, j, counters) < 0;
}

namespace {

// The error bound of q, the rounded N / D, from the bounds of N and D plus q's own rounding;
// infinite when D's bound reaches 0 (nearly parallel planes, see bisector_crossing).
double quotient_error(double q, double N, double error_N, double D, double error_D) {
  const double margin = std::abs(D) - error_D;
  return margin > 0 ? (std::abs(N) * error_D + std::abs(D) * error_N) / (std::abs(D) * margin) +
                          BoundedDouble::kU * std::abs(q)
                    : std::numeric_limits<double>::infinity();
}

// Whether a sum of products of absolute values (aN, aD below) is small enough that a product in
// it may have underflowed (under 2^-1022 a double keeps fewer digits): the bounds count relative
// roundings only, and an underflow's absolute error, divided by a small denominator, may exceed
// them by far. Such a vertex gets an infinite bound, so that every predicate on it goes to exact
// arithmetic. 2^-800 leaves room for factors up to 2^200 after the smallest product. Reached only
// far below unit size (the remesher works at unit size): the RVD of a surface scaled by 2^-250
// had cells other than the unit surface's (Rvd.ScaledByAPowerOfTwoGivesTheSameCells).
bool may_underflow(double magnitude_sum) {
  return magnitude_sum != 0 && magnitude_sum < 0x1p-800;
}

// |a| × |b| with every minus a plus: a bound on the magnitude of each term of a cross product.
Vec3 cross_of_magnitudes(const Vec3& a, const Vec3& b) {
  return {a.y * b.z + a.z * b.y, a.z * b.x + a.x * b.z, a.x * b.y + a.y * b.x};
}

// Position and error bound of a type C vertex, where bisectors k and l cross the facet (rows
// r0 = 2K, r1 = 2L, r2 = n of M, right side b = (K·K, L·L, n·Q0); cell seed at the origin):
// p = M⁻¹ b = N / D with N = (K·K)(r1×n) + (L·L)(n×r0) + (n·Q0)(r0×r1), D = r0·(r1×n). Plain
// doubles with a static bound, as for type B (BoundedDouble's bookkeeping made this a sixth of
// an RVD pass). N and D are polynomials in the inputs, each monomial picking up at most 15 (N)
// and 11 (D) roundings on its way: K, L, Q0 and the facet's edges 1; n = e1×e2 4; r1×n 7;
// r0×r1 4; K·K 5; n·Q0 8; each product of N 13, their sum 15; D 11. So |N − fl(N)| ≤ γ15 times
// the same sum of products taken over absolute values (Higham, "Accuracy and Stability of
// Numerical Algorithms", §3.1), which is evaluated alongside, itself rounded down by at most
// 15u: 16u covers both, and 12u for D. The quotient and the translation back add their own.
void facet_crossing(const ClipFrame& f, const Definition& def, RvdVertex& v) {
  constexpr double u = BoundedDouble::kU;
  const Vec3& xi = f.seeds[f.cell];
  const Vec3 K = f.seeds[def.k] - xi, L = f.seeds[def.l] - xi, Q0 = f.corners[0] - xi;
  const Vec3 e1 = f.corners[1] - f.corners[0], e2 = f.corners[2] - f.corners[0];
  const Vec3 n = cross(e1, e2), r0 = 2 * K, r1 = 2 * L;
  const Vec3 aK = abs(K), aL = abs(L), ar0 = 2 * aK, ar1 = 2 * aL;
  const Vec3 an = cross_of_magnitudes(abs(e1), abs(e2));
  const Vec3 c0 = cross(r1, n), c1 = cross(n, r0), c2 = cross(r0, r1);
  const Vec3 a0 = cross_of_magnitudes(ar1, an), a1 = cross_of_magnitudes(an, ar0),
             a2 = cross_of_magnitudes(ar0, ar1);
  const Vec3 N = dot(K, K) * c0 + dot(L, L) * c1 + dot(n, Q0) * c2;
  const Vec3 aN = dot(aK, aK) * a0 + dot(aL, aL) * a1 + dot(an, abs(Q0)) * a2;
  const double D = dot(r0, c0), aD = dot(ar0, a0), error_D = 12 * u * aD;
  v.error = BoundedDouble::kTiny;
  std::array<double, 3> point{};
  for (int c = 0; c < 3; ++c) {
    const double q = N[c] / D;
    const double error_q = quotient_error(q, N[c], 16 * u * aN[c], D, error_D);
    point[c] = q + xi[c];
    v.error = std::max(v.error, (error_q + u * std::abs(point[c])) * (1 + 4 * u));
  }
  v.point = {point[0], point[1], point[2]};
  if (may_underflow(aN.x) || may_underflow(aN.y) || may_underflow(aN.z) || may_underflow(aD))
    v.error = std::numeric_limits<double>::infinity();
}

// Position and error bound of a type B vertex, q1 + t (q2 − q1) with t = N/D, N = K·K − 2 Q1·K,
// D = 2 (q2 − q1)·K (K = x_k − x_i, Q1 = q1 − x_i): the most frequent construction of the RVD,
// so in plain doubles with a static bound rather than BoundedDouble. With u the unit roundoff:
// N's terms are products of two rounded differences, summed (≤ 8u over their absolute sum, 9u
// taken); D's likewise (≤ 5u, 6u taken); the quotient's bound follows from those of N and D
// plus its own rounding; each coordinate then adds the roundings of t·e_c and of the sum.
// A denominator within its own error bound gives an infinite bound (see bisector_crossing).
void edge_crossing(const ClipFrame& f, const Definition& def, RvdVertex& v) {
  constexpr double u = BoundedDouble::kU;
  const Vec3& xi = f.seeds[f.cell];
  const Vec3& q1 = f.corners[def.edge];
  const Vec3 K = f.seeds[def.k] - xi, Q1 = q1 - xi, e = f.corners[(def.edge + 1) % 3] - q1;
  const Vec3 aK = abs(K), aQ1 = abs(Q1), ae = abs(e);
  const double N = dot(K, K) - 2 * dot(Q1, K), D = 2 * dot(e, K);
  // N and D over absolute values: their rounding errors are bounded relative to these.
  const double aN = dot(aK, aK) + 2 * dot(aQ1, aK), aD = 2 * dot(ae, aK);
  const double error_N = 9 * u * aN, error_D = 6 * u * aD;
  const double t = N / D;
  const double error_t = quotient_error(t, N, error_N, D, error_D);
  v.point = q1 + t * e;
  const Vec3 ap = abs(v.point);
  const double e_max = std::max({ae.x, ae.y, ae.z});
  const double p_max = std::max({ap.x, ap.y, ap.z});
  v.error = may_underflow(aN) || may_underflow(aD)
                ? std::numeric_limits<double>::infinity()
                : (error_t * (1 + 2 * u) + 2.01 * u * std::abs(t)) * e_max + 1.01 * u * p_max +
                      BoundedDouble::kTiny;
}

}  // namespace

std::int32_t common_symbol(const RvdVertex& a, const RvdVertex& b) {
  for (std::int32_t s : a.symbols)
    if (s == b.symbols[0] || s == b.symbols[1]) return s;
  assert(false && "consecutive polygon vertices share no plane");
  return a.symbols[0];
}

RvdVertex vertex_with_symbols(const ClipFrame& f, std::array<std::int32_t, 2> symbols) {
  RvdVertex v;
  v.symbols = symbols;
  const Definition def = define(v);
  if (def.bisectors == 0) return corner_vertex(f, def.corner);
  if (def.bisectors == 1)
    edge_crossing(f, def, v);
  else
    facet_crossing(f, def, v);
  return v;
}

RvdVertex bisector_crossing(const ClipFrame& f, const RvdVertex& a, const RvdVertex& b, Index j) {
  const std::int32_t shared = common_symbol(a, b), k = static_cast<std::int32_t>(j);
  // Two bisectors in a fixed order: their crossing, and its rounding, do not depend on which cut
  // first (the bisectors' order differs with the candidate lists, see NeighborCache).
  RvdVertex v =
      vertex_with_symbols(f, shared >= 0 ? std::array{std::min(shared, k), std::max(shared, k)}
                                         : std::array{shared, k});
  const Vec3& xi = f.seeds[f.cell];
  if (!std::isfinite(v.error) || !std::isfinite(v.point.x + v.point.y + v.point.z)) {
    // Nearly parallel planes: the formula is ill-conditioned. Interpolate along the segment
    // where the (approximate) side function changes sign; this position serves integration
    // only, and the infinite bound sends every predicate on this vertex to exact arithmetic.
    const Vec3& xj = f.seeds[j];
    auto side = [&](const Vec3& q) { return dot(xj - xi, (q - xi) + (q - xj)); };
    const double da = side(a.point), db = side(b.point);
    const double t = da == db ? 0.5 : std::clamp(da / (da - db), 0.0, 1.0);
    v.point = a.point + t * (b.point - a.point);
    v.error = std::numeric_limits<double>::infinity();
  }
  return v;
}

}  // namespace cvtmesh::predicates
