// A conformal area (wrc/wheelset/conformal.hpp) solved with half-space coefficients corrected for the turning of the
// surface, for tests and benchmarks: D_kl (n_k . n_l) instead of D_kl. A half-space pushes the far field of an
// element's pressure along that element's own normal; a body's far field is a translation, of which an element
// whose normal is turned by a sees cos(a). (Persson's exact kernel, tests/halfspace/persson_reference.hpp, has this
// cos factor on its log term.) With n = (0, n_y, n_z) per row, K p = f (n_y o I (n_y o p) + n_z o I (n_z o p)),
// f = 1/(pi E*): two convolutions per product, symmetric positive definite.
#pragma once

#include "wrc/halfspace/convolution.hpp"
#include "wrc/wheelset/contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wrc::test {

// The pressure (Pa, per element of its grid) of a solved conformal area re-solved with the corrected coefficients on
// the same grid and h: an active set (drop negative pressures, add penetrated elements) started from the engine's
// contact set, preconditioned CG inside (the grid's periodic circulant inverse of I, as the engine's solver).
inline std::vector<double> angle_corrected(const ContactModel& model, const PatchContact& pc) {
  const halfspace::Grid& g = pc.solution.grid;
  const ConformalSurface& surf = *pc.conformal;
  const int n = g.size();
  const double f = model.material().pair_compliance();
  const auto linear = model.solver().cache().get(g);
  const auto periodic = model.solver().cache().get(g, halfspace::InfluenceSpectrum::Kind::periodic);
  halfspace::ConvolutionWorkspace ws;
  std::vector<double> ny(n), nz(n), a(n), b(n);
  for (int k = 0; k < n; ++k) ny[k] = surf.normal_y[k / g.nx], nz[k] = surf.normal_z[k / g.nx];
  auto K = [&](const std::vector<double>& x, std::vector<double>& y) {
    for (int k = 0; k < n; ++k) a[k] = ny[k] * x[k], b[k] = nz[k] * x[k];
    halfspace::convolve(*linear, g, a.data(), a.data(), ws, f);
    halfspace::convolve(*linear, g, b.data(), b.data(), ws, f);
    y.resize(n);
    for (int k = 0; k < n; ++k) y[k] = ny[k] * a[k] + nz[k] * b[k];
  };
  const double hmax = *std::max_element(pc.h.begin(), pc.h.end()), tol = 1e-9 * hmax;
  std::vector<double> p = pc.solution.pressure, Kp, r(n), z(n), d(n), q;
  std::vector<char> active(n);
  for (int k = 0; k < n; ++k) active[k] = p[k] > 0;
  for (int round = 0; round < 100; ++round) {
    K(p, Kp);
    for (int k = 0; k < n; ++k) r[k] = active[k] ? pc.h[k] - Kp[k] : 0.0;
    auto precondition = [&] {
      halfspace::deconvolve(*periodic, g, r.data(), z.data(), ws, 1 / f);
      for (int k = 0; k < n; ++k) z[k] = active[k] ? z[k] : 0.0;
    };
    precondition();
    d = z;
    double rz = 0;
    for (int k = 0; k < n; ++k) rz += r[k] * z[k];
    for (int it = 0; it < 1000; ++it) {
      double rmax = 0;
      for (int k = 0; k < n; ++k) rmax = std::max(rmax, std::abs(r[k]));
      if (rmax < tol) break;
      K(d, q);
      double dq = 0;
      for (int k = 0; k < n; ++k) dq += active[k] ? d[k] * q[k] : 0.0;
      const double alpha = rz / dq;
      for (int k = 0; k < n; ++k)
        if (active[k]) p[k] += alpha * d[k], r[k] -= alpha * q[k];
      precondition();
      double rz_new = 0;
      for (int k = 0; k < n; ++k) rz_new += r[k] * z[k];
      for (int k = 0; k < n; ++k) d[k] = z[k] + rz_new / rz * d[k];
      rz = rz_new;
    }
    bool changed = false;
    for (int k = 0; k < n; ++k)
      if (active[k] && p[k] < 0) active[k] = 0, p[k] = 0, changed = true;
    if (!changed) {
      K(p, Kp);
      for (int k = 0; k < n; ++k)
        if (!active[k] && Kp[k] - pc.h[k] < -1e-6 * hmax) active[k] = 1, changed = true;
    }
    if (!changed) return p;
  }
  throw std::runtime_error("angle_corrected: the active set did not settle");
}

}  // namespace wrc::test
