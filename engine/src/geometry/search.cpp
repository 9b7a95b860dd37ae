// The search primitives of SearchContext: brute force in a window, the topology walk, the coarse pre-search.
//
// Bounds used by the walk. In the wheelset frame a rail line is p(x) = p0 + x a with a = A^T e_x. Its distance to
// the axle is rho(x) = |(p0_x + a_x x, p0_z + a_z x)|, smallest at x* (distance rho*), and its lateral coordinate
// Y(x) = p0_y + a_y x is linear. Seen in the meridian half-plane (Y, rho) of the wheel the line is the convex
// trace h(Y)^2 = rho*^2 + (1 - a_y^2) ((Y - Y*) / a_y)^2 (a vertical half-line at Y* when a_y = 0: zero yaw). The
// line crosses the wheel surface exactly where its trace crosses the generatrix polyline, so for a range of cones
// [a, b] (points a .. b+1):
//   - if min h over [y_a, y_b+1] exceeds the largest radius of the points, the trace passes outside every cone of
//     the range: no crossing (all are above the polyline, which is piecewise linear between those points);
//   - if max h there is below the smallest radius, it passes inside: no crossing either (flat rings included:
//     the trace passes under both of their radii).
// min h is rho* when Y* lies in the range, else h at the nearer end; max h is at an end (h is convex). The
// extrema of the radii come from sparse tables in O(1). A margin (kSkipMargin, m^2) keeps every decision well away
// from the rounding of the closed form, so a range is ruled out only when the closed form could not report a
// crossing in it either: the walk finds what brute force finds in the same window.
#include "geometry/crossings.hpp"
#include "wrc/core/error.hpp"
#include "wrc/geometry/location.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {

namespace {

constexpr double kSkipMargin = 1e-12;  // m^2 on squared radii (~1e-12 m of radius)
constexpr double kAlphaSlack = 1e-10;  // rounding band of alpha around shared circles (see location.cpp) ...
constexpr double kNearCircle = 1e-3;   // ... widened, within this of a circle, to a root's own rounding bound
constexpr int kProbe = 1;              // cones probed on each side of the previous line's crossings

// What every line of a pose shares (see the file comment).
struct PoseLines {
  const PoseFrame& f;
  double k, inv_k, inv_a12;  // 1 - a12^2, its inverse, 1 / a12 (inf at zero yaw)
  explicit PoseLines(const PoseFrame& frame)
      : f(frame), k(frame.a11 * frame.a11 + frame.a13 * frame.a13), inv_k(1.0 / k), inv_a12(1.0 / frame.a12) {}
};

// One rail line seen from the wheelset (see the file comment).
struct LineFrame {
  double y_r = 0, z_r = 0;
  double p0y = 0;     // Y at x = 0 (m)
  double a12 = 0;     // dY/dx
  double xstar = 0;   // track x of the closest approach to the axle (m)
  double ystar = 0;   // Y there (m)
  double r2star = 0;  // squared distance to the axle there (m^2)
  double k = 1;       // 1 - a12^2
  double inv_a12 = 0; // 1 / a12 (inf at zero yaw)

  LineFrame() = default;
  LineFrame(const PoseLines& P, double y, double z) : y_r(y), z_r(z), a12(P.f.a12), k(P.k), inv_a12(P.inv_a12) {
    const PoseFrame& f = P.f;
    const double dy = y - f.y, dz = z - f.z;
    const double p0x = f.a21 * dy, p0z = f.a23 * dy + f.a33 * dz;
    p0y = f.a22 * dy + f.a32 * dz;
    xstar = -(p0x * f.a11 + p0z * f.a13) * P.inv_k;
    const double cross = p0x * f.a13 - p0z * f.a11;
    r2star = cross * cross * P.inv_k;
    ystar = p0y + a12 * xstar;
  }
  double h2(double Y) const {
    const double d = Y - ystar;
    if (d == 0) return r2star;
    const double t = d * inv_a12;
    return r2star + k * t * t;
  }
  double Y_at(double x) const { return p0y + a12 * x; }
};

// Tests and walks for one level (fine or coarse) of one side, appending crossings.
class Scanner {
 public:
  Scanner(const PoseFrame& f, const WheelCones& w, const RailLines& l, std::vector<Crossing>& out, long long& tests,
          long long& bounds, long long& lines, int& hint_lo, int& hint_hi)
      : f_(f), P_(f), w_(w), l_(l), out_(out), tests_(tests), bounds_(bounds), lines_(lines), hint_lo_(hint_lo),
        hint_hi_(hint_hi) {}

