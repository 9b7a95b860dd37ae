// Plausibility of set-ups and results (plausibility.hpp).
#include "wrc/wheelset/plausibility.hpp"

#include "wrc/core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace wrc {
namespace {


struct Extent {
  double lo, hi;  // plausible range of a profile's width and height (m)
};
// Widths: S1002 130 mm, a 60E1 head 73 mm, a grooved tram rail with its lip ~115 mm. Heights: a flange 25-40 mm
// plus some of the flange back; a rail head 30-50 mm, a whole rail section 130-190 mm.
constexpr Extent kWheelWidth{5e-3, 0.25}, kWheelHeight{0, 0.1}, kRailWidth{5e-3, 0.2}, kRailHeight{0, 0.2};
constexpr double kFieldSideDrop = 10e-3;  // m: a wheel's radius may grow this much toward the field side (hollow wear)
// m: a rail head falls on its field side (60E1: 30 mm; a crowned test rail R450 over +-25 mm: 0.7 mm), where a wheel
// read as a rail ends at its highest point
constexpr double kHeadCornerDrop = 0.1e-3;
constexpr double kFieldSideRise = 1e-3;   // m: and does not rise again toward its field-side end by more than this
// m: a wheel profile may reach this far past its flange back (a measurement's back face, a chamfer) before its origin
// is taken to be off the tape circle
constexpr double kFlangeBackTolerance = 2e-3;
constexpr double kUpsideDownRise = 10e-3; // m: a wheel rising more above its tape circle is upside down (S1002: 2.6 mm)
// m: the largest lateral play of a wheelset in service between its flanges and the rails: EN 13848-5's widest gauge
// (about 1.470 m) less EN 15313's smallest back-to-back (1.357 m) and flanges (Sd 22 mm); nominal 10 mm
constexpr double kMaxFlangeway = 70e-3;
// m: how far below the rail's top the gauge is measured: EN 13848-1 14 mm, AAR 5/8 in (15.9 mm), GOST 13 mm. Nearer
// the top the gauge point lies on the head's rounded corner, millimetres toward the field side, and the rails close in
// on the flanges: S1002 on 60E1 with gauge_depth = 2 mm touched its flange at y = 3 mm (Y/Q 1.47 for 0.041).
constexpr double kMinGaugeDepth = 10e-3, kMaxGaugeDepth = 25e-3;

std::string describe_profile(const Profile& p, int side) {
  return fmt::format("the {} {} profile '{}' ({})", side_name(side), to_string(p.kind), p.name, p.source);
}

void check_extent(const Profile& p, int side) {
  const bool wheel = p.kind == ProfileKind::wheel;
  const auto [ylo, yhi] = std::minmax_element(p.y.begin(), p.y.end());
  const auto [zlo, zhi] = std::minmax_element(p.z.begin(), p.z.end());
  const double width = *yhi - *ylo, height = *zhi - *zlo;
  const Extent w = wheel ? kWheelWidth : kRailWidth, h = wheel ? kWheelHeight : kRailHeight;
  const char* what = wheel ? "a wheel profile (S1002: 130 mm)" : "a rail head (60E1: 73 mm)";
  if (width > w.hi || height > h.hi)
    fail("wrc.wheelset: {} is {:.4g} mm wide and {:.4g} mm tall; {} is at most {:.0f} mm wide and {:.0f} mm tall: "
         "are its units right? wrc takes metres (points given in mm, or a file in mm read with units = \"m\")", describe_profile(p, side), width * 1e3,
         height * 1e3, what, w.hi * 1e3, h.hi * 1e3);
  if (width < w.lo)
    fail("wrc.wheelset: {} is {:.4g} mm wide; {} is at least {:.0f} mm wide: are its units right (a file in metres "
         "read as mm)?", describe_profile(p, side), width * 1e3, what, w.lo * 1e3);
}

// A wheel whose lowest point (its flange tip) lies in the gauge-side half of its extent, as a wheel's does, but at y >
// 0 is oriented right with its origin elsewhere than the tape circle: MiniProf's X, from the flange back, read as y.
bool origin_off_tape(const Profile& p) {
  const auto tip = static_cast<std::size_t>(std::min_element(p.z.begin(), p.z.end()) - p.z.begin());
  return p.y[tip] > 0 && p.y[tip] - p.y.front() < 0.5 * (p.y.back() - p.y.front());
}

// A wheel's radius does not grow toward the field side (beyond hollow wear): a rail head read as a wheel does, and
// so does a wheel whose y axis is reversed (flange on the field side), or whose y is not measured from the tape circle.
void check_field_side(const Profile& p, int side, double tape_offset) {
  const double z0 = interpolate_z(p, 0.0);
  std::size_t low = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.y[i] > 0 && (low == p.size() || p.z[i] < p.z[low])) low = i;
  if (low < p.size() && p.z[low] < z0 - kFieldSideDrop) {
    const std::size_t i = low;
    if (origin_off_tape(p))
      fail("wrc.wheelset: {} has its flange (lowest point, {:.1f} mm below the height at y = 0) at y = {:+.1f} mm, "
           "toward its gauge-side end as a wheel's is, but on the field side of y = 0: its y is not measured from the "
           "tape circle. Is it measured from the flange back (MiniProf's X)? shift = {{y = {:.4f}}} puts its first "
           "point, the flange back, at y = -tape_offset = {:.1f} mm", describe_profile(p, side), (z0 - p.z[i]) * 1e3,
           p.y[i] * 1e3, -tape_offset - p.y.front(), -tape_offset * 1e3);
    fail("wrc.wheelset: {} is {:.1f} mm below its tape-circle height at y = {:+.1f} mm, on the field side: a "
           "wheel's radius grows by at most a few mm toward the field side (the flange is on the gauge side, y < 0). "
           "Is it a rail profile given as a wheel, or a wheel whose y axis is reversed (mirror_y)?",
           describe_profile(p, side), (z0 - p.z[i]) * 1e3, p.y[i] * 1e3);
  }
}

