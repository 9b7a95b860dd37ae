// From the inter-penetration patches of a wheelset pose to forces (paper section 3, docs/design.md section 3):
// contact plane, potential contact area, undeformed distance h, Kalker's normal problem per area, and the
// resulting forces and moments on the wheelset.
//
// Contact plane of an area: the paper's plane is tangent to the wheel at the nominal point (mid-point of the
// longest segment). The nominal point jumps from one rail line to the next as the pose changes, and so would
// the plane; here the plane is tangent to the wheel at the WEIGHTED nominal point: segment mid-points and the
// wheel's (smooth) normals there, weighted by each segment's share of the inter-penetration volume
// (2/3 length x sagitta x line spacing). The weights vanish with the segments, so the plane -- and the forces --
// vary continuously with the pose, which the equilibrium's Newton solver needs. The paper's nominal point is
// reported too.
//
// Potential contact area: a regular grid of square elements in the plane, aligned with the plane's origin
// (element centres at integer multiples of the element size from it), covering the projected segments plus a
// margin. h at an element: the rail lines project onto the plane as lines parallel to its first axis; along a
// line with a segment, h is the paper's circular arc through the segment's ends with radius = wheel radius /
// cos(conicity angle) (averaged over the two ends' cones, which differ where yaw makes the line cross two);
// along a line without a segment (the margin), the same arc through the line's deepest point, whose (negative)
// height is the exact radial gap times cos(conicity); between lines h is interpolated linearly.
//
// Areas of one wheel are solved together when halfspace::patches_interact says the separate solutions differ
// by more than `merge_tolerance` and their normals differ by less than the merge angle (merge_angle_of below: on a
// plane 15 deg, as one plane must serve both; on the conformal surface 1.2 rad, since the curved surface serves
// both); otherwise each alone.
//
// That is the planar path (ContactOptions::surface = planar). The default, conformal, lays each area on the curved
// surface along the rail's profile instead, with h along the normals and each row's pressure along its own normal
// (wheelset/conformal.hpp); location, merging, solvers and results are shared.
#pragma once

#include "wrc/halfspace/ellipse.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/halfspace/rolling.hpp"
#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/wheelset/plausibility.hpp"
#include "wrc/wheelset/conformal.hpp"
#include "wrc/wheelset/tangential.hpp"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace wrc {

// The element size's range (m): finer than 1 um no wheel-rail area fits any memory, coarser than 10 mm is no grid.
inline constexpr double kElementMin = 1e-6, kElementMax = 0.01;
// Throws wrc::Error naming `context` when the element size (m) is outside that range: checked when the wheelset's
// options are read, before the strategy's default step follows it (native_strategy), and by the contact model.
void validate_element(double element, std::string_view context);

// The deepest inter-penetration of the undeformed profiles an evaluation accepts by default (m; ContactRequest and
// SolveLimits::max_penetration). Wheel-rail contacts at realistic loads are 0.05-0.3 mm deep (S1002/60E1: 0.075
// mm at 100 kN per wheel, 0.24 mm for 367 kN on the flange root); at 1 mm the contact is tens of mm long on a 0.45 m
// wheel, where the half-space model no longer holds (Hertz: ~5 MN).
inline constexpr double kMaxPenetration = 1e-3;