  // Lines of a window that the coarse search certified (Window::skip_within), given their offsets.
  void set_skip(const std::vector<double>* offset, double within) {
    offset_ = offset;
    skip_within_ = within;
  }
  bool skipped(int r) const { return offset_ && (*offset_)[r] < skip_within_; }

  void test(const Window& win) {
    for (int r = win.line_first; r <= win.line_last; ++r) {
      if (skipped(r)) continue;
      ++lines_;
      start_line(r);
      for (int c = win.cone_first; c <= win.cone_last; ++c) closed_form(c);
    }
  }

  // prev/cur: scratch lists of the cones crossed by the previous and the current line.
  void walk(const Window& win, std::vector<int>& prev, std::vector<int>& cur) {
    prev.clear();
    const int c0 = win.cone_first, c1 = win.cone_last;
    for (int r = win.line_first; r <= win.line_last; ++r) {
      if (skipped(r)) {
        prev.clear();
        continue;
      }
      ++lines_;
      start_line(r);
      cur_ = &cur;
      cur.clear();
      if (prev.empty()) {
        reach(c0, c1);
      } else {
        // Probe the cones the previous line crossed (topology: the next line crosses cones nearby), certify or
        // split the ranges between them.
        int pos = c0;
        std::size_t i = 0;
        while (i < prev.size() && pos <= c1) {
          int p0 = std::max(prev[i] - kProbe, pos), p1 = std::min(prev[i] + kProbe, c1);
          ++i;
          while (i < prev.size() && prev[i] - kProbe <= p1 + 1) p1 = std::min(prev[i++] + kProbe, c1);
          if (p0 > p1) continue;
          if (pos < p0) classify(pos, p0 - 1);
          for (int c = p0; c <= p1; ++c) leaf(c);
          pos = p1 + 1;
        }
        if (pos <= c1) classify(pos, c1);
      }
      std::swap(prev, cur);
      // Few entries: insertion sort, then drop repeats.
      for (std::size_t a = 1; a < prev.size(); ++a)
        for (std::size_t b = a; b > 0 && prev[b] < prev[b - 1]; --b) std::swap(prev[b], prev[b - 1]);
      prev.erase(std::unique(prev.begin(), prev.end()), prev.end());
    }
    cur_ = nullptr;
  }

 private:
  void start_line(int r) {
    r_ = r;
    line_ = LineFrame(P_, l_.y[r], l_.z[r]);
  }

