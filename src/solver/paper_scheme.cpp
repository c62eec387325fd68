#include "solver/paper_scheme.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "solver/kinsol_newton.h"
#include "solver/sparse_lu.h"
#include "twb/error_family.h"

namespace twb {

namespace {

enum class Role : unsigned char { rigid, pressure, temperature };

class PaperScheme {
 public:
  PaperScheme(SegregatedSystem& system, const PaperSchemeSettings& settings, PaperSchemeReport& report)
      : system_(system),
        s_(settings),
        rep_(report),
        blocks_(system.segregated_blocks()),
        pattern_(system.pattern()),
        residual_(std::size_t(system.size())),
        jacobian_(std::size_t(pattern_.nnz())),
        change_(std::size_t(system.size()), 0.0),
        role_(std::size_t(system.size()), Role::rigid),
        diagonal_(std::size_t(system.size()), -1) {
    for (Index k : blocks_.pressure) role_[std::size_t(k)] = Role::pressure;
    for (Index k : blocks_.temperature) role_[std::size_t(k)] = Role::temperature;
    for (Index k = 0; k < system.size(); ++k) diagonal_[std::size_t(k)] = pattern_.find(k, k);
    if (blocks_.rigid.empty()) throw InternalError("the paper's scheme needs rigid-body unknowns");
    if (s_.heat_solver == PaperHeatSolver::direct && !blocks_.temperature.empty()) build_heat_matrix();
  }

  void solve(std::vector<double>& u) {
    if (!converge_fields(u)) return fail(u, "the coupled loop of pressures and temperatures did not converge at the start");
    std::vector<double> balance = rigid_rows();
    for (;;) {
      rep_.residual_norm = residual_norm(u, balance);
      if (rep_.residual_norm <= s_.residual_tolerance) {
        rep_.converged = true;
        return;
      }
      if (rep_.newton_iterations == s_.max_newton_iterations)
        return fail(u, fmt::format("the force and moment balances are still {:.3g} off after {} Newton–Raphson "
                                   "iterations",
                                   max_norm(balance), rep_.newton_iterations));
      ++rep_.newton_iterations;
      Eigen::MatrixXd jac;
      if (!differentiate(u, jac)) return fail(u, "the coupled loop did not converge at a differencing point of eq. [38]");
      const Eigen::VectorXd g = Eigen::Map<const Eigen::VectorXd>(balance.data(), Eigen::Index(balance.size()));
      // The Newton–Raphson step, damped the Levenberg–Marquardt way where it does not
      // lower the balances: the washer floats between two films whose stiffnesses nearly
      // cancel, so the undamped step is long and swings between contact on either side
      // (the paper does not say how it damped; plain halving crept there, under 1 % an
      // iteration). The damping shrinks after every accepted step: near the root the
      // steps are Newton's, and converge quadratically.
      const Eigen::MatrixXd normal = jac.transpose() * jac;
      const Eigen::VectorXd gradient = jac.transpose() * g;
      const Eigen::VectorXd scale = normal.diagonal().cwiseMax(1e-300);
      bool improved = false;
      for (int attempt = 0; attempt < 30 && !improved; ++attempt) {
        Eigen::VectorXd step = (normal + Eigen::MatrixXd(damping_ * scale.asDiagonal())).ldlt().solve(-gradient);
        if (!step.allFinite()) {  // a singular Jacobian: damp
          damping_ = std::max(4.0 * damping_, 1e-8);
          continue;
        }
        // At most max_rigid_step in any rigid unknown (σ, γ_ref), as twb's Newton.
        if (const double longest = step.cwiseAbs().maxCoeff(); longest > s_.max_rigid_step)
          step *= s_.max_rigid_step / longest;
        std::vector<double> trial = u;
        for (std::size_t i = 0; i < blocks_.rigid.size(); ++i) trial[std::size_t(blocks_.rigid[i])] += step[Eigen::Index(i)];
        if (converge_fields(trial)) {
          std::vector<double> trial_balance = rigid_rows();
          if (sum_of_squares(trial_balance) < sum_of_squares(balance)) {
            u = std::move(trial);
            balance = std::move(trial_balance);
            improved = true;
            damping_ /= 10.0;
            continue;
          }
        }
        damping_ = std::max(4.0 * damping_, 1e-8);
      }
      if (!improved) {
        // Rows stay as last evaluated at a trial: evaluate at u again for the report.
        converge_fields(u);
        rep_.residual_norm = residual_norm(u, balance);
        if (rep_.residual_norm <= s_.residual_tolerance) {
          rep_.converged = true;
          return;
        }
        return fail(u, fmt::format("no Newton–Raphson step lowers the balances below {:.3g}", max_norm(balance)));
      }
    }
  }

 private:
  void fail(const std::vector<double>& u, std::string why) {
    rep_.converged = false;
    rep_.message = std::move(why);
    rep_.residual_norm = residual_norm(u, rigid_rows());
  }

