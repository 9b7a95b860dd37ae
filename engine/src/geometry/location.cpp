// From crossings to segments and patches (location.hpp), and the per-pose entry points.
//
// Crossings at a shared circle. The appendix counts a crossing through the circle shared by cones w-1 and w once,
// through alpha in ]0, 1] (on cone w-1, alpha = 1). In floating point the two cones compute that crossing
// independently, so rounding may put it at alpha = 1 + 1e-16 on w-1 AND alpha = -1e-16 on w (lost), or inside both
// (counted twice). The searches therefore accept alpha in ]-s, 1 + s] (s = 1e-10, far above rounding, far below any
// geometric scale) and flag the roots within s of a shared circle; here two flagged crossings of one line at the
// same circle, from different cones and on the same side of the line's closest approach to the axle, are the same
// crossing (on one such side the line's trace in the meridian plane is monotone, so it meets the neighbourhood of a
// circle once unless it grazes it), and one is kept: the one with alpha in ]0, 1], else the one on cone w-1. A line
// that merely touches a shared circle (a graze: the trace meets the corner of the polyline without entering) then
// has one crossing too many; it is dropped (counted in grazes_dropped). Any other odd count means a search window
// cut a segment, which is an error of the strategy.
#include "geometry/crossings.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/union_find.hpp"
#include "wrc/geometry/location.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace wrc {

