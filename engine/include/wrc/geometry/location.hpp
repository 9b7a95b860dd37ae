// Contact location at one wheelset pose (paper Section 2): line-cone crossings -> segments -> patches.
//
// Per-pose data live in a LocationState (one per thread); the GeometryModel is shared read-only. The search --
// which (line, cone) pairs are tested -- is a PoseSearch chosen by the model's strategy: native (NativeSearch) or
// Lua (the strategy's `locate` function, see engine/src/lua/strategy_binding.hpp). A search calls the primitives
// of SearchContext, whose inner loops are native; whatever the search, the crossings it finds are assembled
// here the same way:
//  - per line, sorted by x and paired into segments [x_t, x_l] (trailing = smaller x, leading = larger x; travel
//    toward +x), each end with the cone it crosses (two different cones when yaw != 0 makes the line run under
//    several cones);
//  - segments on adjacent lines that overlap in x are connected; each connected group is a patch (separate groups:
//    two-point contact); the nominal contact point is the mid-point of the patch's longest segment.
#pragma once

#include "wrc/geometry/cone_line.hpp"
#include "wrc/geometry/model.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace wrc {

// A crossing of a rail line with the wheel surface (one root of eq. 1 kept by the conditions of the appendix).
struct Crossing {
  int line = 0;        // rail line index (0-based, increasing y) of the side
  int cone = 0;        // cone index (0-based; 0 and the last are the end faces)
  double x = 0;        // track-frame x (m)
  double alpha = 0;    // position on the cone's generatrix
  int vertex = -1;     // generatrix point within the rounding band of alpha (alpha ~ 0 or 1), else -1
  signed char branch = 0;  // +1 / -1: after / before the line's closest approach to the axle
  signed char root = 0;    // which root of the cone's pair (0: smaller x): a tangency gives two at one x
};

// The part [x_t, x_l] of one rail line inside the wheel.
struct Segment {
  int line = 0;            // rail line index (0-based)
  double y = 0, z = 0;     // the rail line (track frame, m)
  double x_t = 0, x_l = 0; // trailing and leading ends (track frame, m), x_t <= x_l
  int cone_t = 0, cone_l = 0;  // cone crossed at the trailing / leading end
  double length() const { return x_l - x_t; }
};

// One inter-penetration area.
struct Patch {
  int side = kLeft;
  int first_segment = 0, segment_count = 0;  // range in LocationState::segments(side), ordered by line then x
  int longest = 0;                           // index in segments(side) of the longest segment
  int first_line = 0, last_line = 0;         // rail lines spanned
  Eigen::Vector3d point = Eigen::Vector3d::Zero();        // nominal contact point (track frame, m)
  Eigen::Vector3d wheel_point = Eigen::Vector3d::Zero();  // the same point in the wheelset frame (m)
  int cone = 0;      // the cone whose y range holds the nominal point's wheelset-frame y (not an end face; a
                     // neighbour when that is a flat ring): the wheel surface above the nominal point
  double eps = 0;                            // angular position of the nominal point on the wheel (rad, eq. 1)
  double wheel_radius = 0;                   // radius of that cone at the nominal point's y (m)
  double depth = 0;                          // wheel radius minus the nominal point's distance to the axle (m)
  // The wheel's outward unit normal on that cone at angle eps (track frame): the normal of the contact plane.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// An index window of lines x cones (0-based, inclusive).
struct Window {
  int line_first = 0, line_last = -1, cone_first = 0, cone_last = -1;
  // Set by the coarse pre-search: the window's lines closer than this (m) to their cell's coarse line cannot
  // cross the wheel (CoarseLevel::offset; proof in search.cpp) and are skipped by test_windows / walk_windows.
  double skip_within = 0;
};

// Work counters of the last pose (per side).
struct SearchCounters {
  long long tests = 0;   // closed-form line-cone tests (cone_line_intersections calls)
  long long bounds = 0;  // bound checks of the walk (each decides a whole range of cones)
  long long lines = 0;   // lines visited by the searches
  long long coarse_tests = 0;  // closed-form tests of the coarse pre-search
};

class LocationState;

// The primitives a search may call for the pose being located. Indices are 0-based and inclusive; a window out
// of range is an error (wrc::Error naming the strategy's call). Crossings accumulate; testing a pair twice is
// harmless (duplicates are dropped when segments are formed).
class SearchContext {
 public:
  SearchContext(const GeometryModel& model, LocationState& state);
  const GeometryModel& model() const { return model_; }
  const Pose& pose() const;
  int line_count(int side) const { return model_.side[side].rail.count(); }
  int cone_count(int side) const { return model_.side[side].wheel.cone_count(); }
  Window all(int side) const { return {0, line_count(side) - 1, 0, cone_count(side) - 1}; }

  // Every line of the window against every cone of the window (brute force inside the window).
  void test(int side, const Window& w);
  // The topology walk: lines in increasing order; each line's tests start at the cones the previous line crossed
  // (paper item 3), and every other range of cones of the window is ruled out by a certified bound (the line's
  // distance to the axle against the range's largest/smallest radius) or split until it is. Finds exactly the
  // crossings `test` finds in the same window (tests/geometry/test_location.cpp), with far fewer tests.
  void walk(int side, const Window& w);
  // Coarse pre-search (paper Fig. 3) on the model's coarse level: stores the windows of fine lines x cones that
  // can hold crossings (their union provably contains every crossing of the side) and returns their number.
  // Throws if the model has no coarse level for the side.
  int coarse(int side);
  const std::vector<Window>& windows(int side) const;
  void test_windows(int side);  // `test` in each stored window
  void walk_windows(int side);  // `walk` in each stored window

