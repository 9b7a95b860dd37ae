// Plausibility of a wheelset set-up (docs/guide/robustness.md): the profiles' sizes and shapes for their kind and the
// flanges against the gauge, checked when the wheelset is built. Results past flange climb are flagged by the
// definitions of geometry/flange.hpp.
#pragma once

#include "wrc/geometry/flange.hpp"
#include "wrc/geometry/track.hpp"
#include "wrc/halfspace/material.hpp"

#include <string>
#include <string_view>

namespace wrc {

// Throws wrc::Error when a set-up cannot be what the user meant: a profile far too wide or tall for its kind (wrong
// units), a "wheel" whose radius grows by more than 10 mm toward the field side (a rail profile, or a wheel with
// reversed y), a "rail" that does not fall by 0.1 mm on the field side of its highest point or rises again there by
// more than 1 mm (a wheel profile: its tread rises toward the field side), a wheel rising more than 10 mm above its
// tape circle (upside down), flanges that do not fit between the rails (back_to_back + both flange thicknesses >=
// gauge) or leave more than 70 mm of play (gauge and back_to_back of different tracks), a gauge of flanged wheels
// measured outside 10 .. 25 mm below the rails' tops (gauge_depth; EN 13848-1: 14 mm).
void check_setup(const Track& track);

// How a refusal of these checks says to turn them off, in no one front end's words: Lua's false, Python's False,
// MATLAB's false and the C API's option text check_setup=false all set the same option of the wheelset.
inline constexpr const char* kUncheckedHint = "set the wheelset's option check_setup to false to accept it";

// The magnitudes a railway wheelset's inputs have (SI units). A value outside was almost surely given in another unit
// (kN for N, GPa for Pa, mm for m, km/h for m/s): refused with the unit in the message, unless the wheelset's check_setup is false.
// The options' validate() functions call check_plausible, so that Lua and C callers get the same checks.
struct Plausible {
  const char* what;  // "a wheelset load"
  const char* unit;  // "N"
  double lo, hi;     // the plausible range of |value| (SI)
  const char* hint;  // "200 kN is 200e3"
};
inline constexpr Plausible kWheelsetLoad{"a wheelset load", "N", 2e3, 2e6, "200 kN is Q = 200e3"};
inline constexpr Plausible kWheelLoad{"a wheel load", "N", 1e3, 1e6, "100 kN is Fz = 100e3"};
inline constexpr Plausible kContactLoad{"a contact point's normal load", "N", 1e3, 1e6, "100 kN is hertz_load = 100e3"};
inline constexpr Plausible kSteelModulus{"Young's modulus of wheel and rail steel", "Pa", 5e10, 5e11,
                                         "210 GPa is E = 2.1e11"};
// Poisson's ratio of wheel and rail steels: 0.27-0.30. Outside 0.2 .. 0.35 is no steel: 28 is a percentage.
inline constexpr Plausible kSteelPoisson{"Poisson's ratio of wheel and rail steel", "", 0.2, 0.35,
                                         "28 % is nu = 0.28; steel's is 0.27 .. 0.30"};
// Wheels in service: 0.33 m (diameter 0.66 m, tram and low-floor wagons) to 1.25 m diameter (locomotives). A radius
// above 0.65 m is a diameter given as the radius (0.92 m: a worn freight-wagon wheel's diameter).
inline constexpr Plausible kWheelRadius{"a railway wheel's radius", "m", 0.15, 0.65,
                                        "450 mm is radius = 0.45; the radius, not the diameter"};
// The distance 2e between a wheelset's contact points: about the gauge plus a rail head's width, 0.66 m on a 600 mm
// gauge to 1.75 m on the Iberian 1668 mm. 1500 is millimetres.
inline constexpr Plausible kContactDistance{"the distance between a wheelset's contact points", "m", 0.5, 2.5,
                                            "1500 mm is contact_distance = 1.5"};
inline constexpr Plausible kTrainSpeed{"a train's speed", "m/s", 0, 160, "300 km/h is V = 83.3"};
// A wheelset yaws at V / R in a curve (0.33 rad/s: a tram at 5 m/s in a 15 m curve) and by a few mrad at a few Hz
// when hunting (5 mrad at 8 Hz: 0.25 rad/s); 10 is deg/s. Its lateral velocity when hunting: 10 mm at 8 Hz, 0.5 m/s.
inline constexpr Plausible kYawRate{"a wheelset's yaw rate", "rad/s", 0, 1, "10 deg/s is yaw_rate = 0.175"};
inline constexpr Plausible kLateralVelocity{"a wheelset's lateral velocity", "m/s", 0, 3, "1 km/h is vy = 0.278"};
// The axle's angular velocity against pure rolling at r0, omega r0 / V: 1 - xi, within 0 (locked, xi = 1) .. 2 (the
// wheel's surface twice as fast as the train, xi = -1). Given in rpm it is 9.55 times the rad/s.
inline constexpr double kMaxSpinRatio = 2;
// A prescribed longitudinal or lateral creepage: the same bound, |xi| <= kMaxSpinRatio - 1 (a locked wheel, or one
// turning twice as fast as it rolls), and |eta| likewise (a wheelset sliding sideways as fast as it runs, 45 deg of
// yaw). Creep curves are measured to a few percent of creepage: xi = 2 is 2 % given as a percentage.
inline constexpr Plausible kCreepage{"a creepage", "", 0, kMaxSpinRatio - 1,
                                     "2 % is xi = 0.02"};
// The slip velocities of CONTACT's falling friction laws (s1, s2): wheel-rail slip velocities are mm/s to a few m/s,
// and CONTACT takes them in mm/s, where wrc takes m/s.
inline constexpr Plausible kFrictionVelocity{"a friction law's slip velocity", "m/s", 0, 10,
                                             "CONTACT's SABSH1 = 100 mm/s is s1 = 0.1"};
// Polach's decay of friction with the slip velocity, mu0 ((1 - A) exp(-B w) + A): his fits give B = 0.6 s/m dry and
// 0.2 s/m wet (Polach, Wear 258, 2005); 50 s/m halves the falling part within 14 mm/s of slip, beyond any measured
// creep curve (B = 600 made every element slide at mu0 A).
inline constexpr Plausible kPolachDecay{"Polach's friction decay B", "s/m", 0, 50, "Polach's dry rail is B = 0.6"};
// A prescribed spin creepage: sin(gamma) / r at a contact angle gamma, at most 1 / r (6.7 1/m on a 0.15 m wheel);
// 1.9 1/m is a flange at 60 degrees on r = 0.45 m.
inline constexpr Plausible kSpinCreepage{"a spin creepage", "1/m", 0, 10, "a flange at 60 deg on r = 0.45 m is "
                                         "phi = 1.9"};
// Wheel on rail: 0.02-0.1 with leaves or a greased gauge face, 0.3-0.6 dry or sanded; 30 is a percentage. The
// no-slip limit (a huge coefficient: Kalker's linear theory) needs check_setup = false.
inline constexpr Plausible kFrictionCoefficient{"a wheel-rail friction coefficient", "", 0.01, 1.0, "30 % is mu = 0.3"};
// Throws "<context>: <key> = <value> <unit> is implausible for <what> ...: is it in another unit? ...; <off>" for a
// finite value outside the range. `off` says how to accept it; empty for a call without the option (wrc.conicity).
void check_plausible(std::string_view context, std::string_view key, double value, const Plausible& range,
                     std::string_view off = kUncheckedHint);

// The wheelset's parameters (wrc.wheelset{}): radius, E and nu, and a cant that tilts the rails outward (< 0).
void check_plausible(const TrackParams& track, const halfspace::Material& material);

}  // namespace wrc
