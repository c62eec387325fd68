// Model problems with known critical points, as SteadySystems, so that continuation,
// fold location and runaway detection are proved on the same code path the bearing
// takes (issue: distress as a trajectory blow-up).
//
// Semenov's thermal explosion, lumped, written as a DAE so that the transient meets an
// algebraic unknown as it does on the bearing:
//     θ' = ψ·a − θ,   0 = a − e^θ        (u = (θ, a), λ = ψ)
// Steady states θ·e^(−θ) = ψ: a fold at θ = 1, ψ = 1/e; above it every trajectory runs
// away (finite-time blow-up).
// With a finite activation energy ε (Frank-Kamenetskii's exponent θ/(1 + εθ) in place
// of θ) and ε < 1/4 the steady curve is S-shaped: past the ignition fold the state
// jumps to a hot branch instead of blowing up, as the bearing's does past distress
// (physics §8). The folds are where (1 + εθ)² = θ.
//
// Bratu's problem in 1-D, u_t = u_xx + λ·e^u on (0, 1), u(0) = u(1) = 0, by second-order
// central differences on n interior nodes. The continuum fold is at λ = 3.513830719;
// the discrete one differs by O(1/n²) (about 1e-5 relative at n = 200).
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "system/steady_system.h"

namespace twb::testing {

// Every entry of a small n×n matrix, row by row.
inline SparsePattern dense_pattern(Index n) {
  SparsePattern p;
  p.rows = p.cols = n;
  for (Index r = 0; r <= n; ++r) p.row_start.push_back(r * n);
  for (Index r = 0; r < n; ++r)
    for (Index c = 0; c < n; ++c) p.column.push_back(c);
  return p;
}

class SemenovProblem final : public SteadySystem {
 public:
  explicit SemenovProblem(double psi, double activation = 0.0)
      : psi_(psi), epsilon_(activation), pattern_(dense_pattern(2)) {}
  Index size() const override { return 2; }
  const SparsePattern& pattern() const override { return pattern_; }
  // Oriented so u' = −F: F_θ = θ − ψ·a (C = 1), F_a = a − e^(θ/(1+εθ)) (algebraic).
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    const double d = 1.0 + epsilon_ * u[0];
    const double e = std::exp(u[0] / d);
    r[0] = u[0] - psi_ * u[1];
    r[1] = u[1] - e;
    if (!jac.empty()) {
      jac[0] = 1.0;
      jac[1] = -psi_;
      jac[2] = -e / (d * d);
      jac[3] = 1.0;
    }
  }
  double parameter() const override { return psi_; }
  void set_parameter(double v) override { psi_ = v; }
  // The second parameter of the fold curve test: ε.
  double activation() const { return epsilon_; }
  void set_activation(double e) { epsilon_ = e; }
  void parameter_derivative(std::span<const double> u, std::span<double> d) const override {
    d[0] = -u[1];
    d[1] = 0.0;
  }
  std::vector<double> capacities() const override { return {1.0, 0.0}; }
  // The steady state on the lower branch (θ < 1) for ψ < 1/e, by Newton on θ e^(−θ) = ψ.
  static std::vector<double> lower_steady_state(double psi) {
    double t = psi;
    for (int k = 0; k < 60; ++k) t -= (t * std::exp(-t) - psi) / ((1.0 - t) * std::exp(-t));
    return {t, std::exp(t)};
  }
  static double critical_parameter() { return std::exp(-1.0); }
  // The ignition fold for ε > 0: the smaller root of ε²θ² + (2ε − 1)θ + 1 = 0.
  double ignition_parameter() const {
    const double b = 2.0 * epsilon_ - 1.0;
    const double theta = (-b - std::sqrt(b * b - 4.0 * epsilon_ * epsilon_)) / (2.0 * epsilon_ * epsilon_);
    return theta * std::exp(-theta / (1.0 + epsilon_ * theta));
  }

 private:
  double psi_, epsilon_;
  SparsePattern pattern_;
};

class BratuProblem final : public SteadySystem {
 public:
  BratuProblem(int interior_nodes, double lambda) : n_(interior_nodes), lambda_(lambda) {
    pattern_.rows = pattern_.cols = n_;
    pattern_.row_start.push_back(0);
    for (Index i = 0; i < n_; ++i) {
      for (Index j = std::max<Index>(0, i - 1); j <= std::min<Index>(n_ - 1, i + 1); ++j)
        pattern_.column.push_back(j);
      pattern_.row_start.push_back(Index(pattern_.column.size()));
    }
  }
  Index size() const override { return n_; }
  const SparsePattern& pattern() const override { return pattern_; }
  // F_i = −(u_{i−1} − 2u_i + u_{i+1})/h² − λ e^{u_i}: u' = −F is the heat equation with
  // an Arrhenius source.
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    const double h = length_ / double(n_ + 1), ih2 = 1.0 / (h * h);
    Index pos = 0;
    for (Index i = 0; i < n_; ++i) {
      const double left = i > 0 ? u[std::size_t(i - 1)] : 0.0;
      const double right = i + 1 < n_ ? u[std::size_t(i + 1)] : 0.0;
      const double e = std::exp(u[std::size_t(i)]);
      r[std::size_t(i)] = -(left - 2.0 * u[std::size_t(i)] + right) * ih2 - lambda_ * e;
      if (jac.empty()) continue;
      if (i > 0) jac[std::size_t(pos++)] = -ih2;
      jac[std::size_t(pos++)] = 2.0 * ih2 - lambda_ * e;
      if (i + 1 < n_) jac[std::size_t(pos++)] = -ih2;
    }
  }
  double parameter() const override { return lambda_; }
  void set_parameter(double v) override { lambda_ = v; }
  void parameter_derivative(std::span<const double> u, std::span<double> d) const override {
    for (std::size_t i = 0; i < u.size(); ++i) d[i] = -std::exp(u[i]);
  }
  std::vector<double> capacities() const override { return std::vector<double>(std::size_t(n_), 1.0); }
  // Grid coordinate of interior node i.
  double x(Index i) const { return double(i + 1) / double(n_ + 1); }
  static double critical_parameter() { return 3.513830719; }
  // The domain (0, L): the problem is the unit one with λ·L², so its fold is λ*(1)/L².
  double length() const { return length_; }
  void set_length(double length) { length_ = length; }

 private:
  Index n_;
  double lambda_, length_ = 1.0;
  SparsePattern pattern_;
};

}  // namespace twb::testing