  void evaluate(const std::vector<double>& u) {
    system_.evaluate(u, residual_, jacobian_);
    ++rep_.evaluations;
  }

  // Every row's residual: the balances, the Reynolds condition, the heat balance.
  double residual_norm(const std::vector<double>& u, const std::vector<double>& balance) const {
    return std::max({max_norm(balance), pressure_norm(u), heat_norm()});
  }
  // The merit a Newton direction always lowers (for a small enough step).
  static double sum_of_squares(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m += x * x;
    return m;
  }
  std::vector<double> rigid_rows() const {
    std::vector<double> g;
    for (Index k : blocks_.rigid) g.push_back(residual_[std::size_t(k)]);
    return g;
  }
  // The Reynolds condition as twb's Newton sees it: |min(p̂, ŵ)| at every node.
  double pressure_norm(const std::vector<double>& u) const {
    double m = 0.0;
    for (Index k : blocks_.pressure) m = std::max(m, std::abs(std::min(u[std::size_t(k)], residual_[std::size_t(k)])));
    return m;
  }
  double heat_norm() const {
    double m = 0.0;
    for (Index k : blocks_.temperature) m = std::max(m, std::abs(residual_[std::size_t(k)]));
    return m;
  }

  // The flow chart's coupled loop at u's rigid-body position: pressures by projected
  // SOR and temperatures by Gauss–Seidel, each on the rows and coefficients evaluated at
  // the loop's last state, until both fields satisfy their rows.
  bool converge_fields(std::vector<double>& u) {
    ++rep_.inner_solves;
    // A loop that has not halved its residual in this many passes is not converging
    // (a rigid-body trial deep in contact, where the films' heat links stiffen): the
    // outer iteration shortens its step instead.
    constexpr int patience = 20;
    double best = INFINITY;
    int since_best = 0;
    for (int pass = 0; pass < s_.max_coupled_iterations; ++pass) {
      evaluate(u);
      const double p_norm = pressure_norm(u), t_norm = heat_norm();
      if (!std::isfinite(p_norm) || !std::isfinite(t_norm)) return false;
      // A tenth of the tolerance: the balances inherit the fields' error, and the outer
      // iteration must see them change below the tolerance it converges them to.
      const double field_tolerance = 0.1 * s_.residual_tolerance;
      if (p_norm <= field_tolerance && t_norm <= field_tolerance) return true;
      const double worst = std::max(p_norm, t_norm);
      if (worst < 0.5 * best) {
        best = worst;
        since_best = 0;
      } else if (++since_best == patience) {
        return false;
      }
      ++rep_.coupled_iterations;
      if (p_norm > field_tolerance)
        rep_.pressure_sweeps += sweep(u, blocks_.pressure, Role::pressure, s_.pressure_over_relaxation);
      if (t_norm > field_tolerance) {
        if (heat_lu_)
          solve_heat(u);
        else
          rep_.heat_sweeps += sweep(u, blocks_.temperature, Role::temperature, s_.heat_over_relaxation);
      }
    }
    return false;
  }

  // Gauss–Seidel with over-relaxation ω on one field's rows, M·δ = −F_B, the other
  // fields held; pressures projected onto p ≥ 0 node by node. M is the field's Jacobian
  // block without its positive couplings: on the Reynolds rows there are none (they are
  // linear in p, the Poiseuille conductances couple negatively), on the heat rows they
  // are the heat sources' growth with the neighbours' temperatures (the viscous heat with
  // the surfaces'), which the paper lags: it recomputes the heat generated from the last
  // pass's temperatures. What remains is the conduction's M-matrix, on which Gauss–Seidel
  // converges; the lagged part enters through the rows the next pass evaluates.
  // Sweeps until M·δ + F_B falls by the reduction factor; returns how many.
  long sweep(std::vector<double>& u, const std::vector<Index>& block, Role role, double omega) {
    const bool projected = role == Role::pressure;
    for (Index k : block) change_[std::size_t(k)] = 0.0;
    auto linearized = [&](Index k) {
      double sum = residual_[std::size_t(k)];
      for (Index e = pattern_.row_start[std::size_t(k)]; e < pattern_.row_start[std::size_t(k) + 1]; ++e) {
        const auto j = std::size_t(pattern_.column[std::size_t(e)]);
        const double coupling = jacobian_[std::size_t(e)];
        if (role_[j] == role && (coupling <= 0.0 || j == std::size_t(k))) sum += coupling * change_[j];
      }
      return sum;
    };
    auto norm = [&] {
      double m = 0.0;
      for (Index k : block) {
        const double row = linearized(k);
        m = std::max(m, std::abs(projected ? std::min(u[std::size_t(k)] + change_[std::size_t(k)], row) : row));
      }
      return m;
    };
    const double target = std::max(0.1 * s_.residual_tolerance, s_.sweep_reduction * norm());
    long sweeps = 0;
    while (sweeps < s_.max_sweeps) {
      ++sweeps;
      for (Index k : block) {
        const auto kk = std::size_t(k);
        const double d = diagonal_[kk] >= 0 ? jacobian_[std::size_t(diagonal_[kk])] : 0.0;
        double next;
        if (d > 0.0)
          next = change_[kk] - omega * linearized(k) / d;
        else if (projected)
          next = -u[kk];  // no flow through the node's faces (closed film): no pressure
        else
          continue;
        change_[kk] = projected ? std::max(next, -u[kk]) : next;
      }
      if (norm() <= target) break;
    }
    for (Index k : block) u[std::size_t(k)] += change_[std::size_t(k)];
    return sweeps;
  }

