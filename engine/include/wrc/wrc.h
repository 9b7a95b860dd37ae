/* wrc.h -- the C API of wrc, the wheel-rail contact engine (docs/design.md, section 5).
 *
 * ABI version 1 (WRC_ABI_VERSION). A library whose wrc_abi_version() differs from the WRC_ABI_VERSION a program was
 * compiled with is not compatible with it. Within one ABI version functions are only added, never changed.
 *
 * Conventions (docs/design.md, section 2): SI units (m, N, Pa, rad). Track frame: x along the track, z up, +y toward
 * the LEFT rail. Pose of the wheelset: lateral y, height z (0 where the centred wheelset first touches, < 0 pressed
 * in), roll (> 0 lifts the left wheel), yaw. Forces are those the rail exerts on the wheel, in the track frame;
 * moments about the wheelset centre.
 *
 * Errors: every function returns a wrc_status. On anything but WRC_OK, wrc_last_error() gives a message that names
 * what is wrong (one line: an error inside a Lua profile definition comes without its Lua traceback). No C++ exception
 * and no Lua state crosses this interface; bad input (a null or freed handle, NaN, an unknown option, an array too
 * small or a size no array has) gives a status and a message, never a crash.
 *
 * Handles: opaque pointers made by the *_new / *_load / solve functions and released by the matching *_free. A
 * handle that was freed (or never made) is detected and refused with WRC_INVALID_ARGUMENT (until its address is
 * reused by a new handle). Handles are independent of each other: freeing a profile does not affect a wheelset
 * built from it, freeing a wheelset does not affect its results.
 *
 * Threads: every function may be called from any thread. One wheelset may be used by several threads at once (each
 * call uses a workspace of its own from the wheelset's pool); profiles and results are read-only after they are
 * made and may be read from several threads at once. A handle must not be freed while another thread uses it.
 *
 * Options: a string of "key=value" pairs separated by blanks or ';' (NULL or "" for none). A value is a number, true
 * or false, a list of numbers "a,b" or a word; dotted keys make nested tables ("shift.y=1e-3"). The keys are those of
 * the Lua API (docs/reference/lua-api.md): an unknown key is an error naming the closest known one. A key given
 * twice, a key of more than 256 characters or 16 dotted levels and a string of more than 32 MB are errors too
 * (WRC_ERROR). A function and its Lua twin are one request of the engine (wrc/api/calls.hpp): the numbers it takes
 * as arguments (y, z, roll, yaw, Fz, Q, the side) join the options under their Lua names, so that one reader checks
 * all; an argument given again as an option is an error (WRC_ERROR). Lua's on_failure is refused: the status
 * WRC_NOT_CONVERGED (with the result) reports a failed solve.
 */
#ifndef WRC_WRC_H
#define WRC_WRC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WRC_ABI_VERSION 1

typedef struct wrc_profile wrc_profile;
typedef struct wrc_wheelset wrc_wheelset;
typedef struct wrc_result wrc_result;
typedef struct wrc_trajectory wrc_trajectory;

typedef enum wrc_status {
  WRC_OK = 0,
  WRC_INVALID_ARGUMENT = 1, /* a null, freed or wrong handle, a NaN argument, a bad side, a null pointer */
  WRC_ERROR = 2,            /* the engine refused the input or failed: an unknown or bad option, a file, a profile,
                               a parameter out of range, a pose far too deep, ... */
  WRC_NOT_CONVERGED = 3,    /* a solve did not converge; its result is still returned (converged = 0, error) */
  WRC_NOT_FOUND = 4,        /* a result path that the result does not hold */
  WRC_TOO_SMALL = 5         /* a caller-owned array is too small; the count says how many values are needed */
} wrc_status;

enum { WRC_LEFT = 0, WRC_RIGHT = 1 };

/* The library's version ("0.1.0"): a static string. */
const char* wrc_version(void);
/* The ABI version the library implements (compare with WRC_ABI_VERSION). */
int wrc_abi_version(void);
/* The message of the calling thread's last call that did not return WRC_OK ("" if none). The string is owned by the
 * library and valid until the calling thread's next wrc call. */
const char* wrc_last_error(void);
/* The words in which the calling thread's messages name option types: "c" (the default: a list "a,b,c", dotted keys
 * for a table) or "matlab" (a numeric array, a struct: the MATLAB/Octave interface passes its name/value pairs and
 * structs as option text). Positions in arrays are named by ordinals ("the 2nd value of 'y'"), whoever asks. */
