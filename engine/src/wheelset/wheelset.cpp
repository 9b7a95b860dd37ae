// The wheelset model (wheelset.hpp): parameters, construction, workspaces and location as a value.
#include "wrc/wheelset/wheelset.hpp"

#include "wrc/core/error.hpp"
#include "wrc/wheelset/plausibility.hpp"

#include <fmt/format.h>

#include <string>

namespace wrc {
namespace {
// The option's help, its defaults written from their one definition (contact.hpp).
const char* merge_angle_doc() {
  static const std::string doc =
      fmt::format("areas whose normals differ more are never merged (default: {} conformal, {} planar)",
                  kMergeAngleConformal, kMergeAnglePlanar);
  return doc.c_str();
}
}  // namespace

WheelsetParams read_wheelset_params(OptionReader& r) {
  WheelsetParams p;
  TrackParams& t = p.track;
  t.radius = r.number("radius", {"m", "wheel nominal radius r0 at the tape circle"}, t.radius);
  t.back_to_back = r.number("back_to_back", {"m", "flange-back distance of the wheels"}, t.back_to_back);
  t.tape_offset = r.number("tape_offset", {"m", "tape circle from the flange back"}, t.tape_offset);
  t.gauge = r.number("gauge", {"m", "track gauge between the gauge points"}, t.gauge);
  t.gauge_depth = r.number("gauge_depth", {"m", "gauge points this far below the top of each rail"}, t.gauge_depth);
  const bool first = t.gauge_rule == TrackParams::GaugeRule::first;
  t.gauge_rule = r.choice("gauge_point", {"first", "innermost"}, {"-", "which gauge-face point is the gauge point"},
                          first ? "first" : "innermost") == "first"
                     ? TrackParams::GaugeRule::first
                     : TrackParams::GaugeRule::innermost;
  t.cant = r.number("cant", {"-", "rail inclination (tan of the angle; 1/40: 0.025)"}, t.cant);
  p.material.E = r.number("E", {"Pa", "Young's modulus of wheel and rail"}, p.material.E);
  p.material.nu = r.number("nu", {"-", "Poisson's ratio of wheel and rail"}, p.material.nu);
  ContactOptions& c = p.contact;
  c.element = r.number("grid", {"m", "element size of the potential contact areas"}, c.element);
  validate_element(c.element, r.context());
  c.margin = r.integer("margin", 1, 100, {"-", "elements around the projected inter-penetration area"}, c.margin);
  c.max_elements = r.integer("max_elements", 1, 1 << 30, {"-", "largest potential contact area (elements)"},
                             c.max_elements);
  c.normal.tolerance = r.number("tolerance", {"-", "normal solver's tolerance (relative)"}, c.normal.tolerance);
  c.merge_tolerance =
      r.number("merge_tolerance", {"-", "relative force error of two areas apart that merges them"}, c.merge_tolerance);
  if (const auto a = r.number("merge_angle", {"rad", merge_angle_doc()})) c.merge_angle = *a;
  c.dense = r.choice("solver", {"fast", "dense"}, {"-", "normal solver: fast, or the dense reference"},
                     c.dense ? "dense" : "fast") == "dense";
  c.surface = r.choice("surface", {"planar", "conformal"}, {"-", "potential contact area: planar or curved"},
                       surface_name(c.surface)) == "conformal"
                  ? ContactSurface::conformal
                  : ContactSurface::planar;
  p.strategy = r.string("strategy", {"-", "the location strategy (a name; Lua: also a table)"}, p.strategy);
  p.check_strategy = r.integer("check_strategy", 0, 10'000'000,
                               {"-", "random poses checked against brute force when built"}, p.check_strategy);
  p.check_setup = r.boolean("check_setup", {"-", "check the set-up's plausibility when built"}, p.check_setup);
  return p;
}

WheelsetProfiles read_wheelset_profiles(OptionReader& r) {
  auto get = [&](const char* key, const char* both) {
    auto p = std::static_pointer_cast<const Profile>(r.object(key, kProfileTypeName));
    if (!p) p = std::static_pointer_cast<const Profile>(r.object(both, kProfileTypeName));
    if (!p) fail("{}: '{}' (or '{}') is required: a {}", r.context(), key, both, kProfileTypeName);
    return *p;
  };
  // 'wheel' (or 'rail') is both sides' profile unless a side has its own: given with both sides' own, it would be
  // read by neither, and which profile was meant is not for wrc to guess.
  for (const char* both : {"wheel", "rail"}) {
    const std::string left = fmt::format("left_{}", both), right = fmt::format("right_{}", both);
    if (r.has(both) && r.has(left) && r.has(right))
      fail("{}: '{}' is given, and so are '{}' and '{}', which take its place on both sides: it would be unused; give "
           "'{}' alone or the two sides' own", r.context(), both, left, right, both);
  }
  WheelsetProfiles w;
  w.wheel = {get("left_wheel", "wheel"), get("right_wheel", "wheel")};
  w.rail = {get("left_rail", "rail"), get("right_rail", "rail")};
  return w;
}

Pose read_pose(OptionReader& r) {
  Pose p;
  p.y = r.number("y", {"m", "lateral position of the wheelset centre"}, p.y);
  p.z = r.number("z", {"m", "height of the wheelset centre (0: the centred wheelset touches; < 0 presses in)"}, p.z);
  p.roll = r.number("roll", {"rad", "roll angle of the wheelset"}, p.roll);
  p.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, p.yaw);
  check_lateral(p.y, r.context());
  check_yaw(p.yaw, r.context());
  check_roll(p.roll, r.context());
  return p;
}

