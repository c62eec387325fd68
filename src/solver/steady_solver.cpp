#include "twb/solver/steady_solver.h"

#include <chrono>
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

SteadyReport SteadySolver::solve(std::vector<double>& u) {
  const auto t0 = std::chrono::steady_clock::now();
  SteadyReport rep;
  rep.strategy = "newton";
  std::vector<double> trial = u;
  const NewtonReport n = newton_.solve(trial, settings_);
  account(rep, n);
  if (n.converged) {
    u = trial;
    rep.converged = true;
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
    const NewtonReport n = newton_.solve(state, settings_);
    account(rep, n);
    if (n.converged) {
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
    const NewtonReport n = newton_.solve(trial, settings_);
    account(rep, n);
    if (n.converged) {
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
