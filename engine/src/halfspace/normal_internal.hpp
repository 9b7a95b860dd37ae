// Shared pieces of the normal solvers (not part of the public API).
#pragma once

#include "wrc/halfspace/normal.hpp"

#include <span>

namespace wrc::halfspace::detail {

// Fills force, centre of pressure, area, max pressure, contact count and the complementarity residuals
// from solution.pressure, the products u = 2 D p (m) on the whole grid, h and solution.approach. Also
// stores the gap. Throws wrc::Error if anything came out non-finite (never hand out NaN).
void finish_solution(NormalSolution& solution, std::span<const double> u, std::span<const double> h);

// A solution with zero pressure everywhere (no contact, or F = 0).
NormalSolution zero_solution(const Grid& grid, std::span<const double> h, const NormalLoad& load);

// Fills the integrals of a response (force, moments) from response.pressure.
void finish_response(NormalResponse& response, const Grid& grid);

// Validates the perturbation of a response against a solution.
void validate_response_input(const NormalSolution& solution, std::span<const double> dh, std::string_view context);

}  // namespace wrc::halfspace::detail
