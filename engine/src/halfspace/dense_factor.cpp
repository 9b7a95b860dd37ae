// The dense normal solver's Cholesky factor, kept across active-set iterations (method in dense_factor.hpp).
#include "dense_factor.hpp"

#include "wrc/halfspace/normal.hpp"
#include "wrc/core/error.hpp"

#include <algorithm>

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
  int p = 0;  // leading elements kept, with their columns
  if (!ldlt_ && m <= K_.rows())
    while (p < static_cast<int>(order_.size()) && in[order_[p]]) ++p;
  if (p == 0) return factorise_from_scratch(in, m);

  std::vector<int> kept;  // positions after p that stay: they move up, their leading columns with them
  for (int a = p; a < static_cast<int>(order_.size()); ++a)
    if (in[order_[a]]) kept.push_back(a);
  for (int c = 0; c < p; ++c)
    for (int r = 0; r < static_cast<int>(kept.size()); ++r) K_(p + r, c) = K_(kept[r], c);
  for (int r = 0; r < static_cast<int>(kept.size()); ++r) order_[p + r] = order_[kept[r]];
  order_.resize(p + kept.size());
  std::vector<int> joining;
  for (int k = 0; k < grid_.size(); ++k)
    if (in[k] && !member_[k]) joining.push_back(k);
  sort_deepest_first(joining);
  order_.insert(order_.end(), joining.begin(), joining.end());
  for (int k = 0; k < grid_.size(); ++k) member_[k] = in[k];

  const int j = static_cast<int>(joining.size()), t = m - p;
  if (j > 0) {  // L_JP = K_JP L_PP^-T
    for (int c = 0; c < p; ++c)
      for (int a = m - j; a < m; ++a) K_(a, c) = entry(a, c);
    auto rows = K_.block(m - j, 0, j, p);
    K_.topLeftCorner(p, p).triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(rows);
  }
  fill_lower(p, m);
  Eigen::Ref<Eigen::MatrixXd> trailing = K_.block(p, p, t, t);
  trailing.selfadjointView<Eigen::Lower>().rankUpdate(K_.block(p, 0, t, p), -1.0);
  m_ = m;
  kept_ = p;
  joined_ = j;
  if (!cholesky_in_place(trailing)) factorise_ldlt();
}

Eigen::VectorXd DenseActiveFactor::solve(const Eigen::VectorXd& rhs) const {
  if (ldlt_) return ldlt_->solve(rhs);
  const auto L = K_.topLeftCorner(m_, m_).triangularView<Eigen::Lower>();
  Eigen::VectorXd x = L.solve(rhs);
  L.adjoint().solveInPlace(x);
  return x;
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
  if (m > K_.rows()) {
    K_ = Eigen::MatrixXd();  // freed before the larger one is allocated
    K_.resize(m, m);
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
  if (!cholesky_in_place(K_.topLeftCorner(m, m))) factorise_ldlt();
}

void DenseActiveFactor::factorise_ldlt() {
  kept_ = 0;
  fill_lower(0, m_);  // the failed factorisation overwrote it
  Eigen::Ref<Eigen::MatrixXd> block = K_.topLeftCorner(m_, m_);
  ldlt_.emplace(block);  // in place
  if (ldlt_->info() != Eigen::Success)
    fail("{}: the influence matrix of {} active elements could not be factorised", context_, m_);
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
  for (int b = from; b < m; ++b)
    for (int a = b; a < m; ++a) K_(a, b) = entry(a, b);
}

}  // namespace wrc::halfspace::detail