void describe(const WheelsetParams& p, FieldSink& out) {
  out.number("radius", p.track.radius, {"m", "wheel nominal radius r0 at the tape circle"});
  out.number("back_to_back", p.track.back_to_back, {"m", "distance between the flange backs"});
  out.number("tape_offset", p.track.tape_offset, {"m", "tape circle from the flange back"});
  out.number("gauge", p.track.gauge, {"m", "track gauge between the gauge points"});
  out.number("gauge_depth", p.track.gauge_depth, {"m", "gauge points this far below the top of each rail"});
  out.string("gauge_point", p.track.gauge_rule == TrackParams::GaugeRule::first ? "first" : "innermost",
             {"", "which gauge-face point is the gauge point: first or innermost"});
  out.number("cant", p.track.cant, {"-", "rail inclination (tan of the angle), the head tilted toward the track centre"});
  out.number("E", p.material.E, {"Pa", "Young's modulus of wheel and rail"});
  out.number("nu", p.material.nu, {"-", "Poisson's ratio of wheel and rail"});
  out.number("grid", p.contact.element, {"m", "element size of the potential contact areas"});
  out.integer("margin", p.contact.margin, {"-", "elements around the projected inter-penetration area"});
  out.integer("max_elements", p.contact.max_elements, {"-", "largest potential contact area accepted (elements)"});
  out.number("tolerance", p.contact.normal.tolerance,
             {"-", "normal solver: max |gap| over the contact set relative to max(h + approach)"});
  out.number("merge_tolerance", p.contact.merge_tolerance,
             {"-", "relative force error of solving two areas apart that merges them"});
  out.number("merge_angle", merge_angle_of(p.contact), {"rad", merge_angle_doc()});
  out.string("solver", p.contact.dense ? "dense" : "fast", {"", "normal solver: fast or dense (the reference)"});
  out.string("surface", surface_name(p.contact.surface), {"", "potential contact areas: conformal or planar"});
  out.string("strategy", p.strategy, {"", "the contact location strategy's name"});
  out.integer("check_strategy", p.check_strategy,
              {"-", "random poses checked against brute force when the wheelset was built (0: none)"});
  out.boolean("check_setup", p.check_setup, {"", "the set-up's plausibility for a railway wheelset was checked when built"});
}

