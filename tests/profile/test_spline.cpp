// Profile splines (profile/spline.hpp) against what the documentation promises, on curves known here:
//  - smooth = 0 passes through the points and gives the curvature of a sampled circle;
//  - the smoothing length l is the documented filter: waviness of wavelength 2 pi l halved, 4 pi l kept to 1/(1 +
//    1/16), pi l cut to 1/17 (measured on a straight profile carrying a small sine);
//  - on a noisy arc the smoothed curvature is the arc's while the interpolating spline's is noise;
//  - the curvature sign convention (wheel above, rail below its profile) and mirrored splines.
#include "wrc/profile/spline.hpp"

#include "wrc/core/error.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

using wrc::test::within_rel;
using namespace wrc;

namespace {

constexpr double pi = std::numbers::pi;

// Deterministic noise in [-1, 1].
struct Noise {
  std::uint64_t s = 12345;
  double operator()() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / static_cast<double>(1ULL << 53) * 2 - 1;
  }
};

// An arc of radius R (m) below its centre (a rail crown: z = -R + sqrt(R^2 - y^2)), sampled every h along y.
void arc(double R, double half_width, double h, std::vector<double>& y, std::vector<double>& z, double noise = 0) {
  Noise n;
  for (double v = -half_width; v <= half_width + 1e-12; v += h) {
    y.push_back(v);
    z.push_back(-R + std::sqrt(R * R - v * v) + noise * n());
  }
}

// Amplitude of the smoothed sine at the middle of a straight profile z = a sin(2 pi y / wavelength).
double smoothed_amplitude(double wavelength, double ell) {
  std::vector<double> y, z;
  const double a = 1e-6, h = wavelength / 64;
  for (int i = 0; i <= 64 * 40; ++i) {
    y.push_back(i * h);
    z.push_back(a * std::sin(2 * pi * y.back() / wavelength));
  }
  const ProfileSpline s = fit_profile_spline(y, z, ell, "sine");
  double amp = 0;
  for (std::size_t i = 64 * 18; i <= 64 * 22; ++i) amp = std::max(amp, std::abs(s.z[i]));
  return amp / a;
}

}  // namespace

TEST_CASE("smooth = 0: the interpolating cubic spline, with the curvature of a sampled circle") {
  std::vector<double> y, z;
  arc(0.013, 0.010, 0.1e-3, y, z);
  const ProfileSpline s = fit_profile_spline(y, z, 0.0, "arc");
  for (std::size_t i = 0; i < y.size(); ++i) {
    CHECK(s.y[i] == y[i]);
    CHECK(s.z[i] == z[i]);
    const ProfileSpline::Point p = s.at(s.t[i]);
    CHECK(std::abs(p.p.x() - y[i]) <= 1e-15);
    CHECK(std::abs(p.p.y() - z[i]) <= 1e-15);
  }
  // Curvature over the inner part (the natural ends bend it near the ends): the rail's crown is convex, 1/R.
  for (double v : {-0.008, -0.003, 0.0, 0.0042, 0.008}) {
    CAPTURE(v);
    const double t = s.param_at_y(v);
    CHECK(std::abs(s.at(t).p.x() - v) <= 1e-12);
    CHECK(surface_curvature(s, ProfileKind::rail, t) == within_rel(1 / 0.013, 2e-4));
    CHECK(surface_curvature(s, ProfileKind::wheel, t) == within_rel(-1 / 0.013, 2e-4));
  }
  // Mirrored (y -> -y, as p:transform{mirror_y = true} maps it), the crown is still convex.
  const ProfileSpline m = mapped_spline(s, -1, 0.002, 1, 0.0);
  CHECK(m.y_order == -1);
  const double t = m.closest({0.002 - 0.004, s.at(s.param_at_y(0.004)).p.y()});
  CHECK(surface_curvature(m, ProfileKind::rail, t) == within_rel(1 / 0.013, 2e-4));
  CHECK(m.param_at_y(0.002 - 0.004) == within_rel(t, 1e-9));
}

TEST_CASE("the smoothing length l is the documented low-pass filter 1 / (1 + (l k)^4)") {
  const double ell = 0.2e-3;
  CHECK(smoothed_amplitude(2 * pi * ell, ell) == within_rel(0.5, 0.02));
  CHECK(smoothed_amplitude(4 * pi * ell, ell) == within_rel(1 / (1 + 1 / 16.0), 0.02));
  CHECK(smoothed_amplitude(pi * ell, ell) == within_rel(1 / 17.0, 0.05));
  CHECK(smoothed_amplitude(2 * pi * ell, 0.0) == within_rel(1.0, 1e-9));
}

TEST_CASE("a noisy arc: the smoothed curvature is the arc's, the interpolating spline's is noise") {
  std::vector<double> y, z;
  arc(0.020, 0.012, 0.1e-3, y, z, 2e-6);  // +-2 um of measurement noise every 0.1 mm
  const ProfileSpline raw = fit_profile_spline(y, z, 0.0, "noisy");
  const ProfileSpline smooth = fit_profile_spline(y, z, 0.5e-3, "noisy");
  double worst_raw = 0, worst_smooth = 0;
  for (double v = -0.008; v <= 0.008; v += 0.25e-3) {
    worst_raw = std::max(worst_raw, std::abs(surface_curvature(raw, ProfileKind::rail, raw.param_at_y(v)) * 0.020 - 1));
    worst_smooth =
        std::max(worst_smooth, std::abs(surface_curvature(smooth, ProfileKind::rail, smooth.param_at_y(v)) * 0.020 - 1));
  }
  MESSAGE("curvature error of the noisy R20 arc: interpolating ", worst_raw * 100, " %, smooth = 0.5 mm ",
          worst_smooth * 100, " %");
  CHECK(worst_raw > 1.0);
  CHECK(worst_smooth < 0.05);
}

TEST_CASE("bad input to a spline") {
  CHECK_THROWS_AS(fit_profile_spline({0, 1e-3}, {0, 0}, 0, "two points"), Error);
  CHECK_THROWS_AS(fit_profile_spline({0, 1e-3, 1e-3}, {0, 0, 0}, 0, "repeated"), Error);
  CHECK_THROWS_AS(fit_profile_spline({0, 1e-3, 2e-3}, {0, 0, 0}, -1, "negative"), Error);
}
