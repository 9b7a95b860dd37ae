// The dense normal solver's Cholesky factor of the active block, kept across active-set iterations (not part of the
// public API).
//
// The active-set iteration solves K x = r, K = 2 D_AA, for a set A that changes from one iteration to the next: a
// cold start from {h > 0} drops the rim of the set, a quarter or less of it per iteration, 5-8 times, and the check of
// the deformed gap re-adds a few elements; a warm start from the last pressure gains a ring as the load grows. The
// factor is kept in an order of its own, deepest h first, so that the elements dropped (small h) come last. For a set
// A' the factor L' (K' = L' L'^T) then shares the old L's leading columns up to the first element that leaves, P (the
// Cholesky factor of a leading block is the leading block of the factor): L'_PP = L_PP, the kept later rows
// L'_TP = L_TP (moved up in place), and the joining elements appended as new trailing rows, L'_JP = K_JP L_PP^-T;
// only the trailing block is formed, as its Schur complement K_TT - L'_TP L'_TP^T, and factorised. Row by row that
// is the Cholesky row-append (l = L^-1 a, d = sqrt(c - l.l)), done here a block of rows at a time. For p leading and
// t trailing elements that is t^2 p + t^3 / 3 flops against (p + t)^3 / 3 from scratch (never more); on
// bench_dense's Hertz cases t is 5-17 % of the set after the first iteration, and a cold solve costs about its first
// factorisation; a warm start that only gains elements keeps every column.
//
// An appended pivot d^2 is checked against kMinPivot times K's diagonal: below it (or not positive), the set is
// factorised from scratch (and should that fail too, by LDLT). Every exact pivot is at least K's smallest eigenvalue,
// which for the half-space's coefficients is a fixed share of the diagonal (kMinPivot's note), so a smaller one means
// rounding has eaten the update (c - l.l cancelling), not a property of the set.
//
// Memory: one m x m block (8 m^2 bytes, of which the factorisations use the lower triangle) for the largest set met,
// allocated only after a set beyond kDenseMaxElements has been refused. A set that outgrows it keeps its leading
// columns too: the block is grown by realloc and its kept columns moved to the new column stride in place. glibc maps
// blocks above its mmap threshold (at most 32 MB) on pages of their own and grows them by remapping, so a large block
// is never held twice; a from-scratch factorisation frees the old block before allocating a larger one.
#pragma once

#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/influence.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cstdlib>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace wrc::halfspace::detail {

// The smallest pivot d^2 an update may append, as a share of K's diagonal. Measured (numpy's eigenvalues of K from
// the closed form, elliptic sets of 80-716 elements): K's smallest eigenvalue over the diagonal is 0.52 for square
// elements, 0.47 / 0.38 / 0.31 / 0.20 at aspect ratios 2 / 4 / 8 / 64 (within 0.01 from 80 to 716 elements: set by
// the element, not the set's size), and the smallest pivot of any order, min 1 / (K^-1)_ii, 0.77 to 0.35. A computed c - l.l carries a rounding error of about m eps c (2e-12 c at
// 10,000 elements): 0.01 sits 20x below every exact pivot measured and far above that error.
inline constexpr double kMinPivot = 0.01;

class DenseActiveFactor {
 public:
  // K_ab = factor * table(offset between elements a and b) (m/Pa). `depth` per grid element: the order's key,
  // deepest first (h); empty: the elements' index order. `context` starts error messages. All are referred to.
  DenseActiveFactor(const InfluenceTable& table, double factor, const Grid& grid, std::span<const double> depth,
                    std::string_view context);
  DenseActiveFactor(const DenseActiveFactor&) = delete;  // the LDLT refers to the block
  DenseActiveFactor& operator=(const DenseActiveFactor&) = delete;

  // Factorises K for the elements k with in[k] != 0 (a grid vector), from the last factorisation where it can.
  // Throws wrc::Error for an empty set, a set beyond kDenseMaxElements (before allocating) or a failed LDLT, and
  // std::bad_alloc if the block cannot be allocated or grown.
  void factorise(const std::vector<char>& in);

  // The set's elements in the factor's order: the order of solve's vectors.
  const std::vector<int>& order() const { return order_; }
  // x = K^-1 rhs, both in the factor's order.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  // L (K = L L^T, m x m, in the factor's order); empty after a fallback to LDLT.
  Eigen::MatrixXd lower() const;

  // The leading columns the last factorise kept from the one before (0: from scratch), the rows it appended, and
  // whether it grew the block to do so.
  int kept_columns() const { return kept_; }
  int joined() const { return joined_; }
  bool grew() const { return grew_; }

 private:
  struct Free {
    void operator()(double* p) const { std::free(p); }
  };

  void refuse_beyond_limit(int m) const;
  void factorise_from_scratch(const std::vector<char>& in, int m);
  void factorise_ldlt();
  void grow(int m, int rows, int columns);
  bool pivots_safe(int from) const;
  void sort_deepest_first(std::vector<int>& elements) const;
  double entry(int a, int b) const;  // K between the elements at positions a and b of the order
  void fill_lower(int from, int m);  // K's lower triangle on positions [from, m)
  // The block: L in the lower triangle of its leading m_ x m_ part (or the LDLT's factors).
  Eigen::Map<Eigen::MatrixXd> K() { return {block_.get(), capacity_, capacity_}; }
  Eigen::Map<const Eigen::MatrixXd> K() const { return {block_.get(), capacity_, capacity_}; }

  const InfluenceTable& table_;
  double factor_;
  const Grid& grid_;
  std::span<const double> depth_;
  std::string_view context_;
  std::unique_ptr<double[], Free> block_;  // capacity_ x capacity_, column-major, from malloc (grown by realloc)
  int capacity_ = 0, m_ = 0, kept_ = 0, joined_ = 0;
  bool grew_ = false;
  std::vector<int> order_;    // the set's elements in the factor's order
  std::vector<char> member_;  // per grid element: in the set
  std::optional<Eigen::LDLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower>> ldlt_;
};

}  // namespace wrc::halfspace::detail