// A rail head falls on its field side, past the head's field corner, and keeps falling (rail frame: y toward the
// field side, z up). A wheel's profile read as a rail does neither: its z (the radius offset, docs/design.md section
// 2) grows toward the field side, where its tread ends, or, hollow-worn, falls over the false flange and rises again
// to the tread's end; its lowest point is the flange tip, on the gauge side. The highest point is taken as far toward
// the field side as it reaches (a flat top). The shape alone decides, whatever the file's format.
void check_head(const Profile& p, int side) {
  std::size_t top = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p.z[i] >= p.z[top]) top = i;
  double low = p.z[top], rise = 0;  // the lowest point beyond the top so far, and the largest rise after one
  for (std::size_t i = top; i < p.size(); ++i) {
    low = std::min(low, p.z[i]);
    rise = std::max(rise, p.z[i] - low);
  }
  const double drop = p.z[top] - low;
  const std::size_t tip = static_cast<std::size_t>(std::min_element(p.z.begin(), p.z.end()) - p.z.begin());
  // A rise on the field side is a hollow wheel's only with a flange on the gauge side: a rail with two crowns (a
  // test geometry) has its lowest point between them.
  const bool flange = tip < top && p.z[top] - p.z[tip] > kMinFlangeHeight;
  if (drop >= kHeadCornerDrop && (rise <= kFieldSideRise || !flange)) return;
  fail("wrc.wheelset: {} falls {:.1f} mm on the field side of its highest point (y = {:+.1f} mm) and rises again by "
       "{:.1f} mm toward its field-side end; a rail head falls more than {:.1f} mm on its field side (60E1: 30 mm) and "
       "does not rise again, a wheel's tread rises toward its field side. Its lowest point, {:.1f} mm below the top at "
       "y = {:+.1f} mm, is where a wheel's flange tip would be. Is it a wheel profile given as a rail (kind = \"rail\")?",
       describe_profile(p, side), drop * 1e3, p.y[top] * 1e3, rise * 1e3, kHeadCornerDrop * 1e3,
       (p.z[top] - p.z[tip]) * 1e3, p.y[tip] * 1e3);
}

