// Kalker's variational normal contact problem (CONTACT) on a regular grid (paper section 3, eq. 2).
//
// Given the undeformed inter-penetration h at the element centres (m, > 0 where the undeformed surfaces
// overlap) find the pressure p >= 0 (Pa) with
//   g = 2 D p - (h + approach w) >= 0,   p >= 0,   p g = 0   at every element,
// where 2 D is the influence matrix of the pair (influence.hpp) and g the deformed gap (m). With a
// prescribed penetration `approach` = 0 (h says everything); with a prescribed normal force F (N) the
// rigid approach (m) is the extra unknown and sum w p dA = F (weights w: NormalLoad, all 1 unless given).
//
// Two solvers give the same answer: solve_normal_dense, the paper's active-set iteration with a dense
// Cholesky solve (the reference, O(n^3)), and NormalSolver, conjugate gradients on the active set with
// FFT products and an FFT preconditioner (about N log N per iteration). NormalSolver::response gives the
// linearised response of a solution to a perturbation of h on its contact set (for Newton solvers).
#pragma once

#include "wrc/halfspace/convolution.hpp"
#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/material.hpp"

#include <span>
#include <utility>
#include <string_view>
#include <vector>

namespace wrc::halfspace {

struct NormalLoad {
  enum class Control { penetration, force };
  Control control = Control::penetration;
  double force = 0;  // N, for Control::force (>= 0)
  // For Control::force only: weights w > 0 per element (empty: all 1). The prescribed force is then
  // sum w p dA = F and the approach enters the gap as approach * w. On a curved surface whose element normals
  // differ, w = each element's vertical normal part makes F the vertical force and the approach the vertical one.
  std::vector<double> weights;
  // For Control::force only, optional: the approach's effect on each element's gap when it is not its weight (the
  // gap is then u - h - approach * gap_weights; the force stays sum w p dA = F). A body moved along a direction
  // whose component along the element normals differs from the force's weights: e.g. the vertical approach of a
  // wheel deepens h by the wheel's normal z part, while its vertical force sums the row normals' (empty: weights).
  std::vector<double> gap_weights;

