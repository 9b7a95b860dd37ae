// The conformal surface's h on a steep face against Hertz: which gap the half-space needs there.
//
// Two convex circles, a pin-shaped wheel profile (radius Rw) on a crowned rail (radius Rr), in contact at the angle
// delta from the vertical: the same elastic problem at every delta (a rotation), apart from the wheel's curvature along
// the track, cos(delta) / r at rolling radius r, which Hertz's solution takes in. So at the same normal overlap D of
// the two circles (Rw + Rr minus the distance of their centres, exact geometry) the normal force must be Hertz's at
// every delta: A = (1 / Rw + 1 / Rr) / 2 across, B = cos(delta) / (2 r) along the track.
//
// A depth measured radially (vertically at x = 0) and turned onto the normal, n_r (r(Y) - distance to the axle),
// equals the normal depth only to first order: its radial foot lies D tan(delta) along the profile from the normal
// foot, and over that distance the profile bends. It is larger than the closest-point depth by the relative
// kappa D tan^2(delta) / 2 (kappa the wheel profile's curvature), 0 at delta = 0 and 3.8 % at 70 deg for D = 40 um on
// Rw = 4 mm, and the force at a given overlap grew by about as much (+4.4 % against Hertz at 70 deg, +0.5 % at 45, 0
// at 0). Asserted: every element's h is the closest-point depth of its 3-D point (brute force) within 0.1 % of D, the
// force within 1 % of Hertz's up to 45 deg and within 2.5 % at 70 deg, pmax within 1 %. (At 70 deg the force stays
// 1.5 % above Hertz with h exact: not h -- the planar surface has it too -- and growing with D; not explained.)
#include "halfspace/hertz_reference.hpp"
#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/wheelset/wheelset.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using wrc::test::within_rel;
using namespace wrc;

