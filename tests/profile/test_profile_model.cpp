// The profile model and the host's post-processing of raw reader output (units, extent, mirrors, crop,
// shift, kind), on small hand-made profiles whose answers are known by construction.
#include "wrc/core/error.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/profile.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

using wrc::test::within_rel;
using namespace wrc;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

#define CHECK_ERROR(expr, text)                       \
  do {                                                \
    const std::string msg_ = error_of([&] { expr; }); \
    INFO(msg_);                                       \
    CHECK(msg_.find(text) != std::string::npos);      \
  } while (0)

RawProfile raw_arc(int n, double radius_mm) {  // a circular arc in mm, points every few degrees
  RawProfile r;
  for (int i = 0; i < n; ++i) {
    const double a = -0.6 + 1.2 * i / (n - 1);
    r.y.push_back(radius_mm * std::sin(a));
    r.z.push_back(radius_mm * (std::cos(a) - 1));
    r.lines.push_back(10 + i);
  }
  return r;
}

}  // namespace

TEST_CASE("make_profile validates, drops duplicates, reverses, and locates a fold-back") {
  const std::vector<int> lines = {3, 4, 5, 6, 7};
  CHECK_ERROR(make_profile(ProfileKind::rail, {0, 1e-3}, {0, 0}, "p", "f.txt"), "at least 3 distinct points, got 2");
  CHECK_ERROR(make_profile(ProfileKind::rail, {0, 1e-3, 2e-3}, {0, NAN, 0}, "p", "f.txt", {3, 4, 5}), "f.txt:4: coordinate is not a finite");
  CHECK_ERROR(make_profile(ProfileKind::rail, {0, 1e-3, 2e-3, 1.5e-3, 3e-3}, {0, 0, 0, 0, 0}, "p", "f.txt", lines), "f.txt:6: the profile folds back");
  CHECK_ERROR(make_profile(ProfileKind::rail, {0, 0, 0}, {0, 1e-3, 2e-3}, "p", "f.txt"), "same y");
  // A vertical run that turns back on itself.
  CHECK_ERROR(make_profile(ProfileKind::rail, {0, 1e-3, 1e-3, 1e-3, 2e-3}, {0, 0, 1e-3, 0.5e-3, 0}, "p", "f.txt", lines),
              "f.txt:6: the profile folds back on itself on a vertical run");

  const Profile p = make_profile(ProfileKind::wheel, {3e-3, 2e-3, 2e-3, 1e-3, 0}, {1, 2, 2, 3, 4}, "w", "src");
  CHECK(p.duplicates_dropped == 1);
  REQUIRE(p.size() == 4);
  CHECK(p.y.front() == 0);  // given in decreasing y: reversed
  CHECK(p.z.front() == 4);
  CHECK(p.transforms.back() == "reversed to increasing y");
}

TEST_CASE("resampling along the arc and along y") {
  // A right-angle polyline: 3 mm along y then 4 mm down: arc length 7 mm.
  const Profile p = make_profile(ProfileKind::rail, {0, 3e-3, 3e-3 + 1e-12, 3e-3 + 2e-12}, {0, 0, -2e-3, -4e-3}, "L", "src");
  CHECK(arc_length(p) == within_rel(7e-3, 1e-9));
  const Profile a = resample_arc(p, 0.5e-3);
  CHECK(a.size() == 15);  // 7 mm / 0.5 mm = 14 intervals
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    CHECK(std::hypot(a.y[i + 1] - a.y[i], a.z[i + 1] - a.z[i]) == within_rel(0.5e-3, 1e-6));
  CHECK(a.y.back() == p.y.back());
  CHECK(a.z.back() == p.z.back());
  const Profile y = resample_y(make_profile(ProfileKind::rail, {0, 1e-3, 2e-3, 2.5e-3}, {0, 1e-3, 0, 0}, "v", "src"), 0.4e-3);
  REQUIRE(y.size() == 8);  // 0, 0.4, ..., 2.4 and the end 2.5
  CHECK(y.z[1] == within_rel(0.4e-3, 1e-5));
  CHECK(y.z[3] == within_rel(0.8e-3, 1e-5));  // 1.2 mm on the falling side
  CHECK(y.y.back() == 2.5e-3);
  CHECK_ERROR(resample_arc(p, 0), "step must be a positive");
  CHECK_ERROR(resample_y(p, -1), "step must be a positive");
}

