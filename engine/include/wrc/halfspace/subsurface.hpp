// Stresses inside the elastic half-space under a contact patch (the steel below the surface), their von Mises and
// Tresca measures with the maxima and their places, and Johnson's shakedown point of the patch.
//
// Load. The patch's surface tractions on a regular grid (grid.hpp), uniform on each element as the solvers give them
// (normal.hpp, rolling.hpp): the pressure p (Pa, >= 0, pressing into the body) and the tangential traction (px, py)
// (Pa) acting ON the stressed body. The solvers' tractions act on body 1, the wheel (rolling.hpp); for body 2, the
// rail, the same pressure and the opposite traction act (StressedBody::rail negates it).
//
// Frame and signs. x, y are the grid's (x the rolling direction t1, y = t2), z is the depth below the surface, positive
// INTO the stressed body; stresses are Pa, tension positive. For the wheel (x, y, z) is right-handed (z along the
// contact normal n, which points into body 1); for the rail it is left-handed (z = depth into the rail, along -n):
// isotropic elasticity does not care, but sigma_xz and sigma_yz of the rail are then components along that depth. At
// the surface sigma_zz -> -p, sigma_xz -> -px, sigma_yz -> -py (the traction on the plane z = 0 facing -z).
//
// Method. Boussinesq-Cerruti potentials (Love, Phil. Trans. A 228, 1929; Johnson, Contact Mechanics, 1985, section 3.2
// and eqs. 3.18-3.19): for a normal load with the harmonic potential H = int p ln(rho + z) dA,
//   sigma_xx = [-(1 - 2 nu) H_xx - z H_xxz + 2 nu H_zz] / (2 pi),   sigma_yy alike,
//   sigma_zz = [H_zz - z H_zzz] / (2 pi),   sigma_xy = [-(1 - 2 nu) H_xy - z H_xyz] / (2 pi),
//   sigma_xz = -z H_xzz / (2 pi),   sigma_yz = -z H_yzz / (2 pi);
// for a traction q_x with F = int q_x ln(rho + z) dA and F1 = int q_x (z ln(rho + z) - rho) dA (F = dF1/dz),
//   sigma_xx = [2 (1 + nu) F_xz + 2 nu F1_xxx - z F_xxx] / (2 pi),   sigma_yy = [2 nu F_xz + 2 nu F1_xyy - z F_xyy] / (2 pi),
//   sigma_zz = -z F_xzz / (2 pi),   sigma_xy = [F_yz + 2 nu F1_xxy - z F_xxy] / (2 pi),
//   sigma_xz = [F_zz - z F_xxz] / (2 pi),   sigma_yz = -z F_xyz / (2 pi)   (Hooke's law on Johnson's displacements);
// q_y by exchanging x and y. A uniform load on a rectangle integrates each derivative in closed form: a corner
// function g(X, Y) with d2g/dXdY the point-load term, summed over the four corners with signs (X = x - xi, Y = y - eta,
// rho^2 = X^2 + Y^2 + z^2); the corner functions (atan, asinh, ln(rho + z) and rational terms) are in subsurface.cpp.
// The stress at the element centres of the grid at depth z is then a sum over the loaded elements of kernels that
// depend only on the offset between elements: a discrete convolution, computed by zero-padded FFT (FFTW, the plans of
// convolution.hpp's PrunedFft; O(N log N) per depth) or by the direct sum (O(N_loaded N) per depth; small grids,
// tests). Each depth is independent. Poisson's ratio is the Material's (both bodies alike, material.hpp); E does not
// enter the stresses.
//
// Derived per point: the principal stresses s1 >= s2 >= s3, von Mises sqrt(((s1 - s2)^2 + (s2 - s3)^2 + (s3 - s1)^2) / 2),
// Tresca s1 - s3 and the maximum shear stress tau_1 = (s1 - s3) / 2 (Johnson's tau_1). For Hertz's circular contact
// (nu = 0.3) tau_1 peaks at 0.31 p0 at z = 0.48 a on the axis (Johnson eq. 3.45), von Mises at 0.62 p0 there.
//
// Shakedown (Johnson's shakedown map: Johnson, "The strength of surfaces in rolling contact", Proc. IMechE C 203, 1989;
// Contact Mechanics section 9.4): the patch's point is the load factor p0 / k (p0 the patch's peak pressure, k the
// shear yield stress) and the traction coefficient mu = |(Fx, Fy)| / Fn of the given tractions. The regime:
//   elastic            p0/k <= the patch's own first-yield factor: von Mises (yield at sqrt(3) k) from the stresses
//                      computed here, over the requested depths (Hertz, circle, mu = 0: 2.8, Johnson's 1.60 Y);
//   elastic shakedown  above it, and p0/k <= min(subsurface limit, 1 / mu);
//   plastic shakedown  p0/k > the subsurface limit while p0/k <= 1 / mu: cyclic plasticity below the surface (the map's
//                      subsurface ratchetting threshold, higher up, is not modelled);
//   ratchetting        p0/k > 1 / mu: the surface limit mu p0 = k exceeded, the surface layer flows a little at every
//                      passage (Ekberg's surface fatigue index mu - k / p0 > 0).
// The subsurface limit is the map's free-rolling value, held constant in mu: 4.7 for a point (circular) contact (Ponter,
// Hearle & Johnson, J. Mech. Phys. Solids 33, 1985) or 4.0 for a line contact (Johnson & Jefferis, 1963), both for an
// elastic-perfectly plastic material. (For such a material the maps' subsurface limit falls somewhat as mu grows
// before the surface limit takes over; that fall is not modelled, so the elastic-shakedown verdict is optimistic at
// moderate mu.)
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/material.hpp"

