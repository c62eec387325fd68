#include "twb/study/distress_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "load_step_march.h"
#include "twb/solver/arclength_continuation.h"
#include "twb/solver/natural_continuation.h"
#include "twb/solver/runaway.h"
#include "twb/solver/steady_solver.h"

namespace twb {

namespace {

double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

NewtonSettings newton_settings(const Scene& s) {
  NewtonSettings n;
  n.residual_tolerance = s.solver.residual_tolerance;
  n.step_tolerance = s.solver.step_tolerance;
  n.max_iterations = s.solver.max_iterations;
  return n;
}

SolvedState record(const BearingModel& model, std::span<const double> u, long iterations, double wall_ms) {
  SolvedState row;
  row.state = model.describe(u);
  row.converged = true;
  row.iterations = iterations;
  std::vector<double> r(u.size());
  model.evaluate(u, r, {});
  row.residual = max_norm(r);
  row.wall_ms = wall_ms;
  return row;
}

// Two Newton-converged states of the same branch at the same load agree to about the
// residual tolerance times the Jacobian's conditioning (≲ 1e-7 in the scaled unknowns:
// σ, K); states of different branches differ by whole kelvins and σ. 1e-4 separates
// them with orders of magnitude on either side.
bool same_state(std::span<const double> a, std::span<const double> b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d <= 1e-4;
}

// Gradual heating (no fold): the load where the mean washer temperature rises fastest,
// by centred differences over the branch's states.
double steepest_sensitivity(const std::vector<SolvedState>& states) {
  double best = states.empty() ? 0.0 : states.front().state.load, slope = -1.0;
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {
    const BearingState &a = states[k - 1].state, &b = states[k + 1].state;
    const double s = (b.washer_mean_temperature - a.washer_mean_temperature) / (b.load - a.load);
    if (s > slope) {
      slope = s;
      best = states[k].state.load;
    }
  }
  return best;
}

}  // namespace

DistressSearch search_distress(BearingModel& model, const DistressSearchSettings& settings,
                               const SearchProgress& progress) {
  DistressSearch out;
  out.row.speed = model.speed();
  const NewtonSettings newton = newton_settings(model.scene());
  const auto started = std::chrono::steady_clock::now();
  auto say = [&](const std::string& s) {
    if (progress) progress(fmt::format("{} [{:.1f} s]", s, elapsed_ms(started) / 1000.0));
  };

  // The light load from the paper's cold start.
  auto t0 = std::chrono::steady_clock::now();
  model.set_load(settings.load_start);
  std::vector<double> u;
  SteadySolver steady(model, newton);
  const SteadyReport first = steady.solve_cold(u);
  if (!first.converged) {
    out.failed = true;
    out.message = fmt::format("no steady state at the starting load {:.6g} N: {}", settings.load_start,
                              first.message);
    out.row.method = "no steady state at load_start";
    return out;
  }
  std::vector<std::vector<double>> branch{u};
  out.states.push_back(record(model, u, first.iterations, first.wall_ms));

  // The cool branch by natural continuation with a secant predictor, through the grid.
  NaturalSettings natural;
  natural.newton = newton;
  natural.newton.max_iterations = 12;
  const double span = settings.load_end - settings.load_start;
  natural.initial_step = span / 20.0;
  natural.max_step = span / 8.0;
  // Natural continuation only has to bring the branch near its end: the bracket and the
  // fold are found by transients and arclength. Creeping closer than a bracket width
  // costs slow corrections (the Jacobian turns singular) and slow transient checks.
  natural.min_step = settings.bracket_width * settings.load_start;
  std::vector<double> targets = settings.grid;
  std::erase_if(targets, [&](double w) { return w <= settings.load_start; });
  if (targets.empty() || targets.back() < settings.load_end) targets.push_back(settings.load_end);
  bool branch_ended = false;
  t0 = std::chrono::steady_clock::now();
  for (double target : targets) {
    natural.max_step = std::min(span / 8.0, std::max(target - model.load(), 1e-9));
    const NaturalReport rep = continue_in_parameter(model, u, target, natural, [&](const BranchPoint& p) {
      if (p.index == 0) return true;
      branch.emplace_back(p.u.begin(), p.u.end());
      out.states.push_back(record(model, p.u, p.corrector_iterations, elapsed_ms(t0)));
      t0 = std::chrono::steady_clock::now();
      say(fmt::format("  {:.6g} rad/s: {:.1f} N on the cool branch ({:.2f} C mean)", model.speed(), p.lambda,
                      out.states.back().state.washer_mean_temperature - 273.15));
      return true;
    });
    if (!rep.reached_target) {
      branch_ended = true;
      say(fmt::format("  the cool branch ends near {:.1f} N: {}", rep.lambda, rep.message));
      break;
    }
  }

  // Every accepted state checked by the transient: the load step from the previous
  // state must settle on it. The first step that runs away (or settles elsewhere) ends
  // the cool branch.
  RunawaySettings runaway;
  runaway.newton = newton;
  runaway.relative_width = settings.bracket_width;
  std::size_t last_cool = branch.size() - 1;
  bool ran_away = false;
  double runaway_load = 0.0;
  for (std::size_t k = 0; k + 1 < branch.size(); ++k) {
    model.set_load(out.states[k].state.load);
    const double next = out.states[k + 1].state.load;
    const StepOutcome step = classify_step(model, branch[k], next, runaway);
    if (!step.settled() || !same_state(step.final_state, branch[k + 1])) {
      last_cool = k;
      ran_away = true;
      runaway_load = next;
      say(fmt::format("  the step {:.1f} -> {:.1f} N does not settle on the branch: {}", out.states[k].state.load,
                      next, step.reason));
      break;
    }
  }
  say(fmt::format("  {} load steps checked by the transient", last_cool + (ran_away ? 1 : 0)));
  out.states.resize(last_cool + 1);
  branch.resize(last_cool + 1);
  out.cool_states = out.states.size();

  if (!ran_away && !branch_ended) {
    out.row.distress_load = steepest_sensitivity(out.states);
    out.row.method = fmt::format("no fold: steepest sensitivity (no distress up to {:.6g} N)", settings.load_end);
    return out;
  }

  // Bracket: from the last cool state, find a step that runs away, then bisect.
  double low = out.states.back().state.load;
  std::vector<double> low_state = branch.back();
  // Past the end of natural continuation the step that runs away is searched in
  // increments of 1 % (or 4 bracket widths).
  const double widen = std::max(4.0 * settings.bracket_width, 0.01);
  double high = ran_away ? runaway_load : low * (1.0 + widen);
  for (int attempt = 0; !ran_away && attempt < 40 && high <= settings.load_end * (1.0 + widen); ++attempt) {
    model.set_load(low);
    const StepOutcome step = classify_step(model, low_state, high, runaway);
    if (!step.settled()) break;
    low = high;
    low_state = step.final_state;
    high = low * (1.0 + widen);
  }
  model.set_load(low);
  const Bracket bracket = bracket_critical(model, low, low_state, high, runaway);
  if (!bracket.valid) {
    out.row.method = "no distress bracket: " + bracket.message;
    out.message = out.row.method;
    return out;
  }
  out.bracket_state = bracket.low_state;
  out.row.bracket_low = bracket.low;
  out.row.bracket_high = bracket.high;
  out.row.distress_load = bracket.critical_estimate();
  say(fmt::format("  distress between {:.2f} and {:.2f} N", bracket.low, bracket.high));

  // The fold of the steady branch, by pseudo-arclength continuation round it.
  ArclengthSettings arc;
  arc.newton = newton;
  arc.newton.max_iterations = 12;
  arc.parameter_scale = bracket.low;
  arc.initial_step = 0.002;
  arc.max_step = 0.05;
  // Round the first turning point only: once the branch has turned back 2 % below the
  // bracket the fold has been passed (and located), and the rest of the S is not needed.
  arc.lambda_min = 0.98 * bracket.low;
  arc.lambda_max = settings.load_end;
  arc.max_points = 200;
  model.set_load(bracket.low);
  const ArclengthReport around = continue_by_arclength(model, bracket.low_state, arc);
  say(fmt::format("  arclength continuation: {} states, {} folds", around.accepted, around.folds.size()));
  if (!around.folds.empty()) {
    const FoldPoint& fold = around.folds.front();
    out.row.fold_load = fold.lambda;
    const double gap = (*out.row.distress_load - fold.lambda) / fold.lambda;
    out.row.method = fmt::format("runaway; fold at {:.6g} N ({}), {:+.2f} % from W_d", fold.lambda,
                                 to_string(fold.method), -100.0 * gap);
  } else {
    out.row.method = "runaway; no fold: " + around.message;
  }

  // Past W_d: march the first runaway step to where it goes and keep its trajectory.
  model.set_load(bracket.low);
  StepMarch hot = march_load_step(model, bracket.low_state, bracket.high, runaway.transient, newton);
  out.runaway = std::move(hot.trajectory);
  say(fmt::format("  the step to {:.2f} N: {}", bracket.high, hot.message));
  if (!hot.settled) {
    out.message = "past distress: " + hot.message;
    return out;
  }
  out.states.push_back(record(model, hot.state, hot.newton_iterations, hot.wall_ms));
  if (!settings.continue_past_distress) return out;

  // Load sweep: the hot branch on to load_end.
  u = hot.state;
  t0 = std::chrono::steady_clock::now();
  for (double target : targets) {
    if (target <= model.load()) continue;
    const NaturalReport rep = continue_in_parameter(model, u, target, natural, [&](const BranchPoint& p) {
      if (p.index == 0) return true;
      out.states.push_back(record(model, p.u, p.corrector_iterations, elapsed_ms(t0)));
      t0 = std::chrono::steady_clock::now();
      say(fmt::format("  {:.6g} rad/s: {:.1f} N past distress ({:.2f} C mean)", model.speed(), p.lambda,
                      out.states.back().state.washer_mean_temperature - 273.15));
      return true;
    });
    if (!rep.reached_target) {
      out.message = fmt::format("past distress the branch was lost at {:.6g} N: {}", rep.lambda, rep.message);
      break;
    }
  }
  return out;
}

}  // namespace twb
