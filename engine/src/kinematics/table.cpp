// Rigid contact geometry tables (table.hpp): rows with continuation on worker threads, jumps by bisection, files.
#include "wrc/kinematics/table.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/geometry/pose.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

namespace wrc {
namespace {

void check_options(const GeometryTableOptions& o) {
  if (o.y.empty()) fail("geometry table: 'y' needs at least one lateral position (m)");
  for (std::size_t i = 0; i < o.y.size(); ++i) {
    check_lateral(o.y[i], fmt::format("geometry table: {}", value_at(i, "y")));
    if (i > 0 && !(o.y[i] > o.y[i - 1]))
      fail("geometry table: y must increase strictly: {} (= {} m) after {} m", value_at(i, "y"), o.y[i], o.y[i - 1]);
  }
  if (!(o.jump_threshold > 0)) fail("geometry table: jump_threshold = {} m must be positive", o.jump_threshold);
}

// The start of a row from the two before it (a straight line through them), or from the one before.
std::optional<Eigen::Vector2d> predict(const std::vector<RigidResult>& rows, const std::vector<double>& y, std::size_t i,
                                       std::size_t first) {
  auto ok = [&](std::size_t k) { return rows[k].converged; };
  auto pose = [&](std::size_t k) { return Eigen::Vector2d(rows[k].z, rows[k].roll); };
  if (i >= first + 2 && ok(i - 1) && ok(i - 2)) {
    const double s = (y[i] - y[i - 1]) / (y[i - 1] - y[i - 2]);
    return pose(i - 1) + s * (pose(i - 1) - pose(i - 2));
  }
  if (i >= first + 1 && ok(i - 1)) return pose(i - 1);
  return std::nullopt;
}

// Solves the rows [first, last) in order, each from its predecessors.
void solve_chunk(const GeometryModel& g, const GeometryTableOptions& o, std::size_t first, std::size_t last,
                 std::vector<RigidResult>& rows, ProgressCount& progress) {
  RigidOptions ro = o.rigid;
  for (std::size_t i = first; i < last; ++i) {
    if (stop_requested(o.stop)) return;
    ro.start = predict(rows, o.y, i, first);
    rows[i] = solve_rigid(g, o.y[i], o.yaw, ro);
    progress.add(!rows[i].converged);
  }
}

// How far apart two touching points are along the wheel and the rail profile (m).
double distance(const RigidContactPoint& a, const RigidContactPoint& b) {
  return std::max(std::abs(a.wheel_profile.x() - b.wheel_profile.x()), std::abs(a.rail_profile.x() - b.rail_profile.x()));
}

// Narrows a large move of a wheel's touching point between two rows down to 1e-8 m of y; a jump if it stays.
void find_jump(const GeometryModel& g, const GeometryTableOptions& o, int side, const RigidResult& ra,
               const RigidResult& rb, std::vector<ContactJump>& out) {
  double ya = ra.y, yb = rb.y;
  RigidContactPoint A = ra.wheel[side].contacts[0], B = rb.wheel[side].contacts[0];
  Eigen::Vector2d pa(ra.z, ra.roll), pb(rb.z, rb.roll);
  RigidOptions ro = o.rigid;
  while (yb - ya > 1e-8) {
    const double ym = 0.5 * (ya + yb);
    ro.start = 0.5 * (pa + pb);
    const RigidResult m = solve_rigid(g, ym, o.yaw, ro);
    if (!m.converged || m.wheel[side].contacts.empty()) return;
    const RigidContactPoint& M = m.wheel[side].contacts[0];
    if (distance(M, A) <= distance(M, B)) {
      ya = ym;
      A = M;
      pa = {m.z, m.roll};
    } else {
      yb = ym;
      B = M;
      pb = {m.z, m.roll};
    }
  }
  if (distance(A, B) > 0.5 * o.jump_threshold) out.push_back({side, ya, yb, A, B});
}

void find_jumps(const GeometryModel& g, const GeometryTableOptions& o, GeometryTable& t) {
  for (std::size_t i = 1; i < t.rows.size() && !stop_requested(o.stop); ++i)
    for (int s : {kLeft, kRight}) {
      const RigidResult &a = t.rows[i - 1], &b = t.rows[i];
      if (!a.converged || !b.converged || a.wheel[s].contacts.empty() || b.wheel[s].contacts.empty()) continue;
      if (distance(a.wheel[s].contacts[0], b.wheel[s].contacts[0]) > o.jump_threshold) find_jump(g, o, s, a, b, t.jumps);
    }
}

}  // namespace

GeometryTable run_geometry_table(const GeometryModel& g, const GeometryTableOptions& o) {
  check_options(o);
  const auto t0 = std::chrono::steady_clock::now();
  GeometryTable t;
  t.yaw = o.yaw;
  t.roll_mode = o.rigid.roll_mode;
  t.roll = o.rigid.roll;
  t.hertz_load = o.rigid.hertz_load;
  t.material = o.rigid.material;
  const std::size_t n = o.y.size();
  t.rows.resize(n);
  // As many contiguous chunks as threads, each solved in order from a cold start: at least 16 rows a chunk, as
  // continuation needs a run-up and threads cost more than short chunks save.
  const int cap = std::max(1, static_cast<int>(n / 16));
  const ThreadCount tc =
      thread_count(o.threads, cap, fmt::format("{} rows make {} chunk{} of at least 16 rows", n, cap, cap == 1 ? "" : "s"));
  t.threads = tc.threads;
  t.threads_note = tc.note;
  if (!tc.note.empty() && o.notice) o.notice(tc.note);
  const auto chunks = static_cast<std::size_t>(tc.threads);
  ProgressCount progress(o.progress, static_cast<int>(n));
  parallel_for(tc.threads, tc.threads, [&](int, int k) {
    const auto c = static_cast<std::size_t>(k);
    solve_chunk(g, o, n * c / chunks, n * (c + 1) / chunks, t.rows, progress);
  });
  find_jumps(g, o, t);
  if (stop_requested(o.stop))
    fail("geometry table: stopped before its {} rows and their jumps were solved: nothing written", n);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!o.csv.empty()) write_geometry_csv(t, o.csv);
  if (!o.file.empty()) write_geometry_text(t, g, o.file);
  return t;
}