#include <numbers>
#include <span>
#include <string_view>
#include <vector>

namespace wrc::halfspace {

// A stress tensor (Pa, tension positive) in the frame (x, y, z = depth into the body).
struct Stress {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};

struct PrincipalStresses {
  double s1 = 0, s2 = 0, s3 = 0;  // Pa, s1 >= s2 >= s3
};
PrincipalStresses principal_stresses(const Stress& s);  // closed form (trigonometric), exact to rounding
double von_mises(const Stress& s);                      // Pa
double tresca(const Stress& s);                         // s1 - s3 (Pa); the maximum shear tau_1 is half of it

// The stress (Pa) at (x, y, z) (m, z > 0) from a uniform pressure p and traction (qx, qy) (Pa) on the rectangle
// [-a, a] x [-b, b] (m) of the surface of a half-space with Poisson's ratio nu. Closed form (the corner functions of
// the header).
Stress rectangle_stress(double nu, double x, double y, double z, double a, double b, double p, double qx, double qy);

// The tractions on the grid (spans over the caller's storage, index i + nx j).
struct SurfaceLoad {
  Grid grid;
  std::span<const double> pressure;         // Pa, >= 0
  std::span<const double> px = {}, py = {};  // Pa, on the wheel (body 1); empty: none
};

enum class SubsurfaceMethod { automatic, fft, direct };
enum class StressedBody { wheel, rail };  // body 1 (the tractions as given) or body 2 (the traction reversed)
enum class ShakedownMap { point, line };   // which of Johnson's maps gives the subsurface limit

// k of wheel steel ER7 (EN 13262: yield strength ReH >= 520 MPa) by von Mises, k = ReH / sqrt(3) = 300 MPa.
inline constexpr double kDefaultShearYield = 520e6 / std::numbers::sqrt3;
// The shear yield stresses k a contact is computed with: 1 MPa (a soft polymer test body) .. 10 GPa (beyond any steel).
// Below is a k given in MPa (shear_yield = 300 made Ekberg's FI_surf the traction coefficient: fatigue everywhere).
inline constexpr double kMinShearYield = 1e6, kMaxShearYield = 1e10;
// m: the deepest depth asked for: below any wheel rim (70 mm thick) or rail head (40-50 mm), the half-space is no longer
// the body. A deeper z is a depth in mm (z = {0.5, 1, 2} gave von Mises 0.2 MPa for 965 at 2 mm).
inline constexpr double kMaxSubsurfaceDepth = 0.1;
// Throws wrc::Error naming `context` when k (Pa) is not finite within [kMinShearYield, kMaxShearYield].
void check_shear_yield(std::string_view context, double k);
// The maps' subsurface shakedown limits p0/k in free rolling (header).
inline constexpr double kPointShakedownLimit = 4.7, kLineShakedownLimit = 4.0;
// At most this many depths per call, and this many stored field values (depths x elements x 11 grids; beyond it ask
// for fields = false, the maxima alone).
inline constexpr std::size_t kMaxSubsurfaceDepths = 10000;
inline constexpr std::size_t kMaxSubsurfaceFieldValues = std::size_t{1} << 27;

struct SubsurfaceRequest {
  std::vector<double> z;  // depths below the surface (m), finite and > 0, in any order
  SubsurfaceMethod method = SubsurfaceMethod::automatic;  // automatic: the cheaper one by an operation count
  StressedBody body = StressedBody::wheel;
  bool fields = true;  // keep the grids of every depth (false: the maxima only)
  double shear_yield = kDefaultShearYield;  // k (Pa), > 0
  ShakedownMap map = ShakedownMap::point;
};

// Reads the keys of a request: z (a list of depths, m; required), method ("auto" | "fft" | "direct"), body ("wheel" |
// "rail"), fields (boolean), shear_yield (Pa), shakedown_map ("point" | "line"). Leaves finish() to the caller.
SubsurfaceRequest read_subsurface_request(OptionReader& options);

// A maximum over the grid (and depths) and its place (m; z the depth). Ties keep the first element (index i + nx j),
// then the first depth as requested.
struct StressMaximum {
  double value = 0;  // Pa
  double x = 0, y = 0, z = 0;
};

struct SubsurfaceDepth {
  double z = 0;  // m
  // Per element (index i + nx j, Pa); empty when the request's fields = false.
  std::vector<double> sxx, syy, szz, sxy, sxz, syz;
  std::vector<double> s1, s2, s3;  // principal stresses, s1 >= s2 >= s3
  std::vector<double> von_mises, tresca;  // the maximum shear tau_1 is tresca / 2
  StressMaximum von_mises_max, tresca_max;  // over this depth's element centres
};

enum class ShakedownRegime { elastic, elastic_shakedown, plastic_shakedown, ratchetting };

struct ShakedownPoint {
  double p0 = 0;                    // Pa: the patch's peak pressure
  double shear_yield = 0;           // k (Pa)
  double load_factor = 0;           // p0 / k
  double traction_coefficient = 0;  // mu = |(Fx, Fy)| / Fn (0 without load)
  double elastic_limit = 0;         // p0 / k at first yield of this patch: sqrt(3) p0 / von_mises_max (inf: no stress)
  double subsurface_limit = 0;      // the map's (kPointShakedownLimit or kLineShakedownLimit)
  double surface_limit = 0;         // 1 / mu (inf for mu = 0)
  ShakedownMap map = ShakedownMap::point;
  ShakedownRegime regime = ShakedownRegime::elastic;
};

struct SubsurfaceResult {
  Grid grid;
  double nu = 0;
  StressedBody body = StressedBody::wheel;
  SubsurfaceMethod method = SubsurfaceMethod::fft;  // the one used (never automatic)
  std::vector<SubsurfaceDepth> depths;              // in the request's order
  StressMaximum von_mises_max, tresca_max;          // over all depths; tau_1 max = tresca_max.value / 2 at its place
  ShakedownPoint shakedown;
};

// The stresses at the element centres of the load's grid at every requested depth. Throws wrc::Error naming what is
// wrong: an invalid material or grid, a pressure or traction of the wrong size, not finite or (pressure) negative, no
// depth, a depth not finite or <= 0, too many depths or field values, k not finite or <= 0.
SubsurfaceResult compute_subsurface(const Material& material, const SurfaceLoad& load, const SubsurfaceRequest& request);

// Fields (Lua and C): body, method, nu, von_mises_max, von_mises_max_x/_y/_z, tresca_max, tresca_max_x/_y/_z,
// tau1_max (Pa, m), shakedown = {p0, shear_yield, load_factor, traction_coefficient, elastic_limit, subsurface_limit,
// surface_limit (the two limits absent when infinite: no stress, no traction), map, regime}, depths = list of {z, von_mises_max (_x, _y), tresca_max (_x, _y)
// and, with fields, the grids sigma_xx, sigma_yy, sigma_zz, sigma_xy, sigma_xz, sigma_yz, sigma_1, sigma_2, sigma_3,
// von_mises, tresca, max_shear}.
void describe(const SubsurfaceResult& result, FieldSink& out);

const char* method_name(SubsurfaceMethod method);
const char* body_name(StressedBody body);
const char* map_name(ShakedownMap map);
const char* regime_name(ShakedownRegime regime);

}  // namespace wrc::halfspace
