#include "solver/pseudo_transient.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/sparse_lu.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// Pseudo-time steps of u' = −F(u), each one linearly implicit Euler step
//   (J(u) + C/Δτ) δ = −F(u),   C = diag(weights),
// with one assembly per step: the residual at the new state decides whether the step
// is kept and sets the next Δτ, and its Jacobian serves the next step. Through KINSOL a
// step cost two assemblies and a residual (KINSOL evaluates at both ends of its step,
// and Δτ needs the unshifted residual it does not return).
//
// The matrices are factored by SparseLu::refactor in the Newton solver's own
// factorization (same pattern): analysed once per solver, not once per cold start,
// refactored with the last pivot sequence while that is safe.
class PseudoTimeStepper {
 public:
  PseudoTimeStepper(const SteadySystem& system, SparseLu& lu)
      : system_(system), pattern_(system.pattern()), lu_(lu), held_(system.held_in_pseudo_time()) {
    for (Index k = 0; k < pattern_.rows; ++k) {
      diagonal_.push_back(pattern_.find(k, k));
      if (diagonal_.back() < 0)
        throw InternalError(fmt::format("pseudo-time step on row {}, which has no diagonal entry", k));
    }
  }

  // F and ∂F/∂u at u, kept as the candidate; returns ‖F‖∞ (∞ if not finite).
  double assemble(const std::vector<double>& u) {
    candidate_.residual.resize(u.size());
    candidate_.jacobian.resize(std::size_t(pattern_.nnz()));
    system_.evaluate(u, candidate_.residual, candidate_.jacobian);
    return max_norm(candidate_.residual);
  }
  // The candidate becomes the state steps start from.
  void accept() { std::swap(state_, candidate_); }
  // |∂F_k/∂u_k| at the state, floored at 1e-8: each unknown's own relaxation rate; none
  // where the system holds the row at every step.
  std::vector<double> diagonal_weights() const {
    std::vector<double> w(diagonal_.size());
    for (std::size_t k = 0; k < w.size(); ++k) {
      const double d = std::abs(state_.jacobian[std::size_t(diagonal_[k])]);
      w[k] = !held_.empty() && held_[k] ? 0.0 : std::isfinite(d) && d > 1e-8 ? d : 1e-8;
    }
    return w;
  }
  // δ from the state with (J + diag(weight)/Δτ) δ = −F; false if the matrix is singular.
  bool step(const std::vector<double>& weight, double dtau, std::vector<double>& delta) {
    values_ = state_.jacobian;
    for (std::size_t k = 0; k < diagonal_.size(); ++k) values_[std::size_t(diagonal_[k])] += weight[k] / dtau;
    if (!lu_.refactor(values_)) return false;
    delta.resize(state_.residual.size());
    for (std::size_t k = 0; k < delta.size(); ++k) delta[k] = -state_.residual[k];
    lu_.solve(delta);
    return true;
  }

 private:
  struct Point {
    std::vector<double> residual, jacobian;
  };
  const SteadySystem& system_;
  const SparsePattern& pattern_;
  SparseLu& lu_;
  std::vector<Index> diagonal_;
  std::vector<char> held_;
  Point state_, candidate_;
  std::vector<double> values_;
};

}  // namespace

namespace {

void account(SteadyReport& rep, const NewtonReport& n) {
  ++rep.newton_solves;
  rep.iterations += n.iterations;
  rep.jacobian_evaluations += n.jacobian_evaluations;
  rep.residual_evaluations += n.residual_evaluations;
  rep.residual_norm = n.residual_norm;
  if (!n.converged) rep.message = n.message;
}

}  // namespace

bool PseudoTransient::newton(std::vector<double>& u, const NewtonSettings& s, SteadyReport& rep) const {
  // Newton's form only where Newton converges on its own; pseudo-time marches the
  // model's own rows, whose slopes do not jump between its steps.
  const NewtonForm form(system_);
  const NewtonReport n = newton_.solve(u, s);
  account(rep, n);
  return n.converged;
}