struct ContactOptions {
  double element = 0.2e-3;        // element size of the potential contact area (m), [kElementMin, kElementMax]
  int margin = 2;                 // elements around the projected inter-penetration area
  double merge_tolerance = 0.01;  // relative force error of solving two areas apart that triggers a merge
  // rad: areas whose normals differ more are never merged; none: the surface's default (merge_angle_of)
  std::optional<double> merge_angle;
  // The calls' loads and speeds checked against a railway wheelset's (wheelset/plausibility.hpp); the wheelset sets it
  // from WheelsetParams::check_setup.
  bool check_magnitudes = true;
  bool dense = false;             // the dense reference solver instead of the fast one (tests)
  // Largest potential contact area (elements, ~kBytesPerElement each): a larger one is an error naming the grid as too
  // fine for the cap, or the pose as far too deep. 2^22: the paper's poses (S1002/60E1, Q = 200 kN, y = -8 .. 8 mm,
  // yaw 0 and 1 deg) need up to ~2.4e6 elements at grid = 0.02 mm (conformal areas; tests/scripts/limits.lua).
  int max_elements = 1 << 22;
  halfspace::NormalOptions normal;  // tolerance etc. of the normal solver
  // The potential contact area: the curved surface along the rail's profile (CONTACT's conformal mode;
  // wheelset/conformal.hpp) or one plane per area (the paper's, CONTACT's planar mode). Conformal by default: it
  // agrees with the plane where the patch is flat and satisfies virtual work where the plane does not
  // (docs/guide/normal.md "Conformal contact").
  ContactSurface surface = ContactSurface::conformal;
};

// The default merge angles (rad; ContactOptions::merge_angle). Planar: 0.26 (15 deg), one plane must serve both areas.
// Conformal: 1.2 (69 deg), the areas lie on the curved rail surface and couple along it; at the flange root and tread
// 18.5 deg apart the bodies' elasticity couples them as the flat half-space along the surface does (a finite-element
// study, docs/validation.md "Against CONTACT"), so only the gauge face's steepest turns stay apart.
inline constexpr double kMergeAnglePlanar = 0.26, kMergeAngleConformal = 1.2;

// The merge angle in force: the option's, or the surface's default.
inline double merge_angle_of(const ContactOptions& o) {
  return o.merge_angle.value_or(o.surface == ContactSurface::planar ? kMergeAnglePlanar : kMergeAngleConformal);
}

// Memory of the normal solve per element of a potential contact area (bytes; measured with the fast solver,
// S1002/60E1 at 0.02 .. 0.04 mm: 350-600): for the messages about max_elements.
inline constexpr double kBytesPerElement = 400;

// Rows of a force/moment sensitivity: (Fx, Fy, Fz, Mx, My, Mz); columns: (z, roll) of the pose.
using Sensitivity = Eigen::Matrix<double, 6, 2>;

// A wheel's Jacobian (ContactRequest::sensitivity; docs/guide/sensitivity.md): rows the derivatives of (Fx, Fy, Fz,
// Mx, My, Mz), the wheel's force and moment (WheelContact::force, moment: track frame, moments about the wheelset
// centre, creep forces included); columns (xi, eta, phi, y, z, roll, yaw): the creepages at every area's reference
// point (N per unit creepage; phi: N m), then the pose (N/m, N/rad; N m/m, N m/rad). Computed from the solvers'
// linearisations at the solution's contact areas and adhesion / slip splits.
using Jacobian = Eigen::Matrix<double, 6, 7>;
inline constexpr const char* kJacobianColumns[7] = {"xi", "eta", "phi", "y", "z", "roll", "yaw"};
inline constexpr int kJacobianPose = 3;  // the first pose column (y)

