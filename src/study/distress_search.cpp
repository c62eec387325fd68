#include "twb/study/distress_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "load_step_march.h"
#include "study_support.h"
#include "twb/solver/arclength_continuation.h"
#include "twb/solver/natural_continuation.h"
#include "twb/solver/runaway.h"
#include "twb/solver/steady_solver.h"

namespace twb {

namespace {

SolvedState record(const BearingModel& model, std::span<const double> u, long iterations, double wall_ms) {
  SolvedState row = solved_state(model, u);
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

// Pseudo-arclength continuation from a state near the end of the cool branch round its
// first turning point only: once the branch has turned back 2 % below the start the
// fold has been passed (and located), and the rest of the S is not needed.
ArclengthReport round_the_fold(BearingModel& model, std::span<const double> state, double load, double load_end,
                               const NewtonSettings& newton) {
  ArclengthSettings arc;
  arc.newton = newton;
  arc.newton.max_iterations = 12;
  arc.parameter_scale = load;
  arc.initial_step = 0.002;
  arc.max_step = 0.05;
  arc.lambda_min = 0.98 * load;
  arc.lambda_max = load_end;
  arc.max_points = 200;
  model.set_load(load);
  return continue_by_arclength(model, state, arc);
}

}  // namespace

RunawaySettings distress_detector(const Scene& scene, double bracket_width) {
  RunawaySettings r;
  r.newton = newton_settings(scene);
  r.relative_width = bracket_width;
  NaturalSettings natural;
  natural.newton = r.newton;
  natural.newton.max_iterations = 12;
  // The branch continued from the start in quarters of the step (a single long step
  // could itself jump across the fold), down to a thousandth of it: past the fold it
  // stops, and reaches nothing.
  r.on_branch = [natural](SteadySystem& system, std::span<const double> start, double start_load,
                          std::span<const double> settled, double load) mutable {
    if (load <= start_load) return true;
    std::vector<double> x(start.begin(), start.end());
    system.set_parameter(start_load);
    natural.initial_step = natural.max_step = 0.25 * (load - start_load);
    natural.min_step = 1e-3 * (load - start_load);
    const NaturalReport rep = continue_in_parameter(system, x, load, natural);
    return rep.reached_target && same_state(x, settled);
  };
  return r;
}

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
  out.states.push_back(record(model, u, first.iterations, first.wall_ms));

  // Without the thermal effect nothing has a heat capacity: there is no transient to
  // check states or bracket W_d with (thermo-viscous distress needs heat), and only the
  // steady branch and its fold remain.
  const std::vector<double> capacity = model.capacities();
  const bool transient = std::any_of(capacity.begin(), capacity.end(), [](double c) { return c > 0.0; });

  // The cool branch by natural continuation (secant predictor), segment by segment:
  // through the requested grid, and never more than 15 % of the load at once, since a
  // longer step can land on the hot branch beyond a fold before the jump shows.
  std::vector<double> targets;
  {
    std::vector<double> stops = settings.grid;
    std::erase_if(stops, [&](double w) { return w <= settings.load_start || w > settings.load_end; });
    if (stops.empty() || stops.back() < settings.load_end) stops.push_back(settings.load_end);
    double at = settings.load_start;
    for (double stop : stops) {
      while (at * 1.15 < stop) targets.push_back(at *= 1.15);
      targets.push_back(at = stop);
    }
  }
  NaturalSettings natural;
  natural.newton = newton;
  natural.newton.max_iterations = 12;
  // Natural continuation only has to bring the branch near its end: the bracket and the
  // fold are found by transients and arclength. Creeping closer than a bracket width
  // costs slow corrections (the Jacobian turns singular) and slow transient checks.
  natural.min_step = settings.bracket_width * settings.load_start;

