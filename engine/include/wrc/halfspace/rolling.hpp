// The tangential problem of steady rolling with Coulomb friction on the grid of a solved normal problem
// (Kalker's exact theory, as CONTACT solves it; docs/design.md sections 2 and 3), and FASTSIM, Kalker's simplified
// theory, on the same grid.
//
// Identical materials (quasi-identity, influence.hpp): the tangential tractions do not change the normal gap, so the
// normal problem is solved first and its pressure p_n sets the traction bound; this file solves the tangential
// problem alone. (Dissimilar materials would couple them; the solution would then alternate between the two
// solvers -- CONTACT's Panagiotopoulos process -- with the normal solver taking the tangential tractions' normal
// displacement as a correction of h. Nothing here assumes more than the one-way order.)
//
// The steady-state problem (grid frame: x the rolling direction t1, y = t2, the normal into body 1, the wheel). The
// bodies roll with speed |V| in the direction `direction` (+1: toward +x): material enters the contact at its
// leading edge (the +x side for +1) and leaves it at the trailing edge. The traction p on body 1 (Pa, the force of
// the rail on the wheel per area) and the displacement difference u = B p (influence.hpp) give the slip of body 1
// relative to body 2, per |V|, at element I:
//   s_I = w_I - (u_{I+} - u_I) / dx,   I+ = the element upstream of I (at x + direction dx),
// with w the rigid slip per |V| (creep.hpp: w = (xi - phi y, eta + phi x) for creepages about a reference point).
// Coulomb's law with the traction bound g = mu p_n: adhesion |p| <= mu_s p_n and s = 0, or slip |p| = mu_k p_n
// and p = -mu_k p_n s / |s|: the traction opposes the slip. With friction falling with the slip velocity
// (friction.hpp) the bound of a slip element is mu(|V| |s|) p_n, and of an adhesion element mu(0) p_n. The upwind
// difference is Kalker's discretisation of the material derivative (CONTACT with the rolling step dq = dx).
#pragma once

#include "wrc/halfspace/creep.hpp"
#include "wrc/halfspace/ellipse.hpp"
#include "wrc/halfspace/friction.hpp"
#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/shear.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace wrc::halfspace {

struct TangentialProblem {
  Grid grid;
  std::span<const double> pressure;  // Pa per element (index i + nx j), >= 0; p > 0 is the contact area
  // The rigid slip per |V| at the elements: `creepages` about the reference point (ref_x, ref_y) of the grid
  // frame (m), plus, when given, the per-element difference `extra_x`, `extra_y` from that linear field (e.g. the
  // varying rolling radius across a wide, curved patch). Dimensionless.
  Creepages creepages;
  double ref_x = 0, ref_y = 0;
  std::span<const double> extra_x = {}, extra_y = {};
  int direction = +1;  // rolling toward +x (+1) or -x (-1)
  Friction friction;
  // The rolling speed |V| (m/s): a slip-dependent friction law takes the slip velocity w = speed |s| of each
  // element (s the slip per |V|); required > 0 with such a law, unused otherwise.
  double speed = 0;
  // Optional, per element (> 0): the factor of the friction law there (every coefficient of the law scaled by it),
  // e.g. friction varying across the rail's profile. Empty: 1.
  std::span<const double> friction_scale = {};
  // Optional, FASTSIM only: the pressure's contact regions as equivalent_ellipses gives them (ellipse.hpp) and each
  // element's region (-1 outside), when the caller has found them on this pressure (the wheelset's areas do, for
  // their results); both or neither. Empty: FASTSIM finds them.
  std::span<const EquivalentEllipse> regions = {};
  std::span<const int> region_label = {};
};

struct TangentialOptions {
  // Convergence: max |slip| of the adhesion elements, max slip across the traction of the slip elements and their
  // traction's distance to the bound times M's diagonal (a slip) <= tolerance * max |w| over the contact (the rigid
  // slip scale), with the adhesion / slip split unchanged.
  double tolerance = 1e-6;
  int max_iterations = 100;  // Newton (active-set) iterations on the finest grid
  // Start from the solution on a grid twice as coarse (recursively, above coarse_limit contact elements).
  bool nested = true;
  int coarse_limit = 400;
  // Optional warm start (Pa per element, both or neither), e.g. the previous point of a creep curve or time step.
  std::span<const double> initial_x = {}, initial_y = {};
  // Optional with it: the start's adhesion / slip split (ElementState per element): slip elements start on the
  // kinetic bound in their traction's direction, the others keep their traction up to the static bound (beyond it
  // they slip). Without it an element at the kinetic bound starts in slip. Either way a start that already meets the
  // tolerance with a consistent split is returned as it is (0 iterations).
  std::span<const unsigned char> initial_state = {};
};

