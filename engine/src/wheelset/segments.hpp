// The located segments of a contact area as the surfaces lay it out (surface.hpp; wrc/wheelset/contact.hpp says how):
// each segment's arc, volume weight and wheel normal, the plane through them, h along one rail line, the index spans
// of a grid and its cap. Small pieces that the planar and conformal surfaces and the grouping of areas (contact.cpp)
// share; none of them calls a surface or the area pipeline. Internal, not installed.
#pragma once

#include "wrc/geometry/location.hpp"
#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/wheelset/contact.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

// The internals of the contact areas of a wheelset pose: from the located patches of a wheel to solved areas.
namespace wrc::areas {

inline double arc_height(double R, double dx) {
  const double q = R * R - dx * dx;
  return q > 0 ? std::sqrt(q) : -R;  // beyond the arc's reach: far below (any negative h means "no contact")
}

// What the plane and h need of one segment. h along it is the circular arc through its ends plus, under yaw, a
// correction that is linear between knots (segments.cpp, section_correction, says why).
struct SegmentInfo {
  int line = 0;
  double y = 0, z = 0;         // rail line (track frame)
  double xm = 0, L = 0, R = 0; // mid-point x, length, arc radius (m)
  double weight = 0;           // share of the inter-penetration volume (m^3)
  Eigen::Vector3d mid, normal; // mid-point (track frame) and the wheel's inward normal there (at its lateral position)
  double rim = 0;              // the arc's height at the mid-point (m)
  double sagitta = 0;          // h at the mid-point (m): rim plus the correction there
  // Under yaw: the correction's knots (x, value; m), ascending track x strictly between the segment's ends; the
  // correction is zero at the ends and beyond them. Empty at yaw 0.
  struct Knot {
    double x, h;
  };
  // A few knots in place (a segment at a small yaw passes under a few profile points), more on the heap: no allocation
  // per segment in the common case.
  class Knots {
   public:
    void reserve(std::size_t n) {
      if (n > kInPlace) heap_.reserve(n);
    }
    void push_back(const Knot& k) {
      if (heap_.empty() && n_ < kInPlace) {
        local_[n_++] = k;
        return;
      }
      if (heap_.empty()) heap_.assign(local_.begin(), local_.end());
      heap_.push_back(k);
      ++n_;
    }
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }
    const Knot* begin() const { return heap_.empty() ? local_.data() : heap_.data(); }
    const Knot* end() const { return begin() + n_; }
    Knot* begin() { return heap_.empty() ? local_.data() : heap_.data(); }
    Knot* end() { return begin() + n_; }
    const Knot& operator[](std::size_t k) const { return begin()[k]; }

   private:
    static constexpr std::size_t kInPlace = 6;
    std::array<Knot, kInPlace> local_{};
    std::vector<Knot> heap_;
    std::size_t n_ = 0;
  };
  Knots knots;
  double arc(double x) const { return arc_height(R, x - xm) - (R - rim); }
  double correction(double x) const;
  // The correction between knots k - 1 and k (the ends: 0); inline, so that a loop over x at one k keeps the ends.
  double knot_lerp(std::size_t k, double x) const {
    const std::size_t m = knots.size();
    const double xa = k == 0 ? xm - 0.5 * L : knots[k - 1].x, ha = k == 0 ? 0.0 : knots[k - 1].h;
    const double xb = k == m ? xm + 0.5 * L : knots[k].x, hb = k == m ? 0.0 : knots[k].h;
    return ha + (hb - ha) * (x - xa) / (xb - xa);
  }
  double height(double x) const { return arc(x) + correction(x); }
};

// The segments of a located patch, appended to `out`.
void collect_segments(const GeometryModel& g, const LocationState& st, int side, const Patch& p,
                      std::vector<SegmentInfo>& out);

// Radius of the wheel's section along a rail line at a wheelset-frame lateral position (segments.cpp says why).
double arc_radius(const WheelSurfacePoint& s, double yaw);

struct Plane {
  Eigen::Vector3d O, n, t1, t2;
};

// The plane tangent to the wheel at the segments' weighted mid-point (wrc/wheelset/contact.hpp); the paper's nominal
// point of `fallback` when only tangencies are left. Its normal: the segments' `normal`s weighted (grouping the areas,
// sizing their grids).
Plane plane_of(const std::vector<SegmentInfo>& infos, const Patch& fallback);
// The same with each mid-point's normal at its normal foot (wheel_foot_normal: the direction of its depth, turned
// from `normal` by kappa d tan(delta) inside a curved profile): the planar surface's plane. feet: mid_feet's.
Plane foot_plane_of(const WheelCones& wheel, const PoseFrame& frame, const std::vector<SegmentInfo>& infos,
                    const std::vector<WheelNormalFoot>& feet, const Patch& fallback);
// The normal foot of each segment's mid-point (wheel_normal_foot), in the order of infos.
std::vector<WheelNormalFoot> mid_feet(const WheelCones& wheel, const PoseFrame& frame,
                                      const std::vector<SegmentInfo>& infos);

// The rectangle of a plane's coordinates (u along t1, v along t2) that holds the segments' end points.
struct Bounds {
  double umin = INFINITY, umax = -INFINITY, vmin = INFINITY, vmax = -INFINITY;
};
Bounds projected_bounds(const std::vector<SegmentInfo>& infos, const Plane& pl);