  double weight(std::size_t k) const { return weights.empty() ? 1.0 : weights[k]; }
  double gap_weight(std::size_t k) const { return gap_weights.empty() ? weight(k) : gap_weights[k]; }
  static NormalLoad penetration() { return {}; }
  static NormalLoad normal_force(double F, std::vector<double> weights = {}) {
    return {Control::force, F, std::move(weights), {}};
  }
};

struct NormalOptions {
  // Convergence: max |g| over the contact set <= tolerance * max(h + approach) (for 20 um of penetration
  // the default leaves 2e-13 m). The relative pressure error is a modest multiple of this (the problem's
  // condition number grows like the contact's width in elements): ~1e-7 against the dense solve.
  double tolerance = 1e-8;
  int max_iterations = 0;  // CG iterations (fast) or active-set iterations (dense); 0: automatic
  bool precondition = true;  // fast solver: FFT preconditioner on (off only to measure what it gains)
  // Fast solver without a warm start: start from the solution on a grid twice as coarse (recursively,
  // while the grid has more than coarse_limit elements). Off only to measure what it gains.
  bool nested = true;
  int coarse_limit = 1000;
  // Fast solver, no warm start: return the nested start itself (the coarse grid's solution at max(tolerance, 1e-2),
  // interpolated, with the coarse approach), without iterating on this grid: an estimate for a predictor, a fraction
  // of a solve's cost (a grid too small to nest is solved as usual).
  bool estimate = false;
  // Optional warm start (Pa, one value per element), e.g. the previous pose's pressure; empty: none.
  std::span<const double> initial_pressure = {};
  // Fast solver, optional: the displacements u = D p of initial_pressure (m, as NormalSolution::displacement) where
  // known, NaN elsewhere; e.g. the last solution's on the elements two grids share. A start whose window they cover
  // needs no product.
  std::span<const double> initial_displacement = {};
};

// How well the final state satisfies the complementarity conditions (recomputed from scratch at the end).
struct Complementarity {
  double negative_pressure = 0;  // Pa: max(0, -min p)
  double contact_gap = 0;        // m: max |g| over the contact set (where p > 0)
  double negative_gap = 0;       // m: max(0, -min g) outside the contact set
  double product = 0;            // Pa m: max |p g|
  double relative = 0;           // max(contact_gap, negative_gap) / max(h + approach)
};

struct NormalSolution {
  Grid grid;
  std::vector<double> pressure;  // Pa, per element (index i + nx j), >= 0
  std::vector<double> gap;       // m, deformed gap g per element (0 in contact, >= 0 outside up to the
                                 // tolerance)
  double force = 0;              // N: sum p dA
  double cop_x = 0, cop_y = 0;   // m: centre of pressure in the grid's frame (grid centre if force = 0)
  double area = 0;               // m^2: elements in contact times dA
  double max_pressure = 0;       // Pa
  int elements_in_contact = 0;   // elements with p > 0
  int edge_elements_in_contact = 0;  // of those, on the grid's border: > 0 means the potential contact
                                     // area cut the contact short (enlarge it)
  int iterations = 0;            // CG iterations on this grid (fast) or active-set iterations (dense)
  int coarse_iterations = 0;     // fast: CG iterations on the coarser grids of the nested start
  int products = 0;              // fast: FFT round trips on this grid (products with D, preconditioner)
  int coarse_products = 0;       // fast: FFT round trips on the coarser grids (each 4x cheaper per level)
  double approach = 0;           // m: solved rigid approach for a prescribed force, 0 for a penetration
  NormalLoad load;
  Complementarity residual;
  std::vector<double> displacement;  // fast solver: u = D p per element (m), for a warm start's reuse; else empty
};

// The dense solver's largest active set (elements): its block takes dense_block_bytes (8 m^2: 0.8 GB at 10,000) and
// one Cholesky factorisation m^3 / 3 flops, about dense_factorisation_seconds (30 s at 10,000 on one core); a cold
// solve factorises the block of {h > 0}, about twice the contact, and of its 5-8 shrinking sets only the trailing
// part the factor does not share (bench_dense: 2,000 elements in contact from a first block of 4,100 in 2.1 s,
// 4,000 from 8,100 in 16 s). Larger sets are refused, before the block is allocated, with an error naming the fast
// solver.
inline constexpr int kDenseMaxElements = 10'000;
inline constexpr double dense_block_bytes(int m) { return 8.0 * m * m; }
// Measured: 11 Gflop/s for Eigen's blocked Cholesky on one core of a 2-core machine (bench_dense's responses).
inline constexpr double dense_factorisation_seconds(int m) { return static_cast<double>(m) * m * m / 3 / 11e9; }

// Reference solver: the paper's active-set iteration (start from {h > 0}, drop elements with negative
// pressure, repeat; then CONTACT's check that no element was wrongly removed, 2Dp - h < 0 outside, and
// re-add those) with a dense Cholesky solve of the active block, its factor kept from one iteration to the next
// where the sets share its leading columns (elements ordered deepest h first). Memory and time O(n_active^2) and
// O(n_active^3): for tests and small grids (kDenseMaxElements). Throws wrc::Error on bad input, an active set
// larger than kDenseMaxElements (before allocating it), or no convergence (max_iterations, default 200; or an
// active set met before, which would repeat the same iterations).
NormalSolution solve_normal_dense(const Material& material, const Grid& grid, std::span<const double> h,
                                  const NormalLoad& load, const NormalOptions& options = {});

// Linearised response of a converged solution: the change of the pressure per unit of a perturbation dh
// of h (m), on the solution's contact set held fixed: 2 D_AA dp_A = dh_A (+ d approach w for a prescribed
// force, where sum w dp = 0). Valid while the contact set does not change (generic).
struct NormalResponse {
  std::vector<double> pressure;  // dp (Pa per unit of the perturbation), per element
  double force = 0;              // dF (N)
  double moment_x = 0;           // d(sum p x dA) (N m): first moment about the grid frame's origin
  double moment_y = 0;           // d(sum p y dA) (N m)
  double approach = 0;           // d approach (m) for a prescribed force; 0 for a penetration
  int iterations = 0;
};

// Dense reference of NormalSolver::response.
NormalResponse normal_response_dense(const Material& material, const NormalSolution& solution,
                                     std::span<const double> dh);

// Buffers of one thread for NormalSolver (not shareable between threads; reused across solves).
class NormalWorkspace {
 public:
  NormalWorkspace() = default;
  ConvolutionWorkspace fft;           // products with D (zero-padded grids)
  ConvolutionWorkspace fft_periodic;  // the preconditioner (periodic grids): its own buffers, so that alternating
                                      // the two does not re-zero a padded buffer at every product
  std::vector<double> p, u, r, z, d, q;
  std::vector<unsigned char> active, previous_active;
};

// The process-wide store of influence spectra for a planning mode: spectra depend only on the element size and the
// FFT shape, so every solver (every wheelset of a fleet study) shares them.
std::shared_ptr<const InfluenceCache> shared_cache(FftPlanning planning);

// The fast solver: conjugate gradients on the active set (a projected CG in the manner of Polonsky and
// Keer, Wear 231, 1999) preconditioned with the inverse of the grid's periodic circulant (an FFT
// deconvolution, in the spirit of Vollebregt's NormCG, J. Comput. Phys. 257, 2014), started from the
// solution on a grid twice as coarse (NormalOptions::nested) unless a warm start is given. Products with
// D by zero-padded FFT (FFTW). Part of an immutable model: one instance can serve many threads at once,
// each with its own NormalWorkspace; it caches the kernel spectra and FFT plans per padded grid shape
// (the first solve of a new shape pays for them: a few ms with FftPlanning::estimate, 0.1-1 s with
// FftPlanning::measure, whose plans then run ~10-30 % faster).
class NormalSolver {
 public:
  explicit NormalSolver(const Material& material, FftPlanning planning = FftPlanning::estimate);

  const Material& material() const { return material_; }
  const InfluenceCache& cache() const { return *cache_; }

  NormalSolution solve(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                       NormalWorkspace& workspace, const NormalOptions& options = {}) const;
  NormalSolution solve(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                       const NormalOptions& options = {}) const;  // with a temporary workspace

  // Linearised response (see NormalResponse) by preconditioned CG on the fixed contact set; relative
  // residual `tolerance`.
  NormalResponse response(const NormalSolution& solution, std::span<const double> dh, NormalWorkspace& workspace,
                          double tolerance = 1e-8) const;

 private:
  NormalSolution solve_checked(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                               NormalWorkspace& workspace, const NormalOptions& options) const;
  Material material_;
  std::shared_ptr<const InfluenceCache> cache_;  // the process-wide one of the planning mode (shared_cache)
};

// Helpers shared by the solvers and useful to callers.
// Validates the inputs of a solve (grid, h size and finiteness, load); throws wrc::Error naming them.
void validate_normal_input(const Material& material, const Grid& grid, std::span<const double> h,
                           const NormalLoad& load, const NormalOptions& options, std::string_view context);

}  // namespace wrc::halfspace