enum ElementState : unsigned char { kExterior = 0, kAdhesion = 1, kSlip = 2 };

struct TangentialSolution {
  Grid grid;
  std::vector<double> px, py;         // traction on body 1 (Pa) per element; 0 outside the contact
  std::vector<double> sx, sy;         // slip per |V| (-); 0 in adhesion and outside
  std::vector<unsigned char> state;   // ElementState per element
  double fx = 0, fy = 0;              // N: sum p dA
  double mz = 0;                      // N m about the reference point: sum (x p_y - y p_x) dA (x, y from it)
  double contact_area = 0;            // m^2 (elements with p_n > 0)
  double adhesion_area = 0;           // m^2
  // Frictional power per unit rolling speed, sum -(p . s) dA (N; W per m/s): >= 0, the work of the traction against
  // the slip.
  double power_per_speed = 0;
  double residual = 0;                // the convergence measure at the end (relative, see TangentialOptions)
  int iterations = 0;                 // Newton iterations on this grid (exact) / 0 (FASTSIM)
  int linear_iterations = 0;          // GMRES iterations on this grid
  int coarse_iterations = 0;          // GMRES iterations on the coarser grids of the nested start
  int products = 0;                   // FFT products with B on this grid
  double adhesion_fraction() const { return contact_area > 0 ? adhesion_area / contact_area : 0.0; }
};

// A first-order change of a tangential problem per unit of some parameter (a creepage, a pose coordinate): of its
// creepages and reference point (as TangentialProblem has them: FASTSIM scales the spin's part), of the extra rigid
// slip and of the pressure (per element of the problem's grid; each vector empty: no change). Dimensionless, m, Pa.
struct TangentialChange {
  Creepages creepages;
  double ref_x = 0, ref_y = 0;
  std::vector<double> extra_x, extra_y;
  std::vector<double> pressure;
};

// The first-order change of a converged solution's traction for a TangentialChange, with the contact area and the
// adhesion / slip split held fixed (the solution's linearisation): adhesion elements keep zero slip, slip elements
// keep their traction on the bound mu_k p_n (which changes by mu_k dp_n) and opposite to their slip. Per element (0
// outside the contact), per unit of the parameter: px, py (Pa); fx, fy (N) and mz (N m about the reference point,
// its change included) as TangentialSolution sums them.
struct TangentialDerivative {
  Grid grid;
  std::vector<double> px, py;
  double fx = 0, fy = 0, mz = 0;
  int iterations = 0;  // GMRES iterations (exact) / 0 (FASTSIM)
};

// Buffers of one thread for RollingSolver (not shareable; reused across solves).
class RollingWorkspace {
 public:
  // FFT buffers of the products with B and of the preconditioner's circulant inverse: apart, because a buffer
  // changing shape is cleared (the padded one is four times the periodic one).
  ShearWorkspace fft, fft_periodic;
  std::vector<double> qx, qy, ux, uy;  // grid vectors of the cropped grid
  std::vector<double> basis, precond;  // GMRES: Krylov vectors and their preconditioned images
  std::vector<double> images;          // GMRES: M times each preconditioned vector (the slip's change, no product)
  // Sums over every exact solve made with this workspace, as each TangentialSolution counts them (a benchmark's
  // view of all the solves of a multibody step, where a step's result keeps only its last).
  struct Totals {
    long solves = 0, iterations = 0, linear_iterations = 0, products = 0;
  } totals;
};