namespace detail {

bool canonical(const Crossing& c) { return c.alpha > 0 && c.alpha <= 1; }

// Crossings of one line, sorted by x: merges duplicates at shared circles, drops a graze if the count is odd.
// Returns false if the count stays odd.
bool clean_line(std::vector<Crossing>& v, std::size_t a, std::size_t& b, int& grazes) {
  // The common case: an even count, no flagged crossing, no repeated (cone, root).
  if ((b - a) % 2 == 0) {
    bool plain = true;
    for (std::size_t i = a; i < b && plain; ++i) {
      plain = v[i].vertex < 0;
      for (std::size_t j = a; j < i && plain; ++j) plain = v[j].cone != v[i].cone || v[j].root != v[i].root;
    }
    if (plain) return true;
  }
  // Same crossing found twice (overlapping windows): the same root of the same cone. (The two roots of a
  // tangency share x and are both kept: a zero-length segment, as d >= 0 counts it.)
  std::size_t out = a;
  for (std::size_t i = a; i < b; ++i) {
    bool dup = false;
    for (std::size_t j = a; j < out && !dup; ++j) dup = v[j].cone == v[i].cone && v[j].root == v[i].root && v[j].x == v[i].x;
    if (!dup) v[out++] = v[i];
  }
  b = out;
  // One crossing seen by both cones of a shared circle.
  for (std::size_t i = a; i < b; ++i) {
    if (v[i].vertex < 0) continue;
    for (std::size_t j = i + 1; j < b; ++j) {
      if (v[j].vertex != v[i].vertex || v[j].branch != v[i].branch || v[j].cone == v[i].cone) continue;
      const bool keep_i = canonical(v[i]) != canonical(v[j]) ? canonical(v[i]) : v[i].cone < v[j].cone;
      const std::size_t drop = keep_i ? j : i;
      v.erase(v.begin() + static_cast<long>(drop));
      --b;
      if (!keep_i) {
        --i;  // v[i] was dropped; look at the element now at i again
        break;
      }
      --j;
    }
  }
  if ((b - a) % 2 == 0) return true;
  // A graze at a shared circle: drop the flagged crossing closest to its circle.
  std::size_t best = b;
  double best_d = 2;
  for (std::size_t i = a; i < b; ++i) {
    if (v[i].vertex < 0) continue;
    const double d = v[i].vertex == v[i].cone ? std::abs(v[i].alpha) : std::abs(1 - v[i].alpha);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  if (best == b) return false;
  v.erase(v.begin() + static_cast<long>(best));
  --b;
  ++grazes;
  return true;
}

}  // namespace detail

void check_pose(const GeometryModel& model, const Pose& pose) {
  if (!std::isfinite(pose.y) || !std::isfinite(pose.z) || !std::isfinite(pose.roll) || !std::isfinite(pose.yaw))
    fail("contact: the pose must be finite (y = {}, z = {}, roll = {}, yaw = {})", pose.y, pose.z, pose.roll, pose.yaw);
  if (std::abs(pose.roll) > 0.5 || std::abs(pose.yaw) > 0.5)
    fail("contact: |roll| and |yaw| must stay below 0.5 rad (roll = {}, yaw = {})", pose.roll, pose.yaw);
  const double radius = std::sqrt(std::max(model.side[kLeft].wheel_r2_max, model.side[kRight].wheel_r2_max));
  if (!(radius > 0)) return;  // a model without wheels (tests)
  if (std::abs(pose.z) > radius)
    fail("contact: z = {:.6g} m is more than the wheels' largest radius ({:.4g} m) from the track: the wheelset would {} (z is "
         "the height in m, 0 where the centred wheelset first touches, < 0 pressed in; realistic contacts are "
         "0.05-0.3 mm deep)", pose.z, radius, pose.z < 0 ? "have passed through its rails" : "hang in the air above them");
  if (std::abs(pose.y) > radius)
    fail("contact: y = {:.6g} m is more than the wheels' largest radius ({:.4g} m) off the track centre: the wheelset would "
         "stand beside its track (y is the lateral shift in m; flange contact begins within about 10 mm)", pose.y, radius);
}

void LocationState::reset(const Pose& pose) {
  pose_ = pose;
  frame_ = PoseFrame(pose);
  for (auto& s : side_) {
    s.crossings.clear();
    s.coarse_crossings.clear();
    s.segments.clear();
    s.patches.clear();
    s.windows.clear();
    s.have_windows = false;
    s.counters = {};
    s.grazes = 0;
  }
}

namespace {


struct Workspace {
  std::vector<Segment>& raw;
  std::vector<int>&parent, &root, &start;
};

// The searches emit crossings nearly in order (lines increasing, few per line): insertion sort, with a full
// sort if that turns out not to be the case.
void sort_crossings(std::vector<Crossing>& xs) {
  auto less = [](const Crossing& a, const Crossing& b) {
    if (a.line != b.line) return a.line < b.line;
    if (a.x != b.x) return a.x < b.x;
    return a.cone < b.cone;
  };
  std::size_t moves = 0;
  for (std::size_t a = 1; a < xs.size() && moves <= 16 * xs.size(); ++a)
    for (std::size_t b = a; b > 0 && less(xs[b], xs[b - 1]); --b, ++moves) std::swap(xs[b], xs[b - 1]);
  if (moves > 16 * xs.size()) std::sort(xs.begin(), xs.end(), less);
}

// Segments, line by line: each line's sorted crossings, cleaned (detail::clean_line), taken in pairs (enter,
// leave). Throws if a line keeps an odd count.
void make_segments(const GeometryModel& model, int side, std::vector<Crossing>& xs, int& grazes,
                   std::vector<Segment>& raw) {
  const SideGeometry& g = model.side[side];
  raw.clear();
  std::size_t i = 0;
  while (i < xs.size()) {
    std::size_t j = i;
    while (j < xs.size() && xs[j].line == xs[i].line) ++j;
    std::size_t end = j;
    const std::size_t start = i;
    if (!detail::clean_line(xs, start, end, grazes))
      fail("contact: rail line {} of the {} side ends with an odd number ({}) of crossings with the wheel: a search "
           "window of the strategy '{}' cuts the line's segment inside the wheel (test every cone the line can reach)",
           xs[start].line + 1, side_name(side), end - start, model.strategy.name);
    const int r = xs[start].line;
    for (std::size_t k = start; k + 1 < end; k += 2) {
      Segment s;
      s.line = r;
      s.y = g.rail.y[r];
      s.z = g.rail.z[r];
      s.x_t = xs[k].x;
      s.x_l = xs[k + 1].x;
      s.cone_t = xs[k].cone;
      s.cone_l = xs[k + 1].cone;
      raw.push_back(s);
    }
    i = end;  // clean_line erased (j - end) entries: the next line now starts at `end`
  }
}

// Patches: union of segments that overlap in x on adjacent lines. raw is ordered by line then x, so the
// segments of two adjacent lines are walked together like two sorted lists.
void link_overlapping(const std::vector<Segment>& raw, UnionFind& sets) {
  const int n = static_cast<int>(raw.size());
  int a = 0;
  while (a < n) {
    int b = a;
    while (b < n && raw[b].line == raw[a].line) ++b;  // [a, b): line L
    int c = b;
    while (c < n && raw[c].line == raw[b < n ? b : a].line) ++c;  // [b, c): the next line with segments
    if (b < n && raw[b].line == raw[a].line + 1) {
      int p = a, q = b;
      while (p < b && q < c) {
        if (raw[p].x_l >= raw[q].x_t && raw[q].x_l >= raw[p].x_t) sets.unite(p, q);
        if (raw[p].x_l < raw[q].x_l) ++p; else ++q;
      }
    }
    a = b;
  }
}

// Order: patches by their first segment (the root: the smallest index of the group); segments of a patch by line
// then x -- a stable counting sort by root into segs. Leaves root[k] (the group of raw segment k) and start[r]
// (the end of group r in segs).
void sort_by_patch(const std::vector<Segment>& raw, UnionFind& sets, std::vector<int>& root, std::vector<int>& start,
                   std::vector<Segment>& segs) {
  const int n = static_cast<int>(raw.size());
  root.resize(n);
  start.assign(n + 1, 0);
  for (int k = 0; k < n; ++k) {
    root[k] = sets.find(k);
    ++start[root[k] + 1];
  }
  for (int k = 0; k < n; ++k) start[k + 1] += start[k];
  segs.resize(n);
  for (int k = 0; k < n; ++k) segs[start[root[k]]++] = raw[k];
}

// The patch of the segments [k, e): its lines, its longest segment, and at the middle of that segment the
// nominal point with the wheel cone above it and the wheel's normal there.
Patch make_patch(const SideGeometry& g, const PoseFrame& frame, int side, const std::vector<Segment>& segs, int k,
                 int e) {
  Patch p;
  p.side = side;
  p.first_segment = k;
  p.segment_count = e - k;
  p.longest = k;
  p.first_line = segs[k].line;
  p.last_line = segs[k].line;
  for (int m = k; m < e; ++m) {
    if (segs[m].length() > segs[p.longest].length()) p.longest = m;
    p.first_line = std::min(p.first_line, segs[m].line);
    p.last_line = std::max(p.last_line, segs[m].line);
  }
  const Segment& s = segs[p.longest];
  p.point = Eigen::Vector3d(0.5 * (s.x_t + s.x_l), s.y, s.z);
  p.wheel_point = frame.to_wheelset(p.point);
  const double rho = std::hypot(p.wheel_point.x(), p.wheel_point.z());
  p.eps = std::atan2(p.wheel_point.x(), -p.wheel_point.z());
  p.cone = g.wheel.running_cone(p.wheel_point.y());
  const Cone cone = g.wheel.cone(p.cone);
  p.wheel_radius = cone.radius_at(p.wheel_point.y());
  p.depth = p.wheel_radius - rho;
  double ny = 0, nr = 0;
  cone.meridian_normal(ny, nr);
  const Eigen::Vector3d n_w(nr * std::sin(p.eps), ny, -nr * std::cos(p.eps));
  p.normal = frame.matrix() * n_w;
  return p;
}

// Crossings -> segments -> patches (groups of touching segments) with their nominal points.
void assemble_side(const GeometryModel& model, const PoseFrame& frame, int side, std::vector<Crossing>& xs,
                   std::vector<Segment>& segs, std::vector<Patch>& patches, int& grazes, Workspace ws) {
  sort_crossings(xs);
  make_segments(model, side, xs, grazes, ws.raw);
  UnionFind sets(std::move(ws.parent));  // the state's storage, handed back below: no allocation per pose
  sets.reset(static_cast<int>(ws.raw.size()));
  link_overlapping(ws.raw, sets);
  sort_by_patch(ws.raw, sets, ws.root, ws.start, segs);
  ws.parent = std::move(sets).take_storage();
  // start[r] now points past group r; the patch ranges in order of their roots.
  patches.clear();
  const int n = static_cast<int>(segs.size());
  for (int k = 0, r = 0; k < n; ++r) {
    if (ws.root[r] != r) continue;  // r is not the first segment of a group
    const int e = ws.start[r];      // the group occupies [k, e)
    patches.push_back(make_patch(model.side[side], frame, side, segs, k, e));
    k = e;
  }
}

}  // namespace

void locate_crossings(const GeometryModel& model, const Pose& pose, LocationState& state, PoseSearch& search) {
  check_pose(model, pose);  // before any geometry: absurd numbers never reach the closed form
  state.reset(pose);
  SearchContext ctx(model, state);
  for (int side : {kLeft, kRight}) search.search(ctx, side);
}

void assemble_patches(const GeometryModel& model, LocationState& state) {
  for (int side : {kLeft, kRight}) {
    auto& s = state.side_[side];
    assemble_side(model, state.frame_, side, s.crossings, s.segments, s.patches, s.grazes,
                  Workspace{s.raw_segments, s.parent, s.root, s.start});
  }
}

void locate_contact(const GeometryModel& model, const Pose& pose, LocationState& state, PoseSearch& search) {
  locate_crossings(model, pose, state, search);
  assemble_patches(model, state);
}

Locator::Locator(std::shared_ptr<const GeometryModel> model) : model_(std::move(model)) {
  if (!model_) fail("Locator: no model");
  if (!model_->strategy.make_search)
    fail("Locator: the model's strategy '{}' cannot make a search for this thread{}", model_->strategy.name,
         model_->strategy.portable ? "" : " (an inline Lua table runs only in the Lua state that built the wheelset)");
  search_ = model_->strategy.make_search();
}

Locator::Locator(std::shared_ptr<const GeometryModel> model, std::unique_ptr<PoseSearch> search)
    : model_(std::move(model)), search_(std::move(search)) {
  if (!model_ || !search_) fail("Locator: no model or no search");
}

const LocationState& Locator::locate(const Pose& pose) {
  locate_contact(*model_, pose, state_, *search_);
  return state_;
}

}  // namespace wrc
