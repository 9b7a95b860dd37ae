// The discretised contact geometry of a wheelset on its track (docs/design.md, sections 1-3): the immutable MODEL
// built once per wheelset from the strategy's discretisation. Per-pose data live in LocationState
// (location.hpp); one model may be used by many threads at once, each with its own state.
//
// Per side (kLeft, kRight):
//  - the wheel as truncated cones in the wheelset frame: generatrix points (y, z), z = -radius, ordered by
//    increasing y. The solid is CLOSED: the first and last points are on the axle (z = 0) at the y of the first
//    and last profile points, so cone 0 and the last cone are flat discs (the end faces). Without them a line
//    entering or leaving through an end face would cross the surface an odd number of times.
//  - the rail as lines parallel to x through the rail points (y, z) of the track frame, ordered by increasing y.
//  - optionally a coarse level for the pre-search of the paper's Fig. 3 (see CoarseLevel).
#pragma once

#include "wrc/geometry/flange.hpp"
#include "wrc/geometry/track.hpp"
#include "wrc/profile/profile.hpp"
#include "wrc/profile/spline.hpp"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace wrc {

// O(1) minimum and maximum of any index range of a fixed array (sparse tables).
class RangeExtrema {
 public:
  void build(const std::vector<double>& v);
  // Minimum and maximum of v[i..j], i <= j.
  void extrema(int i, int j, double& lo, double& hi) const {
    const int k = 31 - __builtin_clz(static_cast<unsigned>(j - i + 1));
    const MinMax* level = table_.data() + offset_[k];
    const MinMax& a = level[i];
    const MinMax& b = level[j - (1 << k) + 1];
    lo = a.min < b.min ? a.min : b.min;
    hi = a.max > b.max ? a.max : b.max;
  }
  double max(int i, int j) const { double lo, hi; extrema(i, j, lo, hi); return hi; }
  double min(int i, int j) const { double lo, hi; extrema(i, j, lo, hi); return lo; }

 private:
  struct MinMax {
    double min, max;
  };
  std::vector<MinMax> table_;   // level k holds the extrema of v[i .. i + 2^k - 1] from offset_[k]
  std::vector<int> offset_;
};

// One truncated cone (wheelset frame, m): joins (y0, z0) and (y1, z1), z = -radius <= 0.
struct Cone {
  double y0 = 0, z0 = 0, y1 = 0, z1 = 0;
  bool is_ring() const { return y0 == y1; }  // flat ring (generatrix parallel to z)
  // Radius (m) of the cone at the wheelset-frame lateral position Y, clamped to the cone (the larger end radius
  // for a flat ring).
  double radius_at(double Y) const;
  // Angle (rad) of the generatrix to the axle, atan2(r1 - r0, y1 - y0) with r = -z: 0 for a cylinder, negative where
  // the radius decreases toward +y (the left tread), +-pi/2 for a flat ring. The rolling-direction curvature radius
  // of the surface at radius r is r / cos(angle) (used for the undeformed distance h of docs/design.md, section 3).
  double slope_angle() const;
  // Outward unit normal of the wheel solid in the meridian half-plane: (n_y, n_r) with n_r >= 0 on the tread.
  // A point at angular position eps (eq. 1) has the wheelset-frame normal (n_r sin eps, n_y, -n_r cos eps).
  void meridian_normal(double& n_y, double& n_r) const;
};

// The wheel of one side as cones (wheelset frame).
struct WheelCones {
  std::vector<double> y, z;  // generatrix points (m), the first and last on the axle (z = 0)
  std::vector<double> r2;    // radius squared of each point (m^2)
  RangeExtrema r2_range;     // extrema of r2 over point ranges
  // Per point: the running surface's unit normal there (y and radial parts; wheel_vertex_normal), kept so that the
  // smooth surface queries need not recompute it (empty: computed on demand).
  std::vector<double> vertex_ny, vertex_nr;
  int cone_count() const { return static_cast<int>(y.size()) - 1; }  // cone w joins points w and w + 1
  Cone cone(int w) const { return {y[w], z[w], y[w + 1], z[w + 1]}; }
  bool is_end_face(int w) const { return w == 0 || w == cone_count() - 1; }
  // The running-surface cone (not an end face) that holds the lateral position Y, clamped to the profile: the cone
  // spanning Y, the next one when a flat ring (a vertical run) sits exactly at Y. The one rule for "the wheel above
  // a point" (location's nominal point, the smooth surface queries of wheel_surface.hpp).
  int running_cone(double Y) const;
  // First cone whose closed y range reaches y_lo, last cone whose closed y range starts at or before y_hi.
  int first_cone_reaching(double y_lo) const;
  int last_cone_starting_before(double y_hi) const;
};

// The rail lines of one side (track frame, m), ordered by increasing y.
struct RailLines {
  std::vector<double> y, z;
  int count() const { return static_cast<int>(y.size()); }
};

