// The dense normal solver's Cholesky factor, kept across active-set iterations (method in dense_factor.hpp).
#include "dense_factor.hpp"

#include "wrc/halfspace/normal.hpp"
#include "wrc/core/error.hpp"

#include <algorithm>
#include <cstring>
#include <new>

namespace wrc::halfspace::detail {
namespace {

// Eigen's blocked Cholesky, in place on the lower triangle of `block`.
bool cholesky_in_place(Eigen::Ref<Eigen::MatrixXd> block) {
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(block);
  return llt.info() == Eigen::Success;
}

}  // namespace

DenseActiveFactor::DenseActiveFactor(const InfluenceTable& table, double factor, const Grid& grid,
                                     std::span<const double> depth, std::string_view context)
    : table_(table), factor_(factor), grid_(grid), depth_(depth), context_(context), member_(grid.size(), 0) {}

void DenseActiveFactor::factorise(const std::vector<char>& in) {
  const int m = static_cast<int>(std::count_if(in.begin(), in.end(), [](char c) { return c != 0; }));
  if (m == 0) fail("{}: the active set is empty (internal error)", context_);
  refuse_beyond_limit(m);
  grew_ = false;
  int p = 0;  // leading elements kept, with their columns
  if (!ldlt_)
    while (p < static_cast<int>(order_.size()) && in[order_[p]]) ++p;
  if (p == 0) return factorise_from_scratch(in, m);

  std::vector<int> kept;  // positions after p that stay: they move up, their leading columns with them
  for (int a = p; a < static_cast<int>(order_.size()); ++a)
    if (in[order_[a]]) kept.push_back(a);
  {
    auto K = this->K();  // at the old stride
    for (int c = 0; c < p; ++c)
      for (int r = 0; r < static_cast<int>(kept.size()); ++r) K(p + r, c) = K(kept[r], c);
  }
  for (int r = 0; r < static_cast<int>(kept.size()); ++r) order_[p + r] = order_[kept[r]];
  order_.resize(p + kept.size());
  grew_ = m > capacity_;
  if (grew_) grow(m, static_cast<int>(order_.size()), p);
  std::vector<int> joining;
  for (int k = 0; k < grid_.size(); ++k)
    if (in[k] && !member_[k]) joining.push_back(k);
  sort_deepest_first(joining);
  order_.insert(order_.end(), joining.begin(), joining.end());
  for (int k = 0; k < grid_.size(); ++k) member_[k] = in[k];

  auto K = this->K();
  const int j = static_cast<int>(joining.size()), t = m - p;
  if (j > 0) {  // the appended rows: L_JP = K_JP L_PP^-T
    for (int c = 0; c < p; ++c)
      for (int a = m - j; a < m; ++a) K(a, c) = entry(a, c);
    auto rows = K.block(m - j, 0, j, p);
    K.topLeftCorner(p, p).triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(rows);
  }
  fill_lower(p, m);
  Eigen::Ref<Eigen::MatrixXd> trailing = K.block(p, p, t, t);
  trailing.selfadjointView<Eigen::Lower>().rankUpdate(K.block(p, 0, t, p), -1.0);
  m_ = m;
  kept_ = p;
  joined_ = j;
  if (!cholesky_in_place(trailing) || !pivots_safe(p)) factorise_from_scratch(in, m);
}

Eigen::VectorXd DenseActiveFactor::solve(const Eigen::VectorXd& rhs) const {
  if (ldlt_) return ldlt_->solve(rhs);
  const auto L = K().topLeftCorner(m_, m_).triangularView<Eigen::Lower>();
  Eigen::VectorXd x = L.solve(rhs);
  L.adjoint().solveInPlace(x);
  return x;
}

Eigen::MatrixXd DenseActiveFactor::lower() const {
  if (ldlt_) return {};
  return K().topLeftCorner(m_, m_).triangularView<Eigen::Lower>();
}

void DenseActiveFactor::refuse_beyond_limit(int m) const {
  if (m > kDenseMaxElements)
    fail("{}: {} elements in the active set would need a dense {} x {} matrix of {:.0f} MB (8 bytes each) and about "
         "{:.0f} s per Cholesky factorisation; the dense reference solver takes at most {} ({:.0f} MB): use the "
         "fast solver (solver = \"fast\", the default; NormalSolver in C++) or a coarser grid",
         context_, m, m, m, dense_block_bytes(m) / 1e6, dense_factorisation_seconds(m), kDenseMaxElements,
         dense_block_bytes(kDenseMaxElements) / 1e6);
}

void DenseActiveFactor::factorise_from_scratch(const std::vector<char>& in, int m) {
  ldlt_.reset();
  if (m > capacity_) {
    block_.reset();  // freed before the larger one is allocated
    capacity_ = 0;
    block_.reset(static_cast<double*>(std::malloc(sizeof(double) * static_cast<std::size_t>(m) * m)));
    if (!block_) throw std::bad_alloc();
    capacity_ = m;
  }
  order_.clear();
  for (int k = 0; k < grid_.size(); ++k)
    if (in[k]) order_.push_back(k);
  sort_deepest_first(order_);
  for (int k = 0; k < grid_.size(); ++k) member_[k] = in[k];
  m_ = m;
  kept_ = 0;
  joined_ = 0;
  fill_lower(0, m);
  if (!cholesky_in_place(K().topLeftCorner(m, m))) factorise_ldlt();
}

void DenseActiveFactor::factorise_ldlt() {
  kept_ = 0;
  fill_lower(0, m_);  // the failed factorisation overwrote it
  Eigen::Ref<Eigen::MatrixXd> block = K().topLeftCorner(m_, m_);
  ldlt_.emplace(block);  // in place
  if (ldlt_->info() != Eigen::Success)
    fail("{}: the influence matrix of {} active elements could not be factorised", context_, m_);
}

// The block to m x m, rows [c, rows) of each column c < `columns` kept (their lower triangle). Columns move to the
// larger stride from the last one down: column c's new place, from c m + c on, lies beyond the columns not yet moved
// (they end before c capacity_), and memmove allows it to overlap its own old place.
void DenseActiveFactor::grow(int m, int rows, int columns) {
  const std::size_t bytes = sizeof(double) * static_cast<std::size_t>(m) * m;
  auto* grown = static_cast<double*>(std::realloc(block_.get(), bytes));
  if (!grown) throw std::bad_alloc();  // the old block stays valid, and is freed with the factor
  (void)block_.release();
  block_.reset(grown);
  for (int c = columns - 1; c >= 0; --c)
    std::memmove(grown + static_cast<std::size_t>(c) * m + c, grown + static_cast<std::size_t>(c) * capacity_ + c,
                 sizeof(double) * static_cast<std::size_t>(rows - c));
  capacity_ = m;
}

// The trailing factor's pivots d^2 from position `from` on against kMinPivot times K's diagonal.
bool DenseActiveFactor::pivots_safe(int from) const {
  if (from == m_) return true;  // nothing appended
  const double least = K().diagonal().segment(from, m_ - from).cwiseAbs2().minCoeff();
  return least >= kMinPivot * factor_ * table_(0, 0);
}

void DenseActiveFactor::sort_deepest_first(std::vector<int>& elements) const {
  if (!depth_.empty())
    std::stable_sort(elements.begin(), elements.end(), [&](int a, int b) { return depth_[a] > depth_[b]; });
}

double DenseActiveFactor::entry(int a, int b) const {
  const int ka = order_[a], kb = order_[b];
  return factor_ * table_(ka % grid_.nx - kb % grid_.nx, ka / grid_.nx - kb / grid_.nx);
}

void DenseActiveFactor::fill_lower(int from, int m) {
  auto K = this->K();
  for (int b = from; b < m; ++b)
    for (int a = b; a < m; ++a) K(a, b) = entry(a, b);
}

}  // namespace wrc::halfspace::detail