GeometryTableOptions read_geometry_table_options(OptionReader& r) {
  GeometryTableOptions o;
  const auto ys = r.number_list("y", {"m", "lateral positions (required): an array or {from, to, step}"});
  if (!ys && !r.documenting())
    fail("{}: 'y' is required ({} or {}, m)", r.context(), r.words().numbers, r.words().range);
  if (ys) o.y = *ys;
  o.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, o.yaw);
  o.rigid = read_rigid_options(r, o.rigid);
  if (o.rigid.start && !r.documenting())
    fail("{}: 'start' does not apply to a table (each row starts from its neighbours)", r.context());
  o.threads = read_threads(r, o.threads);
  o.jump_threshold = r.number("jump_threshold", {"m", "a larger move of the touching point between rows is examined"},
                              o.jump_threshold);
  o.csv = r.string("csv", {"-", "write the table as CSV to this file"}, o.csv);
  o.file = r.string("file", {"-", "write the multibody table to this file"}, o.file);
  return o;
}

// ---- files ----

namespace {

constexpr double kDeg = 180 / std::numbers::pi;

// A CSV cell: a finite number, or empty.
std::string cell(double v, bool present = true) {
  if (!present) return "";
  if (!std::isfinite(v)) fail("geometry table: a value is not finite ({})", v);
  return fmt::format("{:.10g}", v);
}

std::vector<std::string> csv_columns() {
  std::vector<std::string> c{"yaw_deg", "y_mm", "converged", "z_mm", "roll_mrad", "dr_mm", "dtan_gamma"};
  for (const char* s : {"left", "right"}) {
    for (const char* k : {"lifted", "touch_z_mm", "gap_mm", "contacts", "wheel_y_mm", "wheel_z_mm", "rail_y_mm",
                          "rail_z_mm", "track_x_mm", "track_y_mm", "track_z_mm", "r_mm", "angle_deg",
                          "wheel_curvature_per_m", "rail_curvature_per_m", "wheel_radius_mm", "rail_radius_mm",
                          "hertz_a_mm", "hertz_b_mm", "hertz_p0_MPa", "C11", "C22", "C23", "C33", "2_gap_mm",
                          "2_wheel_y_mm", "2_rail_y_mm", "2_r_mm", "2_angle_deg"})
      c.push_back(fmt::format("{}_{}", s, k));
  }
  return c;
}

void csv_wheel(const RigidWheel& w, std::vector<std::string>& row) {
  row.push_back(w.lifted ? "1" : "0");
  const bool on = !w.lifted && !w.contacts.empty();
  const RigidContactPoint c = on ? w.contacts[0] : RigidContactPoint{};
  for (double v : {w.z * 1e3, w.gap * 1e3}) row.push_back(cell(v, !w.lifted));
  row.push_back(on ? std::to_string(w.contacts.size()) : "");
  for (double v : {c.wheel_profile.x() * 1e3, c.wheel_profile.y() * 1e3, c.rail_profile.x() * 1e3,
                   c.rail_profile.y() * 1e3, c.point.x() * 1e3, c.point.y() * 1e3, c.point.z() * 1e3,
                   c.rolling_radius * 1e3, c.angle * kDeg, c.wheel_curvature, c.rail_curvature})
    row.push_back(cell(v, on));
  row.push_back(cell(on && c.wheel_curvature != 0 ? 1e3 / c.wheel_curvature : 0, on && c.wheel_curvature != 0));
  row.push_back(cell(on && c.rail_curvature != 0 ? 1e3 / c.rail_curvature : 0, on && c.rail_curvature != 0));
  const auto& h = c.ellipses.hertz;
  for (double v : {h ? h->a * 1e3 : 0, h ? h->b * 1e3 : 0, h ? h->p0 * 1e-6 : 0}) row.push_back(cell(v, on && h));
  const halfspace::CreepCoefficients k = c.ellipses.kalker.value_or(halfspace::CreepCoefficients{});
  for (double v : {k.c11, k.c22, k.c23, k.c33}) row.push_back(cell(v, on && c.ellipses.kalker));
  const bool two = on && w.contacts.size() > 1;
  const RigidContactPoint d = two ? w.contacts[1] : RigidContactPoint{};
  for (double v : {d.gap * 1e3, d.wheel_profile.x() * 1e3, d.rail_profile.x() * 1e3, d.rolling_radius * 1e3, d.angle * kDeg})
    row.push_back(cell(v, two));
}

}  // namespace