wrc_status wrc_set_option_dialect(const char* front_end);
/* Whether the calling thread's wrc_profile_load and wrc_profile_from_points print a profile's warnings on stderr: 1
 * (the default) or 0, for a caller that shows wrc_profile_warnings in its own way (the MATLAB/Octave interface raises
 * them as MATLAB warnings, and Octave in a terminal would show each twice). The warnings stay in the profile either
 * way. Any other value is WRC_INVALID_ARGUMENT. */
wrc_status wrc_set_profile_warnings_printed(int printed);
/* The entry of names[0 .. count) that `word` is plausibly a misspelling of, by the rule of the option readers' "did
 * you mean" (same letters in another case first, else the fewest edits, at most max(2, length / 3)); NULL when none
 * is, or for a NULL word or names. The pointer is the caller's names[i]. For a front end that reads some names
 * itself: the MATLAB interface's required arguments. Sets no error. */
const char* wrc_closest_name(const char* word, const char* const* names, size_t count);

/* ---- profiles ---- */

/* Loads a profile: a Lua definition (.lua, e.g. "profiles/s1002.lua") or a file read by a reader plugin (.txt, .csv,
 * .prr, .prw, .ban, .whl, ...). "profiles/NAME" is the profile NAME shipped with wrc (in its installed data folder),
 * never a file of the working directory; any other path, "./profiles/NAME" included, is a file (a relative one in the
 * working directory). A Lua definition is data, whoever wrote it: it runs in a sandbox of its own, without os, io,
 * package, require, dofile, loadfile, debug or binary chunks, so that it cannot reach the file system, run programs or
 * load libraries, within budgets of 1e9 Lua instructions and 256 MB; past one it fails with WRC_ERROR and a message
 * (docs/guide/studies.md "What is code and what is data"). A profile has at most 1000000 points. Options: those of
 * wrc.profile.load (units, mirror_y, mirror_z, crop.y, crop.z, shift.y, shift.z, kind, name, reader, the reader's own
 * options; a Lua definition's own options such as step). The caller owns *out. */
wrc_status wrc_profile_load(const char* path, const char* options, wrc_profile** out);
/* A profile from n points (m, left-side frame; docs/design.md section 2): the polyline through them; kind is "wheel"
 * or "rail"; name may be NULL. The arrays are copied; n above 10,000,000 is WRC_INVALID_ARGUMENT. Points that scatter
 * as measurement noise are warned of as a loaded file's are (wrc_profile_warnings; printed on stderr as
 * "wrc: warning: ..." unless wrc_set_profile_warnings_printed(0)). The caller owns *out. */
wrc_status wrc_profile_from_points(const char* kind, const double* y, const double* z, size_t n, const char* name,
                                   wrc_profile** out);
/* Copies the points into caller-owned arrays of `capacity` values; *n = the number of points (WRC_TOO_SMALL when
 * capacity < *n; y and z may be NULL with capacity 0 to ask for the size). */
wrc_status wrc_profile_points(const wrc_profile* profile, double* y, double* z, size_t capacity, size_t* n);
/* The profile's warnings: what looks wrong in it but was accepted when it was loaded or made (an orientation that
 * looks reversed, points that scatter as measurement noise; docs/guide/profiles.md), each of which wrc_profile_load
 * also prints on stderr as "wrc.profile.load: warning: ..." (wrc_profile_from_points as "wrc: warning: ...") unless
 * the thread set wrc_set_profile_warnings_printed(0). *n = their number; *text = warning `index` (0-based), a string
 * owned by the profile and valid until it is freed. For a caller whose users do not see stderr (the MATLAB desktop). */
wrc_status wrc_profile_warnings(const wrc_profile* profile, size_t* n);
wrc_status wrc_profile_warning(const wrc_profile* profile, size_t index, const char** text);
/* Writes the profile to `path` in a format a reader plugin reads back (docs/guide/profiles.md "Writing profiles"),
 * whole or not at all: a failure leaves no file (or the old one). Options: those of p:write (format = "text", "csv",
 * "simpack", "miniprof" or "vampire", default from the extension; tape_offset, flange_back, gauge, gauge_depth). The
 * profile stays the caller's; nothing is allocated for the caller. */
wrc_status wrc_profile_write(const wrc_profile* profile, const char* path, const char* options);
/* Releases a profile (NULL: nothing to do). */
wrc_status wrc_profile_free(wrc_profile* profile);