namespace {

constexpr double kRw = 4e-3, kRr = 2e-3, kStep = 5e-6, kR0 = 0.06;
constexpr double kDeg = std::numbers::pi / 180;

// A circular arc of radius R between the angles -a and a from its lowest (wheel) or highest (rail) point.
Profile arc(ProfileKind kind, double R, double a, double dz = 0) {
  std::vector<double> y, z;
  const int n = static_cast<int>(std::lround(2 * R * a / kStep));
  const double s = kind == ProfileKind::wheel ? 1 : -1;  // the wheel's radius falls away from its crown
  for (int k = 0; k <= n; ++k) {
    const double t = -a + 2 * a * k / n;
    y.push_back(R * std::sin(t));
    z.push_back(s * R * (1 - std::cos(t)) + dz);
  }
  return make_profile(kind, y, z, kind == ProfileKind::wheel ? "pin" : "crown", "test_conformal_inclined");
}

// The pin over the left crown, crown under crown at y = 0 (the crown's gauge point at 60 deg placed where the pin's
// crown, 0.75 m, lies + Rr sin 60); the right rail far below, out of reach.
std::shared_ptr<const Wheelset> pin_on_crown(double element) {
  WheelsetProfiles pr;
  const Profile pin = arc(ProfileKind::wheel, kRw, 85 * kDeg);
  pr.wheel = {pin, pin};
  pr.rail = {arc(ProfileKind::rail, kRr, 85 * kDeg), arc(ProfileKind::rail, kRr, 85 * kDeg, -0.05)};
  WheelsetParams p;
  p.track.radius = kR0;
  p.track.cant = 0;
  p.track.gauge_depth = kRr * (1 - std::cos(60 * kDeg));
  p.track.gauge = 2 * (0.75 + kRr * std::sin(60 * kDeg));
  p.contact.element = element;
  p.strategy = "brute";   // the profiles as given: lines and cones every 5 um
  p.check_setup = false;  // a 4 mm pin is no railway wheel, on purpose
  return build_wheelset(pr, p);
}

// The largest radial overlap of the left wheel over every rail line (< 0: apart).
double overlap(const ContactModel& m, const Pose& pose) {
  const PoseFrame f(pose);
  const RailLines& rail = m.geometry().side[kLeft].rail;
  double best = -INFINITY;
  for (int r = 0; r < rail.count(); ++r)
    best = std::max(best, line_approach(m.geometry().side[kLeft].wheel, f, rail.y[r], rail.z[r]).overlap);
  return best;
}

// The height of the pose at which the pin first touches its crown at lateral shift y (bisection on the exact
// line-cone geometry: at first touch every definition of the gap is zero).
double touch_z(const ContactModel& m, double y) {
  double lo = -5e-3, hi = 5e-3;  // lo: inside, hi: apart
  REQUIRE(overlap(m, {y, lo, 0, 0}) > 0);
  REQUIRE(overlap(m, {y, hi, 0, 0}) < 0);
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (overlap(m, {y, mid, 0, 0}) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Distance of the wheelset-frame point q from the wheel's generatrix in its meridian plane, by brute force over every
// running-surface segment.
double depth(const WheelCones& w, const Eigen::Vector3d& q) {
  const double rho = std::hypot(q.x(), q.z());
  double best = INFINITY;
  for (int k = 1; k + 2 < static_cast<int>(w.y.size()); ++k) {
    const double ay = w.y[k], ar = -w.z[k], dy = w.y[k + 1] - ay, dr = -w.z[k + 1] - ar, L2 = dy * dy + dr * dr;
    const double t = std::clamp(((q.y() - ay) * dy + (rho - ar) * dr) / L2, 0.0, 1.0);
    best = std::min(best, std::hypot(q.y() - (ay + t * dy), rho - (ar + t * dr)));
  }
  return best;
}

}  // namespace

TEST_CASE("conformal h on a steep face: the force at a given normal overlap is Hertz's at any angle") {
  const auto ws = pin_on_crown(0.02e-3);
  const ContactModel& model = ws->contact_model();
  auto work = ws->make_workspace();
  const double Rs = kRw + kRr, Es = model.material().combined_modulus(), D = 40e-6;
  // Where the crowns are one above the other: the centre of the circle of the touch heights through three shifts,
  // whose radius must be Rs (the placed circles).
  const double y1 = -1e-3, y2 = 0, y3 = 1e-3, z1 = touch_z(model, y1), z2 = touch_z(model, y2), z3 = touch_z(model, y3);
  const double a = y2 - y1, b = z2 - z1, c = y3 - y1, e = z3 - z1, g = 2 * (a * e - b * c);
  const double yc = y1 + (e * (a * a + b * b) - b * (c * c + e * e)) / g;
  const double zc = z1 + (a * (c * c + e * e) - c * (a * a + b * b)) / g;
  CHECK(std::hypot(y1 - yc, z1 - zc) == within_rel(Rs, 1e-3));
  const double z_top = zc + Rs;
  const WheelCones& wheel = model.geometry().side[kLeft].wheel;
  fmt::print("pin (Rw 4 mm) on a crown (Rr 2 mm), normal overlap 40 um: normal force against Hertz\n"
             "{:>6} {:>10} {:>10} {:>8} {:>10} {:>10} {:>7}\n", "delta", "force N", "Hertz N", "diff", "pmax MPa",
             "Hertz MPa", "diff");
  for (double deg : {0.0, 45.0, 70.0}) {
    CAPTURE(deg);
    const double d = deg * kDeg, y = yc + Rs * std::sin(d);
    // The centres' distance Rs at first touch; lowering by dz from there leaves Rs - D.
    const double z0 = touch_z(model, y);
    CHECK(z_top - z0 == doctest::Approx(Rs * (1 - std::cos(d))).epsilon(1e-4).scale(Rs));  // the circles placed
    const double dz = Rs * std::cos(d) - std::sqrt((Rs - D) * (Rs - D) - Rs * Rs * std::sin(d) * std::sin(d));
    ContactRequest left;
    left.only_side = kLeft;
    const ContactResult c = evaluate_contact(model, {y, z0 - dz, 0, 0}, *work, left);
    REQUIRE(c.wheel[kLeft].patches.size() == 1);
    const PatchContact& pc = c.wheel[kLeft].patches.front();
    CHECK(std::abs(std::abs(pc.angle) - d) < 0.3 * kDeg);
    // Every element's h against the closest-point depth of its 3-D point (brute force over the generatrix in the
    // point's meridian plane, exact for a surface of revolution).
    REQUIRE(pc.conformal);
    const ConformalSurface& cs = *pc.conformal;
    const halfspace::Grid& g = pc.solution.grid;
    const PoseFrame f({y, z0 - dz, 0, 0});
    double worst = 0;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double h = pc.h[static_cast<std::size_t>(g.index(i, j))];
        const Eigen::Vector3d q = f.to_wheelset({cs.x0 + g.x(i), cs.y[j], cs.z[j]});
        if (h > 0) worst = std::max(worst, std::abs(h - depth(wheel, q)));
      }
    CHECK(worst < 1e-3 * D);
    const double r = kR0 - kRw * (1 - std::cos(d));  // rolling radius at the contact
    const auto hz = test::hertz_from_approach(0.5 * (1 / kRw + 1 / kRr), 0.5 * std::cos(d) / r, Es, D);
    const double pmax = pc.solution.max_pressure;
    fmt::print("{:6.1f} {:10.2f} {:10.2f} {:7.2f}% {:10.1f} {:10.1f} {:6.2f}%\n", deg, pc.normal_force, hz.force,
               100 * (pc.normal_force / hz.force - 1), pmax / 1e6, hz.p0 / 1e6, 100 * (pmax / hz.p0 - 1));
    // Within 1 % up to 45 deg; at 70 deg 1.5 % above Hertz with h exact as checked above (see the head).
    CHECK(pc.normal_force == within_rel(hz.force, deg < 60 ? 0.01 : 0.025));
    CHECK(pmax == within_rel(hz.p0, 0.01));
  }
}