namespace {

// The centred wheelset pressed kReferenceApproach into the rails (S1002/60E1 at 100 kN per wheel: 0.075 mm) must fit
// max_elements, or every solve at a realistic load would fail after the time it took to get there.
constexpr double kReferenceApproach = 0.1e-3;

void check_grid_cap(const ContactModel& model) {
  if (model.options().max_elements < 1) fail("wrc.wheelset: max_elements must be >= 1");
  NativeSearch walk({false, NativePlan::Scan::walk});  // exact on any discretisation; not the user's strategy
  LocationState st;
  locate_contact(model.geometry(), {0, -kReferenceApproach, 0, 0}, st, walk);
  const double n = largest_potential_area(model, st);
  const ContactOptions& o = model.options();
  if (!(n <= o.max_elements))
    fail("wrc.wheelset: grid = {:.4g} mm is too fine for max_elements = {}: the centred wheelset pressed {:.2f} mm into "
         "the rails (about what 100 kN per wheel does on S1002/60E1) already needs {:.0f} elements in one potential "
         "contact area (about {:.0f} MB); raise max_elements (about {:.0f} bytes per element) or use a coarser grid",
         o.element * 1e3, o.max_elements, kReferenceApproach * 1e3, n, n * kBytesPerElement / 1e6, kBytesPerElement);
}

}  // namespace

Wheelset::Wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params,
                   std::shared_ptr<const LocationStrategy> strategy, const std::atomic<bool>* stop)
    : params_(params), strategy_(std::move(strategy)) {
  if (!strategy_) fail("wheelset: no location strategy");
  if (params.check_setup) check_plausible(params.track, params.material);  // radius, E and nu in their units
  halfspace::validate(params.material, "wrc.wheelset");  // named as the call, not the solver that would refuse it
  track_ = std::make_shared<const Track>(assemble_track(profiles.wheel, profiles.rail, params.track));
  if (params.check_setup) check_setup(*track_);  // sizes and shapes for their kind, flanges against the gauge
  std::array<SideDiscretisation, 2> sides;
  for (int s : {kLeft, kRight}) sides[s] = strategy_->discretise(s, profiles.wheel[s], profiles.rail[s]);
  StrategyInfo info = strategy_->info();
  if (info.portable) {
    std::shared_ptr<const LocationStrategy> st = strategy_;
    info.make_search = [st] { return st->make_search(); };
  }
  geometry_ = std::make_shared<const GeometryModel>(build_geometry(track_, sides, std::move(info)));
  ContactOptions contact = params.contact;
  contact.check_magnitudes = params.check_setup;
  contact_ = std::make_shared<const ContactModel>(geometry_, params.material, contact);
  check_grid_cap(*contact_);
  if (params.check_strategy > 0) {
    StrategyCheckOptions o;
    o.poses = params.check_strategy;
    o.stop = stop;
    if (!strategy_->info().portable) o.threads = 1;  // bound to the building thread
    strategy_check_ = check_strategy(*geometry_, o, [this] { return strategy_->make_search(); });
  }
}

std::unique_ptr<ContactWorkspace> Wheelset::make_workspace() const {
  return std::make_unique<ContactWorkspace>(*contact_, strategy_->make_search());
}

std::unique_ptr<ContactWorkspace> Wheelset::make_workspace_with(PoseSearch& search) const {
  return std::make_unique<ContactWorkspace>(*contact_, std::make_unique<SearchRef>(search));
}

std::shared_ptr<const Wheelset> build_wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params,
                                               std::shared_ptr<const LocationStrategy> strategy,
                                               const std::atomic<bool>* stop) {
  return std::make_shared<const Wheelset>(profiles, params, std::move(strategy), stop);
}

std::shared_ptr<const Wheelset> build_wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params) {
  validate_element(params.contact.element, "build_wheelset");  // before the strategy's step follows it
  return build_wheelset(profiles, params, native_strategy(params.strategy, {}, params.contact.element));
}

namespace {

LocateResult copy_location(const LocationState& st) {
  LocateResult r;
  r.pose = st.pose();
  for (int s : {kLeft, kRight}) {
    r.side[s].patches = st.patches(s);
    r.side[s].segments = st.segments(s);
    r.side[s].counters = st.counters(s);
    r.side[s].grazes = st.grazes_dropped(s);
  }
  return r;
}

}  // namespace