/* ---- wheelsets ---- */

/* A wheelset from one wheel and one rail profile (the right side their mirror image), or from four. The profiles are
 * copied. Options: those of wrc.wheelset (radius, back_to_back, tape_offset, gauge, gauge_depth, gauge_point, cant, E,
 * nu, grid, margin, max_elements, tolerance, merge_tolerance, merge_angle, solver, surface, strategy, check_strategy,
 * check_setup) where strategy is one of the built-in strategies (accurate, fast, uniform, topology, coarse,
 * constant_slope, brute or a composition "uniform+coarse+topology") and strategy_options.<key> its options;
 * check_strategy=N checks the strategy against brute force on N random poses first (an error names the first pose
 * that differs); check_setup=false skips the set-up's plausibility checks. The caller owns *out. */
wrc_status wrc_wheelset_new(const wrc_profile* wheel, const wrc_profile* rail, const char* options, wrc_wheelset** out);
wrc_status wrc_wheelset_new4(const wrc_profile* left_wheel, const wrc_profile* right_wheel,
                             const wrc_profile* left_rail, const wrc_profile* right_rail, const char* options,
                             wrc_wheelset** out);
/* Releases a wheelset (NULL: nothing to do). */
wrc_status wrc_wheelset_free(wrc_wheelset* wheelset);

/* ---- solves; each makes a result the caller owns (*out), also when it returns WRC_NOT_CONVERGED ---- */

/* Contact at a prescribed pose (m, rad). WRC_ERROR for a pose far too deep: a wheel and its rail inter-penetrating
 * deeper than max_penetration (m, default 1e-3; an option), |z| beyond the wheel radius, or |y| beyond 0.1 m, |yaw|
 * beyond 0.3 rad, |roll| beyond 0.1 rad (mm or degrees given; the limits of every call, wrc/geometry/pose.hpp). Options: grids (keep pressure and h grids, default true), sensitivity (each wheel's Jacobian: paths
 * left.jacobian.xi, .eta, .phi, .y, .z, .roll, .yaw, 6 numbers each, d(Fx, Fy, Fz, Mx, My, Mz) in the track frame,
 * moments about the wheelset centre; N per unit creepage, N m per 1/m of spin, N/m, N m/m, N/rad, N m/rad;
 * docs/guide/sensitivity.md; and sensitivity.z, sensitivity.roll of both wheels), max_penetration; with
 * friction (rolling contact, docs/guide/rolling.md): the kinematics V (m/s, != 0), omega (rad/s; default V / r0),
 * vy (m/s), yaw_rate (rad/s), slip_reference (undeformed, the default, or deformed: where the rigid slip is taken,
 * docs/guide/rolling.md), or the creepages creepage.xi, creepage.eta, creepage.phi (1/m) with V optional; and
 * mu (or mu_static and mu_kinetic, or a law falling with the slip velocity: friction.law=polach friction.mu0=
 * friction.A= friction.B=, friction.law=linear|rational|exponential with friction.mu_inf, m1, s1, m2, s2, or
 * friction.preset=polach_dry|polach_wet|contact_example), friction_profile.y=..., friction_profile.mu=... (lists: mu
 * across the rail's profile; or friction_profile.left.y= ... per wheel), method (exact or fastsim),
 * rolling_tolerance; search (strategy, the default, or
 * brute: every rail line against every cone, a check of the strategy). The areas then hold Fx, Fy, Mz,
 * creepage.*, creep_force.*, adhesion, power, px, py, slip_x, slip_y, adhesion_map, power_density, and the damage
 * indices Tgamma, Tgamma_spin, rcf_damage, fi_surf, ... (docs/guide/damage.md); with a wear model (wear.model=archard
 * or usfd, wear.k, wear.hardness, wear.density; fatigue.shear_yield, ...) also wear_volume and the grid wear_depth. */
wrc_status wrc_contact(wrc_wheelset* wheelset, double y, double z, double roll, double yaw, const char* options,
                       wrc_result** out);
/* One wheel (WRC_LEFT or WRC_RIGHT) with its vertical contact force Fz (N, at most 1e10) prescribed at y, yaw, roll.
 * Options: force_tolerance, max_iterations, max_evaluations, max_penetration (m; deeper and still short of Fz: out of
 * reach; a solution deeper: not converged), sensitivity (the wheel's jacobian.* as wrc_contact's, and jacobian_fz.*
 * with Fz held, its z column per N of Fz), and the rolling options of wrc_contact (Fz then includes the vertical part
 * of the creep forces). */