void write_geometry_csv(const GeometryTable& t, const std::string& path) {
  const std::vector<std::string> cols = csv_columns();
  std::string text = fmt::format("{}\n", fmt::join(cols, ","));
  for (const RigidResult& r : t.rows) {
    std::vector<std::string> row{cell(r.yaw * kDeg), cell(r.y * 1e3), r.converged ? "1" : "0"};
    const bool on = r.touching();
    for (double v : {r.z * 1e3, r.roll * 1e3}) row.push_back(cell(v, r.converged));
    row.push_back(cell(on ? r.rolling_radius_difference() * 1e3 : 0, on));
    row.push_back(cell(on ? std::tan(r.wheel[kLeft].contacts[0].angle) - std::tan(r.wheel[kRight].contacts[0].angle) : 0, on));
    for (int s : {kLeft, kRight}) {
      if (r.converged) csv_wheel(r.wheel[s], row);
      else row.resize(row.size() + (cols.size() - 7) / 2);
    }
    text += fmt::format("{}\n", fmt::join(row, ","));
  }
  write_file_atomic(path, text);  // whole or not at all (a killed run leaves no partial table)
}

void write_geometry_text(const GeometryTable& t, const GeometryModel& g, const std::string& path) {
  for (const RigidResult& r : t.rows)
    if (!r.touching())
      fail("geometry table: {}: the row y = {:.4f} mm has no contact on both wheels ({}); a multibody table needs both: "
           "narrow the y range",
           path, r.y * 1e3, r.converged ? "a wheel lifted" : r.message);
  const Track& tr = *g.track;
  const TrackParams& p = tr.params;
  std::string h;
  h += "# wrc rigid contact geometry table, format 2\n";
  h += fmt::format("# wheel: {} ({}), rail: {} ({})\n", tr.wheel[kLeft].name, tr.wheel[kLeft].source, tr.rail[kLeft].name,
                   tr.rail[kLeft].source);
  if (tr.wheel[kRight].source != tr.wheel[kLeft].source || tr.rail[kRight].source != tr.rail[kLeft].source)
    h += fmt::format("# right wheel: {} ({}), right rail: {} ({})\n", tr.wheel[kRight].name, tr.wheel[kRight].source,
                     tr.rail[kRight].name, tr.rail[kRight].source);
  h += fmt::format("# track: gauge {} m at {} m below the rail top, cant {}, back_to_back {} m, tape_offset {} m, "
                   "radius {} m\n", p.gauge, p.gauge_depth, p.cant, p.back_to_back, p.tape_offset, p.radius);
  h += fmt::format("# roll: {}; yaw: {} rad; rows: {}\n",
                   t.roll_mode == RollMode::free ? std::string("free (both wheels on their rails)")
                                                 : fmt::format("fixed at {} rad (each wheel on its own rail)", t.roll),
                   t.yaw, t.rows.size());
  if (t.material)
    h += fmt::format("# Hertz ellipses for a normal load of {} N per contact point (hertz_load), E = {} Pa, nu = {}\n",
                     t.hertz_load, t.material->E, t.material->nu);
  else
    h += "# no material given: no Hertz ellipses (their columns 0)\n";
  h += "# units SI (m, rad, 1/m). Track frame: x along the track, z up, +y toward the LEFT rail. Profile coordinates\n"
       "# are those of the profiles as loaded (wheel: s from the tape circle, + toward the field side; rail: y + toward\n"
       "# the field side, z up). Contact angle > 0 toward the track centre on both wheels. Curvature > 0 convex.\n";
  const char* columns[] = {
      "y      lateral displacement of the wheelset (m)", "z      height of the wheelset centre (m; 0 = centred first touch)",
      "roll   roll angle (rad; > 0 lifts the left wheel)", "dr     rolling radius difference r_left - r_right (m)",
      "rL     rolling radius of the left wheel (m)", "rR     rolling radius of the right wheel (m)",
      "gL     contact angle, left (rad)", "gR     contact angle, right (rad)",
      "sL     contact point on the left wheel profile, s (m)", "sR     contact point on the right wheel profile, s (m)",
      "yrL    contact point on the left rail profile, y (m)", "yrR    contact point on the right rail profile, y (m)",
      "zrL    contact point on the left rail profile, z (m)", "zrR    contact point on the right rail profile, z (m)",
      "kwL    lateral curvature of the left wheel profile there (1/m)", "kwR    the same, right wheel (1/m)",
      "krL    lateral curvature of the left rail profile there (1/m)", "krR    the same, right rail (1/m)",
      "xL     longitudinal position of the left contact point (m; 0 at zero yaw)", "xR     the same, right (m)",
      "nL     contact points of the left wheel (2: two-point contact)", "nR     the same, right wheel",
      "aL     Hertz semi-axis along the track, left touching point (m; 0: no Hertz ellipse, a concave pair)",
      "aR     the same, right (m)", "bL     Hertz semi-axis across the track, left (m)", "bR     the same, right (m)",
      "C11L   Kalker's coefficient C11 for the left ellipse's a/b and nu (-; 0 without an ellipse or nu < 0)",
      "C11R   the same, right (-)",
      "C22L   Kalker's C22, left (-)", "C22R   the same, right (-)", "C23L   Kalker's C23, left (-)",
      "C23R   the same, right (-)", "C33L   Kalker's C33, left (-)", "C33R   the same, right (-)"};
  h += "# columns:\n";
  int k = 0;
  for (const char* c : columns) h += fmt::format("# {:2d} {}\n", ++k, c);
  h += "# y z roll dr rL rR gL gR sL sR yrL yrR zrL zrR kwL kwR krL krR xL xR nL nR aL aR bL bR C11L C11R C22L C22R "
       "C23L C23R C33L C33R\n";
  for (const RigidResult& r : t.rows) {
    const RigidContactPoint &L = r.wheel[kLeft].contacts[0], &R = r.wheel[kRight].contacts[0];
    std::vector<double> v{r.y, r.z, r.roll, r.rolling_radius_difference(), L.rolling_radius, R.rolling_radius,
                          L.angle, R.angle, L.wheel_profile.x(), R.wheel_profile.x(), L.rail_profile.x(),
                          R.rail_profile.x(), L.rail_profile.y(), R.rail_profile.y(), L.wheel_curvature,
                          R.wheel_curvature, L.rail_curvature, R.rail_curvature, L.point.x(), R.point.x()};
    std::string line;
    for (double x : v) {
      if (!std::isfinite(x)) fail("geometry table: a value is not finite at y = {} m", r.y);
      line += fmt::format("{: .12e} ", x);
    }
    line += fmt::format("{} {}", r.wheel[kLeft].contacts.size(), r.wheel[kRight].contacts.size());
    const auto ellipse = [](const RigidContactPoint& c, bool a) {
      return c.ellipses.hertz ? (a ? c.ellipses.hertz->a : c.ellipses.hertz->b) : 0.0;
    };
    const halfspace::CreepCoefficients kL = L.ellipses.kalker.value_or(halfspace::CreepCoefficients{}),
                                       kR = R.ellipses.kalker.value_or(halfspace::CreepCoefficients{});
    for (double x : {ellipse(L, true), ellipse(R, true), ellipse(L, false), ellipse(R, false), kL.c11, kR.c11, kL.c22,
                     kR.c22, kL.c23, kR.c23, kL.c33, kR.c33}) {
      if (!std::isfinite(x)) fail("geometry table: a value is not finite at y = {} m", r.y);
      line += fmt::format(" {: .12e}", x);
    }
    h += line + "\n";
  }
  write_file_atomic(path, h);
}