bool PseudoTransient::reach(std::vector<double>& u, SteadyReport& rep, bool newton_first) const {
  std::vector<double> trial = u;
  if (newton_first) {
    // Newton converges in a few steps from a neighbouring state (6 full steps for a 5 %
    // load step on the hot branch), so it gets a short budget (KINSOL's full steps,
    // then as many damped ones) before pseudo-time takes over.
    NewtonSettings quick = settings_;
    quick.max_iterations = std::min(settings_.max_iterations, 8);
    if (newton(trial, quick, rep)) {
      u = trial;
      return true;
    }
  }
  // Pseudo-transient continuation (Kelley & Keyes' ΨTC): one linearly implicit step of
  // u' = −F(u) per pseudo-time step, i.e. one Newton step on F(u) + (u − u_old)/Δτ,
  // with Δτ grown by switched evolution relaxation (Mulder & van Leer) as the residual
  // falls, and cut when a step leaves the domain. As Δτ → ∞ the steps become Newton's.
  rep.strategy = "pseudo-transient";
  // Pseudo-time marches the system's own rows even inside a caller's Newton form.
  const NewtonForm own_rows(system_, false);
  PseudoTimeStepper stepper(system_, newton_.factorization());
  // A step that shifts the washer or gear by more than a few σ leaves the region where
  // the contact law is nearly linear. Measured like KINSOL's step cap: ‖D δ‖₂ with D
  // the model's step weights. The cap and the first Δτ below are tuned together on the
  // paper's 36 cold starts (benchmarks/cold_start_survey, 9×66 mesh): with a first Δτ
  // of 0.1 and a 2σ cap the steps were 31 (median) and 1367 rad/s, 300 N needed the
  // speed ramp (332 iterations); a first Δτ of 3 with a 4σ cap gives 16, every state
  // by pseudo-time (the others in at most 21, 1367 rad/s, 300 N, just past that speed's
  // fold, in 85–157 depending on rounding), on the same states (to 2e-12). Every pair
  // within first Δτ 2…5 and cap 4…5σ reaches all 36 without a ramp (median 15.5–16);
  // with a 3σ cap a first Δτ of 2 or 3 sends two 300 N states to the ramp. On the 5×24
  // and 17×132 meshes: median 30 → 19.5 and 37.5 → 20 steps, ramps 2 → 0 and 3 → 0.
  const double max_step = std::min(settings_.max_step, 4.0);
  const std::vector<double> step_weight = system_.step_weights();
  std::vector<double> state = u, delta;
  double norm = stepper.assemble(state);
  ++rep.residual_evaluations;
  if (!std::isfinite(norm)) return false;
  stepper.accept();
  // With diagonal weights Δτ is in units of each unknown's own relaxation time: the
  // first step relaxes the cold state most of the way (the cap above bounds it).
  double dtau = 3.0;
  std::vector<double> weight;
  // Successful runs take at most ~150 steps on the paper's 36 cold starts; the ones
  // that fail stagnate, and 250 leaves a margin before the ramps take over.
  for (int step = 0; step < 250; ++step) {
    if (step % 20 == 0) weight = stepper.diagonal_weights();
    ++rep.iterations;
    if (!stepper.step(weight, dtau, delta)) {
      dtau *= 0.1;
      if (dtau < 1e-12) break;
      continue;
    }
    double scaled = 0.0;
    for (std::size_t k = 0; k < delta.size(); ++k) scaled += std::pow(step_weight[k] * delta[k], 2);
    const double shrink = std::sqrt(scaled) > max_step ? max_step / std::sqrt(scaled) : 1.0;
    trial = state;
    for (std::size_t k = 0; k < delta.size(); ++k) trial[k] += shrink * delta[k];
    const double next = stepper.assemble(trial);
    ++rep.residual_evaluations;
    ++rep.jacobian_evaluations;
    if (!std::isfinite(next) || next > 1e3 * norm) {
      dtau *= 0.1;
      if (dtau < 1e-12) break;
      continue;
    }
    stepper.accept();
    state = trial;
    rep.residual_norm = next;
    if (next <= settings_.residual_tolerance) {
      u = state;
      return true;
    }
    // Grow at least geometrically while the residual does not rise: SER alone stalls
    // when the residual falls slowly through a long transient. Hold Δτ while it rises
    // (the heating transient raises the thermal rows' residual over several steps): SER
    // would shrink Δτ by the rise and then need as many steps to grow it back. Only a
    // rejected step (above) cuts Δτ. On the 36 paper cold starts this halves the steps.
    const double ratio = norm / next;
    if (ratio >= 1.0) dtau *= std::clamp(ratio, 1.2, 10.0);
    norm = next;
    if (dtau > 1e4 && norm < 1e-4) {
      // Close enough for Newton's quadratic convergence to take over.
      trial = state;
      if (newton(trial, settings_, rep)) {
        u = trial;
        return true;
      }
      dtau = 1e2;
    }
  }
  rep.message = "pseudo-transient continuation did not reach a steady state: " + rep.message;
  return false;
}

}  // namespace twb