// One potential contact area (one or more merged inter-penetration patches of one wheel) and its solution.
// A conformal area (`conformal` set, wheelset/conformal.hpp) has no plane: origin, t1, t2 are the local frame at its
// grid's origin on the curved surface, `normal` is the direction of the resultant force (normal_force = |force|,
// below the pressure's integral), `point` the centre of pressure on the surface and `moment` the sum of the
// elements' moments.
struct PatchContact {
  int side = kLeft;
  std::vector<Patch> located;          // the inter-penetration patches of the area (copied from the location;
  std::vector<Segment> segments;       // Patch::first_segment indexes `segments`)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // contact plane (track frame, m)
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();     // first axis (rolling direction), grid x
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();     // second axis (lateral), grid y
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit, from the rail into the wheel
  Eigen::Vector3d nominal = Eigen::Vector3d::Zero(); // the paper's nominal point of the first patch (m)
  double nominal_angle = 0;            // contact angle of the wheel's normal there (rad): the paper's plane
  halfspace::NormalSolution solution;    // grid (m, plane frame), pressure (Pa), area, ... (see normal.hpp)
  std::vector<double> h;               // undeformed distance per element (m, > 0 inter-penetration)
  std::vector<double> h_gain;          // per element, dh per unit of the wheel's approach along its normal: 1 but on a
                                       // curved steep face, where h is the normal depth (design.md section 3)
  std::optional<ConformalSurface> conformal;  // the curved surface of a conformal area (rows, normals); none: planar
  double normal_force = 0;             // N
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // on the wheel (N, track frame): normal + creep force
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // centre of pressure (track frame, m)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // of the area's tractions about the wheelset centre (N m)
  double angle = 0;                    // contact angle (rad): normal vs z, > 0 tilted toward the track centre
  double angle_min = 0, angle_max = 0; // range of the directions the pressure acts in (rad; planar: = angle)
  double rolling_radius = 0;           // wheel radius at the centre of pressure (m)
  double penetration = 0;              // max h (m)
  int regions = 0;                     // separate contact regions in the area (p > 0, 8-connected, each with
                                       // >= 0.1 % of the force): 2 for a tread and flange-root contact that one
                                       // inter-penetration area holds
  // How many elements the contact spans: of the regions that hold its peak pressure or carry 10 % of its force, the
  // smallest of each one's most elements in contact in one grid row (span_x, along t1) and in one grid column (span_y,
  // along t2). Below kMinSpan in either the peak pressure and the area are not resolved by the grid (resolved(),
  // resolution_note()).
  int span_x = 0, span_y = 0;
  // What multibody tables carry (halfspace/ellipse.hpp): FASTSIM's equivalent ellipse of the region carrying the most
  // force; Hertz's ellipse for normal_force and the curvatures at the centre of pressure (the wheel's rolling radius
  // and profile curvature, the rail's profile curvature) with Kalker's coefficients for it, when both are convex.
  halfspace::ContactEllipses ellipses;
  // Every contact region's equivalent ellipse (halfspace::equivalent_ellipses of the pressure; `regions` counts those
  // with >= 0.1 % of the force) and each element's region (-1 outside): FASTSIM's layers, found once with `regions`
  // (dropped with the grids).
  std::vector<halfspace::EquivalentEllipse> region_ellipses;
  std::vector<int> region_label;
  Sensitivity sensitivity = Sensitivity::Zero();  // d(force, moment)/d(z, roll) of the normal problem, when asked for
  std::optional<PatchRolling> rolling;  // the tangential solution, when the call gave kinematics or creepages
  double nu = 0;                        // Poisson's ratio of the bodies (the model's material): what the stresses
                                        // below the area take (halfspace/subsurface.hpp, api::SubsurfaceCall)
};

// What the damage indices read of an area with a tangential solution and its grids (spans over its storage);
// throws wrc::Error when it has neither.
damage::AreaFields area_fields(const PatchContact& area);

// The fewest elements a contact region may span along t1 or t2 for its peak pressure to be resolved. Measured on
// Hertzian contacts (B/A = 1, 5, 20; elements of 0.2 to 2 minor semi-axes, the grid shifted against the contact; the
// force prescribed; 510 grids, 90 of them in tests/wheelset/test_resolution.cpp), pmax against Hertz's p0 (and the
// area, elements times their size) at worst: spanning 4-5 elements the narrower way, 3.3 % (52 %); 6-7, 1.8 % (17 %);
// 8-9, 1.0 % (10 %); 1, 2 and 3 elements, 74, 57 and 26 %. S1002 on 60E1, a flange contact of 1 kN: 2 elements wide
// at 0.5 mm, pmax 635 MPa against 1,143-1,181 MPa at 0.1-0.05 mm.
inline constexpr int kMinSpan = 4;
inline bool resolved(const PatchContact& area) {  // an area without pressure has nothing to resolve
  return area.regions == 0 || (area.span_x >= kMinSpan && area.span_y >= kMinSpan);
}