// ---- wheelset conicity ----

WheelsetConicity wheelset_conicity(const GeometryModel& g, WheelsetConicityOptions o) {
  if (o.table.y.empty()) {
    double ymax = 0;
    for (double a : o.conicity.yhat) ymax = std::max(ymax, a);
    const double step = 0.05e-3;
    const int n = static_cast<int>(std::ceil((1.5 * ymax + 1e-3) / step));
    for (int i = -n; i <= n; ++i) o.table.y.push_back(i * step);
  }
  WheelsetConicity w;
  w.table = run_geometry_table(g, o.table);
  const RigidResult* centre = nullptr;
  for (const RigidResult& r : w.table.rows) {
    if (!r.touching())
      fail("wheelset conicity: no rigid contact of both wheels at y = {:.4f} mm ({}): the Δr table needs both",
           r.y * 1e3, r.converged ? "a wheel lifted" : r.message);
    const RigidContactPoint &L = r.wheel[kLeft].contacts[0], &R = r.wheel[kRight].contacts[0];
    w.dr.y.push_back(r.y);
    w.dr.dr.push_back(r.rolling_radius_difference());
    w.dr.flange.push_back(std::max(L.angle, R.angle) > o.flange_angle);
    if (!centre || std::abs(r.y) < std::abs(centre->y)) centre = &r;
  }
  if (o.conicity.r0 <= 0) o.conicity.r0 = g.track->params.radius;
  if (o.conicity.contact_distance <= 0)
    o.conicity.contact_distance = centre->wheel[kLeft].contacts[0].point.y() - centre->wheel[kRight].contacts[0].point.y();
  w.conicity = equivalent_conicity(w.dr, o.conicity);
  return w;
}

