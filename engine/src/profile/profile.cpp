#include "wrc/profile/profile.hpp"

#include "wrc/core/error.hpp"
#include "wrc/profile/spline.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {

const char* to_string(ProfileKind kind) { return kind == ProfileKind::wheel ? "wheel" : "rail"; }

ProfileKind parse_profile_kind(std::string_view text, std::string_view context) {
  if (text == "wheel") return ProfileKind::wheel;
  if (text == "rail") return ProfileKind::rail;
  fail("{}: kind must be \"wheel\" or \"rail\", got \"{}\"", context, text);
}

namespace {

std::string where(const std::string& source, const std::vector<int>& lines, std::size_t i) {
  if (i < lines.size() && lines[i] > 0) return fmt::format("{}:{}", source, lines[i]);
  return fmt::format("{}: point {}", source, i + 1);
}

// A spike: one point that leaves the height range of its two neighbours by more than kSpikeHeight and comes back,
// steeper than kSpikeSlope both ways (out by e within a lateral span of e / kSpikeSlope). Wheel and rail surfaces turn
// by 90 degrees at most between samples (a flange back, a rail's flank), never out and back; measurement noise is
// micrometres. Such a point is a mistyped number (a sign, a digit), which the contact would take for a real ridge.
constexpr double kSpikeHeight = 1e-3;  // m
constexpr double kSpikeSlope = 20;     // |dz / dy| of both flanks: 87 degrees

void refuse_spike(const Profile& p, const std::vector<int>& lines) {
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const double lo = std::min(p.z[i - 1], p.z[i + 1]), hi = std::max(p.z[i - 1], p.z[i + 1]);
    const double out = std::max(p.z[i] - hi, lo - p.z[i]), span = std::abs(p.y[i + 1] - p.y[i - 1]);
    if (out > kSpikeHeight && out > kSpikeSlope * span)
      fail("{}: the point y = {:.6g} mm, z = {:.6g} mm sticks out {:.6g} mm {} its neighbours (z = {:.6g} and {:.6g} mm, "
           "{:.3g} mm apart in y) and comes back: a spike, which no wheel or rail has; a mistyped z?",
           where(p.source, lines, i), p.y[i] * 1e3, p.z[i] * 1e3, out * 1e3, p.z[i] > hi ? "above" : "below",
           p.z[i - 1] * 1e3, p.z[i + 1] * 1e3, span * 1e3);
  }
}

}  // namespace

void check_point_count(double n, std::string_view what) {
  if (!(n <= static_cast<double>(kMaxProfilePoints)))
    fail("{} gives {:.0f} points, more than a profile may have (at most {}; is the step in metres?)", what, n,
         kMaxProfilePoints);
}