// Totals of the tangential solutions (when solved): creep forces, their moments, frictional power.
struct CreepTotals {
  bool solved = false;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, track frame
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N m, about the wheelset centre
  double power = 0;                                  // W
  double axle_torque = 0;  // N m: the moment's component along the axle a (> 0 drives the spin omega a forward)
};

struct WheelContact {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // on the wheel (N, track frame), creep forces included
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about the wheelset centre (N m)
  std::vector<PatchContact> patches;
  double angle = 0;           // contact angle of the resultant force (rad)
  double rolling_radius = 0;  // normal-force weighted mean of the areas' rolling radii (m); not described when lifted
  Sensitivity sensitivity = Sensitivity::Zero();
  std::optional<Jacobian> jacobian;  // with ContactRequest::sensitivity
  // ws:wheel with sensitivity: the Jacobian with the wheel's vertical force Fz held (z adjusting): column z is
  // d(.)/dFz (per N), the others d(.)/d(column) at constant Fz.
  std::optional<Jacobian> jacobian_fz;
  std::string flange_climb;   // why the wheel is past flange climb (wheelset/plausibility.hpp); "" when it is not
  CreepTotals creep;
};

// "" when every area of the wheel spans kMinSpan elements both ways; else what is not resolved, by how much, and the
// grid that would resolve it, for the front ends to show (the engine prints nothing).
std::string resolution_note(const WheelContact& wheel);

struct ContactResult {
  Pose pose;
  std::array<WheelContact, 2> wheel;  // indexed by Side
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // both wheels (N)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // both wheels, about the wheelset centre (N m)
  Sensitivity sensitivity = Sensitivity::Zero();     // both wheels
  CreepTotals creep;                                 // both wheels
  std::optional<double> omega;  // rad/s: the axle's angular velocity the creep forces were solved at (kinematics)
  int spin_evaluations = 0;     // free rolling: the tangential solves of both wheels its search for omega took
};

// resolution_note of the first wheel that has one, "" when none has.
std::string resolution_note(const ContactResult& result);

// The immutable contact model: discretised geometry, material, normal solver (with its FFT caches) and options.
class ContactModel {
 public:
  ContactModel(std::shared_ptr<const GeometryModel> geometry, const halfspace::Material& material,
               const ContactOptions& options);
  const GeometryModel& geometry() const { return *geometry_; }
  const std::shared_ptr<const GeometryModel>& geometry_ptr() const { return geometry_; }
  const halfspace::Material& material() const { return solver_.material(); }
  const ContactOptions& options() const { return options_; }
  const halfspace::NormalSolver& solver() const { return solver_; }
  // The flange of each side's wheel profile (for the flange-climb flags of the results).
  const Flange& flange(int side) const { return flange_[static_cast<std::size_t>(side)]; }
  const halfspace::RollingSolver& rolling_solver() const { return rolling_; }
  // Arc length of each of a side's rail lines along the rail profile from its first line (m): the conformal
  // surface's coordinate s (chords between neighbouring lines summed once, here).
  const std::vector<double>& rail_arc(int side) const { return rail_arc_[static_cast<std::size_t>(side)]; }
  // The arc length (m, as rail_arc) of the point of a side's rail nearest to its profile's origin (0 without a
  // track): the conformal grids' elements lie at this s plus integer multiples of the element, so that mirrored
  // rails have mirrored lattices and a contact centred on a symmetric rail head has an element at its centre.
  double rail_lattice_origin(int side) const { return rail_lattice_[static_cast<std::size_t>(side)]; }