  // classify(a, b) restricted first to the cones the line can reach: outside [Y* - W, Y* + W], where
  // h^2 = r2max (the largest radius of the range), the trace is above every point of the range.
  void reach(int a, int b) {
    ++bounds_;
    double rmin, rmax;
    w_.r2_range.extrema(a, b + 1, rmin, rmax);
    const double top = rmax + kSkipMargin;
    if (line_.r2star > top) return;
    const double W = std::sqrt((top - line_.r2star) / line_.k) * std::abs(line_.a12);
    const double lo = line_.ystar - W, hi = line_.ystar + W;
    // First cone of a..b whose y range reaches lo (y[c + 1] >= lo), last one starting at or before hi (y[c] <= hi),
    // searched from the previous line's answer (lines move little from one to the next).
    const double* y = w_.y.data();
    int ca = seek_first(y, a, b, std::clamp(hint_lo_, a, b), lo);
    int cb = seek_last(y, a, b, std::clamp(hint_hi_, a, b), hi);
    hint_lo_ = ca;
    hint_hi_ = cb;
    if (ca > cb || y[ca + 1] < lo || y[cb] > hi) return;
    // Shrink again with the largest radius of the reachable cones only (certified the same way: outside the new
    // range the trace is above that radius, which bounds every point of the old range), while it helps.
    for (int pass = 0; pass < 3 && ca < cb; ++pass) {
      ++bounds_;
      w_.r2_range.extrema(ca, cb + 1, rmin, rmax);
      const double top2 = rmax + kSkipMargin;
      if (line_.r2star > top2) return;
      const double W2 = std::sqrt((top2 - line_.r2star) / line_.k) * std::abs(line_.a12);
      const int na = seek_first(y, ca, cb, ca, line_.ystar - W2), nb = seek_last(y, ca, cb, cb, line_.ystar + W2);
      if (na > nb || y[na + 1] < line_.ystar - W2 || y[nb] > line_.ystar + W2) return;
      if (na == ca && nb == cb) break;
      ca = na;
      cb = nb;
    }
    classify(ca, cb);
  }

public:
  // Smallest c in [a, b] with y[c + 1] >= v (b if none), starting from c.
  static int seek_first(const double* y, int a, int b, int c, double v) {
    int steps = 0;
    while (c > a && y[c] >= v) {  // y[c] = y[(c - 1) + 1] >= v: c - 1 qualifies too
      if (++steps > 8) return static_cast<int>(std::lower_bound(y + a + 1, y + c + 1, v) - y) - 1;
      --c;
    }
    while (c < b && y[c + 1] < v) {
      if (++steps > 8) return std::min(b, static_cast<int>(std::lower_bound(y + c + 1, y + b + 2, v) - y) - 1);
      ++c;
    }
    return c;
  }
  // Largest c in [a, b] with y[c] <= v (a if none), starting from c.
  static int seek_last(const double* y, int a, int b, int c, double v) {
    int steps = 0;
    while (c < b && y[c + 1] <= v) {
      if (++steps > 8) return static_cast<int>(std::upper_bound(y + c + 1, y + b + 1, v) - y) - 1;
      ++c;
    }
    while (c > a && y[c] > v) {
      if (++steps > 8) return std::max(a, static_cast<int>(std::upper_bound(y + a, y + c, v) - y) - 1);
      --c;
    }
    return c;
  }

private:
  // One cone: the bounds, then the closed form if they do not rule it out.
  void leaf(int c) {
    ++bounds_;
    const double Ya = w_.y[c], Yb = w_.y[c + 1];
    const double ha = line_.h2(Ya), hb = line_.h2(Yb);
    const double hmin = (line_.ystar >= Ya && line_.ystar <= Yb) ? line_.r2star : std::min(ha, hb);
    const double ra = w_.r2[c], rb = w_.r2[c + 1];
    if (hmin > std::max(ra, rb) + kSkipMargin) return;
    if (std::max(ha, hb) < std::min(ra, rb) - kSkipMargin) return;
    closed_form(c);
  }

  // Rules out the cones a..b with the bounds of the file comment, splitting the range until each part is ruled
  // out or is one cone, which gets the closed form.
  void classify(int a, int b) {
    int stack[128][2];
    int top = 0;
    stack[top][0] = a;
    stack[top][1] = b;
    ++top;
    while (top > 0) {
      --top;
      const int lo = stack[top][0], hi = stack[top][1];
      if (hi - lo < 3) {  // a few cones: their own checks cost less than a range check and a split
        for (int c = lo; c <= hi; ++c) leaf(c);
        continue;
      }
      ++bounds_;
      const double Ya = w_.y[lo], Yb = w_.y[hi + 1];
      const double ha = line_.h2(Ya), hb = line_.h2(Yb);
      const double hmin = (line_.ystar >= Ya && line_.ystar <= Yb) ? line_.r2star : std::min(ha, hb);
      double rmin, rmax;
      w_.r2_range.extrema(lo, hi + 1, rmin, rmax);
      if (hmin > rmax + kSkipMargin) continue;                // trace outside the whole range
      if (std::max(ha, hb) < rmin - kSkipMargin) continue;    // inside the whole range
      const int mid = lo + (hi - lo) / 2;
      // Near half first (the one holding Y*), so crossings come in increasing order of distance from it.
      stack[top][0] = mid + 1;
      stack[top][1] = hi;
      ++top;
      stack[top][0] = lo;
      stack[top][1] = mid;
      ++top;
    }
  }