// A wheel's flange tip points down, z < 0 (docs/design.md section 2): a wheel whose profile rises above its tape-circle
// height by more than a flange's depth, and more than twice as far as it falls, is upside down (z read pointing down).
// The profile loader warns of it by the same rule (profile/orientation.cpp); a wheelset built on it is anti-centring.
void check_upright(const Profile& p, int side) {
  const double z0 = interpolate_z(p, 0.0);
  const auto [lo, hi] = std::minmax_element(p.z.begin(), p.z.end());
  const double up = *hi - z0, down = z0 - *lo;
  if (up <= kUpsideDownRise || up <= 2 * down) return;
  fail("wrc.wheelset: {} rises {:.1f} mm above its tape-circle height at y = {:+.1f} mm and falls only {:.1f} mm below "
       "it: a wheel's flange tip points down, z < 0 (S1002: z = -28 mm at y = -55 mm), and its tread stays within a "
       "few mm of the tape circle. Is the wheel upside down (a file with z pointing down: mirror_z = true)?",
       describe_profile(p, side), up * 1e3, p.y[static_cast<std::size_t>(hi - p.z.begin())] * 1e3, down * 1e3);
}

// A wheel ends at its flange back, the inner face from which back_to_back is measured, at y = -tape_offset: a profile
// reaching farther toward the track centre has its origin off the tape circle (or another tape_offset), and every
// lateral position in the wheelset with it.
void check_flange_back(const Profile& p, int side, double tape_offset) {
  const double beyond = -tape_offset - p.y.front();
  if (beyond <= kFlangeBackTolerance) return;
  fail("wrc.wheelset: {} reaches y = {:.1f} mm, {:.1f} mm beyond its flange back at y = -tape_offset = {:.1f} mm (the "
       "wheel's inner face, from which back_to_back is measured): a wheel's y is measured from its tape circle, "
       "tape_offset from the flange back. Is the profile's origin off the tape circle (shift = {{y = {:.4f}}}), or "
       "tape_offset not this wheel's?", describe_profile(p, side), p.y.front() * 1e3, beyond * 1e3,
       -tape_offset * 1e3, beyond);
}

// back_to_back + both flange thicknesses must be less than the gauge, or the flanges sit on the rails; and not so
// much less that the wheels could not be meant for this track (a broad gauge with standard flange backs).
void check_flangeway(const Track& t) {
  const std::array<Flange, 2> f{flange_of(t.wheel[kLeft]), flange_of(t.wheel[kRight])};
  if (!f[kLeft].present && !f[kRight].present) return;
  const double thick[2] = {f[kLeft].present ? t.params.tape_offset + f[kLeft].face_y : 0.0,
                           f[kRight].present ? t.params.tape_offset + f[kRight].face_y : 0.0};
  const double span = t.params.back_to_back + thick[kLeft] + thick[kRight];
  if (span >= t.params.gauge)
    fail("wrc.wheelset: the flanges do not fit between the rails: back_to_back {:.4f} m + flange thicknesses {:.1f} "
         "and {:.1f} mm (left, right; measured {:.0f} mm above the tape circle, {:.0f} mm from the flange back to the "
         "tape circle) = {:.4f} m, not less than the gauge {:.4f} m; expected gauge > back_to_back + both flanges "
         "(standard gauge: 1.435 m with 1.360 m and S1002's 32.5 mm)", t.params.back_to_back, thick[kLeft] * 1e3,
         thick[kRight] * 1e3, kFlangeThicknessHeight * 1e3, t.params.tape_offset * 1e3, span, t.params.gauge);
  if (!f[kLeft].present || !f[kRight].present || t.params.gauge - span <= kMaxFlangeway) return;
  fail("wrc.wheelset: the wheelset has {:.1f} mm of lateral play between its flanges and the rails: gauge {:.4f} m - "
       "(back_to_back {:.4f} m + flange thicknesses {:.1f} and {:.1f} mm); a wheelset in service has at most {:.0f} mm "
       "(standard gauge: 1.435 - (1.360 + 2 x 0.0325) = 10 mm). Are gauge and back_to_back those of one track (1.520 m "
       "gauge takes about 1.440 m between flange backs, 1.668 m about 1.590 m, 1.000 m about 0.930 m)? If the play is meant, {}",
       (t.params.gauge - span) * 1e3, t.params.gauge, t.params.back_to_back, thick[kLeft] * 1e3, thick[kRight] * 1e3,
       kMaxFlangeway * 1e3, kUncheckedHint);
}