TEST_CASE("finish_profile: units, extent check, kind, mirrors, crop and shift in their order") {
  LoadOptions o;
  o.kind = ProfileKind::rail;
  const Profile mm = finish_profile(raw_arc(50, 30), o, "arc.txt", "text");
  CHECK(mm.y.back() == within_rel(30e-3 * std::sin(0.6), 1e-5));
  CHECK(mm.transforms.front() == "read by 'text'");

  // Numbers in metres taken as mm: the chord is 1000 times too small.
  RawProfile metres = raw_arc(50, 0.030);
  CHECK_ERROR(finish_profile(metres, o, "arc.txt", "text"), "arc.txt:10: the profile's total chord is 0.03");
  LoadOptions om = o;
  om.metres_per_unit = 1.0;
  om.units_text = std::string("m");  // not the literal: GCC 12 mistakes its assignment for a -Wrestrict overlap
  CHECK(finish_profile(metres, om, "arc.txt", "text").y.back() == within_rel(0.030 * std::sin(0.6), 1e-5));
  // Metres declared but mm given: too large.
  RawProfile declared = raw_arc(50, 30);
  declared.metres_per_unit = 1.0;
  declared.units_declared_by = "units.len.f = 1 (line 9)";
  CHECK_ERROR(finish_profile(declared, o, "arc.prr", "simpack"), "taken as units.len.f = 1 (line 9)");

  // Kind.
  RawProfile wheel = raw_arc(50, 30);
  wheel.kind = ProfileKind::wheel;
  CHECK_ERROR(finish_profile(wheel, o, "w.prw", "simpack"), "holds a wheel profile but the option kind = \"rail\"");
  CHECK_ERROR(finish_profile(raw_arc(50, 30), LoadOptions{}, "a.txt", "text"), "pass kind = \"wheel\" or \"rail\"");

  // Too few points names the line of the last one.
  RawProfile two;
  two.y = {0, 1};
  two.z = {0, 0};
  two.lines = {4, 5};
  CHECK_ERROR(finish_profile(two, o, "two.txt", "text"), "two.txt:5: only 2 points read");

  // Mirror, crop (before the shift), shift.
  LoadOptions t = o;
  t.mirror_y = true;
  t.shift_y = 0.001;
  t.shift_z = -0.002;
  t.crop = CropWindow{-0.010, 0.010, -1, 1};
  const Profile s = finish_profile(raw_arc(61, 30), t, "arc.txt", "text");
  CHECK(s.y.front() >= -0.009 - 1e-12);  // the first point inside the window, shifted by 1 mm
  CHECK(s.y.front() < -0.009 + 0.0007);
  CHECK(s.y.back() <= 0.010 + 0.001 + 1e-12);
  CHECK(s.z[s.size() / 2] == within_rel(-0.002, 1e-3));
  // The crop window cutting the profile in two.
  LoadOptions c = o;
  c.crop = CropWindow{-1, 1, -1, -0.001};  // drops the crown, keeps both flanks
  CHECK_ERROR(finish_profile(raw_arc(61, 30), c, "arc.txt", "text"), "the crop window cuts the profile into 2 separate pieces");

  CHECK(parse_units("mm", "x") == 1e-3);
  CHECK(parse_units("0.0254", "x") == 0.0254);
  CHECK_ERROR(parse_units("furlong", "x"), "units must be");
  CHECK_ERROR(parse_units("-1", "x"), "units must be");
}

TEST_CASE("transform_profile keeps a profile's history and applies mirror, crop and shift") {
  const Profile p = make_profile(ProfileKind::wheel, {-0.01, 0, 0.01, 0.02}, {0.001, 0, -0.001, -0.002}, "w", "src");
  LoadOptions o;
  o.mirror_y = true;
  o.shift_z = 0.5e-3;
  const Profile q = transform_profile(p, o);
  REQUIRE(q.size() == 4);
  CHECK(q.y.front() == within_rel(-0.02, 1e-5));
  CHECK(q.z.front() == within_rel(-0.0015, 1e-5));
  CHECK(q.transforms.back() == "reversed to increasing y");
  LoadOptions k;
  k.kind = ProfileKind::rail;
  CHECK_ERROR(transform_profile(p, k), "is a wheel profile but the option kind");
}
