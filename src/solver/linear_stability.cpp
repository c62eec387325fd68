#include "solver/linear_stability.h"
#include "twb/error_family.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>

namespace twb {

const char* to_string(Stability s) {
  switch (s) {
    case Stability::stable: return "stable";
    case Stability::unstable: return "unstable";
    case Stability::inconclusive: return "inconclusive";
  }
  return "?";
}

double StabilityReport::growth_rate() const {
  double g = -std::numeric_limits<double>::infinity();
  for (const auto& m : modes) g = std::max(g, -m.real());
  return g;
}

namespace {

struct Ritz {
  std::complex<double> nu;  // eigenvalue of S⁻¹C_d: 1/μ
  double residual;
};

}  // namespace

StabilityReport linear_stability(const SteadySystem& system, const SparseLu& factors,
                                 const StabilitySettings& settings) {
  const auto n = std::size_t(system.size());
  const std::vector<double> capacity = system.capacities();
  std::vector<std::size_t> differential;
  for (std::size_t k = 0; k < n; ++k)
    if (capacity[k] > 0.0) differential.push_back(k);
  if (differential.empty()) throw InternalError("linear_stability: no unknown has a capacity");
  const auto nd = Eigen::Index(differential.size());
  const Eigen::Index m = std::min<Eigen::Index>(settings.krylov_dimension, nd);

  StabilityReport rep;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(nd, m + 1), hessenberg = Eigen::MatrixXd::Zero(m + 1, m);
  // A start with a share of every mode: the slowest mode of a heated body is one-signed,
  // and the deterministic ripple reaches the others (results must not depend on a seed).
  for (Eigen::Index k = 0; k < nd; ++k) basis(k, 0) = 1.0 + 0.5 * std::sin(1.7 * double(k) + 0.3);
  basis.col(0).normalize();
  std::vector<double> x(n);
  Eigen::Index size = m;
  for (Eigen::Index j = 0; j < m; ++j) {
    std::fill(x.begin(), x.end(), 0.0);
    for (Eigen::Index k = 0; k < nd; ++k) x[differential[std::size_t(k)]] = capacity[differential[std::size_t(k)]] * basis(k, j);
    factors.solve(x);
    ++rep.solves;
    Eigen::VectorXd w(nd);
    for (Eigen::Index k = 0; k < nd; ++k) w(k) = x[differential[std::size_t(k)]];
    if (!w.allFinite()) {
      rep.reason = "the solve with the Jacobian gave non-finite values (a singular Jacobian)";
      return rep;
    }
    const double start_norm = w.norm();
    // Gram–Schmidt twice: once is not enough to keep the basis orthogonal when the
    // slow modes dominate (Kahan's "twice is enough").
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index i = 0; i <= j; ++i) {
        const double h = basis.col(i).dot(w);
        hessenberg(i, j) += h;
        w -= h * basis.col(i);
      }
    const double h = w.norm();
    hessenberg(j + 1, j) = h;
    if (h <= 1e-14 * start_norm) {  // an invariant subspace: its Ritz values are exact
      size = j + 1;
      break;
    }
    basis.col(j + 1) = w / h;
  }

  const Eigen::MatrixXd small = hessenberg.topLeftCorner(size, size);
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(small);
  if (eigen.info() != Eigen::Success) {
    rep.reason = "the Hessenberg eigenproblem did not converge";
    return rep;
  }
  const double beta = size < m || size == nd ? 0.0 : hessenberg(size, size - 1);
  std::vector<Ritz> ritz;
  for (Eigen::Index i = 0; i < size; ++i) {
    const Eigen::VectorXcd y = eigen.eigenvectors().col(i).normalized();
    ritz.push_back({eigen.eigenvalues()(i), beta * std::abs(y(size - 1))});
  }
  std::sort(ritz.begin(), ritz.end(), [](const Ritz& a, const Ritz& b) { return std::abs(a.nu) > std::abs(b.nu); });
  const double dominant = std::abs(ritz.front().nu);
  if (!(dominant > 0.0) || !std::isfinite(dominant)) {
    rep.reason = "no slow mode found (the operator vanished)";
    return rep;
  }

  // Walk from the slowest mode down: every mode passed must be resolved and decided.
  // A mode's sign is decided when Re ν (same sign as Re μ) is clear of both the angle
  // margin and a hundred times its own residual (a Ritz value is within about its
  // residual of an eigenvalue for the nearly normal thermal operator).
  int decided = 0;
  for (const Ritz& r : ritz) {
    if (r.residual > settings.resolved * dominant) break;
    const double clear = std::max(settings.margin * std::abs(r.nu), 100.0 * r.residual);
    rep.modes.push_back(1.0 / r.nu);
    if (r.nu.real() < -clear) {
      rep.verdict = Stability::unstable;
      rep.reason = fmt::format("a mode grows at the rate {:.4g} (its relaxation rate's real part is negative)",
                               -rep.modes.back().real());
      return rep;
    }
    if (r.nu.real() <= clear) {
      rep.reason = fmt::format("the slow mode μ = {:.4g}{:+.4g}i lies within its error of the imaginary axis",
                               rep.modes.back().real(), rep.modes.back().imag());
      return rep;
    }
    ++decided;
  }
  if (decided >= std::min<int>(settings.required_modes, int(size))) {
    rep.verdict = Stability::stable;
    rep.reason = fmt::format("the {} slowest modes all decay (slowest relaxation rate {:.4g})", decided,
                             rep.modes.front().real());
  } else {
    rep.reason = fmt::format("only {} of the {} slowest modes resolved by {} Arnoldi steps", decided,
                             settings.required_modes, size);
  }
  return rep;
}

}  // namespace twb
