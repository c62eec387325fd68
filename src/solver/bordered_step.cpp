#include "solver/bordered_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "twb/error_family.h"

namespace twb {

namespace {

double largest(std::span<const double> v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The scale that brings a border of size `size` to `target`'s (1 where either vanishes).
double scale_to(double target, double size) { return size > 0.0 && target > 0.0 ? target / size : 1.0; }

}  // namespace

BorderedStep::BorderedStep(const BorderedMatrix& matrix, std::vector<double> b, std::vector<double> c)
    : matrix_(matrix), b_(std::move(b)), c_(std::move(c)), lu_(matrix.pattern()) {
  if (b_.size() != std::size_t(matrix.base_size()) || c_.size() != b_.size())
    throw InternalError("BorderedStep: borders of another size");
}

bool BorderedStep::hold(const std::vector<double>& m) {
  if (m == held_) return true;
  held_.clear();
  // Consecutive Newton points differ little: the pivot sequence is reused while KLU's
  // growth check allows (sparse_lu.h).
  if (!lu_.refactor(m)) return false;
  held_ = m;
  return true;
}

bool BorderedStep::factor(std::span<const double> base_jacobian) {
  std::vector<double> m(std::size_t(matrix_.pattern().nnz()));
  matrix_.assemble(base_jacobian, b_, c_, 0.0, m);
  return hold(m);
}

void BorderedStep::border(std::span<const double> a_values, std::vector<double>& m) const {
  const auto n = std::size_t(matrix_.base_size());
  const auto& start = matrix_.pattern().row_start;
  m.assign(a_values.begin(), a_values.end());
  for (std::size_t i = 0; i < n; ++i) m[std::size_t(start[i + 1]) - 1] = b_[i];
  const auto bottom = std::size_t(start[n]);
  std::copy(c_.begin(), c_.end(), m.begin() + std::ptrdiff_t(bottom));
  m[bottom + n] = 0.0;
}

bool BorderedStep::setup(std::span<const double> values) {
  ready_ = false;
  const auto n = std::size_t(matrix_.base_size());
  border(values, setup_);
  if (!hold(setup_)) return false;
  // A's border: its last column a, last row d, corner δ.
  const auto& start = matrix_.pattern().row_start;
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = values[std::size_t(start[i + 1]) - 1];
  const auto bottom = std::size_t(start[n]);
  const std::span<const double> d = values.subspan(bottom, n);
  const double delta = values[bottom + n];
  sigma_ = scale_to(largest(b_), largest(a));
  rho_ = scale_to(largest(c_), largest(d));

  z1_.assign(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) z1_[i] = sigma_ * a[i] - b_[i];
  lu_.solve(z1_);
  z2_.assign(n + 1, 0.0);
  z2_[n] = 1.0;
  lu_.solve(z2_);
  q_.resize(n + 1);
  for (std::size_t j = 0; j < n; ++j) q_[j] = rho_ * d[j] - c_[j];
  q_[n] = rho_ * sigma_ * delta;
  double qz1 = 0.0, qz2 = 0.0;
  for (std::size_t j = 0; j <= n; ++j) {
    qz1 += q_[j] * z1_[j];
    qz2 += q_[j] * z2_[j];
  }
  const double c11 = 1.0 + z1_[n], c12 = z2_[n], c21 = qz1, c22 = 1.0 + qz2;
  const double det = c11 * c22 - c12 * c21;
  const double size = std::max({std::abs(c11), std::abs(c12), std::abs(c21), std::abs(c22)});
  // C singular to working precision: A is (a singular fold system: not a regular fold).
  if (!std::isfinite(det) || !(std::abs(det) > 64.0 * std::numeric_limits<double>::epsilon() * size * size))
    return false;
  inverse_[0][0] = c22 / det;
  inverse_[0][1] = -c12 / det;
  inverse_[1][0] = -c21 / det;
  inverse_[1][1] = c11 / det;
  ready_ = true;
  return true;
}

bool BorderedStep::solve(std::span<double> rhs) {
  if (!ready_) throw InternalError("BorderedStep::solve without a setup");
  const auto n = std::size_t(matrix_.base_size());
  // An evaluation since the setup may have factored M at another J: the setup's again.
  if (!hold(setup_)) return false;
  rhs[n] *= rho_;
  lu_.solve(rhs);
  double t2 = 0.0;
  for (std::size_t j = 0; j <= n; ++j) t2 += q_[j] * rhs[j];
  const double t1 = rhs[n];
  const double alpha1 = inverse_[0][0] * t1 + inverse_[0][1] * t2;
  const double alpha2 = inverse_[1][0] * t1 + inverse_[1][1] * t2;
  for (std::size_t j = 0; j <= n; ++j) rhs[j] -= alpha1 * z1_[j] + alpha2 * z2_[j];
  rhs[n] *= sigma_;
  return true;
}

}  // namespace twb