 private:
  std::shared_ptr<const GeometryModel> geometry_;
  std::array<std::vector<double>, 2> rail_arc_;
  std::array<double, 2> rail_lattice_{0.0, 0.0};
  std::array<Flange, 2> flange_;
  ContactOptions options_;
  halfspace::NormalSolver solver_;
  halfspace::RollingSolver rolling_;
};

// Per-thread state: the locator (the model's strategy bound to this thread), the solver's buffers and the
// pressures of the last evaluation, which start the next solve of the same area (a Newton step or a sweep
// moves the wheelset little between evaluations).
class ContactWorkspace {
 public:
  explicit ContactWorkspace(const ContactModel& model);  // the strategy's own per-thread search
  ContactWorkspace(const ContactModel& model, std::unique_ptr<PoseSearch> search);
  Locator locator;
  halfspace::NormalWorkspace normal;
  halfspace::RollingWorkspace rolling;
  struct Previous {
    Eigen::Vector3d origin, t1, t2, normal;
    halfspace::Grid grid;
    std::vector<double> pressure;
    std::vector<double> displacement;  // the solver's u = D pressure (empty if it gave none)
    // In `tangential` only: the exact solver's tractions (Pa) and adhesion / slip split (halfspace::ElementState).
    std::vector<double> px, py;
    std::vector<unsigned char> state;
  };
  std::array<std::vector<Previous>, 2> previous;  // per side, the areas of the last evaluation
  bool warm_start = true;                         // use them (off to measure what it gains)
  // Start from the linear extrapolation of the last two evaluations (2 p_last - p_before, where both were in
  // contact) instead of the last alone: for poses along a trajectory at a fixed time step (Trajectory::contact).
  bool extrapolate = false;
  std::array<std::vector<Previous>, 2> before;    // per side, the areas of the evaluation before the last
  // Per side, the areas of the last exact tangential solve, which start the next (with warm_start): along a
  // trajectory, and when a wheel solve's creep forces are solved again on a slightly different normal solution.
  std::array<std::vector<Previous>, 2> tangential;
  // Per side, the areas of the exact tangential solve that ended the time step before the one `tangential` ended
  // (with `extrapolate`: kept by each evaluation as `before`; Trajectory::wheel gives it for its step's first solve),
  // from which the next solve starts at 2 p_last - p_before; dropped when `tangential` changes otherwise, so that a
  // wheel step's later solves start from the last alone.
  std::array<std::vector<Previous>, 2> tangential_before;
  // The extra rigid slip of the area whose tangential problem is being solved (scratch: each solve writes every
  // element, so that two grids are neither allocated nor zeroed per solve).
  std::vector<double> extra_x, extra_y;
  // Grids of a discarded FASTSIM solution (recycle_tangential), which the next FASTSIM solve writes over instead of
  // allocating and zeroing its own.
  halfspace::TangentialSolution fastsim_grids;
  // The last free-rolling solve's spin, where the next one's search starts (a neighbouring case's).
  struct Spin {
    double ratio = 1;  // omega r0 / V
    double slope = 0;  // d(axle torque) / d(ratio) there (N m), the secant the search ended with; 0: unknown
  };
  std::optional<Spin> spin;
  // Drops the previous areas: the next evaluation starts cold, so that a call's result does not depend on what
  // the workspace did before (every top-level operation and every chain of a sweep starts so).
  void forget();
  // Where the evaluations' time goes (thread CPU seconds, accumulated while `timing` is on; benchmarks).
  struct Times {
    double locate = 0;       // contact location (line-cone crossings, segments, patches)
    double geometry = 0;     // planes, merging, potential areas, undeformed distance h
    double solve = 0;        // normal problems (including spectra and FFT plans made on first use)
    double sensitivity = 0;  // linearised responses
    double results = 0;      // forces, regions, copies into the result
    int evaluations = 0, areas = 0;
    long long elements = 0, iterations = 0;  // potential elements and CG iterations (fine + coarse) summed
  };
  bool timing = false;
  Times times;
};