WheelsetConicityOptions read_wheelset_conicity_options(OptionReader& r) {
  WheelsetConicityOptions o;
  o.conicity = read_conicity_options(r, o.conicity);
  if (auto y = r.number_list("y", {"m", "lateral positions of the table (default: +-(1.5 max yhat + 1 mm))"}))
    o.table.y = *y;
  o.table.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, o.table.yaw);
  o.table.rigid = read_rigid_options(r, o.table.rigid);
  o.table.threads = read_threads(r, o.table.threads);
  o.flange_angle =
      r.number("flange_angle", {"rad", "a touching point steeper than this is flange contact"}, o.flange_angle);
  if (!r.documenting() && !(o.flange_angle > 0 && o.flange_angle < 1.5)) fail("{}: flange_angle = {} rad must lie in ]0, 1.5[", r.context(), o.flange_angle);
  return o;
}

void describe(const WheelsetConicity& c, FieldSink& out) {
  describe(c.conicity, out);
  out.string("roll_mode", c.table.roll_mode == RollMode::free ? "free" : "fixed",
             {"", "roll of the table's rows: fixed (held at 0 unless given) or free"});
  out.begin("dr", {"", "the rolling-radius difference table the conicity used"});
  out.numbers("y", c.dr.y.data(), c.dr.y.size(), {"m", "lateral positions of the wheelset, + toward the left rail"});
  out.numbers("dr", c.dr.dr.data(), c.dr.dr.size(), {"m", "rolling radius difference r_left - r_right at each y"});
  std::vector<long long> f(c.dr.flange.begin(), c.dr.flange.end());
  out.integers("flange", f.data(), f.size(), {"-", "1 where a touching point is steeper than flange_angle (flange contact)"});
  out.end();
}