  // The heat field's matrix M (sweep()) on its own pattern, for the direct solve: the
  // temperature rows' entries in temperature columns, each mapped to its place there.
  void build_heat_matrix() {
    std::vector<Index> local(role_.size(), -1);
    for (std::size_t i = 0; i < blocks_.temperature.size(); ++i) local[std::size_t(blocks_.temperature[i])] = Index(i);
    SparsePattern p;
    p.rows = p.cols = Index(blocks_.temperature.size());
    p.row_start.push_back(0);
    for (Index k : blocks_.temperature) {
      for (Index e = pattern_.row_start[std::size_t(k)]; e < pattern_.row_start[std::size_t(k) + 1]; ++e) {
        const Index j = local[std::size_t(pattern_.column[std::size_t(e)])];
        if (j < 0) continue;
        p.column.push_back(j);
        heat_entries_.push_back(e);
      }
      p.row_start.push_back(p.nnz());
    }
    heat_pattern_ = std::move(p);
    heat_lu_ = std::make_unique<SparseLu>(heat_pattern_);
  }

  // M·δ = −F_T by KLU, M as the sweeps use it (the heat sources' positive couplings lagged).
  void solve_heat(std::vector<double>& u) {
    std::vector<double> values(heat_entries_.size());
    for (std::size_t e = 0; e < heat_entries_.size(); ++e) {
      const auto global = std::size_t(heat_entries_[e]);
      const double coupling = jacobian_[global];
      const bool diagonal = diagonal_[std::size_t(pattern_.column[global])] == heat_entries_[e];
      values[e] = coupling <= 0.0 || diagonal ? coupling : 0.0;
    }
    if (!heat_lu_->refactor(values)) throw std::runtime_error("the heat conduction matrix is singular");
    std::vector<double> delta(blocks_.temperature.size());
    for (std::size_t i = 0; i < delta.size(); ++i) delta[i] = -residual_[std::size_t(blocks_.temperature[i])];
    heat_lu_->solve(delta);
    for (std::size_t i = 0; i < delta.size(); ++i) u[std::size_t(blocks_.temperature[i])] += delta[i];
  }

  // The balance rows' Jacobian in the rigid unknowns by eq. [38]: the centred five-point
  // difference, each point with its own converged coupled loop.
  bool differentiate(const std::vector<double>& u, Eigen::MatrixXd& jac) {
    const auto m = Eigen::Index(blocks_.rigid.size());
    jac.resize(m, m);
    const double dx = s_.difference_step;
    constexpr std::array<int, 4> offsets{2, 1, -1, -2};
    constexpr std::array<double, 4> weights{-1.0, 8.0, -8.0, 1.0};
    for (Eigen::Index i = 0; i < m; ++i) {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(m);
      for (std::size_t o = 0; o < offsets.size(); ++o) {
        std::vector<double> at = u;
        at[std::size_t(blocks_.rigid[std::size_t(i)])] += offsets[o] * dx;
        if (!converge_fields(at)) return false;
        const std::vector<double> g = rigid_rows();
        for (Eigen::Index r = 0; r < m; ++r) column[r] += weights[o] * g[std::size_t(r)];
      }
      jac.col(i) = column / (12.0 * dx);
    }
    return true;
  }

  SegregatedSystem& system_;
  const PaperSchemeSettings& s_;
  PaperSchemeReport& rep_;
  SegregatedSystem::Blocks blocks_;
  const SparsePattern& pattern_;
  std::vector<double> residual_, jacobian_, change_;
  std::vector<Role> role_;
  std::vector<Index> diagonal_;
  double damping_ = 0.0;  // Levenberg–Marquardt's, relative to the normal matrix's diagonal
  SparsePattern heat_pattern_;
  std::vector<Index> heat_entries_;  // their places in the system's pattern
  std::unique_ptr<SparseLu> heat_lu_;
};

}  // namespace

PaperSchemeReport solve_by_paper_scheme(SegregatedSystem& system, std::vector<double>& u,
                                        const PaperSchemeSettings& settings) {
  if (Index(u.size()) != system.size()) throw InternalError("solve_by_paper_scheme: state has the wrong size");
  PaperSchemeReport report;
  const FlowBalanceRows flow_rows(system);
  PaperScheme(system, settings, report).solve(u);
  return report;
}

}  // namespace twb