Profile make_profile(ProfileKind kind, std::vector<double> y, std::vector<double> z, std::string name,
                     std::string source, const std::vector<int>& lines) {
  if (y.size() != z.size())
    fail("{}: y has {} values but z has {}", source, y.size(), z.size());
  check_point_count(static_cast<double>(y.size()), source);
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i]) || !std::isfinite(z[i]))
      fail("{}: coordinate is not a finite number (y = {}, z = {})", where(source, lines, i), y[i], z[i]);
    if (std::max(std::abs(y[i]), std::abs(z[i])) > kMaxProfileCoordinate)
      fail("{}: the point (y = {:.6g} m, z = {:.6g} m) lies more than {:g} m from the origin, no wheel or rail profile "
           "does: are the coordinates in metres?", where(source, lines, i), y[i], z[i], kMaxProfileCoordinate);
  }
  // Drop consecutive duplicates, remembering the source line of each kept point.
  Profile p;
  p.kind = kind;
  p.name = std::move(name);
  p.source = std::move(source);
  std::vector<int> kept_lines;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!p.y.empty() && std::hypot(y[i] - p.y.back(), z[i] - p.z.back()) < kDuplicateTolerance) {
      ++p.duplicates_dropped;
      continue;
    }
    p.y.push_back(y[i]);
    p.z.push_back(z[i]);
    kept_lines.push_back(i < lines.size() ? lines[i] : 0);
  }
  if (p.duplicates_dropped > 0)
    p.transforms.push_back(fmt::format("dropped {} duplicate points", p.duplicates_dropped));
  if (p.y.size() < 3)
    fail("{}: a profile needs at least 3 distinct points, got {}", p.source, p.y.size());

  // Fold-back: y must keep one direction; a vertical run (dy ~ 0) must keep one z direction.
  const std::size_t n = p.y.size();
  int ydir = 0, zdir = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dy = p.y[i + 1] - p.y[i], dz = p.z[i + 1] - p.z[i];
    if (std::abs(dy) > kDuplicateTolerance) {
      const int d = dy > 0 ? 1 : -1;
      if (ydir == 0) ydir = d;
      if (d != ydir)
        fail("{}: the profile folds back on itself at y = {:.6f} m, z = {:.6f} m (y turns from {} to {}); "
             "a profile must be monotone in y",
             where(p.source, kept_lines, i + 1), p.y[i + 1], p.z[i + 1], ydir > 0 ? "increasing" : "decreasing",
             d > 0 ? "increasing" : "decreasing");
      zdir = 0;
    } else {
      const int d = dz > 0 ? 1 : -1;
      if (zdir != 0 && d != zdir)
        fail("{}: the profile folds back on itself on a vertical run at y = {:.6f} m, z = {:.6f} m",
             where(p.source, kept_lines, i + 1), p.y[i + 1], p.z[i + 1]);
      zdir = d;
    }
  }
  if (ydir == 0) fail("{}: all points have the same y; a profile must extend laterally", p.source);
  refuse_spike(p, kept_lines);
  if (ydir < 0) {
    std::reverse(p.y.begin(), p.y.end());
    std::reverse(p.z.begin(), p.z.end());
    p.transforms.push_back("reversed to increasing y");
  }
  return p;
}

double arc_length(const Profile& p) {
  double L = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) L += std::hypot(p.y[i + 1] - p.y[i], p.z[i + 1] - p.z[i]);
  return L;
}

namespace {

Profile resampled_copy(const Profile& p, std::vector<double> y, std::vector<double> z, std::string what) {
  Profile r;
  r.kind = p.kind;
  r.name = p.name;
  r.source = p.source;
  r.y = std::move(y);
  r.z = std::move(z);
  r.transforms = p.transforms;
  r.metadata = p.metadata;
  r.warnings = p.warnings;
  r.spline = p.spline;
  r.transforms.push_back(std::move(what));
  return r;
}

// The intervals of a resampling every `step` over `length` of arc (rounded up), checked before the points are made:
// at most kMaxProfilePoints points, and at least 3, the fewest a profile has (a step as long as the arc gave 2,
// which no later step accepts).
std::size_t arc_intervals(double length, double step) {
  const double intervals = std::max(1.0, std::ceil(length / step - 1e-9));
  check_point_count(intervals + 1, fmt::format("resample: step {:.6g} m over {:.6g} m of arc", step, length));
  if (intervals < 2)
    fail("resample: step {:.6g} m over {:.6g} m of arc gives 2 points; a profile needs at least 3 (a step shorter "
         "than the arc; is the step in metres?)", step, length);
  return static_cast<std::size_t>(intervals);
}

// Points every `step` of arc along the profile's spline between its first and last points (end points kept).
Profile resample_spline_arc(const Profile& p, double step) {
  const ProfileSpline& c = *p.spline;
  const double ta = c.closest({p.y.front(), p.z.front()}), tb = c.closest({p.y.back(), p.z.back()});
  // Arc length along t by chords of 8 sub-steps per knot interval.
  std::vector<double> ts{ta}, len{0.0};
  const double lo = std::min(ta, tb), hi = std::max(ta, tb);
  std::vector<double> cuts{lo};
  for (double k : c.t)
    if (k > lo && k < hi) cuts.push_back(k);
  cuts.push_back(hi);
  if (ta > tb) std::reverse(cuts.begin(), cuts.end());
  Eigen::Vector2d prev = c.at(ta).p;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    for (int k = 1; k <= 8; ++k) {
      const double tt = cuts[i] + (cuts[i + 1] - cuts[i]) * k / 8.0;
      const Eigen::Vector2d q = c.at(tt).p;
      ts.push_back(tt);
      len.push_back(len.back() + (q - prev).norm());
      prev = q;
    }
  const double L = len.back();
  const std::size_t m = arc_intervals(L, step);
  std::vector<double> y(m + 1), z(m + 1);
  std::size_t k = 0;
  for (std::size_t j = 0; j <= m; ++j) {
    const double target = L * static_cast<double>(j) / static_cast<double>(m);
    while (k + 2 < len.size() && len[k + 1] < target) ++k;
    const double seg = len[k + 1] - len[k];
    const double a = seg > 0 ? std::clamp((target - len[k]) / seg, 0.0, 1.0) : 0.0;
    const Eigen::Vector2d q = c.at(ts[k] + a * (ts[k + 1] - ts[k])).p;
    y[j] = q.x();
    z[j] = q.y();
  }
  y.front() = p.y.front();
  z.front() = p.z.front();
  y.back() = p.y.back();
  z.back() = p.z.back();
  return resampled_copy(p, std::move(y), std::move(z), fmt::format("resampled along the spline's arc every {:.6g} m", L / m));
}

}  // namespace