void describe(const GeometryTable& t, FieldSink& out) {
  out.number("yaw", t.yaw, {"rad", "yaw of every row, > 0 counter-clockwise seen from above"});
  out.string("roll_mode", t.roll_mode == RollMode::free ? "free" : "fixed", {"", "free (roll solved) or fixed (held)"});
  out.number("roll", t.roll, {"rad", "the held roll (roll fixed)"});
  out.number("hertz_load", t.hertz_load, {"N", "the normal load of the contact points' Hertz ellipses (hertz, kalker)"});
  out.number("seconds", t.seconds, {"s", "wall time"});
  out.integer("threads", t.threads, {"-", "worker threads used"});
  if (!t.threads_note.empty())
    out.string("threads_note", t.threads_note, {"", "why fewer threads ran than asked for (only then)"});
  out.begin_list("rows", t.rows.size(), {"", "one rigid contact result per y, in order"});
  for (const RigidResult& r : t.rows) {
    out.item();
    describe(r, out);
    out.end();
  }
  out.end();
  out.begin_list("jumps", t.jumps.size(), {"", "jumps of a wheel's touching point between rows, by y then side"});
  for (const ContactJump& j : t.jumps) {
    out.item();
    out.string("side", side_name(j.side), {"", "the wheel: left or right"});
    out.number("y_before", j.y_before, {"m", "y just before the jump (bisected to 1e-8 m)"});
    out.number("y_after", j.y_after, {"m", "y just after the jump"});
    out.number("wheel_jump", j.after.wheel_profile.x() - j.before.wheel_profile.x(),
               {"m", "move of the touching point along the wheel profile (profile y after minus before)"});
    out.number("rail_jump", j.after.rail_profile.x() - j.before.rail_profile.x(),
               {"m", "move of the touching point along the rail profile (profile y after minus before)"});
    out.begin("before", {"", "the touching point before the jump"});
    describe(j.before, out);
    out.end();
    out.begin("after", {"", "the touching point after the jump"});
    describe(j.after, out);
    out.end();
    out.end();
  }
  out.end();
}

}  // namespace wrc