// Coarse level of the pre-search (paper Fig. 3). Each coarse line stands for a CELL of consecutive fine lines,
// all within `dilation` (y-z distance) of it, and the coarse wheel contains the fine wheel dilated by `dilation`
// (checked when the model is built). Then a fine line that enters the fine wheel at a point q has, on its coarse
// line, the point q + (coarse - fine) inside the coarse wheel, at a wheelset-frame y within `dilation` of q's: the
// fine search need only look at the cells whose coarse line enters the coarse wheel, and there only at the fine
// cones within `dilation` (in y) of the coarse segments. Proof in search.cpp.
struct CoarseLevel {
  WheelCones wheel;                          // closed like the fine wheel
  RailLines lines;                           // one per cell
  std::vector<int> cell_first, cell_last;    // fine line range of each cell (inclusive)
  std::vector<double> offset;                // per fine line: its distance (y-z) to its cell's coarse line (m)
  double dilation = 0;                       // D (m)
  int every = 0;                             // fine lines per cell
};

struct SideGeometry {
  WheelCones wheel;
  RailLines rail;
  std::optional<CoarseLevel> coarse;
  double wheel_r2_max = 0;  // largest wheel radius squared (m^2)
  std::string wheel_name, rail_name;
  // The profiles as given (track.wheel/rail, their own frames) as smooth curves: their spline when loaded with
  // `smooth`, else the interpolating cubic spline through their points (profile/spline.hpp). The lateral curvature
  // at a rigid contact point is read from them (a polyline has none).
  std::shared_ptr<const ProfileSpline> wheel_curve, rail_curve;
  Flange flange;  // of the wheel profile as given (geometry/flange.hpp), for the flange-climb flags of the results
};

// A strategy's option values (numbers, strings, booleans), kept so that a worker thread can rebuild the strategy.
using StrategyOption = std::variant<double, std::string, bool>;

class PoseSearch;  // location.hpp

// What the model knows of its discretisation strategy.
struct StrategyInfo {
  std::string name;                    // "topology", "constant_slope+coarse+topology", "(inline)", ...
  std::vector<std::string> components; // names as given (module names or file paths); empty for an inline table
  std::map<std::string, StrategyOption> options;
  bool portable = true;                // false for an inline Lua table: its per-pose code lives in one Lua state
  // Makes a per-thread search (see location.hpp). Thread-safe; for a Lua strategy chosen by name it creates a
  // fresh Lua state owned by the returned object. Null when the model was built without one (tests).
  std::function<std::unique_ptr<PoseSearch>()> make_search;
};

struct GeometryModel {
  std::shared_ptr<const Track> track;
  std::array<SideGeometry, 2> side;
  StrategyInfo strategy;
};

// What a discretisation strategy produces for one side, in the profiles' own frames (left-side frame; the
// engine places and mirrors them): the fine wheel and rail, and optionally the coarse level.
struct SideDiscretisation {
  Profile wheel, rail;
  int coarse_every = 0;                  // 0: no coarse level; else fine lines per coarse cell (>= 2)
  std::optional<Profile> coarse_wheel;   // given coarse wheel (checked), or built with coarse_wheel_step
  double coarse_wheel_step = 2e-3;       // y spacing of the built coarse wheel's points (m)
};

// Builds the model. Throws wrc::Error on bad input (wrong kind, a coarse wheel that does not contain the dilated
// fine wheel, cells that do not fit, ...), naming the side and what is wrong.
GeometryModel build_geometry(std::shared_ptr<const Track> track, const std::array<SideDiscretisation, 2>& sides,
                             StrategyInfo strategy = {});

// A contact point of one side in the profiles' own frames (as loaded, before placement) and the lateral curvature of
// the profiles there (1/m, > 0 convex, from their smooth curves; 0 without one): what rigid contact points report
// and the Hertz ellipse of a contact needs.
struct ProfilePoint {
  Eigen::Vector2d wheel = Eigen::Vector2d::Zero();  // (s from the tape circle, z) on the wheel profile (m)
  Eigen::Vector2d rail = Eigen::Vector2d::Zero();   // (y, z) on the rail profile (m)
  double wheel_curvature = 0, rail_curvature = 0;   // 1/m
};
// `point`: the contact point (track frame), `wheel_y`: its lateral coordinate in the wheelset frame, `radius`: the
// wheel's radius there (m).
ProfilePoint profile_point(const GeometryModel& geometry, int side, const Eigen::Vector3d& point, double wheel_y,
                           double radius);

// ---- profile operations used by discretisation strategies (profile frame, metres) ----

// Constant-slope resampling (paper Section 2, item 2): a subset of the profile's points such that the turning
// of the tangent between consecutive kept points reaches `slope_step` (rad) -- few points on conical parts, many
// where the curvature is high -- with at most `max_step` (m) of arc between kept points. The end points are kept.
Profile resample_constant_slope(const Profile& p, double slope_step, double max_step);
// Its defaults (the native strategy "constant_slope" and wrc.geometry.constant_slope).
struct ConstantSlope {
  double slope_step = 0.01;  // rad
  double max_step = 1e-3;    // m
};

// An enclosing polyline of the profile's solid dilated by `distance` (m), with points every `step` (m or less) of
// y over [y_first - distance, y_last + distance]: above the dilated rail (solid below the profile) or, for a
// wheel (solid above the profile in the profile frame: radius = r0 - z), below the dilated wheel. The outward
// offset of the paper's Fig. 3, certified: every point of the dilated solid is inside the returned polyline.
Profile offset_outward(const Profile& p, double distance, double step);

// Largest y-z distance from a rail point to the middle point of its cell when the points are grouped in cells of
// `every` consecutive points (the dilation D of the coarse level).
double cell_dilation(const Profile& rail, int every);

}  // namespace wrc
