// The flange of a wheel profile and the flange-climb criteria (wheelset/plausibility.hpp) against the nominal
// dimensions of S1002 (EN 13715: flange height 28 mm, thickness 32.5 mm at 10 mm above the tape circle, flank 70 deg)
// and Nadal's formula written out here.
#include "wheelset/paper_profiles.hpp"
#include "wrc/wheelset/plausibility.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>

using wrc::test::within_rel;
using namespace wrc;

namespace {

Profile s1002() { return test::load_text("s1002", ProfileKind::wheel); }

}  // namespace

TEST_CASE("the flange of S1002: height, thickness and flank angle of EN 13715") {
  const Flange f = flange_of(s1002());
  REQUIRE(f.present);
  CHECK(f.height == within_rel(0.028, 1e-6));
  CHECK(0.070 + f.face_y == within_rel(0.0325, 1e-3));  // Sd, from the flange back at s = -70 mm
  CHECK(f.max_angle * 180 / M_PI == within_rel(70.0, 1e-4));
  // The straight 70 deg flank ends toward the tip between s = -40 and -39.7 mm.
  CHECK(f.steep_y > -0.0400);
  CHECK(f.steep_y < -0.0397);
  // A cylinder has no flange: no criterion applies.
  Profile cyl = make_profile(ProfileKind::wheel, {-0.07, 0.0, 0.06}, {0, 0, 0}, "cylinder", "test");
  CHECK_FALSE(flange_of(cyl).present);
  CHECK(beyond_steepest(flange_of(cyl), -0.05).empty());
}

TEST_CASE("flange climb: beyond the steepest part, Nadal's limit, lifted off the rail") {
  const Flange f = flange_of(s1002());
  CHECK(beyond_steepest(f, f.steep_y + 1e-4).empty());
  CHECK(beyond_steepest(f, f.steep_y - 1e-4).find("beyond the steepest part") != std::string::npos);
  // Nadal, frictionless: L/V > tan(70 deg) = 2.7475; L toward the track centre (-y on the left wheel, +y on the right).
  const double tan70 = std::tan(70 * M_PI / 180);
  CHECK(nadal_exceeded(f, kLeft, -0.99 * tan70 * 1e5, 1e5).empty());
  CHECK(nadal_exceeded(f, kLeft, -1.01 * tan70 * 1e5, 1e5).find("Nadal's limit tan(70.0 deg) = 2.747") != std::string::npos);
  CHECK(nadal_exceeded(f, kRight, 1.01 * tan70 * 1e5, 1e5).find("Nadal") != std::string::npos);
  CHECK(nadal_exceeded(f, kRight, -1.01 * tan70 * 1e5, 1e5).empty());  // pushed toward the field side
  CHECK(nadal_exceeded(f, kLeft, -1e3, 0).find("Nadal") != std::string::npos);  // no vertical force at all
  CHECK(lifted_off(f, 0.027).empty());
  CHECK(lifted_off(f, 0.029).find("more than its flange height (28.0 mm)") != std::string::npos);
}
