// Equivalent conicity tan(gamma_e) of a rolling-radius-difference function (EN 15302), independent of any wheelset.
//
// The input is Δr(y) = r_left - r_right (m) against the lateral displacement y of the wheelset (m, + toward the
// left rail) on a sorted grid, linear between its points. A self-centring wheelset has Δr rising through zero at
// the centre of its motion y0 (y0 != 0 when the wheels differ in diameter).
//
// Methods (tan(gamma_e) for an amplitude yhat):
//  - "integral" (default; EN 15302 Annex B): the kinematic (Klingel) motion of the wheelset, rolling without slip,
//        d2y/dx2 = -Δr(y) / (2 e r0),
//    oscillates between turning points y1 < y0 < y2 with G(y1) = G(y2), G(y) = integral of Δr from y0, and
//    yhat = (y2 - y1) / 2. Its wavelength is lambda = 2 sqrt(e r0) I, I = integral_{y1}^{y2} dy / sqrt(G(y2) - G(y));
//    tan(gamma_e) is the cone slope with the same wavelength by Klingel's formula lambda = 2 pi sqrt(e r0 / tan),
//    i.e. tan(gamma_e) = pi^2 / I^2: the definition of equivalent conicity, with no approximation beyond the motion
//    being kinematic. e and r0 cancel; they only scale the reported wavelength.
//  - "harmonic": harmonic linearisation (describing function) of Δr for y = y0 + yhat sin(phi):
//        tan(gamma_e) = 1 / (2 pi yhat) * integral_0^{2 pi} Δr(y0 + yhat sin phi) sin phi dphi.
//  - "regression" (EN 15302 Annex C): half the slope of the least-squares line through Δr over y0 +- yhat (on the
//    piecewise-linear Δr, so independent of the grid).
//  - "simple": (Δr(y0 + yhat) - Δr(y0 - yhat)) / (4 yhat), i.e. Δr(yhat) / (2 yhat) for an odd Δr.
// For a pure cone pair (Δr = 2 gamma (y - y0)) all four give gamma at every amplitude. Where Δr rises through a run of
// knots at exactly zero (a flat zone), y0 is the zone's middle and amplitudes within the zone give 0 (no restoring
// Δr: EN 15302's infinite wavelength), with a note in the result.
//
// Bad input is an error naming it: fewer than 3 points, y not strictly increasing, a value that is not finite,
// values out of any plausible range (y beyond +-kMaxLateral = 0.1 m, |Δr| beyond 0.05 m: probably millimetres), Δr without a
// rising zero (never changes sign, or falls through zero: not self-centring, or r_right - r_left), an amplitude
// whose motion leaves the table, a motion of amplitude yhat that is not one oscillation about y0 (Δr has other
// zeros inside it), or flange contact inside the motion (where the Δr table marks it): the standard's method is
// not defined there.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"

#include <array>
#include <string>
#include <vector>

namespace wrc {

enum class ConicityMethod { integral, harmonic, regression, simple };

struct DeltaRFunction {
  std::vector<double> y, dr;   // m, y strictly increasing
  std::vector<bool> flange;    // optional, one per point: flange contact there (the motion must not reach it)
};

struct ConicityOptions {
  std::vector<double> yhat;                        // amplitudes (m, > 0)
  ConicityMethod method = ConicityMethod::integral;
  double r0 = 0.45;                                // nominal rolling radius (m): the wavelength only
  double contact_distance = 1.5;                   // 2 e, the distance between the contact points (m): the wavelength only
};

struct ConicityResult {
  ConicityMethod method = ConicityMethod::integral;
  double centre = 0;                  // y0, where Δr rises through zero (m)
  std::vector<double> yhat;           // m
  std::vector<double> tan_gamma;      // tan(gamma_e), one per amplitude
  std::vector<double> y_min, y_max;   // the range of y the method used (integral: the turning points) (m)
  std::vector<double> wavelength;     // Klingel wavelength of tan(gamma_e) with r0 and e (m); infinite in a flat zone
  // A flat zone: Δr exactly 0 over [flat_zone[0], flat_zone[1]] (m) around the centre (a worn pair), y0 its middle.
  // Amplitudes within it (yhat <= half its width) have tan(gamma_e) = 0 and an infinite wavelength (no restoring Δr;
  // EN 15302), and `note` says so ("" without a flat zone).
  std::array<double, 2> flat_zone{0.0, 0.0};
  std::string note;
};

ConicityResult equivalent_conicity(const DeltaRFunction& dr, const ConicityOptions& options);

const char* to_string(ConicityMethod m);
// yhat (a number or an array, m; required), method, r0, contact_distance.
ConicityOptions read_conicity_options(OptionReader& options, ConicityOptions base = {});
// {y = {...}, dr = {...}, flange = {booleans}} (a Lua table or C arrays).
DeltaRFunction read_delta_r(OptionReader& table);

// method, centre, yhat, tan_gamma, y_min, y_max, wavelength (arrays, one per amplitude); note and flat_zone = {from,
// to} with a flat zone.
void describe(const ConicityResult& r, FieldSink& out);

}  // namespace wrc