Profile resample_arc(const Profile& p, double step) {
  if (!(step > 0) || !std::isfinite(step)) fail("resample: step must be a positive number of metres, got {}", step);
  if (p.spline) return resample_spline_arc(p, step);
  const std::size_t n = p.size();
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::hypot(p.y[i] - p.y[i - 1], p.z[i] - p.z[i - 1]);
  const double L = s.back();
  const std::size_t m = arc_intervals(L, step);
  std::vector<double> y(m + 1), z(m + 1);
  std::size_t k = 0;
  for (std::size_t j = 0; j <= m; ++j) {
    const double t = L * static_cast<double>(j) / static_cast<double>(m);
    while (k + 2 < n && s[k + 1] < t) ++k;
    const double seg = s[k + 1] - s[k];
    const double a = seg > 0 ? std::clamp((t - s[k]) / seg, 0.0, 1.0) : 0.0;
    y[j] = p.y[k] + a * (p.y[k + 1] - p.y[k]);
    z[j] = p.z[k] + a * (p.z[k + 1] - p.z[k]);
  }
  y.front() = p.y.front();
  z.front() = p.z.front();
  y.back() = p.y.back();
  z.back() = p.z.back();
  return resampled_copy(p, std::move(y), std::move(z), fmt::format("resampled along the arc every {:.6g} m", L / m));
}

double interpolate(const std::vector<double>& x, const std::vector<double>& f, double xq) {
  if (xq <= x.front()) return f.front();
  if (xq >= x.back()) return f.back();
  const auto it = std::lower_bound(x.begin(), x.end(), xq);  // first x >= xq
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  if (x[i] == xq) return f[i];
  const double a = (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return f[i - 1] + a * (f[i] - f[i - 1]);
}

double interpolate_z(const Profile& p, double yq) { return interpolate(p.y, p.z, yq); }

Profile resample_y(const Profile& p, double step) {
  if (!(step > 0) || !std::isfinite(step)) fail("resample: step must be a positive number of metres, got {}", step);
  const double y0 = p.y.front(), y1 = p.y.back();
  const double intervals = std::floor((y1 - y0) / step + 1e-9);
  check_point_count(intervals + 2, fmt::format("resample: step {:.6g} m over {:.6g} m", step, y1 - y0));
  const auto m = static_cast<std::size_t>(intervals);
  std::vector<double> y, z;
  y.reserve(m + 2);
  z.reserve(m + 2);
  for (std::size_t j = 0; j <= m; ++j) {
    const double yq = y0 + step * static_cast<double>(j);
    y.push_back(yq);
    z.push_back(p.spline ? p.spline->at(p.spline->param_at_y(yq)).p.y() : interpolate_z(p, yq));
  }
  if (y1 - y.back() > kDuplicateTolerance) {
    y.push_back(y1);
    z.push_back(p.z.back());
  }
  if (y.size() < 3)
    fail("resample: step {:.6g} m over {:.6g} m of y gives {} points; a profile needs at least 3 (a step shorter "
         "than its width; is the step in metres?)", step, y1 - y0, y.size());
  return resampled_copy(p, std::move(y), std::move(z),
                        fmt::format("resampled along {}y every {:.6g} m", p.spline ? "the spline in " : "", step));
}

}  // namespace wrc