wrc_status wrc_wheel(wrc_wheelset* wheelset, int side, double y, double yaw, double roll, double Fz,
                     const char* options, wrc_result** out);
/* The static equilibrium under the vertical load Q (N) at the centre: z and roll solved at y, yaw. Options: grids
 * (default true), force_tolerance, moment_tolerance, max_iterations, max_evaluations, max_penetration, start.z,
 * start.roll. */
wrc_status wrc_equilibrium(wrc_wheelset* wheelset, double y, double yaw, double Q, const char* options,
                           wrc_result** out);
/* The stresses below a contact area of a result (docs/guide/damage.md): `patch` is the area's path in `result`
 * ("left.patches.1"; the result must hold its pressure grid: grids kept), whose grid, pressure, px and py (with
 * rolling) and nu it reads. Options: z (depths below the surface, m, > 0: "z=0.5e-3,1e-3"; required), method (auto,
 * fft or direct), body (wheel or rail), fields (false: the maxima alone), shear_yield (Pa), shakedown_map (point or
 * line). The new result holds von_mises_max, von_mises_max_z, tresca_max, tresca_max_z, tau1_max, shakedown.*,
 * depths.N.* (Pa, m). */
wrc_status wrc_subsurface(const wrc_result* result, const char* patch, const char* options, wrc_result** out);
/* The rigid (kinematic) reference at y, yaw with load Q. */
wrc_status wrc_rigid(wrc_wheelset* wheelset, double y, double yaw, double Q, wrc_result** out);

/* ---- trajectories: a wheelset followed along time steps (a multibody code's calls); each step starts from the
 * previous step's solution (warm), so its result depends on the steps before to the solver's tolerance. A trajectory
 * is used by one thread at a time (concurrent calls on one trajectory are serialised); it keeps its wheelset alive. */

/* Options: tolerance (relative gap of the normal problems, default 1e-6), grids (default false), extrapolate
 * (default true: wrc_trajectory_contact starts each step from the linear extrapolation of the last two, as for a
 * fixed time step; false: from the last step alone), max_penetration (m, default 1e-3, as wrc_contact's). A step that
 * fails from the previous steps' state is solved again from a cold start before it fails. The caller owns *out. */
wrc_status wrc_trajectory_new(wrc_wheelset* wheelset, const char* options, wrc_trajectory** out);
/* Contact at a prescribed pose (m, rad), as wrc_contact without options (frictionless). */
wrc_status wrc_trajectory_contact(wrc_trajectory* trajectory, double y, double z, double roll, double yaw,
                                  wrc_result** out);
/* The same with options (NULL or "": none): the rolling options of wrc_contact (V, omega, vy, yaw_rate or
 * creepage.xi/eta/phi, mu or mu_static and mu_kinetic, method "exact" | "fastsim", rolling_tolerance), read at every
 * step, since a multibody code's velocities change from step to step, and sensitivity (each wheel's jacobian.*, as
 * wrc_contact's; wrc_trajectory_wheel_with also jacobian_fz.*). */
wrc_status wrc_trajectory_contact_with(wrc_trajectory* trajectory, double y, double z, double roll, double yaw,
                                       const char* options, wrc_result** out);
/* One wheel with its vertical force Fz (N) given, as wrc_wheel, from the previous steps' approach (its depth below
 * the touching height, extrapolated in time unless the trajectory's extrapolate is 0). */
wrc_status wrc_trajectory_wheel(wrc_trajectory* trajectory, int side, double y, double yaw, double roll, double Fz,
                                wrc_result** out);
/* The same with the rolling options of wrc_trajectory_contact_with (Fz then includes the creep forces' vertical
 * part, as in wrc_wheel). */
wrc_status wrc_trajectory_wheel_with(wrc_trajectory* trajectory, int side, double y, double yaw, double roll, double Fz,
                                     const char* options, wrc_result** out);
/* Forgets the previous steps. */
wrc_status wrc_trajectory_reset(wrc_trajectory* trajectory);
/* Releases a trajectory (NULL: nothing to do). */
wrc_status wrc_trajectory_free(wrc_trajectory* trajectory);
/* ---- rigid contact geometry, equivalent conicity, profile measures (docs/guide/geometry.md) ---- */