LocateResult locate(const Wheelset&, const Pose& pose, ContactWorkspace& workspace) {
  return copy_location(workspace.locator.locate(pose));
}

LocateResult locate_with(const Wheelset& wheelset, const Pose& pose, PoseSearch& search) {
  LocationState st;
  locate_contact(wheelset.geometry(), pose, st, search);
  return copy_location(st);
}

void describe_patch_fields(const Patch& p, FieldSink& out) {
  out.string("side", side_name(p.side), {"", "the wheel of the area: left or right"});
  // "point" is the centre of pressure of the normal-contact stage.
  out.vec3("nominal_point", p.point, {"m", "the paper's nominal point: mid-point of the longest segment (track frame)"});
  out.vec3("nominal_normal", p.normal, {"-", "the wheel's outward unit normal at the nominal point (track frame)"});
  out.vec3("wheel_point", p.wheel_point, {"m", "the nominal point in the wheelset frame"});
  out.integer("cone", p.cone + 1, {"-", "the wheel cone under the nominal point (1-based)"});
  out.number("eps", p.eps, {"rad", "angle of the nominal point about the axle from the lowest point toward +x (paper eq. 1)"});
  out.number("wheel_radius", p.wheel_radius, {"m", "radius of that cone at the nominal point"});
  out.number("depth", p.depth, {"m", "wheel radius minus the nominal point's distance to the axle"});
  out.integer("first_line", p.first_line + 1, {"-", "first rail line the patch spans (1-based)"});
  out.integer("last_line", p.last_line + 1, {"-", "last rail line the patch spans (1-based)"});
  out.integer("longest", p.longest - p.first_segment + 1, {"-", "the patch's longest segment (1-based, in its segments)"});
}

void describe(const Segment& s, FieldSink& out) {
  out.integer("line", s.line + 1, {"-", "the rail line (1-based)"});
  out.number("y", s.y, {"m", "the rail line's y (track frame)"});
  out.number("z", s.z, {"m", "the rail line's z (track frame)"});
  out.number("x_t", s.x_t, {"m", "trailing end of the segment inside the wheel (track x)"});
  out.number("x_l", s.x_l, {"m", "leading end of the segment inside the wheel (track x), >= x_t"});
  const long long cones[2] = {s.cone_t + 1, s.cone_l + 1};
  out.integers("cones", cones, 2, {"-", "the wheel cones crossed at the trailing and the leading end (1-based)"});
}

void describe(const Patch& p, const std::vector<Segment>& segments, FieldSink& out) {
  describe_patch_fields(p, out);
  out.begin_list("segments", static_cast<std::size_t>(p.segment_count), {"", "the patch's segments, by line then x"});
  for (int i = 0; i < p.segment_count; ++i) {
    out.item();
    describe(segments[static_cast<std::size_t>(p.first_segment + i)], out);
    out.end();
  }
  out.end();
}

void describe(const LocateResult& r, FieldSink& out) {
  long long tests = 0;
  for (int s : {kLeft, kRight}) {
    const SideLocation& l = r.side[s];
    out.begin(side_name(s), {"", "the location on that side's wheel (left: +y)"});
    out.begin_list("patches", l.patches.size(), {"", "the inter-penetration patches of the undeformed profiles"});
    for (const Patch& p : l.patches) {
      out.item();
      describe(p, l.segments, out);
      out.end();
    }
    out.end();
    out.integer("tests", l.counters.tests, {"-", "closed-form line-cone tests on that side"});
    out.integer("coarse_tests", l.counters.coarse_tests, {"-", "closed-form tests of the coarse pre-search"});
    out.integer("bounds", l.counters.bounds, {"-", "bound checks of the walk (each decides a range of cones)"});
    out.integer("lines_visited", l.counters.lines, {"-", "rail lines visited by the searches"});
    out.integer("grazes", l.grazes, {"-", "graze crossings dropped"});
    tests += l.counters.tests;
    out.end();
  }
  describe(r.pose, out);
  out.integer("tests", tests, {"-", "closed-form line-cone tests, both sides"});
}

}  // namespace wrc