// The depth along the wheel's normal from the radial one turned onto it, d = n_r (r(Y) - distance to the axle): the
// radial foot of a point lies d tan(delta) along the profile from its normal foot, and over that distance the profile
// bends, so d exceeds the closest-point distance by the relative kappa d tan^2(delta) / 2 (kappa the profile's
// curvature, delta its slope; 4 % at the S1002 flange root's 67-70 deg at 0.2 mm). `bend` is that
// kappa tan^2(delta) / 2 (1/m, depth_bend: fitted to the exact depth at the line's deepest point); the product is bounded so that h keeps its sign and stays monotone far
// from contact, where the expansion does not hold and only the sign counts.
inline double normal_depth(double d, double bend) {
  return d * (1 - std::clamp(bend * d, -0.25, 0.25));
}
// Its derivative in d: how much of a change of the radial depth reaches h (the sensitivities' and the vertical load's
// factor per element).
inline double normal_depth_slope(double d, double bend) {
  const double u = bend * d;
  return u > 0.25 ? 0.75 : u < -0.25 ? 1.25 : 1 - 2 * u;
}

// h along one rail line as a function of x: the arcs of its segments, or the arc through its deepest point, as depths
// along the wheel's normal (normal_depth with the line's `bend`, the wheel's at the line's deepest point).
struct LineProfile {
  double v = 0, u0 = 0;          // plane coordinates: v of the line, u of its point at x = 0
  std::vector<const SegmentInfo*> arcs;
  double apex = 0, x_apex = 0, R = 1;  // no segment: arc with height `apex` (< 0) at x_apex
  double bend = 0;                     // normal_depth's (1/m)
  // normal_depth's bend as a function of x along a line with segments: (x, bend) ascending, linear between, constant
  // beyond (fit_bend says why). Empty: `bend` everywhere.
  SegmentInfo::Knots bends;
  // The radial depth turned onto the normal (before normal_depth).
  double radial(double x) const {
    if (arcs.empty()) return apex + arc_height(R, x - x_apex) - R;
    double h = -INFINITY;
    for (const SegmentInfo* s : arcs) h = std::max(h, s->height(x));
    return h;
  }
  // normal_depth(radial(x), the bend at x) at ascending x[0 .. n) into out and its normal_depth_slope into slope, each
  // x's numbers as a single x gives them, the corrections' knots and the bend's samples walked along instead of
  // searched for each x (the planar surface's columns).
  void walked_heights(const double* x, std::size_t n, double* out, double* slope) const;
  // h at x[0 .. n) into out computed arc by arc and interval by interval between the knots and samples (a loop the
  // compiler vectorises; the same as walked_heights but for rounding); with `slope`, normal_depth_slope there too.
  void heights(const double* x, std::size_t n, double* out, double* slope = nullptr) const {
    radials(x, n, out);
    if (!bends.empty()) return bent_heights(x, n, out, slope);
    if (bend == 0) {
      if (slope) std::fill_n(slope, n, 1.0);
      return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double u = std::clamp(bend * out[i], -0.25, 0.25);  // normal_depth and its slope in one pass
      if (slope) slope[i] = u == bend * out[i] ? 1 - 2 * u : 1 - u;
      out[i] *= 1 - u;
    }
  }
  // normal_depth with the bend linear between its samples at ascending x[0 .. n) of the radial depths in out (and its
  // slope).
  void bent_heights(const double* x, std::size_t n, double* out, double* slope) const;
  void radials(const double* x, std::size_t n, double* out) const {
    if (arcs.empty()) {
      for (std::size_t i = 0; i < n; ++i) out[i] = radial(x[i]);
      return;
    }
    std::fill_n(out, n, -INFINITY);
    for (const SegmentInfo* s : arcs) {
      const double drop = s->R - s->rim;
      if (s->knots.empty()) {
        for (std::size_t i = 0; i < n; ++i) out[i] = std::max(out[i], arc_height(s->R, x[i] - s->xm) - drop);
        continue;
      }
      corrected_heights(*s, x, n, out);
    }
  }
  // One arc with its correction at ascending x[0 .. n), maximised into out.
  static void corrected_heights(const SegmentInfo& s, const double* x, std::size_t n, double* out);
};

// LineProfile's bend along a line whose deepest segment is s, fitted at a few points of s (segments.cpp says why); foot:
// the normal foot of s's mid-point (wheel_normal_foot), whose depth the bend at that point is fitted to.
void fit_bend(const WheelCones& wheel, const PoseFrame& frame, const SegmentInfo& s, const WheelNormalFoot& foot,
              LineProfile& lp);

// h along the rail line (y, z) that has no segment: the arc through the line's deepest point, whose (negative) height
// is the exact radial gap times cos(conicity), so that h is continuous when the line starts to penetrate. Sets lp's
// apex, x_apex and R; returns the deepest point.
LineApproach arc_through_deepest(const WheelCones& wheel, const LocationState& st, double y, double z, LineProfile& lp);

// The element indices of a lattice of element e that cover [lo, hi] (m) plus `margin` elements on each side: the
// first index and the count, in double -- a grid of 1e-30 m would overflow any integer type, and the count must be
// compared with max_elements before it is converted.
struct IndexSpan {
  double first = 0, count = 0;
};
inline IndexSpan index_span(double lo, double hi, double e, int margin) {
  const double first = std::floor(lo / e) - margin;
  return {first, std::ceil(hi / e) + margin - first + 1};
}
// A potential contact area of nx x ny elements exceeds max_elements: an error that says whether the grid is too fine
// for the cap or the pose far too deep.
[[noreturn]] void too_many_elements(const ContactOptions& opt, const std::vector<SegmentInfo>& all, int side,
                                    const Pose& pose, double nx, double ny);
// The grid of two index spans (x along the first axis, y along the second) of element e, or too_many_elements when it
// holds more than max_elements.
halfspace::Grid span_grid(const ContactOptions& opt, const IndexSpan& x, const IndexSpan& y,
                          const std::vector<SegmentInfo>& all, int side, const Pose& pose);

}  // namespace wrc::areas
