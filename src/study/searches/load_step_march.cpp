#include "study/searches/load_step_march.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "solver/kinsol_newton.h"
#include "solver/relaxation_time.h"
#include "study/searches/steady_solver.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// The horizon when no duration is given, in slowest relaxation times at the start: the
// runaway passes through a slow ghost, then the hot branch relaxes on its own (slower,
// contact-softened) time scale; 500 covers both on the paper's case, and the march
// stops as soon as it has settled anyway.
constexpr double horizon_multiple = 500.0;
// Newton is tried once the steady residual has fallen below this fraction of the
// largest it reached (and is falling): near a stable steady state the residual decays
// geometrically, so the trajectory is then well inside Newton's basin.
constexpr double settle_fraction = 1e-3;

}  // namespace

StepMarch march_load_step(BearingModel& model, std::span<const double> start_state, double start_load,
                          double new_load, const TransientSettings& settings, const NewtonSettings& newton,
                          double duration, double start_time) {
  const auto t0 = std::chrono::steady_clock::now();
  const ParameterScope at_start(model, start_load);
  StepMarch out;
  // The horizon's time scale, needed only when no duration is given. Near a fold the
  // Jacobian can be singular: then the march is bounded by a generous fixed span.
  double tau = 0.0;
  if (!(duration > 0)) {
    try {
      tau = slowest_relaxation_time(model, start_state, 20);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception&) {
      tau = 0.0;
    }
    if (!(tau > 0) || !std::isfinite(tau)) tau = 10.0;  // s: several times the carrier's own ρ c t²/K
  }
  const double old_load = start_load;
  model.set_load(new_load);
  IdaTransient ida(model, settings);
  const double horizon = start_time + (duration > 0 ? duration : horizon_multiple * tau);
  TransientStatus status = ida.start(start_time, start_state);
  // The consistent start solves the film and the rigid body at the new load with the
  // temperatures of the old state (IDACalcIC); from the old load's film a large step can
  // lie outside its Newton's reach. Those algebraic equations have a solution at every
  // load between (the film carries any load at given temperatures, docs/physics.md section
  // 8), so the load is walked there in 2, 4, ... 64 equal pieces, each consistent start
  // from the last, the temperatures held.
  for (int pieces = 2; !status.ok && pieces <= 64; pieces *= 2) {
    std::vector<double> u(start_state.begin(), start_state.end());
    for (int k = 1; k <= pieces; ++k) {
      model.set_load(old_load + (new_load - old_load) * double(k) / double(pieces));
      status = ida.start(start_time, u);
      if (!status.ok) break;
      u.assign(ida.state().begin(), ida.state().end());
    }
  }
  model.set_load(new_load);
  std::vector<double> r(start_state.size());
  auto sample = [&](double t, std::span<const double> u) {
    TrajectorySample& sample = out.trajectory.emplace_back();
    sample.time = t;
    sample.state = model.describe(u);
  };
  // IDA's counters restart with it: banked before each restart and at the end.
  auto bank = [&] {
    const TransientStatistics s = ida.statistics();
    out.ida_steps += s.steps;
    out.ida_factorizations += s.linear_setups;
  };
  auto finish = [&](std::string message) {
    bank();
    const std::span<const double> u = ida.state();
    out.state.assign(u.begin(), u.end());
    out.time = ida.time();
    out.message = std::move(message);
    out.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (!status.ok) {
    out.state.assign(start_state.begin(), start_state.end());
    out.message = "no consistent start after the load step: " + status.flag_name + " " + status.message;
    return out;
  }
  out.started = true;
  sample(start_time, ida.state());

  KinsolNewton polish(model);
  // Where IDA cannot go on, the film's mechanical equilibrium has typically lost its
  // branch under the rising temperatures (the collapse itself, an impasse of the DAE):
  // the steady solver's pseudo-transient continuation, in which every unknown relaxes,
  // carries the state on from the last point integrated to where it lands. From there
  // only: the steady solver's ramps from the cold start would reach a state that owes
  // nothing to the trajectory (and on a fed, oil-cooled washer past its fold took two
  // minutes to fail).
  auto land = [&](std::string why) {
    finish(std::move(why));
    if (duration > 0) return out;
    std::vector<double> u = out.state;
    SteadySolver steady(model, newton);
    const SteadyReport rep = steady.solve_near(u);
    out.newton_iterations += rep.iterations;
    if (rep.converged) {
      out.state = u;
      out.settled = true;
      out.message += fmt::format("; from there the steady solver ({}) reached a steady state, which need not be "
                                 "where the trajectory was heading",
                                 rep.strategy);
    } else {
      out.message += "; from there the steady solver found no steady state either: " + rep.message;
    }
    out.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  double largest = 0.0, previous = INFINITY;
  int restarts = 0;
  while (ida.time() < horizon) {
    status = ida.step(horizon);
    if (!status.ok && restarts < 3) {
      // A kink of the model (contact or cavitation switching on) rather than a
      // collapse: fresh consistent values there usually carry the march on.
      ++restarts;
      const std::vector<double> here(ida.state().begin(), ida.state().end());
      bank();
      if (ida.start(ida.time(), here).ok) continue;
    }
    if (!status.ok)
      return land(fmt::format("IDA could not go on at t = {:.4g} s ({}, {} restarts)", ida.time(), status.flag_name,
                              restarts));
    const std::span<const double> u = ida.state();
    sample(ida.time(), u);
    model.evaluate(u, r, {});
    const double rate = max_norm(r);
    largest = std::max(largest, rate);
    const bool slowing = rate < previous;
    previous = rate;
    if (duration > 0 || !slowing || rate > settle_fraction * largest) continue;
    std::vector<double> trial(u.begin(), u.end());
    const NewtonReport rep = polish.solve(trial, newton);
    out.newton_iterations += rep.iterations;
    // Only a steady state next to the trajectory is where it is going (as in the runaway
    // detector): no closer than the way the trajectory has come from the start.
    const double gap = ida.differential_distance(trial, u);
    const double travel = ida.differential_distance(u, start_state);
    if (rep.converged && gap <= std::max(travel, 1.0)) {
      finish(fmt::format("settled at t = {:.4g} s", ida.time()));
      out.state = trial;
      out.settled = true;
      return out;
    }
    largest = rate;  // try again after a further fall by the same fraction
  }
  if (duration > 0) {
    model.evaluate(ida.state(), r, {});
    out.settled = max_norm(r) <= newton.residual_tolerance;
    return finish(fmt::format("marched to t = {:.4g} s", ida.time()));
  }
  return land(fmt::format("not settled within the horizon t = {:.4g} s ({} slowest relaxation times)", horizon,
                          horizon_multiple));
}

}  // namespace twb