// The gauge of flanged wheels is measured where standards measure it; a flangeless test body's gauge point is only
// where its rails are placed.
void check_gauge_depth(const Track& t) {
  const double d = t.params.gauge_depth;
  if (d >= kMinGaugeDepth && d <= kMaxGaugeDepth) return;
  if (!flange_of(t.wheel[kLeft]).present && !flange_of(t.wheel[kRight]).present) return;
  fail("wrc.wheelset: gauge_depth = {:.4g} m puts the gauge points {:.1f} mm below the rails' tops; the gauge is "
       "measured {:.0f} .. {:.0f} mm below them (EN 13848-1: 14 mm, gauge_depth = 0.014; AAR: 5/8 in, 0.0159), where "
       "the head's gauge face is, and gauge = {:.4f} m is the distance between those points. Nearer the top the rails "
       "close in on the flanges. To measure it there anyway, {}", d, d * 1e3, kMinGaugeDepth * 1e3,
       kMaxGaugeDepth * 1e3, t.params.gauge, kUncheckedHint);
}

}  // namespace

void check_plausible(std::string_view context, std::string_view key, double value, const Plausible& r,
                     std::string_view off) {
  if (!std::isfinite(value) || (std::abs(value) >= r.lo && std::abs(value) <= r.hi)) return;  // NaN: the range checks
  const std::string unit = *r.unit ? fmt::format(" {}", r.unit) : "";  // a friction coefficient has none
  fail("{}: {} = {:.6g}{} is implausible for {} ({:.3g} .. {:.3g}{}): is it in another unit? wrc takes SI units ({}){}{}",
       context, key, value, unit, r.what, r.lo, r.hi, unit, r.hint, off.empty() ? "" : "; ", off);
}

void check_plausible(const TrackParams& track, const halfspace::Material& material) {
  check_plausible("wrc.wheelset", "radius", track.radius, kWheelRadius);
  check_plausible("wrc.wheelset", "E", material.E, kSteelModulus);
  check_plausible("wrc.wheelset", "nu", material.nu, kSteelPoisson);
  // The range above is of |nu| (a percentage is refused either sign): a negative ratio, which the half-space allows
  // (> -1), is a sign slip for steel.
  if (material.nu < 0)
    fail("wrc.wheelset: nu = {:.6g} is negative; steel's Poisson's ratio is 0.27 .. 0.30 (nu = 0.28); {}", material.nu,
         kUncheckedHint);
  if (track.cant < 0)
    fail("wrc.wheelset: cant = {:.6g} tilts the rails' heads outward, toward the field side; rails are inclined toward "
         "the track centre, cant > 0 (1:40 is cant = 0.025, 1:20 cant = 0.05), and a rail already canted in its file "
         "is used with cant = 0; {}", track.cant, kUncheckedHint);
}

void check_setup(const Track& t) {
  for (int s : {kLeft, kRight}) {
    check_extent(t.wheel[s], s);
    check_extent(t.rail[s], s);
    check_field_side(t.wheel[s], s, t.params.tape_offset);
    check_upright(t.wheel[s], s);
    check_flange_back(t.wheel[s], s, t.params.tape_offset);
    check_head(t.rail[s], s);
  }
  check_gauge_depth(t);
  check_flangeway(t);
}

}  // namespace wrc
