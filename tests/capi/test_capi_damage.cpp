// The damage indices and the subsurface stresses through the C API (libwrc alone) on a circular Hertz contact (a
// cylinder wheel on a rail crowned with the wheel's radius), against references computed here: Hertz's force, Archard's
// k Fn |xi| / H in full sliding, and Hamilton's closed form (1983) for the stresses below a sliding spherical contact
// (tests/halfspace/hamilton_reference.hpp, no engine code).
#include "wrc/wrc.h"
#include "approx.hpp"
#include "halfspace/hamilton_reference.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using wrc::test::within_rel;

namespace {

std::string last() { return wrc_last_error(); }

constexpr double kE = 2.1e11, kNu = 0.3, kR = 0.45, kLoad = 100e3, kGaugeDepth = 0.2e-3;
const double kEstar = kE / (2 * (1 - kNu * kNu));
// Hertz, a sphere of radius R on a flat (A = B = 1 / (2 R)): contact radius, approach, peak pressure.
const double kA = std::cbrt(3 * kLoad * kR / (4 * kEstar));
const double kDelta = kA * kA / kR;
const double kP0 = 3 * kLoad / (2 * std::numbers::pi * kA * kA);

struct HertzPair {
  wrc_profile *wheel = nullptr, *rail = nullptr;
  wrc_wheelset* ws = nullptr;
  explicit HertzPair(int n) {
    std::vector<double> wy, wz, ry, rz;
    for (int k = 0; k <= 130; ++k) wy.push_back(-0.070 + k * 1e-3), wz.push_back(0.0);
    for (int k = -1250; k <= 1250; ++k) {
      const double y = k * 0.02e-3;
      ry.push_back(y), rz.push_back(std::sqrt(kR * kR - y * y) - kR);
    }
    REQUIRE_MESSAGE(wrc_profile_from_points("wheel", wy.data(), wz.data(), wy.size(), "cylinder", &wheel) == WRC_OK,
                    last());
    REQUIRE_MESSAGE(wrc_profile_from_points("rail", ry.data(), rz.data(), ry.size(), "crown", &rail) == WRC_OK, last());
    const double yg = std::sqrt(kR * kR - (kR - kGaugeDepth) * (kR - kGaugeDepth));
    const std::string options =
        fmt::format("radius={} cant=0 gauge_depth={} gauge={} E={} nu={} grid={} strategy=coarse+topology", kR,
                    kGaugeDepth, 2 * (0.75 - yg), kE, kNu, kA / n);
    REQUIRE_MESSAGE(wrc_wheelset_new(wheel, rail, options.c_str(), &ws) == WRC_OK, last());
  }
  ~HertzPair() {
    wrc_wheelset_free(ws);
    wrc_profile_free(wheel);
    wrc_profile_free(rail);
  }
};

double number(const wrc_result* r, const std::string& path) {
  double v = NAN;
  REQUIRE_MESSAGE(wrc_result_number(r, path.c_str(), &v) == WRC_OK, last());
  return v;
}

}  // namespace

TEST_CASE("wrc_contact: Archard in full sliding on a Hertzian patch, wear volume = k Fn |xi| / H within 1 %") {
  HertzPair h(10);
  // xi = 0.05: ~20 times the creepage at which the creep force saturates (adhesion 0 is checked).
  const double xi = 0.05, k = 1e-3, H = 2.5e9;
  wrc_result* r = nullptr;
  const std::string options = fmt::format("creepage.xi={} mu=0.3 wear.model=archard wear.k={} wear.hardness={}", xi, k, H);
  REQUIRE_MESSAGE(wrc_contact(h.ws, 0, -kDelta, 0, 0, options.c_str(), &r) == WRC_OK, last());
  CHECK(number(r, "left.patches.1.adhesion") == 0);
  CHECK(number(r, "left.patches.1.pressure_integral") == within_rel(kLoad, 0.01));
  const double volume = number(r, "left.patches.1.wear_volume");  // m^3 per metre rolled
  CHECK(volume == within_rel(k * kLoad * xi / H, 0.01));
  // T gamma in full sliding: mu Fn |xi|; and the spin term absent (phi = 0).
  CHECK(number(r, "left.patches.1.Tgamma") == within_rel(0.3 * kLoad * xi, 0.01));
  CHECK(number(r, "left.patches.1.Tgamma_spin") == number(r, "left.patches.1.Tgamma"));
  size_t n = 0;
  CHECK(wrc_result_numbers(r, "left.patches.1.wear_depth", nullptr, 0, &n) == WRC_TOO_SMALL);
  CHECK(n == static_cast<size_t>(number(r, "left.patches.1.grid.nx") * number(r, "left.patches.1.grid.ny")));
  MESSAGE(fmt::format("Archard, full sliding, 10 elements on a: {:.5e} m^3/m against k Fn |xi| / H = {:.5e} ({:+.3f} %)",
                      volume, k * kLoad * xi / H, (volume / (k * kLoad * xi / H) - 1) * 100));
  wrc_result_free(r);
  // A bad wear option names the key.
  CHECK(wrc_contact(h.ws, 0, -kDelta, 0, 0, "creepage.xi=0.05 mu=0.3 wear.model=archard wear.k=2", &r) == WRC_ERROR);
  CHECK(last().find("k = 2 must be in") != std::string::npos);
}