  // Every state continuation accepts is checked by the transient: the load step from
  // the previous state must settle, and on that state. Where it settles elsewhere the
  // corrector had jumped branches: the transient's state is the one the machine
  // reaches, and continuation restarts from it. The first step that runs away ends the
  // cool branch.
  // (The check against the continuation's own state replaces the detector's branch test here.)
  RunawaySettings runaway = distress_detector(model.scene(), settings.bracket_width);
  const auto branch_test = runaway.on_branch;
  runaway.on_branch = nullptr;
  struct Pending {
    std::vector<double> u;
    double load;
    long iterations;
    double wall_ms;
  };
  std::vector<double> low_state = u;
  double low = settings.load_start;
  bool branch_ended = false, ran_away = false;
  double runaway_load = 0.0;
  int checked = 0;
  for (std::size_t t = 0; t < targets.size() && !ran_away;) {
    std::vector<Pending> pending;
    natural.initial_step = natural.max_step = std::max(targets[t] - low, natural.min_step);
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> x = low_state;
    model.set_load(low);
    const NaturalReport rep = continue_in_parameter(model, x, targets[t], natural, [&](const BranchPoint& p) {
      if (p.index > 0) pending.push_back({{p.u.begin(), p.u.end()}, p.lambda, p.corrector_iterations, elapsed_ms(t0)});
      t0 = std::chrono::steady_clock::now();
      return true;
    });
    bool replaced = false;
    for (Pending& p : pending) {
      if (!transient) {
        low = p.load;
        low_state = p.u;
        model.set_load(low);
        out.states.push_back(record(model, low_state, p.iterations, p.wall_ms));
        continue;
      }
      model.set_load(low);
      StepOutcome step;
      try {
        step = classify_step(model, low_state, p.load, runaway);
      } catch (const std::exception& e) {
        // Near a fold the Jacobian may turn singular under the detector's relaxation
        // estimate: the branch ends here, and the bracket below takes over.
        branch_ended = true;
        say(fmt::format("  the step {:.2f} -> {:.2f} N could not be judged: {}", low, p.load, e.what()));
        break;
      }
      ++checked;
      if (!step.settled()) {
        ran_away = true;
        runaway_load = p.load;
        say(fmt::format("  the step {:.2f} -> {:.2f} N runs away: {}", low, p.load, step.reason));
        break;
      }
      replaced = !same_state(step.final_state, p.u);
      if (replaced) {
        // Either continuation jumped (the transient's state is the branch's) or the
        // step itself jumped to the hot branch without an acceleration the detector
        // saw: the branch test tells which.
        const bool reachable = branch_test(model, low_state, low, step.final_state, p.load);
        if (!reachable) {
          ran_away = true;
          runaway_load = p.load;
          say(fmt::format("  the step {:.2f} -> {:.2f} N settles off the branch: a runaway", low, p.load));
          break;
        }
        say(fmt::format("  at {:.2f} N continuation had jumped to another branch; the transient's state is kept",
                        p.load));
        p.u = step.final_state;
      }
      low = p.load;
      low_state = p.u;
      model.set_load(low);
      out.states.push_back(record(model, low_state, p.iterations, p.wall_ms));
      const double done = (low - settings.load_start) / (settings.load_end - settings.load_start);
      say(fmt::format("  {:.6g} rad/s: {:.2f} N on the cool branch ({:.2f} C mean; {:.0f} % of the load range, "
                      "about {:.0f} s left if no distress comes)",
                      model.speed(), low, out.states.back().state.washer_mean_temperature - 273.15, 100 * done,
                      elapsed_ms(started) / 1000.0 * (1.0 - done) / std::max(done, 1e-3)));
      if (replaced) break;
    }
    if (ran_away || replaced) continue;
    if (!rep.reached_target) {
      branch_ended = true;
      say(fmt::format("  the cool branch ends near {:.2f} N: {}", low, rep.message));
      break;
    }
    ++t;
  }
  say(fmt::format("  {} load steps checked by the transient", checked));
  out.cool_states = out.states.size();

  if (!ran_away && !branch_ended && !transient) {
    out.row.method = fmt::format("no fold up to {:.6g} N (no thermal effect: no thermo-viscous distress)",
                                 settings.load_end);
    return out;
  }
  if (!ran_away && !branch_ended) {
    const double steepest = steepest_sensitivity(out.states);
    out.row.method = fmt::format("no fold up to {:.6g} N (gradual heating); steepest rise of T_mean at {:.6g} N",
                                 settings.load_end, steepest);
    return out;
  }

  if (!transient) {
    // The steady branch's end only: locate its fold.
    const ArclengthReport around = round_the_fold(model, low_state, low, settings.load_end, newton);
    if (!around.folds.empty()) out.row.fold_load = around.folds.front().lambda;
    out.row.method = out.row.fold_load
                         ? fmt::format("no thermal effect, so no transient to bracket W_d: the steady branch folds at "
                                       "{:.6g} N",
                                       *out.row.fold_load)
                         : "no thermal effect, so no transient to bracket W_d; the steady branch ends near " +
                               fmt::format("{:.6g} N without a located fold: {}", low, around.message);
    return out;
  }

  // From here on a step that settles must also land on the cool branch.
  runaway = distress_detector(model.scene(), settings.bracket_width);

  // Bracket: from the last cool state, find a step that runs away, then bisect.
  // Past the end of natural continuation the step that runs away is searched in
  // increments of 1 % (or 4 bracket widths).
  const double widen = std::max(4.0 * settings.bracket_width, 0.01);
  double high = ran_away ? runaway_load : std::min(low * (1.0 + widen), settings.load_end);
  try {
    for (int attempt = 0; !ran_away && attempt < 400 && low < settings.load_end; ++attempt) {
      model.set_load(low);
      const StepOutcome step = classify_step(model, low_state, high, runaway);
      if (!step.settled()) break;
      low = high;
      low_state = step.final_state;
      model.set_load(low);
      out.states.push_back(record(model, low_state, step.newton_attempts, 0.0));
      ++out.cool_states;
      high = std::min(low * (1.0 + widen), settings.load_end);
    }
    if (!ran_away && low >= settings.load_end) {
      out.row.method = fmt::format("no distress up to {:.6g} N: every load step settled on the branch",
                                   settings.load_end);
      return out;
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
  const ArclengthReport around = round_the_fold(model, bracket.low_state, bracket.low, settings.load_end, newton);
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
  u = hot.state;
  } catch (const std::exception& e) {
    // A singular Jacobian under the detector or the march, at the fold itself: what
    // was found so far stays, and the row says why the search stopped.
    if (!out.row.distress_load) out.row.method = std::string("distress search stopped: ") + e.what();
    out.message = std::string("distress search stopped: ") + e.what();
    return out;
  }
  if (!settings.continue_past_distress) return out;

  // Load sweep: the hot branch on to load_end, from the state the runaway reached (u).
  auto t0 = std::chrono::steady_clock::now();
  for (double target : targets) {
    if (target <= model.load()) continue;
    natural.initial_step = natural.max_step = target - model.load();
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
