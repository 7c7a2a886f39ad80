// A double with a certified bound on its distance to the exact value of the expression that
// produced it: running error analysis (Higham, "Accuracy and Stability of Numerical
// Algorithms", §3.3). Each operation adds its own rounding error, u·|result|, to the bounds
// propagated from its operands. This is the floating-point filter of the exact predicates.
#pragma once

#include <cmath>
#include <limits>

namespace cvtmesh::predicates {

struct BoundedDouble {
  // Unit roundoff 2^-53, inflated so that the rounding of the bound's own arithmetic (a few
  // ulps over the few dozen operations of a predicate) is covered too.
  static constexpr double kU = 1.001 * 0x1p-53;
  // Absolute slack for underflow: below this, relative bounds say nothing.
  static constexpr double kTiny = 0x1p-960;

  double value = 0, error = 0;

  BoundedDouble() = default;
  BoundedDouble(double exact) : value(exact), error(0) {}  // NOLINT: inputs are exact
  BoundedDouble(double v, double e) : value(v), error(e) {}

  friend BoundedDouble operator+(const BoundedDouble& a, const BoundedDouble& b) {
    const double s = a.value + b.value;
    return {s, a.error + b.error + kU * std::abs(s)};
  }
  friend BoundedDouble operator-(const BoundedDouble& a, const BoundedDouble& b) {
    const double s = a.value - b.value;
    return {s, a.error + b.error + kU * std::abs(s)};
  }
  friend BoundedDouble operator*(const BoundedDouble& a, const BoundedDouble& b) {
    const double p = a.value * b.value;
    return {p, std::abs(a.value) * b.error + std::abs(b.value) * a.error + a.error * b.error +
                   kU * std::abs(p)};
  }
  // a / b, with an infinite bound when b's interval contains 0.
  friend BoundedDouble operator/(const BoundedDouble& a, const BoundedDouble& b) {
    const double q = a.value / b.value;
    const double margin = std::abs(b.value) - b.error;
    if (!(margin > 0)) return {q, std::numeric_limits<double>::infinity()};
    return {q, (std::abs(a.value) * b.error + std::abs(b.value) * a.error) /
                       (std::abs(b.value) * margin) +
                   kU * std::abs(q)};
  }

  // The sign of the exact value (-1, 0 unknown, +1): certain when |value| exceeds the bound.
  int certain_sign() const {
    const double bound = error * (1 + 1e-12) + kTiny;
    if (value > bound) return 1;
    if (value < -bound) return -1;
    return 0;
  }
};

}  // namespace cvtmesh::predicates
