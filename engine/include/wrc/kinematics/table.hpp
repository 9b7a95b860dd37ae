// Rigid contact geometry tables (docs/guide/geometry.md): the rigid contact (rigid.hpp) for a sorted
// series of lateral displacements at one yaw, the way multibody codes precompute it, in one engine call on worker
// threads, with the contact-point jumps found and written as CSV or as a plain-text table for multibody programs.
//
// Rows are solved in order with continuation (each row starts from the straight line through the previous two);
// the rows are split into as many contiguous chunks as threads, each chunk starting cold. Where the touching point
// of a wheel moves along its wheel or rail profile by more than `jump_threshold` between two rows, the interval is
// bisected to 1e-8 m of y: if the move stays (a jump), it is reported with the positions on both sides.
#pragma once

#include "wrc/core/parallel.hpp"
#include "wrc/kinematics/conicity.hpp"
#include "wrc/kinematics/rigid.hpp"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace wrc {

struct GeometryTableOptions {
  std::vector<double> y;             // lateral displacements (m), strictly increasing
  double yaw = 0;                    // rad
  RigidOptions rigid;                // roll mode, Q, two_point_tolerance (start: ignored)
  int threads = 0;                   // 0: the cores this process may use (available_cores)
  double jump_threshold = 0.5e-3;    // m: a move of the touching point larger than this between rows is examined
  Progress progress;                 // (rows done, rows, rows without a solution): from the workers, serialised
  std::string csv, file;             // when not empty: write the CSV / the multibody table there
  std::function<void(const std::string&)> notice;  // once, when fewer threads run than `threads` asked for
  // The front end's stop (Ctrl-C): once it turns true no row begins, and the table throws "stopped" before it writes
  // any file (an output keeps its previous content).
  const std::atomic<bool>* stop = nullptr;
};

// A jump of one wheel's touching point between y_before and y_after (bisected to 1e-8 m).
struct ContactJump {
  int side = kLeft;
  double y_before = 0, y_after = 0;  // m
  RigidContactPoint before, after;   // the touching point on each side of the jump
};

struct GeometryTable {
  double yaw = 0;
  RollMode roll_mode = RollMode::free;
  double roll = 0;                   // the held roll (roll fixed)
  double hertz_load = kHertzLoad;    // N: the load of the contact points' Hertz ellipses (RigidOptions)
  std::optional<halfspace::Material> material;  // the material they assume (none: no ellipses)
  std::vector<RigidResult> rows;     // one per y, in order
  std::vector<ContactJump> jumps;    // by y, then side
  double seconds = 0;
  int threads = 1;                   // worker threads used
  std::string threads_note;          // why fewer than GeometryTableOptions::threads (when given) ran; "" otherwise
};

// Throws wrc::Error on bad input (no y, y not increasing, yaw or roll out of range) or when a file cannot be written;
// a row without a solution is kept with converged = false and its reason.
GeometryTable run_geometry_table(const GeometryModel& geometry, const GeometryTableOptions& options);

// y (an array or {from =, to =, step =}, required), yaw, roll, Q, two_point_tolerance, threads, jump_threshold,
// csv, file. `progress` and `notice` are left to the front end: a reader prints nothing.
GeometryTableOptions read_geometry_table_options(OptionReader& options);

// The CSV columns (units in the names) and the multibody table (docs/guide/geometry.md "Geometry tables" lists both).
void write_geometry_csv(const GeometryTable& table, const std::string& path);
void write_geometry_text(const GeometryTable& table, const GeometryModel& geometry, const std::string& path);

// yaw, roll_mode, roll, seconds, threads, threads_note (when set), rows = {rigid results}, jumps = {{side, y_before, y_after,
// before = {contact point}, after = {...}, wheel_jump, rail_jump (m: along each profile)}}.
void describe(const GeometryTable& table, FieldSink& out);

// ---- the equivalent conicity of a wheelset: its rigid Δr table, then conicity.hpp ----

struct WheelsetConicityOptions {
  ConicityOptions conicity;        // yhat, method; r0 and contact_distance 0: the wheelset's (see below)
  GeometryTableOptions table;      // y (default: +-(1.5 max yhat + 1 mm) every 0.05 mm), roll (default fixed at 0)
  double flange_angle = 0.7853981633974483;  // rad (45 deg): a touching point steeper than this is flange contact
  WheelsetConicityOptions() {
    conicity.r0 = conicity.contact_distance = 0;
    table.rigid.roll_mode = RollMode::fixed;  // roll held at 0 unless asked: the usual way of EN 15302 tables
  }
};

struct WheelsetConicity {
  ConicityResult conicity;
  DeltaRFunction dr;               // the table it used (flange: a touching point steeper than flange_angle)
  GeometryTable table;
};

// r0 = the wheelset's nominal radius, contact_distance = the lateral distance of the touching points of the row
// nearest y = 0, unless given. Throws when a row of the table has no contact on both wheels, or as
// equivalent_conicity does.
WheelsetConicity wheelset_conicity(const GeometryModel& geometry, WheelsetConicityOptions options);
// yhat, method, r0, contact_distance, roll (default "fixed"), y, yaw, threads, flange_angle, two_point_tolerance.
WheelsetConicityOptions read_wheelset_conicity_options(OptionReader& options);
// The conicity's fields, roll_mode, and dr = {y, dr, flange}.
void describe(const WheelsetConicity& c, FieldSink& out);

}  // namespace wrc