 private:
  void check_window(int side, const Window& w, const char* what) const;
  const GeometryModel& model_;
  LocationState& state_;
};

// The per-pose search of a strategy, bound to one thread (a Lua strategy holds its Lua state).
class PoseSearch {
 public:
  virtual ~PoseSearch() = default;
  // Calls ctx's primitives for one side. May throw wrc::Error.
  virtual void search(SearchContext& ctx, int side) = 0;
};

// A non-owning view of another search (e.g. one bound to a Lua state), for a workspace that must not own it.
class SearchRef final : public PoseSearch {
 public:
  explicit SearchRef(PoseSearch& s) : s_(&s) {}
  void search(SearchContext& ctx, int side) override { s_->search(ctx, side); }

 private:
  PoseSearch* s_;
};

// The strategies' pipelines run natively (used by tests and benchmarks, and by models built without Lua).
struct NativePlan {
  bool coarse = false;  // coarse pre-search first, then the scan inside its windows
  enum class Scan { test, walk } scan = Scan::walk;
};
class NativeSearch final : public PoseSearch {
 public:
  explicit NativeSearch(NativePlan plan) : plan_(plan) {}
  void search(SearchContext& ctx, int side) override;

 private:
  NativePlan plan_;
};

// Per-pose results and workspace. Reusing one state across poses avoids allocations.
class LocationState {
 public:
  const Pose& pose() const { return pose_; }
  const PoseFrame& frame() const { return frame_; }
  const std::vector<Crossing>& crossings(int side) const { return side_[side].crossings; }
  const std::vector<Segment>& segments(int side) const { return side_[side].segments; }
  const std::vector<Patch>& patches(int side) const { return side_[side].patches; }
  const std::vector<Window>& windows(int side) const { return side_[side].windows; }
  const SearchCounters& counters(int side) const { return side_[side].counters; }
  // Graze crossings dropped to keep a line's count even (a line through a shared circle of two cones, touching
  // the surface without entering it); reported for inspection.
  int grazes_dropped(int side) const { return side_[side].grazes; }

 private:
  friend class SearchContext;
  friend void locate_contact(const GeometryModel&, const Pose&, LocationState&, PoseSearch&);
  friend void locate_crossings(const GeometryModel&, const Pose&, LocationState&, PoseSearch&);
  friend void assemble_patches(const GeometryModel&, LocationState&);
  struct PerSide {
    std::vector<Crossing> crossings, coarse_crossings;
    std::vector<Segment> segments;
    std::vector<Patch> patches;
    std::vector<Window> windows;
    bool have_windows = false;
    SearchCounters counters;
    int grazes = 0;
    std::vector<int> scratch_int, scratch_int2;
    int hint_lo = 0, hint_hi = 0, coarse_hint_lo = 0, coarse_hint_hi = 0;  // the walk's last cone indices
    std::vector<std::pair<int, int>> scratch_ranges;
    std::vector<Segment> raw_segments;      // assembly workspace
    std::vector<int> parent, root, start;
  };
  void reset(const Pose& pose);
  Pose pose_;
  PoseFrame frame_;
  std::array<PerSide, 2> side_;
};

// Throws wrc::Error naming the value if `pose` is no pose of a wheelset on its track: not finite, |roll| or |yaw| above
// 0.5 rad, or |y| or |z| more than the wheels' largest radius (m) -- a wheelset lowered that far has passed through its
// rails, where no rail line crosses the wheel any more and the location would find nothing. The geometry's own guard,
// for any caller; the calls refuse a pose beyond the tighter limits of geometry/pose.hpp before (kMaxRoll, ...).
void check_pose(const GeometryModel& model, const Pose& pose);

// Locates the contact at `pose`: runs `search` on both sides, then forms segments and patches in `state`.
// Throws wrc::Error if the pose fails check_pose or a line ends with an odd number of crossings that no graze
// explains (a strategy whose windows cut a segment).
void locate_contact(const GeometryModel& model, const Pose& pose, LocationState& state, PoseSearch& search);
// The two halves of locate_contact (benchmarks time them apart).
void locate_crossings(const GeometryModel& model, const Pose& pose, LocationState& state, PoseSearch& search);
void assemble_patches(const GeometryModel& model, LocationState& state);

// A per-thread locator: the model's strategy bound to the calling thread, with its own state.
class Locator {
 public:
  // Uses model->strategy.make_search(); throws if the model has none or its strategy is not portable to
  // another thread (an inline Lua table: run it from the Lua state that built the wheelset).
  explicit Locator(std::shared_ptr<const GeometryModel> model);
  Locator(std::shared_ptr<const GeometryModel> model, std::unique_ptr<PoseSearch> search);
  const LocationState& locate(const Pose& pose);
  const LocationState& state() const { return state_; }
  const GeometryModel& model() const { return *model_; }

 private:
  std::shared_ptr<const GeometryModel> model_;
  std::unique_ptr<PoseSearch> search_;
  LocationState state_;
};

}  // namespace wrc
