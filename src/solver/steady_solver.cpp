#include "twb/solver/steady_solver.h"

#include <chrono>
#include <algorithm>
#include <cmath>

namespace twb {

namespace {
double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

SteadySolver::SteadySolver(BearingModel& model, NewtonSettings settings)
    : model_(model), settings_(settings), newton_(model) {}

void SteadySolver::account(SteadyReport& rep, const NewtonReport& n) const {
  ++rep.newton_solves;
  rep.iterations += n.iterations;
  rep.jacobian_evaluations += n.jacobian_evaluations;
  rep.residual_evaluations += n.residual_evaluations;
  rep.residual_norm = n.residual_norm;
  if (!n.converged) rep.message = n.message;
}

double SteadySolver::residual_norm(const std::vector<double>& u) const {
  std::vector<double> r(u.size());
  model_.evaluate(u, r, {});
  return max_norm(r);
}

bool SteadySolver::reach(std::vector<double>& u, SteadyReport& rep) {
  std::vector<double> trial = u;
  const NewtonReport n = newton_.solve(trial, settings_);
  account(rep, n);
  if (n.converged) {
    u = trial;
    return true;
  }
  // Pseudo-transient continuation with switched evolution relaxation: Δτ grows as the
  // residual falls (Mulder & van Leer), shrinks when a pseudo-step fails.
  rep.strategy = "pseudo-transient";
  NewtonSettings inner = settings_;
  inner.max_iterations = 25;
  std::vector<double> state = u;
  double norm = residual_norm(state);
  if (!std::isfinite(norm)) return false;
  double dtau = 1e-2;
  for (int step = 0; step < 400; ++step) {
    PseudoTimeShift shift{1.0 / dtau, state};
    trial = state;
    const NewtonReport ns = newton_.solve(trial, inner, &shift);
    account(rep, ns);
    if (!ns.converged) {
      dtau *= 0.25;
      if (dtau < 1e-10) break;
      continue;
    }
    const double next = residual_norm(trial);
    state = trial;
    if (next <= settings_.residual_tolerance) {
      u = state;
      return true;
    }
    dtau *= std::clamp(norm / next, 0.5, 10.0);
    norm = next;
    if (dtau > 1e3) {
      trial = state;
      const NewtonReport nf = newton_.solve(trial, settings_);
      account(rep, nf);
      if (nf.converged) {
        u = trial;
        return true;
      }
    }
  }
  rep.message = "pseudo-transient continuation did not reach a steady state: " + rep.message;
  return false;
}

SteadyReport SteadySolver::solve(std::vector<double>& u) {
  const auto t0 = std::chrono::steady_clock::now();
  SteadyReport rep;
  rep.strategy = "newton";
  std::vector<double> trial = u;
  if (reach(trial, rep)) {
    u = trial;
    rep.converged = true;
    rep.message.clear();
  } else {
    rep = ramp(u, rep);
  }
  rep.wall_ms = elapsed_ms(t0);
  return rep;
}

SteadyReport SteadySolver::solve_cold(std::vector<double>& u) {
  u = model_.cold_start();
  return solve(u);
}

SteadyReport SteadySolver::ramp(std::vector<double>& u, SteadyReport rep) {
  rep.strategy = "load ramp";
  const double target = model_.load();
  // Find a fraction of the load that Newton reaches from the cold start.
  std::vector<double> state;
  double reached = 0.0;
  for (double fraction = 0.5; fraction >= 1.0 / 64.0; fraction *= 0.5) {
    model_.set_load(target * fraction);
    state = model_.cold_start();
    if (reach(state, rep)) {
      reached = target * fraction;
      break;
    }
  }
  if (reached == 0.0) {
    model_.set_load(target);
    rep.message = "no fraction of the load down to 1/64 converges from the cold start: " + rep.message;
    return rep;
  }
  // Walk up, warm-starting each step; halve the step on failure.
  double step = reached;
  while (reached < target) {
    const double next = std::min(target, reached + step);
    model_.set_load(next);
    std::vector<double> trial = state;
    if (reach(trial, rep)) {
      state = trial;
      reached = next;
      step *= 1.5;
    } else {
      step *= 0.5;
      if (step < 1e-4 * target) {
        model_.set_load(target);
        rep.message = "load ramp stalled at " + std::to_string(reached) + " N: " + rep.message;
        return rep;
      }
    }
  }
  model_.set_load(target);
  u = state;
  rep.converged = true;
  rep.message.clear();
  return rep;
}

}  // namespace twb
