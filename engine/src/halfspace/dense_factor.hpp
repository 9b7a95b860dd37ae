// The dense normal solver's Cholesky factor of the active block, kept across active-set iterations (not part of the
// public API).
//
// The active-set iteration solves K x = r, K = 2 D_AA, for a set A that changes from one iteration to the next: a
// cold start from {h > 0} drops the rim of the set, a quarter or less of it per iteration, 5-8 times, and the check of
// the deformed gap re-adds a few elements. The factor is kept in an order of its own, deepest h first, so that the
// elements dropped (small h) come last. For a set A' the factor L' (K' = L' L'^T) then shares the old L's leading
// columns up to the first element that leaves, P (the Cholesky factor of a leading block is the leading block of
// the factor): L'_PP = L_PP, the kept later rows L'_TP = L_TP (moved up in place) and joining elements' rows, placed
// last, L'_JP = K_JP L_PP^-T; only the trailing block is formed, as its Schur complement K_TT - L'_TP L'_TP^T, and
// factorised. For p leading and t trailing elements that is t^2 p + t^3 / 3 flops against (p + t)^3 / 3 from
// scratch (never more); on bench_dense's Hertz cases t is 5-17 % of the set after the first iteration, and a cold
// solve costs about its first factorisation.
//
// Memory: one m x m matrix (8 m^2 bytes, of which the factorisations use the lower triangle) for the largest set
// met, allocated only after a set beyond kDenseMaxElements has been refused. A set that outgrows it (a warm start
// that gains elements) is factorised from scratch in a new matrix, the old one freed first: at most one matrix at a
// time, as large as the largest set. Should rounding make a Cholesky factorisation fail, LDLT from scratch.
#pragma once

#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/influence.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace wrc::halfspace::detail {

class DenseActiveFactor {
 public:
  // K_ab = factor * table(offset between elements a and b) (m/Pa). `depth` per grid element: the order's key,
  // deepest first (h); empty: the elements' index order. `context` starts error messages. All are referred to.
  DenseActiveFactor(const InfluenceTable& table, double factor, const Grid& grid, std::span<const double> depth,
                    std::string_view context);
  DenseActiveFactor(const DenseActiveFactor&) = delete;  // the LDLT refers to K_
  DenseActiveFactor& operator=(const DenseActiveFactor&) = delete;

  // Factorises K for the elements k with in[k] != 0 (a grid vector), from the last factorisation where it can.
  // Throws wrc::Error for an empty set, a set beyond kDenseMaxElements (before allocating) or a failed LDLT.
  void factorise(const std::vector<char>& in);

  // The set's elements in the factor's order: the order of solve's vectors.
  const std::vector<int>& order() const { return order_; }
  // x = K^-1 rhs, both in the factor's order.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

  // The leading columns the last factorise kept from the one before (0: from scratch) and the rows it appended.
  int kept_columns() const { return kept_; }
  int joined() const { return joined_; }

 private:
  void refuse_beyond_limit(int m) const;
  void factorise_from_scratch(const std::vector<char>& in, int m);
  void factorise_ldlt();
  void sort_deepest_first(std::vector<int>& elements) const;
  double entry(int a, int b) const;  // K between the elements at positions a and b of the order
  void fill_lower(int from, int m);  // K's lower triangle on positions [from, m)

  const InfluenceTable& table_;
  double factor_;
  const Grid& grid_;
  std::span<const double> depth_;
  std::string_view context_;
  Eigen::MatrixXd K_;         // L in the lower triangle of its leading m_ x m_ block (or the LDLT's factors)
  int m_ = 0, kept_ = 0, joined_ = 0;
  std::vector<int> order_;    // the set's elements in the factor's order
  std::vector<char> member_;  // per grid element: in the set
  std::optional<Eigen::LDLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower>> ldlt_;
};

}  // namespace wrc::halfspace::detail