/* The rigid contact at y, yaw (m, rad). Options: roll ("free": both wheels on their rails, the default; "fixed": held
 * at 0 with each wheel on its own rail; or a number: held at that roll, rad), Q, hertz_load (N: the load of every
 * contact point's Hertz ellipse), two_point_tolerance, start.z, start.roll. Fields as ws:rigid has them: "z", "roll",
 * "rolling_radius_difference" (absent when a wheel is lifted), "left.lifted", "left.contacts.1.rolling_radius",
 * "left.contacts.1.wheel_profile.y", "left.contacts.1.hertz.a", "left.contacts.1.kalker.C11", ... Returns WRC_NOT_CONVERGED
 * (with the result) when there is no such pose. */
wrc_status wrc_rigid_contact(wrc_wheelset* wheelset, double y, double yaw, const char* options, wrc_result** out);
/* A rigid contact geometry table in one call, on worker threads. Options: y.from, y.to, y.step (m; or y=a,b,c), yaw,
 * roll, Q, hertz_load, two_point_tolerance, threads, jump_threshold, csv=<path>, file=<path> (the multibody table), progress
 * (true: a progress line on stderr; default false, the library prints nothing). Fields: "rows.<i>.<field of
 * wrc_rigid_contact>", "jumps.<i>.side|y_before|y_after|wheel_jump|rail_jump", "seconds", "threads", "threads_note"
 * (why fewer threads ran than asked for). */
wrc_status wrc_geometry_table(wrc_wheelset* wheelset, const char* options, wrc_result** out);
/* Equivalent conicity (EN 15302) of a Δr table of n points (at most 10,000,000): y (m, increasing) and
 * dr = r_left - r_right (m). Options:
 * yhat (amplitudes, m: "yhat=0.001,0.003"), method (integral, harmonic, regression, simple), r0, contact_distance.
 * Fields: "tan_gamma" (an array, one per amplitude), "yhat", "y_min", "y_max", "wavelength", "centre", "method". */
wrc_status wrc_conicity(const double* y, const double* dr, size_t n, const char* options, wrc_result** out);
/* The equivalent conicity of a wheelset from its own rigid Δr table. Options as ws:conicity (yhat, method, roll --
 * "fixed" by default --, y.from/to/step, yaw, threads, flange_angle, r0, contact_distance); fields as wrc_conicity
 * plus "dr.y", "dr.dr", "dr.flange". */
wrc_status wrc_wheelset_conicity(wrc_wheelset* wheelset, const char* options, wrc_result** out);
/* EN 15313 flange measures of a wheel profile: fields "Sh", "Sd", "qR" (m), "tip.y", "sd_point.y", ... Options:
 * tape_offset (m, the inner face at s = -tape_offset; default: the wheelset's, 0.070). */
wrc_status wrc_profile_flange_measures(const wrc_profile* profile, const char* options, wrc_result** out);

/* ---- results: fields by path, as the Lua tables have them ("Y", "z", "left.force.z", "left.patches.1.pmax",
 * "left.patches.1.pressure"; lists are 1-based). Booleans and integers read as numbers. Every path of every result,
 * with its type, unit, sign and meaning: docs/reference/fields.md (generated from the code that fills results). ---- */

/* A number (or boolean: 0/1, or integer). */
wrc_status wrc_result_number(const wrc_result* result, const char* path, double* value);
/* The length of a list ("left.patches") or of an array or grid ("left.patches.1.pressure": nx * ny values). */
wrc_status wrc_result_count(const wrc_result* result, const char* path, size_t* n);
/* Copies an array or grid (grid values row by row: v[i + nx j], nx and ny in "<patch>.grid.nx/ny") into values[0 ..
 * capacity); *n = its length (WRC_TOO_SMALL when capacity < *n). */
wrc_status wrc_result_numbers(const wrc_result* result, const char* path, double* values, size_t capacity, size_t* n);
/* Copies a string field ("error") into buffer (NUL-terminated, truncated to capacity - 1); *length = its length. */
wrc_status wrc_result_string(const wrc_result* result, const char* path, char* buffer, size_t capacity,
                             size_t* length);
/* The number of fields and the path of field i (a string owned by the result), to list what a result holds. */
wrc_status wrc_result_fields(const wrc_result* result, size_t* n);
wrc_status wrc_result_field(const wrc_result* result, size_t index, const char** path);
/* Releases a result (NULL: nothing to do). */
wrc_status wrc_result_free(wrc_result* result);

#ifdef __cplusplus
}
#endif

#endif /* WRC_WRC_H */
