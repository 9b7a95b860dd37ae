// Pieces of the steady-rolling solver shared by its files (not part of the public API).
#pragma once

#include "wrc/halfspace/rolling.hpp"

#include <memory>
#include <vector>

namespace wrc::halfspace::detail {

// A tangential problem on a grid: pressure and rigid slip per |V| per element (grid vectors).
struct Field {
  Grid grid;
  std::vector<double> pressure, wx, wy;
  std::vector<double> scale;  // the friction law's factor per element (TangentialProblem::friction_scale); empty: 1
};

// One grid level as the Newton solver sees it: the field cropped to the contact's bounding box plus the upstream
// column, and its contact elements in marching order (rows, each from its upstream end).
struct Level {
  Field field;                  // cropped
  int direction = 1;
  Friction friction;
  int i0 = 0, j0 = 0;           // cropped cell (0, 0) is cell (i0, j0) of the field it was cropped from
  std::vector<int> cell;        // contact element -> cropped grid index
  std::vector<int> up;          // contact element -> its upstream neighbour (contact element) or -1
  std::vector<double> gs, gk;   // traction bounds mu_s p_n, mu_k p_n (Pa); a slip-dependent law: mu(0) p_n and
                                // mu(|V| |w|) p_n, the bound at the rigid slip (a start)
  double speed = 0;             // |V| (m/s), with a slip-dependent law
  std::vector<double> gp;       // a slip-dependent law: p_n times the law's factor (Pa), the bound being mu(w) gp
  bool falling() const { return friction.slip_dependent(); }
  // A slip element's bound at slip s per |V| (Pa).
  double bound(int k, double s) const { return friction.at(speed * s) * gp[static_cast<std::size_t>(k)]; }
  std::vector<double> wx, wy;   // rigid slip per |V| of the contact elements
  double scale = 0;             // max |w| over the contact
  int size() const { return static_cast<int>(cell.size()); }
};

Level make_level(const Field& field, const Friction& friction, int direction, double speed);
// The field of a level made twice as coarse (coarse cell (I, J) covers cells 2I..2I+1, 2J..2J+1 of the cropped
// grid): pressure and rigid slip averaged (the slip and the friction factor over the contact cells only).
Field coarsen(const Level& level);

// The state of a level's solution: traction (Pa) and state per contact element.
struct LevelState {
  std::vector<double> px, py;
  std::vector<unsigned char> state;  // kAdhesion or kSlip
  int iterations = 0, linear = 0, products = 0, coarse_linear = 0;
  std::vector<double> slip;  // after newton: the slip per |V| of these tractions (x, y per element), its last product
  std::vector<double> bound;  // a slip-dependent law: each slip element's bound at its last slip (Pa)
  double residual = 0;
};

// Traction start for `level` from a coarser level's solution (bilinear at the element centres), clipped to the
// bound; elements at the bound start in slip.
LevelState prolong(const Level& coarse, const LevelState& coarse_state, const Level& level);
// Start from given tractions (grid vectors of the level's field), clipped likewise; `state` (optional, a grid vector
// too): the elements that start in slip, else those at the kinetic bound.
LevelState start_from(const Level& level, std::span<const double> px, std::span<const double> py,
                      std::span<const unsigned char> state = {});

// Semi-smooth Newton with GMRES on one level, from `state` (updated in place); false when it did not converge within
// options.max_iterations (state.residual says how far it got). `settled`: the start's split may already be the
// solution's (a warm start): it is checked before the first step, which is skipped when the start converged.
bool newton(const Level& level, const Material& material, const ShearSpectrum& linear, const ShearSpectrum& periodic,
            RollingWorkspace& ws, const TangentialOptions& options, LevelState& state, bool settled = false);

// The linearisation of a converged `state` (newton's, at its split) for right-hand sides of the rigid slip's change
// dw (x, y per contact element) and the slip elements' bound change dg (Pa per contact element): dp (x, y per contact
// element) by GMRES to the relative residual rtol. Returns the GMRES iterations.
int linearise(const Level& level, const Material& material, const ShearSpectrum& linear, const ShearSpectrum& periodic,
              RollingWorkspace& ws, const LevelState& state, const std::vector<double>& dw,
              const std::vector<double>& dg, double rtol, std::vector<double>& dp);

// The slip per |V| of the contact elements for the tractions of `state` (one product).
void slip_of(const Level& level, const ShearSpectrum& linear, RollingWorkspace& ws, const LevelState& state,
             std::vector<double>& sx, std::vector<double>& sy);

// The checks of a linearisation's input (RollingSolver::linearise, linearise_fastsim): the problem, a constant
// friction law, a solution on the problem's grid with the problem's contact, changes of the grid's size.
void check_linearisation(const TangentialProblem& problem, const TangentialSolution& solution,
                         std::span<const TangentialChange> changes, std::string_view context);
// A derivative's fx, fy and mz (about the reference point, moving by change.ref_x, ref_y) from its px, py.
void summarise(TangentialDerivative& d, const TangentialProblem& problem, const TangentialSolution& solution,
               const TangentialChange& change);

// A solution of `grid` with no traction, no slip and every element exterior.
TangentialSolution empty_solution(const Grid& grid);
// Fills forces, the moment about (ref_x, ref_y), areas and power from the solution's grids.
void summarise(TangentialSolution& solution, double ref_x, double ref_y);

}  // namespace wrc::halfspace::detail
