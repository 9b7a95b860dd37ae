// 2-D wheel and rail profiles (docs/design.md, section 2): ordered points in the LEFT-side frame, metres, z up.
// wheel: y = s (lateral from the tape circle, + toward the field side), z = height offset (flange tip of
//        S1002 at z = -0.028); rail: y lateral (+ toward the field side), z up, origin at the top of the
//        uncanted head unless the source says the profile is already canted.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wrc {

enum class ProfileKind { wheel, rail };

// The type name of a profile passed as an option value (OptionValue::object) and of the Lua userdata.
inline constexpr const char* kProfileTypeName = "wrc.Profile";

const char* to_string(ProfileKind kind);
// "wheel" or "rail"; anything else is an error naming `context`.
ProfileKind parse_profile_kind(std::string_view text, std::string_view context);

struct ProfileSpline;  // spline.hpp

struct Profile {
  ProfileKind kind = ProfileKind::rail;
  std::string name;                     // e.g. "S1002"
  std::string source;                   // file path or "wrc.profile.points"
  std::vector<double> y, z;             // metres, ordered by increasing y
  int duplicates_dropped = 0;           // consecutive duplicates removed on creation
  std::vector<std::string> transforms;  // what was applied on the way in, in order ("mirror_y", ...)
  std::vector<std::pair<std::string, std::string>> metadata;  // kept from the source file (header keys)
  // The smooth curve the points lie on (loaded with `smooth = ...`; spline.hpp), or null: a polyline. Resampling
  // evaluates it; copies share it.
  std::shared_ptr<const ProfileSpline> spline;
  std::vector<std::string> warnings;    // what looks wrong but was accepted (e.g. the orientation; orientation.hpp)

  std::size_t size() const { return y.size(); }
};

// The most points a profile may have, however it is made (points, files, definitions, resampling): a step of 0.13 um
// over the S1002's 130 mm, finer than any measurement; more is a step given in the wrong unit, and would take memory
// in proportion (a definition's tables, the geometry built from the profile). check_point_count names `what`.
inline constexpr std::size_t kMaxProfilePoints = 1'000'000;
void check_point_count(double n, std::string_view what);

// The largest coordinate (m, either sign) of a profile's point. A wheel or rail profile spans a few dozen mm (a test
// body or a scale model a few metres at most); a kilometre is a number in the wrong unit, and bounding the points
// keeps every sum and square of them finite (points at +-1.7e308 m were accepted, and their arc length was inf).
inline constexpr double kMaxProfileCoordinate = 1e3;

// Points closer than this (m) to their predecessor are duplicates.
inline constexpr double kDuplicateTolerance = 1e-9;

// Builds a validated profile. Checks: at least 3 and at most kMaxProfilePoints points, all finite and within
// +-kMaxProfileCoordinate, consecutive duplicates dropped and
// counted, no fold-back: y must be monotone along the profile (vertical runs allowed, but a vertical run
// must keep one z direction). A profile given in decreasing y is reversed (noted in `transforms`).
// `lines` (optional, one per point) are source line numbers used in messages ("file:line: ...").
// Throws wrc::Error naming `source` (and the line or point index) on bad input.
Profile make_profile(ProfileKind kind, std::vector<double> y, std::vector<double> z, std::string name,
                     std::string source, const std::vector<int>& lines = {});

// Total arc length (m) of the polyline.
double arc_length(const Profile& p);

// Resampled along the arc: end points kept, interior points every `step` metres of arc (the step is
// shrunk so that it divides the length evenly). step > 0; at most kMaxProfilePoints points.
Profile resample_arc(const Profile& p, double step);

// Resampled along y: points at y_min + k*step (and y_max), z interpolated linearly. step > 0; at most
// kMaxProfilePoints points.
Profile resample_y(const Profile& p, double step);

// Linear interpolation of z at y (y clamped to the profile's range). On a vertical run, the first z.
double interpolate_z(const Profile& p, double y);
// The same on any polyline: f at xq for x sorted increasing (clamped to [x.front(), x.back()]).
double interpolate(const std::vector<double>& x, const std::vector<double>& f, double xq);

}  // namespace wrc
