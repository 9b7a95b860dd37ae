// The scatter of a profile's points (profile/scatter.hpp) against scatter drawn here: Gaussian noise of a known
// standard deviation added to z of a curve whose curvature varies along it (half an ellipse, a rail head's shape), and
// the same curve clean, finely and coarsely sampled; the warning of a profile that follows such points.
#include "wrc/profile/scatter.hpp"

#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace wrc;
using wrc::test::within_rel;

namespace {

// z = B (sqrt(1 - y^2 / A^2) - 1) for |y| <= 30 mm, A = 40 mm, B = 15 mm (radius of curvature 107 .. 40 mm;
// slopes up to 0.43, where z's scatter is 0.92 normal to the curve), sampled every h along y, Gaussian scatter s
// added to z.
struct Curve {
  std::vector<double> y, z;
};
Curve ellipse(double h, double s, unsigned seed = 1) {
  const double A = 40e-3, B = 15e-3;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, s > 0 ? s : 1.0);
  Curve c;
  for (double v = -30e-3; v <= 30e-3 + 1e-12; v += h) {
    c.y.push_back(v);
    c.z.push_back(B * (std::sqrt(1 - v * v / (A * A)) - 1) + (s > 0 ? noise(rng) : 0.0));
  }
  return c;
}
PointScatter scatter_of(const Curve& c) { return point_scatter(c.y, c.z); }

}  // namespace

TEST_CASE("the scatter estimated from the points is the scatter drawn, and is told as noise") {
  // A draw's estimate is the median of 120-600 differences: one draw lies within ~30 % of s (8 draws on 121 points,
  // 0.5 mm: 0.80-1.30 s), their mean within a few per cent.
  for (const double h : {0.1e-3, 0.25e-3, 0.5e-3}) {
    double sum = 0;
    const int draws = 8;
    for (unsigned seed = 1; seed <= draws; ++seed) {
      const PointScatter got = scatter_of(ellipse(h, 1e-6, seed));
      // The same draw ten times smaller or three times larger: the estimate in proportion, within what the curve's
      // own differences (kappa' h^3 / 2, most at the 0.5 mm samples' steep ends) move the median.
      const PointScatter small = scatter_of(ellipse(h, 0.1e-6, seed));
      const PointScatter large = scatter_of(ellipse(h, 3e-6, seed));
      CAPTURE(h);
      CAPTURE(seed);
      CHECK(got.sigma == within_rel(1e-6, 0.35));
      CHECK(small.sigma == within_rel(0.1 * got.sigma, 0.1));
      CHECK(large.sigma == within_rel(3 * got.sigma, 0.05));
      // The median chord: h along slopes of up to 0.43, about 1 % longer at the median.
      CHECK(got.spacing == within_rel(h, 0.03));
      CHECK(got.noise);
      CHECK(got.sign_changes > 0.6);  // 0.77 for noise alone
      sum += got.sigma;
    }
    CAPTURE(h);
    CHECK(sum / draws == within_rel(1e-6, 0.1));
  }
}

TEST_CASE("a clean curve has no scatter, and sampled coarsely its curvature's change is not taken for noise") {
  CHECK(scatter_of(ellipse(0.1e-3, 0)).sigma < 1e-9);
  CHECK(scatter_of(ellipse(0.5e-3, 0)).sigma < 0.1 * kScatterWarning);  // 0.015 um: the curvature's change
  for (const double h : {1e-3, 2e-3}) {  // the curvature's change over h: kappa' h^3 / 2 up to ~0.1 um at 2 mm
    const PointScatter got = scatter_of(ellipse(h, 0));
    CAPTURE(h);
    CAPTURE(got.sigma);
    CHECK_FALSE(got.noise);
    CHECK(got.sign_changes < 0.3);
  }
}

TEST_CASE("fewer than kMinScatterPoints points give no estimate") {
  const Curve c = ellipse(4e-3, 5e-6);  // 16 points
  REQUIRE(c.y.size() < kMinScatterPoints);
  const PointScatter got = scatter_of(c);
  CHECK(got.sigma == 0);
  CHECK_FALSE(got.noise);
}

TEST_CASE("a profile that follows scattered points is warned of, naming its file and the remedy") {
  const auto profile = [](const Curve& c) { return make_profile(ProfileKind::rail, c.y, c.z, "head", "measured.txt"); };
  const auto w = scatter_warning(profile(ellipse(0.1e-3, 1e-6)));
  REQUIRE(w);
  CHECK(w->find("measured.txt:") == 0);
  CHECK(w->find("smooth = 0.5e-3") != std::string::npos);
  CHECK(w->find("a polyline through them") != std::string::npos);  // make_profile gives no spline
  CHECK(is_scatter_warning(*w));
  CHECK_FALSE(is_scatter_warning("measured.txt: the wheel profile looks mirrored: its flange ..."));

  CHECK_FALSE(scatter_warning(profile(ellipse(0.1e-3, 0))));
  CHECK_FALSE(scatter_warning(profile(ellipse(0.1e-3, 0.1e-6))));  // below kScatterWarning
  CHECK_FALSE(scatter_warning(profile(ellipse(2e-3, 0))));         // coarse, clean

  Curve rounded = ellipse(0.1e-3, 0);  // written with 1 um resolution: a scatter of 1 / sqrt(12) um
  for (double& v : rounded.z) v = std::round(v * 1e6) * 1e-6;
  CHECK(scatter_of(rounded).sigma == within_rel(1e-6 / std::sqrt(12.0), 0.25));
  CHECK(scatter_warning(profile(rounded)));
}