// The exact steady-rolling solver: semi-smooth Newton on the adhesion / slip split (an active-set method: adhesion
// elements carry the equations s = 0; slip elements the direction of their traction, whose magnitude is the
// bound), each linearisation solved by restarted GMRES with FFT products. Preconditioner: on adhesion elements the
// exact inverse of the upwind difference (a sum along the row from the upstream end of the adhesion run) followed
// by the inverse of B's periodic circulant (FFT); on slip elements a sweep from the leading edge with the element's
// own and upstream coupling. Started from the solution on a grid twice as coarse. The problem is cropped to the
// contact's bounding box plus the upstream column before the FFTs. Part of an immutable model: one instance serves
// many threads, each with its own workspace.
class RollingSolver {
 public:
  explicit RollingSolver(const Material& material, FftPlanning planning = FftPlanning::estimate);
  const Material& material() const { return cache_.material(); }
  TangentialSolution solve(const TangentialProblem& problem, RollingWorkspace& workspace,
                           const TangentialOptions& options = {}) const;
  TangentialSolution solve(const TangentialProblem& problem, const TangentialOptions& options = {}) const;
  // The linearisation of `solution` (this solver's for `problem`) for each change: its Newton linearisation at the
  // converged split (the Jacobian products and preconditioner of the solve), solved by GMRES to the relative residual
  // `tolerance`. Throws wrc::Error on a solution that does not fit the problem, and for a friction law falling with
  // the slip velocity (not linearised).
  std::vector<TangentialDerivative> linearise(const TangentialProblem& problem, const TangentialSolution& solution,
                                              std::span<const TangentialChange> changes, RollingWorkspace& workspace,
                                              double tolerance = 1e-9) const;

 private:
  ShearCache cache_;
};

// How much of a problem FASTSIM checks (validate): every value (the default), or the pressure's and the extra rigid
// slip's sizes alone, for grids the engine has just made from checked inputs (the wheelset's areas: a normal
// solution's pressure, the rigid slip of checked kinematics on a checked pose). A result that is not finite then
// throws, after the full check has named an input if one is at fault.
enum class ProblemCheck { values, sizes };

// FASTSIM (Kalker, Vehicle System Dynamics 11, 1982) on the same grid and pressure, strip by strip: every run of
// contact elements along a grid row starts from zero traction at its leading edge and integrates the simplified
// theory's u = L p toward the trailing edge, with the traction bound mu p_n of the actual pressure, so that it
// applies to non-elliptic patches (each contact region gets the flexibilities of its equivalent ellipse: the
// region's length and width in the grid directions and its area). Kalker's three flexibilities (creep.hpp) enter as
// an anisotropic layer diag(L1, L2) with the spin scaled by L1/L3 and L2/L3, which reproduces the linear theory's
// Fx, Fy for any creepages; in slip the predicted traction is projected onto the bound in the layer's energy norm,
// so that the traction opposes the slip of that layer (for L1 = L2 Kalker's radial scaling) and full sliding gives
// |F| = mu N opposite to the translational slip. Mz is not matched to C33 (a known limit of the simplified theory).
TangentialSolution solve_fastsim(const Material& material, const TangentialProblem& problem,
                                 ProblemCheck check = ProblemCheck::values);
// The same into `solution`, reusing its grids' storage (a dynamics code calling it at every step).
void solve_fastsim(const Material& material, const TangentialProblem& problem, TangentialSolution& solution,
                   ProblemCheck check = ProblemCheck::values);

// FASTSIM's derivative for each change: the strip march differentiated with each element's state (adhesion, slip)
// held, the slip elements' projection onto the bound differentiated exactly, the regions' flexibilities changing with
// the pressure change (through their ellipses' edge elements, ellipse_changes).
// Throws wrc::Error as RollingSolver::linearise does.
std::vector<TangentialDerivative> linearise_fastsim(const Material& material, const TangentialProblem& problem,
                                                    const TangentialSolution& solution,
                                                    std::span<const TangentialChange> changes);

// Throws wrc::Error naming `context` on a bad problem: grid, sizes, non-finite or negative pressure, non-finite
// creepages or rigid slip, friction coefficients outside [kFrictionMin, kFrictionMax] or kinetic > static, a bad
// falling law (friction.hpp), a slip-dependent law without a speed > 0, a friction scale of the wrong size or not
// > 0, direction not +-1, regions without labels or labels of the wrong size. ProblemCheck::sizes: the pressure's and
// the extra slip's values unchecked.
void validate(const TangentialProblem& problem, std::string_view context, ProblemCheck check = ProblemCheck::values);

// The rigid slip per |V| of the problem at every element (x and y components).
void rigid_slip(const TangentialProblem& problem, std::vector<double>& wx, std::vector<double>& wy);

}  // namespace wrc::halfspace