// What a case's solve leaves in a workspace (per side, the areas of its last normal evaluation and of its exact
// tangential solve), kept to start the same case's solve on slightly changed profiles (a wear loop's next step: the
// pose moves little, the areas with it): `adopt` puts them into a workspace as its last evaluation, from which
// warm_start and tangential_start (warm_start.hpp) map them onto the new areas' grids where an area of the same side
// lies within 5 mm in nearly the same plane. A start changes a result only within the solvers' tolerances.
struct ContactStart {
  static constexpr const char* kTypeName = "wrc.ContactStart";  // its name as an option value (OptionValue::object)
  std::array<std::vector<ContactWorkspace::Previous>, 2> normal, tangential;
  std::optional<ContactWorkspace::Spin> spin;  // a free-rolling solve's spin (ContactWorkspace::spin)
  void adopt_normal(ContactWorkspace& ws) const {
    ws.previous = normal;
    for (auto& b : ws.before) b.clear();
  }
  void adopt_tangential(ContactWorkspace& ws) const {
    ws.tangential = tangential;
    for (auto& b : ws.tangential_before) b.clear();
    if (spin) ws.spin = spin;
  }
};

struct ContactRequest {
  bool sensitivity = false;  // fill d(force, moment)/d(z, roll) (linearised normal problems)
  bool jacobian = false;     // fill every wheel's Jacobian (WheelContact::jacobian); the calls' key `sensitivity` sets
                             // both
  bool keep_grids = true;    // keep pressure and h grids in the result (large)
  int only_side = -1;        // kLeft or kRight: evaluate that wheel only
  double tolerance = 0;      // in ]0, 1e-2]: the normal solver's tolerance for this evaluation (inexact Newton
                             // steps); 0: the model's
  std::optional<RollingRequest> rolling;  // also solve the tangential problem of every area (wheelset/tangential.hpp)
  // A wheel whose undeformed profiles inter-penetrate deeper than this (m) is an error naming the depth, the limit and
  // the option max_penetration, before its areas are gridded (a pose far too deep is a mistake: 17.5 mm gave 120 MN
  // and 68 GPa). The solvers that search a pose (solve_equilibrium, solve_wheel) pass infinity for their iterates and
  // check their solution against their own SolveLimits::max_penetration (equilibrium/limits.hpp).
  double max_penetration = kMaxPenetration;
  // Throws wrc::Error naming the member, its value and its range (evaluate_contact calls it first).
  // `plausible` (ContactOptions::check_magnitudes): the rolling request's magnitudes checked against a railway
  // wheelset's of nominal radius r0 (m) too (RollingRequest::validate).
  void validate(bool plausible = false, double r0 = 0) const;
};

// Reads ws:contact's keys (wrc_contact's options) into a request: grids (default true), sensitivity (false),
// max_penetration (m, > 0; default kMaxPenetration) and the rolling keys (read_rolling_request).
ContactRequest read_contact_request(OptionReader& options);
// Reads `sensitivity` (default false): the calls' one key for the Jacobians (ws:contact, ws:wheel, tr:contact,
// tr:wheel and their C and Python forms).
bool read_sensitivity(OptionReader& options);
// Reads max_penetration (m, finite and > 0) over `fallback`.
double read_max_penetration(OptionReader& options, double fallback = kMaxPenetration);

// Locates the contact at `pose` and solves the normal problem of every area. Throws wrc::Error on bad input (a pose
// that check_pose refuses), a wheel deeper than request.max_penetration, or a potential contact area beyond
// options.max_elements.
ContactResult evaluate_contact(const ContactModel& model, const Pose& pose, ContactWorkspace& workspace,
                               const ContactRequest& request = {});

// The largest potential contact area (elements) that evaluate_contact would grid for the inter-penetration areas of
// `location` (each area alone, before any merging): the estimate of a grid's cost. A double: a grid far too fine
// counts beyond any integer type.
double largest_potential_area(const ContactModel& model, const LocationState& location);