  void closed_form(int c) {
    ++tests_;
    ConeLineRoot roots[2];
    const double *wy = w_.y.data() + c, *wz = w_.z.data() + c;
    const int n = cone_line_intersections(f_, line_.y_r, line_.z_r, wy[0], wz[0], wy[1], wz[1], roots, kNearCircle);
    bool found = false;
    for (int i = 0; i < n; ++i) {
      // The band at the circles: kAlphaSlack, or a root's own rounding bound, which far exceeds it where the line
      // grazes a circle (cone_line_alpha_error; computed only for roots this near a circle, a few per line at most).
      const double alpha = roots[i].alpha;
      double band = kAlphaSlack;
      if (alpha < kNearCircle || alpha > 1 - kNearCircle)
        band = std::clamp(cone_line_alpha_error(f_, line_.y_r, line_.z_r, wy[0], wz[0], wy[1], wz[1], roots[i]),
                          kAlphaSlack, kNearCircle);
      if (!(alpha > -band && alpha <= 1 + band)) continue;
      found = true;
      Crossing x;
      x.line = r_;
      x.cone = c;
      x.x = roots[i].x;
      x.alpha = alpha;
      x.vertex = alpha <= band ? c : (alpha > 1 - band ? c + 1 : -1);
      x.branch = roots[i].x >= line_.xstar ? 1 : -1;
      x.root = static_cast<signed char>(i);
      out_.push_back(x);
    }
    if (found && cur_) cur_->push_back(c);
  }

  const PoseFrame& f_;
  PoseLines P_;
  const WheelCones& w_;
  const RailLines& l_;
  std::vector<Crossing>& out_;
  long long &tests_, &bounds_, &lines_;
  std::vector<int>* cur_ = nullptr;
  int r_ = 0;
  int &hint_lo_, &hint_hi_;  // reach's last cone indices (kept across windows and poses)
  const std::vector<double>* offset_ = nullptr;
  double skip_within_ = 0;
  LineFrame line_;
};

}  // namespace

SearchContext::SearchContext(const GeometryModel& model, LocationState& state) : model_(model), state_(state) {}

const Pose& SearchContext::pose() const { return state_.pose(); }

void SearchContext::check_window(int side, const Window& w, const char* what) const {
  if (side != kLeft && side != kRight) fail("{}: side must be left or right", what);
  const int nl = line_count(side), nc = cone_count(side);
  if (w.line_first < 0 || w.line_last >= nl || w.line_first > w.line_last || w.cone_first < 0 || w.cone_last >= nc ||
      w.cone_first > w.cone_last)
    fail("{}: window lines {}..{} x cones {}..{} is outside the {} side's {} lines x {} cones (1-based in Lua: add 1)",
         what, w.line_first, w.line_last, w.cone_first, w.cone_last, side_name(side), nl, nc);
}

namespace {

// The scanner of one side's fine lines and cones at the state's pose, writing into the state (with the coarse
// level's skip bound when the window carries one).
template <class PerSide>  // LocationState::PerSide (private; deduced)
Scanner side_scanner(const GeometryModel& model, PerSide& s, const PoseFrame& frame, int side,
                     const Window& w) {
  Scanner sc(frame, model.side[side].wheel, model.side[side].rail, s.crossings, s.counters.tests, s.counters.bounds,
             s.counters.lines, s.hint_lo, s.hint_hi);
  if (w.skip_within > 0 && model.side[side].coarse) sc.set_skip(&model.side[side].coarse->offset, w.skip_within);
  return sc;
}

}  // namespace

