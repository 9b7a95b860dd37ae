// Tolerant comparisons for doctest checks, the tolerance stated in the quantity's own terms.
//
// doctest::Approx(x) passes when |a - x| < epsilon * (scale + max(|a|, |x|)), scale = 1 unless set: the 1 is an
// absolute floor in whatever unit the quantity has, so for metres, radians or creepages ~1e-3 the check accepts
// anything below epsilon, even 0. Use these instead:
//   CHECK(a == within_rel(x, 1e-9));      |a - x| <= 1e-9 |x|    (x not 0: the tolerance scales with it)
//   CHECK(a == within_abs(x, 1e-12));     |a - x| <= 1e-12       (in x's unit; for x that may be 0)
// The test "lint: no bare doctest Approx" (tests/lint/approx.cmake) refuses an Approx( in tests/ without .scale( unless
// its line says `// approx: unit scale` (the quantity is of order 1, so the floor is what was meant).
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <ostream>

namespace wrc::test {

struct Within {
  double expected;
  double tolerance;  // relative (of |expected|) or absolute, by `relative`
  bool relative;

  double bound() const { return relative ? tolerance * std::abs(expected) : tolerance; }
  friend bool operator==(double a, const Within& w) { return std::abs(a - w.expected) <= w.bound(); }
  friend bool operator==(const Within& w, double a) { return a == w; }
  friend bool operator!=(double a, const Within& w) { return !(a == w); }
  friend bool operator!=(const Within& w, double a) { return !(a == w); }
  friend std::ostream& operator<<(std::ostream& out, const Within& w) {
    out << doctest::toString(w.expected) << " +- " << doctest::toString(w.bound());
    if (w.relative) return out << " (relative " << doctest::toString(w.tolerance) << ")";
    return out << " (absolute)";
  }
};

// Within rtol of x, relative to |x|; x must not be 0 (then only a == 0 passes: use within_abs).
inline Within within_rel(double x, double rtol) { return {x, rtol, true}; }
// Within tol of x, tol in x's unit.
inline Within within_abs(double x, double tol) { return {x, tol, false}; }

}  // namespace wrc::test