// Fills the sensitivities of a result evaluated without them (its grids must have been kept).
void add_sensitivity(const ContactModel& model, ContactResult& result, ContactWorkspace& workspace);
// Solves the tangential problem of every area of a result evaluated without it (its grids must have been kept) and
// adds the creep forces to the areas', wheels' and total forces and moments (replacing an earlier solution).
void add_rolling(const ContactModel& model, ContactResult& result, const RollingRequest& request,
                 ContactWorkspace& workspace);
// Before a result is discarded: its first FASTSIM tangential solution's grids go to workspace.fastsim_grids, whose
// storage the next FASTSIM solve then fills instead of new zeroed grids (a wheel solve's evaluations in turn).
void recycle_tangential(ContactResult& result, ContactWorkspace& workspace);
// Fills every wheel's Jacobian of a result (its grids kept); `rolling`: the request its tangential problems were
// solved for (none: frictionless, the creepage columns 0).
void add_jacobian(const ContactModel& model, ContactResult& result, const std::optional<RollingRequest>& rolling,
                  ContactWorkspace& workspace);
// The Jacobian at constant Fz of a wheel's Jacobian J (WheelContact::jacobian_fz): z adjusts so that Fz stays,
// dz = -(dFz/dq) / (dFz/dz) per unit of column q; the z column becomes d(.)/dFz = J.col(z) / (dFz/dz). Throws
// wrc::Error when dFz/dz is not negative (no vertical stiffness).
Jacobian constant_fz(const Jacobian& J);
// Releases the pressure, gap and h grids of a result; with keep_rows, each area's per-row results (the wear per
// grid row, wear_passage: a wear loop's input) stay.
void drop_grids(ContactResult& result, bool keep_rows = false);

// The object type of an area's description (FieldSink::object_type): Lua gives the table the methods of that type.
inline constexpr const char* kPatchType = "wrc.Patch";

// The results as fields (the Lua tables, the C API's paths). A wheel: lifted, flange_climb (and
// flange_climb_reason when true), force, moment, angle and rolling_radius (absent when lifted), patches; a patch: the
// located patch's fields (nominal point, segments, ...) then normal_force, force, moment, point, normal, angle,
// nominal_angle, area, pmax, elements, regions, span, resolved, penetration, rolling_radius, ellipse, hertz, kalker,
// iterations, complementarity, frame, grid, and the pressure and h grids when kept; with a tangential solution also its
// fields (wheelset/tangential.hpp) and, for a wheel and the result, creep_force, creep_moment, power.
void describe(const PatchContact& area, FieldSink& out);
void describe(const WheelContact& wheel, FieldSink& out);
// With `sensitivity`, also d(force, moment)/d(z, roll) as {z = {6 values}, roll = {6 values}}.
void describe(const ContactResult& result, FieldSink& out, bool sensitivity = false);
// The spin of a rolling result: omega (with kinematics) and spin_evaluations (free rolling).
void describe_spin(const ContactResult& result, FieldSink& out);
void describe_sensitivity(const Sensitivity& s, FieldSink& out);
// A Jacobian as fields: one list of 6 values (Fx, Fy, Fz, Mx, My, Mz) per column, named by kJacobianColumns.
void describe_jacobian(const char* name, const Jacobian& J, bool constant_fz, FieldSink& out);
// Creep totals as fields (nothing when no area was solved): creep_force, creep_moment, power.
void describe(const CreepTotals& totals, FieldSink& out);
void describe(const Pose& pose, FieldSink& out);  // pose = {y, z, roll, yaw}
// The fields of a located patch (side, nominal_point, nominal_normal, wheel_point, cone, eps, wheel_radius, depth,
// first_line, last_line, longest; 1-based indices) without its segments, and one segment (line, y, z, x_t, x_l,
// cones).
void describe_patch_fields(const Patch& patch, FieldSink& out);
void describe(const Segment& segment, FieldSink& out);

}  // namespace wrc