void SearchContext::test(int side, const Window& w) {
  check_window(side, w, "test");
  side_scanner(model_, state_.side_[side], state_.frame(), side, w).test(w);
}

void SearchContext::walk(int side, const Window& w) {
  check_window(side, w, "walk");
  auto& s = state_.side_[side];
  side_scanner(model_, s, state_.frame(), side, w).walk(w, s.scratch_int, s.scratch_int2);
}

// Coarse pre-search (paper Fig. 3).
//
// Claim: if a fine line r of cell c crosses the fine wheel surface on cone w, then the coarse line c enters the
// coarse wheel, and cone w overlaps [Ymin - D, Ymax + D], the wheelset-frame y range of one of the coarse line's
// segments (pieces inside the coarse wheel) widened by the dilation D.
// Proof: let q be the crossing point, P_r and P_c the (y, z) points of the fine and coarse lines, v = P_c - P_r,
// |v| <= D (the cell's size, CoarseLevel). q lies on the fine wheel's surface, so in the fine solid W; q' = q + v lies
// on the coarse line and within D of W. The coarse solid contains W dilated by D (built by offset_outward and
// checked by build_geometry in the meridian half-plane, which suffices: two points at distance <= D have meridian
// images at distance <= D, since |Y - Y'| and |rho - rho'| are bounded by the distance), so q' is inside the
// coarse solid, i.e. in a segment [x_t, x_l] of the coarse line, whose y range is [Ymin, Ymax] (Y is linear along
// the line). The wheelset-frame y of q differs from q''s by at most |v| <= D, and cone w's closed y range contains
// q's y. The coarse segments are complete because the coarse walk is (it finds what brute force finds, see walk).
// So the windows (cell's lines) x (cones overlapping the widened ranges) hold every fine crossing of the side.
// A coarse line with an odd number of crossings (a rounding graze) gets the whole cone range, which is safe.
// Lines skipped inside a window: the ball of radius D - |v| about q' lies in W dilated by D, so in the coarse solid;
// in the meridian half-plane (where that ball's image holds the disc of the same radius) q' is then at least
// D - |v| below the coarse generatrix, so the coarse line's radial depth inside the coarse wheel reaches D - |v|.
// That depth is at most P = (largest coarse radius over the y range of the coarse segment) - rho* (the coarse
// line's least distance to the axle). Hence |v| >= D - P for every fine line that crosses: the lines of the cell
// closer than D - P to the coarse line cannot cross (Window::skip_within, CoarseLevel::offset).
int SearchContext::coarse(int side) {
  if (side != kLeft && side != kRight) fail("coarse: side must be left or right");
  const SideGeometry& g = model_.side[side];
  if (!g.coarse)
    fail("coarse: the {} side has no coarse level (the strategy's discretisation must set coarse = {{every = ...}})",
         side_name(side));
  const CoarseLevel& c = *g.coarse;
  auto& s = state_.side_[side];
  s.windows.clear();
  s.have_windows = true;
  s.coarse_crossings.clear();
  long long bounds = 0, lines = 0;
  Scanner sc(state_.frame(), c.wheel, c.lines, s.coarse_crossings, s.counters.coarse_tests, bounds, lines,
             s.coarse_hint_lo, s.coarse_hint_hi);
  sc.walk({0, c.lines.count() - 1, 0, c.wheel.cone_count() - 1}, s.scratch_int, s.scratch_int2);
  s.counters.bounds += bounds;

  auto& xs = s.coarse_crossings;
  std::sort(xs.begin(), xs.end(), [](const Crossing& a, const Crossing& b) {
    if (a.line != b.line) return a.line < b.line;
    if (a.x != b.x) return a.x < b.x;
    return a.cone < b.cone;
  });
  const double widen = c.dilation + 1e-9;
  const int nc = g.wheel.cone_count();
  std::vector<std::pair<int, int>>& ranges = s.scratch_ranges;
  int coarse_grazes = 0;
  for (std::size_t i = 0; i < xs.size();) {
    std::size_t j = i;
    while (j < xs.size() && xs[j].line == xs[i].line) ++j;
    const int cl = xs[i].line;
    ranges.clear();
    double skip_within = 0;
    // The same clean-up as the fine segments (shared circles); a count that stays odd gets every cone (safe).
    if (!detail::clean_line(xs, i, j, coarse_grazes)) {
      ranges.emplace_back(0, nc - 1);
    } else {
      const LineFrame lf(PoseLines(state_.frame()), c.lines.y[cl], c.lines.z[cl]);
      double depth = 0;  // upper bound of the coarse line's radial depth inside the coarse wheel (see below)
      const int ncc = c.wheel.cone_count();
      for (std::size_t k = i; k < j; k += 2) {
        const double ya = lf.Y_at(xs[k].x), yb = lf.Y_at(xs[k + 1].x);
        const double* cy = c.wheel.y.data();
        const int ca = Scanner::seek_first(cy, 0, ncc - 1, std::clamp(xs[k].cone, 0, ncc - 1), std::min(ya, yb));
        const int cb = Scanner::seek_last(cy, 0, ncc - 1, std::clamp(xs[k + 1].cone, ca, ncc - 1), std::max(ya, yb));
        depth = std::max(depth, std::sqrt(c.wheel.r2_range.max(ca, std::max(ca, cb) + 1)) - std::sqrt(lf.r2star));
        const double lo = std::min(ya, yb) - widen, hi = std::max(ya, yb) + widen;
        const double* y = g.wheel.y.data();
        const int a = Scanner::seek_first(y, 0, nc - 1, std::clamp(s.hint_lo, 0, nc - 1), lo);
        const int b = Scanner::seek_last(y, 0, nc - 1, std::clamp(s.hint_hi, a, nc - 1), hi);
        ranges.emplace_back(a, b);
      }
      std::sort(ranges.begin(), ranges.end());
      skip_within = c.dilation - depth - 1e-9;
    }
    // Merge overlapping or touching ranges, one window each.
    for (std::size_t k = 0; k < ranges.size();) {
      int a = ranges[k].first, b = ranges[k].second;
      std::size_t m = k + 1;
      while (m < ranges.size() && ranges[m].first <= b + 1) b = std::max(b, ranges[m++].second);
      if (a <= b) s.windows.push_back({c.cell_first[cl], c.cell_last[cl], a, b, std::max(0.0, skip_within)});
      k = m;
    }
    i = j;
  }
  return static_cast<int>(s.windows.size());
}

const std::vector<Window>& SearchContext::windows(int side) const { return state_.side_[side].windows; }

void SearchContext::test_windows(int side) {
  if (!state_.side_[side].have_windows) fail("test_windows: no windows at this pose (call coarse first)");
  const std::vector<Window> ws = state_.side_[side].windows;  // test may not invalidate, but keep it simple
  for (const Window& w : ws) test(side, w);
}

void SearchContext::walk_windows(int side) {
  if (!state_.side_[side].have_windows) fail("walk_windows: no windows at this pose (call coarse first)");
  for (std::size_t i = 0; i < state_.side_[side].windows.size(); ++i) {
    const Window w = state_.side_[side].windows[i];
    walk(side, w);
  }
}

void NativeSearch::search(SearchContext& ctx, int side) {
  if (plan_.coarse) {
    ctx.coarse(side);
    if (plan_.scan == NativePlan::Scan::walk) ctx.walk_windows(side);
    else ctx.test_windows(side);
  } else {
    if (plan_.scan == NativePlan::Scan::walk) ctx.walk(side, ctx.all(side));
    else ctx.test(side, ctx.all(side));
  }
}

}  // namespace wrc