TEST_CASE("wrc_subsurface: Hertz circle against Johnson eq. 3.45, and sliding against Hamilton (1983)") {
  const int n = 10;  // elements on the contact radius
  HertzPair h(n);
  std::string z = "z=";
  for (int k = 1; k <= 400; ++k) z += fmt::format("{}{}", k > 1 ? "," : "", 0.0025 * k * kA);  // 0.0025 a .. 1.0 a
  // Frictionless: tau_1 max on the axis (Johnson: 0.31 p0 at 0.48 a for nu = 0.3), found here by a fine search.
  double tau_ref = 0, z_ref = 0;
  for (double t = 0.2; t < 1.0; t += 1e-5) {
    const double tau = 0.5 * std::abs(wrc::test::axis_srr(kNu, t) - wrc::test::axis_szz(t));
    if (tau > tau_ref) tau_ref = tau, z_ref = t;
  }
  CHECK(tau_ref == within_rel(0.31, 0.005));
  CHECK(z_ref == within_rel(0.48, 0.005));
  wrc_result *c = nullptr, *s = nullptr;
  REQUIRE_MESSAGE(wrc_contact(h.ws, 0, -kDelta, 0, 0, nullptr, &c) == WRC_OK, last());
  REQUIRE_MESSAGE(wrc_subsurface(c, "left.patches.1", (z + " fields=false").c_str(), &s) == WRC_OK, last());
  CHECK(number(s, "tau1_max") == within_rel(tau_ref * kP0, 0.02));
  CHECK(number(s, "tresca_max") == within_rel(2 * tau_ref * kP0, 0.02));
  CHECK(number(s, "tresca_max_z") == within_rel(z_ref * kA, 0.02));
  CHECK(number(s, "shakedown.load_factor") == within_rel(number(c, "left.patches.1.pmax") / 300e6, 0.001));
  wrc_result_free(s);
  // Bad calls name what is wrong.
  CHECK(wrc_subsurface(c, "left.patches.7", "z=1e-3", &s) == WRC_NOT_FOUND);
  CHECK(wrc_subsurface(c, "left.patches.1", "z=-1e-3", &s) == WRC_ERROR);
  CHECK(wrc_subsurface(c, "left.patches.1", nullptr, &s) == WRC_ERROR);
  CHECK(last().find("'z' is required") != std::string::npos);
  wrc_result_free(c);

  // Full sliding at mu = 0.3: the traction mu p along the sign of Fx. Hamilton's maximum of von Mises, searched on the
  // plane y = 0 every 0.0025 a in x and in depth, against the C call's over the grid and the depths.
  REQUIRE_MESSAGE(wrc_contact(h.ws, 0, -kDelta, 0, 0, "creepage.xi=0.05 mu=0.3", &c) == WRC_OK, last());
  const double mu = 0.3, sign = number(c, "left.patches.1.Fx") > 0 ? 1 : -1;
  double vm_ref = 0, x_ref = 0, zz_ref = 0;
  for (double t = 0.0025; t <= 1.0; t += 0.0025)
    for (double x = -1.25 + 0.00125; x < 1.25; x += 0.0025) {
      const double vm = wrc::test::von_mises_of(wrc::test::hamilton_normal(kNu, x, 0, t) +
                                                (sign * mu) * wrc::test::hamilton_tangential(kNu, x, 0, t));
      if (vm > vm_ref) vm_ref = vm, x_ref = x, zz_ref = t;
    }
  REQUIRE_MESSAGE(wrc_subsurface(c, "left.patches.1", (z + " fields=false").c_str(), &s) == WRC_OK, last());
  const double vm = number(s, "von_mises_max"), vz = number(s, "von_mises_max_z");
  const double vx = number(s, "von_mises_max_x") - (number(c, "left.patches.1.point.x") - number(c, "left.patches.1.frame.origin.x"));
  MESSAGE(fmt::format("sliding Hertz circle, mu = 0.3, {} elements on a: von Mises max {:.4f} p0 at x = {:+.3f} a, z = {:.4f} a; "
                      "Hamilton {:.4f} p0 at {:+.3f} a, {:.4f} a",
                      n, vm / kP0, vx / kA, vz / kA, vm_ref, x_ref, zz_ref));
  CHECK(vm == within_rel(vm_ref * kP0, 0.02));
  CHECK(std::abs(vz / kA - zz_ref) < 0.02);
  CHECK(std::abs(vx / kA - x_ref) < 1.5 / n);
  CHECK(zz_ref < 0.45);  // Hamilton's maximum has moved up from 0.48 a (frictionless)
  CHECK(number(s, "shakedown.traction_coefficient") == within_rel(mu, 0.01));
  wrc_result_free(s);
  wrc_result_free(c);
}
