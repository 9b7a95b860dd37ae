// Pieces of the patch -> normal problem bridge shared by the planar path (contact.cpp) and the conformal path
// (conformal.cpp). Not part of the public API.
#pragma once

#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/wheelset/contact.hpp"

#include <Eigen/Core>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wrc::contact_detail {

inline double thread_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Adds the thread CPU time of its scope to a field of the workspace's times (when timing is on).
class PhaseTimer {
 public:
  PhaseTimer(const ContactWorkspace& ws, double& slot) : slot_(ws.timing ? &slot : nullptr) {
    if (slot_) t0_ = thread_seconds();
  }
  ~PhaseTimer() {
    if (slot_) *slot_ += thread_seconds() - t0_;
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double* slot_;
  double t0_ = 0;
};

// What the plane and h need of one segment.
struct SegmentInfo {
  int line = 0;
  double y = 0, z = 0;         // rail line (track frame)
  double xm = 0, L = 0, R = 0; // mid-point x, length, arc radius (m)
  double weight = 0;           // share of the inter-penetration volume (m^3)
  Eigen::Vector3d mid, normal; // mid-point (track frame) and the wheel's inward normal there
  double sagitta = 0;          // arc height at the mid-point (m)
};

inline double arc_height(double R, double dx) {
  const double q = R * R - dx * dx;
  return q > 0 ? std::sqrt(q) : -R;  // beyond the arc's reach: far below (any negative h means "no contact")
}

// Radius of the wheel's section along a rail line (contact.cpp).
double arc_radius(const WheelSurfacePoint& s, double yaw);

struct Plane {
  Eigen::Vector3d O, n, t1, t2;
};

// h along one rail line as a function of x: the arcs of its segments, or the arc through its deepest point.
struct LineProfile {
  double v = 0, u0 = 0;          // plane coordinates: v of the line, u of its point at x = 0
  std::vector<const SegmentInfo*> arcs;
  double apex = 0, x_apex = 0, R = 1;  // no segment: arc with height `apex` (< 0) at x_apex
  double height(double x) const {
    if (arcs.empty()) return apex + arc_height(R, x - x_apex) - R;
    double h = -INFINITY;
    for (const SegmentInfo* s : arcs) h = std::max(h, arc_height(s->R, x - s->xm) - (s->R - s->sagitta));
    return h;
  }
  // height at x[0 .. n) into out, the same numbers computed arc by arc (a loop the compiler vectorises).
  void heights(const double* x, std::size_t n, double* out) const {
    if (arcs.empty()) {
      for (std::size_t i = 0; i < n; ++i) out[i] = height(x[i]);
      return;
    }
    std::fill_n(out, n, -INFINITY);
    for (const SegmentInfo* s : arcs) {
      const double drop = s->R - s->sagitta;
      for (std::size_t i = 0; i < n; ++i) out[i] = std::max(out[i], arc_height(s->R, x[i] - s->xm) - drop);
    }
  }
};

// Separate contact regions of a solution (8-connected, each >= 0.1 % of the force).
int contact_regions(const halfspace::NormalSolution& sol);
// The normal problem of one area on its grid (contact.cpp), at the request's tolerance, warm-started from the
// workspace's last evaluation of that side (extrapolated with the one before when the workspace extrapolates). A
// conformal area passes its unrolled coordinates as the plane (origin (x, s, 0), axes e_x, e_y, normal e_z).
// vertical: per grid row, the vertical part of its normal (for the request's vertical_force); deepening: per row,
// dh/dz (h's growth as the wheel moves down; the request's vertical approach enters the gap so).
halfspace::NormalSolution solve_area_normal(const ContactModel& model, const ContactRequest& request, int side,
                                          const Plane& pl, const halfspace::Grid& grid, const std::vector<double>& h,
                                          const std::vector<double>& vertical, const std::vector<double>& deepening,
                                          ContactWorkspace& ws);
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
// A potential contact area of nx x ny elements exceeds max_elements (contact.cpp): an error that says whether the
// grid is too fine for the cap or the pose far too deep.
[[noreturn]] void too_many_elements(const ContactOptions& opt, const std::vector<SegmentInfo>& all, int side,
                                    const Pose& pose, double nx, double ny);
// The grid of two index spans (x along the first axis, y along the second) of element e, or too_many_elements when it
// holds more than max_elements.
halfspace::Grid span_grid(const ContactOptions& opt, const IndexSpan& x, const IndexSpan& y,
                        const std::vector<SegmentInfo>& all, int side, const Pose& pose);
// The located patches of a group and their segments, copied into the result.
void copy_located(const LocationState& st, int side, const std::vector<int>& group, PatchContact& pc);

// The conformal path (conformal.cpp): one area solved on the curved surface, its sensitivities, its fields.
PatchContact solve_conformal_area(const ContactModel& model, const LocationState& st, int side,
                                  const std::vector<SegmentInfo>& all, const Patch& first, ContactWorkspace& ws,
                                  const ContactRequest& request, std::vector<ContactWorkspace::Previous>& next_previous);
void conformal_sensitivity(const ContactModel& model, const Pose& pose, PatchContact& pc, ContactWorkspace& ws);
void describe_conformal(const PatchContact& pc, FieldSink& out);

}  // namespace wrc::contact_detail
