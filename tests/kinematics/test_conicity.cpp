// Equivalent conicity (kinematics/conicity.hpp) against references written here:
//  - pure cone pairs, centred and offset (wheels of different diameters): tan(gamma_e) = gamma at every amplitude,
//    by every method;
//  - a polynomial Δr = 2 g y + 2 c y^3: the integral method against the wavelength integral computed here by another
//    substitution (y = yhat sin(theta)) and Simpson's rule; harmonic linearisation, regression and the simple
//    quotient against their closed forms g + 3/4 c yhat^2, g + 3/5 c yhat^2, g + c yhat^2;
//  - an asymmetric nonlinear Δr: the integral method against a time integration (RK4) of Klingel's kinematic motion
//    d2y/dx2 = -Δr(y) / (2 e r0): its wavelength, turning points and amplitude;
//  - bad input: each a wrc::Error naming what is wrong.
#include "wrc/kinematics/conicity.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

using wrc::test::within_rel;
using namespace wrc;

namespace {

DeltaRFunction tabulate(const std::function<double(double)>& f, double from, double to, double step) {
  DeltaRFunction d;
  const int n = static_cast<int>(std::lround((to - from) / step));
  for (int i = 0; i <= n; ++i) {
    d.y.push_back(from + i * step);
    d.dr.push_back(f(d.y.back()));
  }
  return d;
}

ConicityOptions amplitudes(std::vector<double> yhat, ConicityMethod m = ConicityMethod::integral) {
  ConicityOptions o;
  o.yhat = std::move(yhat);
  o.method = m;
  return o;
}

// Linear interpolation of the table, written here for the time integration.
double lerp_table(const DeltaRFunction& d, double y) {
  std::size_t i = 0;
  while (i + 2 < d.y.size() && d.y[i + 1] < y) ++i;
  return d.dr[i] + (d.dr[i + 1] - d.dr[i]) * (y - d.y[i]) / (d.y[i + 1] - d.y[i]);
}

std::string error_of(const DeltaRFunction& d, const ConicityOptions& o) {
  try {
    equivalent_conicity(d, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("a pure cone pair: tan(gamma_e) = gamma at every amplitude, by every method, centred or offset") {
  for (double gamma : {0.025, 0.05, 0.2}) {
    for (double centre : {0.0, -1.5e-3, 2e-3}) {  // Δr(0) != 0: wheels of different diameters
      const double offset = -2 * gamma * centre;
      CAPTURE(gamma);
      CAPTURE(offset);
      const DeltaRFunction d = tabulate([&](double y) { return 2 * gamma * y + offset; }, -15e-3, 15e-3, 0.1e-3);
      for (auto m : {ConicityMethod::integral, ConicityMethod::harmonic, ConicityMethod::regression, ConicityMethod::simple}) {
        const ConicityResult r = equivalent_conicity(d, amplitudes({0.5e-3, 1e-3, 3e-3, 6e-3}, m));
        CHECK(r.centre == doctest::Approx(-offset / (2 * gamma)).epsilon(1e-12).scale(1e-3));
        for (std::size_t k = 0; k < r.yhat.size(); ++k) {
          CHECK(r.tan_gamma[k] == within_rel(gamma, 1e-9));
          CHECK(r.y_max[k] - r.y_min[k] == within_rel(2 * r.yhat[k], 1e-9));
          CHECK(0.5 * (r.y_max[k] + r.y_min[k]) == doctest::Approx(r.centre).scale(1e-3).epsilon(1e-9));
          // Klingel: lambda = 2 pi sqrt(e r0 / tan), e = 0.75 m, r0 = 0.45 m by default.
          CHECK(r.wavelength[k] == within_rel(2 * std::numbers::pi * std::sqrt(0.75 * 0.45 / gamma), 1e-9));
        }
      }
    }
  }
}

TEST_CASE("a polynomial Δr: each method against its reference computed here") {
  const double g = 0.08, c = 3000;  // 2 c y^3 is half of 2 g y at y = 3.65 mm
  const DeltaRFunction d = tabulate([&](double y) { return 2 * g * y + 2 * c * y * y * y; }, -10e-3, 10e-3, 0.01e-3);
  const std::vector<double> yhat{0.5e-3, 2e-3, 4e-3, 7e-3};
  // Integral method: G(y) = g y^2 + c y^4 / 2; with y = a sin(theta), G(a) - G(y) = cos^2(theta) (g a^2 + c a^4 (1 +
  // sin^2 theta) / 2), so I = integral_{-pi/2}^{pi/2} dtheta / sqrt(g + c a^2 (1 + sin^2 theta) / 2) and tan = pi^2/I^2.
  const ConicityResult r = equivalent_conicity(d, amplitudes(yhat));
  for (std::size_t k = 0; k < yhat.size(); ++k) {
    const double a = yhat[k], pi = std::numbers::pi;
    const int n = 2000;  // Simpson
    double I = 0;
    for (int i = 0; i <= n; ++i) {
      const double th = -pi / 2 + pi * i / n, s = std::sin(th);
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      I += w / std::sqrt(g + c * a * a * (1 + s * s) / 2);
    }
    I *= pi / n / 3;
    CAPTURE(a);
    CHECK(r.tan_gamma[k] == within_rel(pi * pi / (I * I), 2e-6));
    CHECK(r.y_min[k] == within_rel(-a, 1e-9));
  }
  const ConicityResult h = equivalent_conicity(d, amplitudes(yhat, ConicityMethod::harmonic));
  const ConicityResult q = equivalent_conicity(d, amplitudes(yhat, ConicityMethod::regression));
  const ConicityResult s = equivalent_conicity(d, amplitudes(yhat, ConicityMethod::simple));
  for (std::size_t k = 0; k < yhat.size(); ++k) {
    const double a = yhat[k];
    CAPTURE(a);
    CHECK(h.tan_gamma[k] == within_rel(g + 0.75 * c * a * a, 2e-6));
    CHECK(q.tan_gamma[k] == within_rel(g + 0.6 * c * a * a, 2e-6));
    CHECK(s.tan_gamma[k] == within_rel(g + c * a * a, 2e-6));
  }
}

TEST_CASE("the integral method against a time integration of Klingel's kinematic wheelset motion") {
  // An asymmetric, nonlinear Δr: offset (different diameters), a quadratic and a cubic term, a kink (a table on a
  // coarse 0.2 mm grid: linear between its points, as the engine reads it).
  const DeltaRFunction d = tabulate([](double y) { return 0.2e-3 + 0.3 * y + 40 * y * y + 4000 * y * y * y; }, -12e-3,
                                    12e-3, 0.2e-3);
  const double e = 0.7465, r0 = 0.46;
  ConicityOptions o = amplitudes({1e-3, 3e-3, 6e-3});
  o.r0 = r0;
  o.contact_distance = 2 * e;
  const ConicityResult r = equivalent_conicity(d, o);
  for (std::size_t k = 0; k < o.yhat.size(); ++k) {
    // RK4 in x from the upper turning point at rest (yaw 0), until the yaw angle psi = dy/dx returns to zero from
    // below twice: one period. The lower turning point is where it first does.
    auto acc = [&](double y) { return -lerp_table(d, y) / (2 * e * r0); };
    double y = r.y_max[k], psi = 0, x = 0, y_low = y;
    const double h = r.wavelength[k] / 20000;
    int turns = 0;
    double x_turn = 0;
    while (turns < 2 && x < 10 * r.wavelength[k]) {
      const double k1y = psi, k1p = acc(y);
      const double k2y = psi + 0.5 * h * k1p, k2p = acc(y + 0.5 * h * k1y);
      const double k3y = psi + 0.5 * h * k2p, k3p = acc(y + 0.5 * h * k2y);
      const double k4y = psi + h * k3p, k4p = acc(y + h * k3y);
      const double ny = y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y), np = psi + h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
      if ((psi < 0 && np >= 0) || (psi > 0 && np <= 0)) {  // a turning point inside the step: interpolate it
        const double f = psi / (psi - np);
        x_turn = x + f * h;
        if (++turns == 1) y_low = y + f * (ny - y);
      }
      y = ny;
      psi = np;
      x += h;
    }
    CAPTURE(o.yhat[k]);
    REQUIRE(turns == 2);
    const double lambda = x_turn;
    CHECK(lambda == within_rel(r.wavelength[k], 1e-6));
    CHECK(y_low == within_rel(r.y_min[k], 1e-6));
    CHECK(0.5 * (r.y_max[k] - y_low) == within_rel(o.yhat[k], 1e-6));
    CHECK(r.tan_gamma[k] == within_rel(e * r0 * std::pow(2 * std::numbers::pi / lambda, 2), 2e-6));
  }
}

TEST_CASE("bad Δr tables and amplitudes are errors that say what is wrong") {
  const DeltaRFunction good = tabulate([](double y) { return 0.3 * y; }, -5e-3, 5e-3, 0.5e-3);
  auto with = [&](auto change) {
    DeltaRFunction d = good;
    change(d);
    return d;
  };
  const ConicityOptions o = amplitudes({2e-3});
  CHECK(error_of(with([](DeltaRFunction& d) { std::swap(d.y[3], d.y[4]); }), o).find("y must increase strictly") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { d.dr[5] = std::nan(""); }), o).find("the 6th point is not a finite number") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { for (double& v : d.y) v *= 1e3; }), o).find("mm given?") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { for (double& v : d.dr) v *= 1e3; }), o).find("mm given?") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { for (double& v : d.dr) v = -v; }), o).find("not self-centring") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { for (double& v : d.dr) v = std::abs(v) + 1e-4; }), o).find("does not change sign") != std::string::npos);
  CHECK(error_of(with([](DeltaRFunction& d) { d.dr.pop_back(); }), o).find("dr has") != std::string::npos);
  CHECK(error_of(good, amplitudes({6e-3})).find("leaves the Δr table") != std::string::npos);
  CHECK(error_of(good, amplitudes({6e-3}, ConicityMethod::regression)).find("beyond the table") != std::string::npos);
  CHECK(error_of(good, amplitudes({-1e-3})).find("positive number of metres") != std::string::npos);
  CHECK(error_of(good, amplitudes({})).find("at least one amplitude") != std::string::npos);
  // Flange contact marked inside the motion.
  DeltaRFunction f = good;
  f.flange.assign(f.y.size(), false);
  f.flange.back() = f.flange[f.y.size() - 2] = true;  // y = 4.5 and 5 mm
  CHECK_NOTHROW(equivalent_conicity(f, amplitudes({4e-3})));
  CHECK(error_of(f, amplitudes({4.6e-3})).find("flange contact inside the motion") != std::string::npos);
  // A Δr with three zeros (negative conicity at the centre, as on some hollow-worn pairs): the wheelset rests off
  // the centre, at a rising zero (+-3.54 mm); a small motion oscillates about it.
  const DeltaRFunction w = tabulate([](double y) { return -0.1 * y + 8000 * y * y * y; }, -10e-3, 10e-3, 0.1e-3);
  const ConicityResult rw = equivalent_conicity(w, amplitudes({0.5e-3}));
  CHECK(std::abs(rw.centre) == within_rel(std::sqrt(0.1 / 8000), 1e-3));
  CHECK(rw.y_max[0] - rw.y_min[0] == within_rel(1e-3, 1e-9));
}
