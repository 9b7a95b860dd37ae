// One-dimensional root finding shared by the solvers (the rigid contact, the equilibrium's fallbacks).
#pragma once

#include <algorithm>
#include <cmath>

namespace wrc {

// Root of f on a bracket [a, b] (f(a), f(b) of opposite signs) by the Illinois variant of regula falsi:
// superlinear on smooth functions, never leaves the bracket. Stops when |f| <= ftol, or when the bracket is no wider
// than xtol (a function known only to a resolution, e.g. an iterative solver's, may never reach ftol): `ok` says
// whether it did. Returns the point where |f| <= ftol, else the end of the last bracket with the smaller |f| as the
// method holds it (a kept end's value halved), which need not be the point f was called at last.
template <class F>
double bracketed_root(F&& f, double a, double b, double fa, double fb, double ftol, int max_iter, bool& ok,
                      double xtol = 0) {
  ok = false;
  int kept = 0;  // +1 / -1: which end was kept last (halve its value when kept twice)
  for (int it = 0; it < max_iter; ++it) {
    if (std::abs(b - a) <= xtol) {
      ok = true;
      break;
    }
    double x = b - fb * (b - a) / (fb - fa);
    if (!(x > std::min(a, b) && x < std::max(a, b))) x = 0.5 * (a + b);
    const double fx = f(x);
    if (std::abs(fx) <= ftol) {
      ok = true;
      return x;
    }
    if ((fx < 0) == (fb < 0)) {  // x replaces b, a is kept
      b = x;
      fb = fx;
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else {  // x replaces a... the bracket is now [b, x]
      a = b;
      fa = fb;
      b = x;
      fb = fx;
      kept = -1;
    }
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

}  // namespace wrc
