#include "study/distress_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "fold_approach.h"
#include "failure_load.h"
#include "fold_proof.h"
#include "load_step_march.h"
#include "study_support.h"
#include "solver/arclength_continuation.h"
#include "solver/linear_stability.h"
#include "solver/natural_continuation.h"
#include "solver/runaway.h"
#include "solver/steady_solver.h"
#include "twb/error_family.h"

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

// The corrector of a natural continuation along the cool branch, whose predictions lie
// in Newton's quadratic basin: a few full steps converge, and a failure (a step that
// outran the branch) is cut short, without a line search, and the step halved.
NewtonSettings in_basin(NewtonSettings newton) {
  newton.max_iterations = 12;
  newton.line_search = false;
  return newton;
}

// The light load a start is checked against: a tenth of it. On the paper's bearing the
// cool branch is the only one a tenth of the distress load (the hot branch turns back
// well above that), and the branch down there costs a handful of continuation steps.
constexpr double light_load_fraction = 0.1;

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
// first turning point only: the step whose tangent turns back in load has passed the
// fold and located it, and the rest of the S is not needed (nor is the middle branch
// below the fold: a bound 2 % below the start stops a continuation that turns without
// a located fold). cool_side, if given, receives the states it passes before the turn.
ArclengthReport round_the_fold(BearingModel& model, std::span<const double> state, double load, double load_end,
                               const NewtonSettings& newton, BranchStates* cool_side = nullptr) {
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
  return continue_by_arclength(model, state, arc, [&](const BranchPoint& p) {
    const bool turned = !p.tangent.empty() && p.tangent.back() < 0.0;
    if (cool_side && !turned && p.index > 0) cool_side->emplace_back(p.lambda, std::vector<double>(p.u.begin(), p.u.end()));
    return !turned;
  });
}

}  // namespace

RunawaySettings distress_detector(const Scene& scene, double bracket_width) {
  RunawaySettings r;
  // The scene's tolerances, the detector's own bound on the settle test's iterations.
  const int settle_iterations = r.newton.max_iterations;
  r.newton = newton_settings(scene);
  r.newton.max_iterations = std::min(r.newton.max_iterations, settle_iterations);
  r.relative_width = bracket_width;
  // An integration error δ acts on the slow drift near the fold like a shift of the load
  // by a relative O(δ) (ida_transient.h). The proof's steps lie half a bracket width
  // from the fold, and a bisection stops at a bracket width: a relative tolerance of a
  // two-hundredth of the width keeps that shift 100 times below the nearest step (1e-5
  // at the default 0.2 %; IDA takes ~115 steps per W_d instead of ~183 at 1e-6, for the
  // same brackets), and never below what double precision resolves over a transient.
  r.transient.relative_tolerance = std::max(1e-10, bracket_width / 200.0);
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

namespace {

// The search from a steady state `u` at settings.load_start, on the cool branch. The
// branch's states are left in `cool` (continued in load) and `approach` (by arclength,
// before the fold), for the failure criteria.
DistressSearch search_from(BearingModel& model, const DistressSearchSettings& settings, std::vector<double> u,
                           const SteadyReport& first, const SearchProgress& progress, BranchStates& cool,
                           BranchStates& approach_states) {
  DistressSearch out;
  out.row.speed = model.speed();
  const NewtonSettings newton = newton_settings(model.scene());
  const auto started = std::chrono::steady_clock::now();
  auto say = [&](const std::string& s) {
    if (progress) progress(fmt::format("{} [{:.1f} s]", s, elapsed_ms(started) / 1000.0));
  };
  // Each state recorded as solved, its unknowns kept where every state gets an error bar.
  auto keep = [&](std::span<const double> v, long iterations, double wall_ms) {
    out.states.push_back(record(model, v, iterations, wall_ms));
    if (settings.keep_state_vectors) out.state_vectors.emplace_back(v.begin(), v.end());
  };
  model.set_load(settings.load_start);
  keep(u, first.iterations, first.wall_ms);

  // Without the thermal effect nothing has a heat capacity: there is no transient to
  // check states or bracket W_d with (thermo-viscous distress needs heat), and only the
  // steady branch and its fold remain.
  const std::vector<double> capacity = model.capacities();
  const bool dynamics = std::any_of(capacity.begin(), capacity.end(), [](double c) { return c > 0.0; });
  // Only the fold (a mesh refined for the error estimate): the steady branch alone.
  const bool transient = dynamics && !settings.fold_only;

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
  natural.newton = in_basin(newton);
  // Natural continuation only has to bring the branch near its end: the fold is located
  // by arclength. Creeping closer than a bracket width costs slow corrections (the
  // Jacobian turns singular).
  natural.min_step = settings.bracket_width * settings.load_start;

  // Every state continuation accepts is judged by its linear stability, with the
  // corrector's own factors (linear_stability.h). A stable verdict cannot tell a jump to
  // the hot branch (stable too): that is natural continuation's own test, which rejects
  // a corrected state farther from the tangent's prediction than half the predicted
  // change (a jump moves tens of kelvins where a cool step predicts a few), and near the
  // fold, where the prediction grows, arclength continuation has taken over. Only where
  // the stability test is not conclusive does the transient decide: the load step from
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
    Stability stability;
    std::string why;
  };
  std::vector<double> low_state = u;
  double low = settings.load_start;
  // The cool branch's states (load, state), to start the proof of a fold from.
  cool = {{low, low_state}};
  approach_states.clear();
  bool branch_ended = false, ran_away = false, near_fold = false;
  double runaway_load = 0.0;
  FoldApproach approach;
  NaturalContinuation cool_branch(model);
  std::optional<ArclengthReport> around_fold;  // the arclength round the fold, once run (its states
                                               // before the turn: approach_states)
  for (std::size_t t = 0; t < targets.size() && !ran_away && !branch_ended;) {
    std::vector<Pending> pending;
    near_fold = false;
    // A segment that would cross the fold the slowest mode foresees costs rejected
    // corrections: stop short of it, at 70 % of the way there (the estimate lies beyond
    // the fold, and once within 3 % of it arclength continuation takes over).
    double target = targets[t];
    const double foreseen = approach.fold_estimate();
    if (std::isfinite(foreseen) && foreseen > low)
      target = std::min(target, low + 0.7 * (foreseen - low));
    bool replan = false;
    natural.initial_step = natural.max_step = std::max(target - low, natural.min_step);
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> x = low_state;
    model.set_load(low);
    const NaturalReport rep = cool_branch.continue_to(x, target, natural, [&](const BranchPoint& p) {
      if (p.index > 0) {
        Pending& q = pending.emplace_back(
            Pending{{p.u.begin(), p.u.end()}, p.lambda, p.corrector_iterations, 0.0, Stability::inconclusive, {}});
        if (dynamics && p.factors) {
          const StabilityReport st = linear_stability(model, *p.factors, settings.stability);
          ++out.counts.stability_tests;
          q.stability = st.verdict;
          q.why = st.reason;
          if (st.verdict == Stability::stable) approach.add(p.lambda, st.modes.front().real());
        }
        q.wall_ms = elapsed_ms(t0);
        // Near the fold natural continuation only creeps (its Jacobian turns singular):
        // arclength continuation takes over once the fold is near.
        if (approach.near(p.lambda)) {
          near_fold = true;
          return false;
        }
        // A fold foreseen short of this segment's end: plan the segment again (above).
        const double ahead = approach.fold_estimate();
        if (std::isfinite(ahead) && ahead < target) {
          replan = true;
          return false;
        }
      }
      t0 = std::chrono::steady_clock::now();
      return true;
    });
    bool replaced = false;
    for (Pending& p : pending) {
      if (transient && p.stability != Stability::stable) {
        say(fmt::format("  {:.2f} N: linear stability {} ({}); the transient decides", p.load,
                        to_string(p.stability), p.why));
        model.set_load(low);
        StepOutcome step;
        try {
          step = classify_step(model, low_state, p.load, runaway);
        } catch (const InternalError&) {
          throw;  // a bug: no fallback may hide it
        } catch (const std::exception& e) {
          // Near a fold the Jacobian may turn singular under the detector's relaxation
          // estimate: the branch ends here, and the bracket below takes over.
          branch_ended = true;
          say(fmt::format("  the step {:.2f} -> {:.2f} N could not be judged: {}", low, p.load, e.what()));
          break;
        }
        out.counts.add(step);
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
      }
      low = p.load;
      low_state = p.u;
      cool.emplace_back(low, low_state);
      model.set_load(low);
      keep(low_state, p.iterations, p.wall_ms);
      const double done = (low - settings.load_start) / (settings.load_end - settings.load_start);
      say(fmt::format("  {:.6g} rad/s: {:.2f} N on the cool branch ({:.2f} C mean; {:.0f} % of the load range)",
                      model.speed(), low, out.states.back().state.washer_mean_temperature - 273.15, 100 * done));
      if (replaced) break;
    }
    // The states after a replaced one were never accepted: their slow modes must not feed
    // the fold estimate.
    if (replaced) approach.forget();
    if (ran_away || replaced || branch_ended) continue;
    if (near_fold) {
      say(fmt::format("  the slowest thermal mode says a fold is near {:.2f} N; arclength continuation from "
                      "{:.2f} N",
                      approach.fold_estimate(), low));
      // The estimate lies beyond a fold it sees coming (μ² bends away from its chord): a
      // branch that climbs 10 % past it without turning has no fold there.
      approach_states.clear();
      around_fold = round_the_fold(model, low_state, low,
                                   std::min(settings.load_end, 1.1 * std::max(approach.fold_estimate(), low)), newton,
                                   &approach_states);
      if (!around_fold->folds.empty()) {
        branch_ended = true;
        break;
      }
      // Near a cusp the slowest mode slows without a fold (steep, gradual heating): the
      // estimate is no longer trusted, and natural continuation goes on as without it.
      say("  no fold there: the branch only steepens; natural continuation goes on");
      out.diagnostics.push_back("arclength found no fold: " + around_fold->message);
      around_fold.reset();
      approach_states.clear();
      approach.disable();
      near_fold = false;
      continue;
    }
    if (replan) continue;
    if (!rep.reached_target) {
      branch_ended = true;
      say(fmt::format("  the cool branch ends near {:.2f} N", low));
      out.diagnostics.push_back(rep.message);
      break;
    }
    if (target == targets[t]) ++t;
  }
  out.cool_states = out.states.size();

  if (!ran_away && !branch_ended && !transient) {
    out.row.verdict = DistressVerdict::no_heating;
    out.row.method = fmt::format("no fold up to {:.6g} N (no thermal effect: no thermo-viscous distress)",
                                 settings.load_end);
    return out;
  }
  if (!ran_away && !branch_ended && model.scene().lubricant.viscosity_model == ViscosityModel::constant) {
    out.row.verdict = DistressVerdict::no_heating;
    out.row.method = fmt::format("no fold up to {:.6g} N (the oil's viscosity does not depend on temperature: no "
                                 "thermo-viscous distress)",
                                 settings.load_end);
    return out;
  }
  if (!ran_away && !branch_ended) {
    const double steepest = steepest_sensitivity(out.states);
    out.row.verdict = DistressVerdict::gradual_heating;
    out.row.method = fmt::format("no fold up to {:.6g} N (gradual heating); steepest rise of T_mean at {:.6g} N",
                                 settings.load_end, steepest);
    return out;
  }

  if (!transient) {
    // The steady branch's end only: locate its fold.
    const ArclengthReport around =
        around_fold ? *around_fold : round_the_fold(model, low_state, low, settings.load_end, newton);
    if (!around.folds.empty()) {
      out.row.fold_load = around.folds.front().lambda;
      out.fold = around.folds.front();
    }
    if (settings.fold_only) {
      out.row.verdict = DistressVerdict::fold_only;
      out.row.method = out.row.fold_load ? "fold only" : "no fold located: " + around.message;
      return out;
    }
    out.row.verdict = DistressVerdict::steady_fold;
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
  try {
    // The fold first: pseudo-arclength continuation round the branch's end locates it
    // (minimally augmented Newton); two transients then prove it.
    std::optional<FoldPoint> fold;
    FoldProof proof;
    Bracket& bracket = proof.bracket;
    std::string disagreement;
    if (!ran_away) {
      if (!around_fold) {
        say(fmt::format("  locating the fold by arclength continuation from {:.2f} N", low));
        around_fold = round_the_fold(model, low_state, low, settings.load_end, newton, &approach_states);
      }
      const ArclengthReport& around = *around_fold;
      if (!around.folds.empty()) {
        fold = around.folds.front();
        out.row.fold_load = fold->lambda;
        proof = prove_fold(model, cool, approach_states, fold->lambda, runaway, settings.march_past_distress,
                           out.counts, say);
        if (!bracket.valid) disagreement = bracket.message;
      }
    }

    if (!bracket.valid) {
      // Bisection by transients: no fold in range, a runaway continuation did not
      // expect, or dynamics that disagree with the fold. From the last cool state, find
      // a step that runs away (in increments of 1 %, or 4 bracket widths), then bisect.
      say(fmt::format("  bisecting by transients from {:.2f} N", low));
      const double widen = std::max(4.0 * settings.bracket_width, 0.01);
      double high = ran_away ? runaway_load : std::min(low * (1.0 + widen), settings.load_end);
      for (int attempt = 0; !ran_away && attempt < 400 && low < settings.load_end; ++attempt) {
        model.set_load(low);
        const StepOutcome step = classify_step(model, low_state, high, runaway);
        out.counts.add(step);
        if (!step.settled()) break;
        low = high;
        low_state = step.final_state;
        model.set_load(low);
        keep(low_state, step.newton_attempts, 0.0);
        cool.emplace_back(low, low_state);
        ++out.cool_states;
        say(fmt::format("  the step to {:.2f} N settles", low));
        high = std::min(low * (1.0 + widen), settings.load_end);
      }
      if (!ran_away && low >= settings.load_end) {
        out.row.verdict = DistressVerdict::settled;
        out.row.method = fmt::format("no distress up to {:.6g} N: every load step settled on the branch",
                                     settings.load_end);
        return out;
      }
      model.set_load(low);
      bracket = bracket_critical(model, low, low_state, high, runaway, [&](const BracketStep& step) {
        say(fmt::format("  the step to {:.2f} N {}", step.parameter,
                        step.verdict == StepVerdict::settled ? "settles" : "runs away"));
      });
      out.counts.transients += long(bracket.steps.size());
      out.counts.ida_steps += bracket.ida_steps;
      out.counts.ida_factorizations += bracket.ida_factorizations;
      if (!bracket.valid) {
        out.row.verdict = DistressVerdict::no_bracket;
        out.row.method = "no distress bracket: " + bracket.message;
        out.message = out.row.method;
        return out;
      }
      if (!fold) {
        const ArclengthReport around = round_the_fold(model, bracket.low_state, bracket.low, settings.load_end, newton);
        if (!around.folds.empty()) {
          fold = around.folds.front();
          out.row.fold_load = fold->lambda;
        } else {
          disagreement = "no fold: " + around.message;
        }
      }
    }
    out.fold = fold;
    out.bracket_state = bracket.low_state;
    out.row.bracket_low = bracket.low;
    out.row.bracket_high = bracket.high;
    if (fold && disagreement.empty()) {
      // The bracket is centred on the fold: W_d is the fold, proven to the bracket's width.
      out.fold_proven = !ran_away;
      out.row.distress_load = fold->lambda;
      out.row.verdict = DistressVerdict::fold_proven;
      out.row.method = fmt::format("runaway; fold at {:.6g} N ({}), proven by transients: the step to {:.6g} N "
                                   "settles, to {:.6g} N runs away",
                                   fold->lambda, to_string(fold->method), bracket.low, bracket.high);
    } else {
      out.row.distress_load = bracket.critical_estimate();
      out.row.verdict = DistressVerdict::bisection;
      if (fold) {
        const double gap = (*out.row.distress_load - fold->lambda) / fold->lambda;
        out.row.method = fmt::format("runaway bracketed by bisection; fold at {:.6g} N ({}), {:+.2f} % from W_d ({})",
                                     fold->lambda, to_string(fold->method), -100.0 * gap, disagreement);
      } else {
        out.row.method = "runaway bracketed by bisection; " + disagreement;
      }
    }
    say(fmt::format("  distress between {:.2f} and {:.2f} N", bracket.low, bracket.high));

    // Past W_d: march the first runaway step to where it goes and keep its trajectory
    // (after a proof, on from where the step above the fold was judged a runaway).
    const NewtonSettings settle = runaway.newton;
    StepMarch hot;
    if (!proof.runaway_state.empty() && !settings.march_past_distress) {
      // W_d and its proof only (the proof kept no trajectory: nothing marches on).
      out.runaway = std::move(proof.runaway);
      return out;
    }
    if (!proof.runaway_state.empty()) {
      model.set_load(bracket.high);
      hot = march_load_step(model, proof.runaway_state, bracket.high, runaway.transient, settle, 0.0,
                            proof.runaway_time);
      out.runaway = std::move(proof.runaway);
      // (the march's first sample is the proof's last; a march that could not start has none)
      if (hot.trajectory.size() > 1) out.runaway.insert(out.runaway.end(), hot.trajectory.begin() + 1, hot.trajectory.end());
    } else {
      model.set_load(bracket.low);
      hot = march_load_step(model, bracket.low_state, bracket.high, runaway.transient, settle);
      out.runaway = std::move(hot.trajectory);
    }
    say(fmt::format("  the step to {:.2f} N: {}", bracket.high, hot.message));
    if (!hot.settled) {
      out.message = "past distress: " + hot.message;
      return out;
    }
    keep(hot.state, hot.newton_iterations, hot.wall_ms);
    u = hot.state;
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
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
      keep(p.u, p.corrector_iterations, elapsed_ms(t0));
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

DistressSearch search_from_start(BearingModel& model, const DistressSearchSettings& settings,
                                 const SearchProgress& progress, BranchStates& cool, BranchStates& approach) {
  const NewtonSettings newton = newton_settings(model.scene());
  model.set_load(settings.load_start);
  std::vector<double> u;
  SteadySolver steady(model, newton);
  const SteadyReport first = steady.solve_cold(u);
  if (!first.converged) {
    DistressSearch out;
    out.row.speed = model.speed();
    out.failed = true;
    out.message = fmt::format("no steady state at the starting load {:.6g} N: {}", settings.load_start,
                              first.message);
    out.row.method = "no steady state at load_start";
    return out;
  }
  DistressSearch out = search_from(model, settings, u, first, progress, cool, approach);
  const std::vector<double> capacity = model.capacities();
  if (settings.fold_only || std::none_of(capacity.begin(), capacity.end(), [](double c) { return c > 0.0; }))
    return out;

  // Which branch the start lies on. The cold start finds some steady state, and past
  // distress that is a hot one. A branch continued up from the start through stable
  // states to a turning point the dynamics confirm (the step below settles, the step
  // above runs away) is the cool branch of the S: the hot branch turns back only at its
  // lower end, and a start on the unstable middle branch runs away at its first step.
  // Otherwise the start's branch is checked: the cool branch is the one that goes on down
  // to light loads, where the bearing has one steady state, so continued down to a tenth
  // of the start, the start's branch must get there without a turning point and land on
  // that light load's own cold start. If it does not, the search starts from the light load.
  if (out.fold_proven) return out;
  const double light = settings.load_start * light_load_fraction;
  if (progress) progress(fmt::format("  is the start on the cool branch? following it down to {:.3g} N", light));
  std::vector<double> down = u;
  NaturalSettings natural;
  natural.newton = in_basin(newton);
  natural.initial_step = natural.max_step = 0.15 * settings.load_start;
  natural.min_step = settings.bracket_width * light;
  model.set_load(settings.load_start);
  const NaturalReport descent = continue_in_parameter(model, down, light, natural);
  model.set_load(light);
  std::vector<double> light_state;
  const SteadyReport light_start = steady.solve_cold(light_state);
  if (descent.reached_target && light_start.converged && same_state(down, light_state)) return out;
  if (!light_start.converged) {
    // No reference to judge by: the search from the start as it is, and say so.
    out.row.method = fmt::format("the start's branch could not be checked (no steady state at {:.3g} N); {}", light,
                                 out.row.method);
    return out;
  }
  if (progress)
    progress(fmt::format("  the start at {:.6g} N is not on the cool branch ({}); searching from {:.3g} N",
                         settings.load_start,
                         descent.reached_target ? "it continues down to another state than the light load's"
                                                : "its branch turns back on the way down",
                         light));
  // The first search's work counts too.
  const SearchCounts spent = out.counts;
  DistressSearchSettings from_light = settings;
  from_light.load_start = light;
  out = search_from(model, from_light, light_state, light_start, progress, cool, approach);
  out.counts.add(spent);
  if (out.row.distress_load && *out.row.distress_load < settings.load_start) {
    out.start_past_distress = true;
    out.row.method = fmt::format("the start at {:.6g} N is already past distress (W_d ≈ {:.6g} N, continued from "
                                 "{:.3g} N): {}",
                                 settings.load_start, *out.row.distress_load, light, out.row.method);
  } else {
    // The start's branch did not lead down to the light load's state, yet the branch from
    // there has no distress below the start: say what was done, claim nothing more.
    out.row.method = fmt::format("the start at {:.6g} N did not continue down to the light load's state; searched "
                                 "from {:.3g} N instead: {}",
                                 settings.load_start, light, out.row.method);
  }
  return out;
}

}  // namespace

DistressSearch search_distress(BearingModel& model, const DistressSearchSettings& settings,
                               const SearchProgress& progress) {
  const SparseLu::Counts before = SparseLu::thread_counts();
  BranchStates cool, approach;
  DistressSearch out = search_from_start(model, settings, progress, cool, approach);
  if (!settings.fold_only && !out.failed) {
    // The branch from the start up to where it ends: the states continuation accepted,
    // those arclength passed before the turn, and the fold.
    BranchStates branch = std::move(cool);
    for (auto& state : approach)
      if (branch.empty() || state.first > branch.back().first) branch.push_back(std::move(state));
    if (out.fold && out.fold->u.size() >= std::size_t(model.size()) &&
        (branch.empty() || out.fold->lambda > branch.back().first))
      branch.emplace_back(out.fold->lambda, std::vector<double>(out.fold->u.begin(), out.fold->u.begin() +
                                                                   std::ptrdiff_t(model.size())));
    const double start = out.states.empty() ? settings.load_start : out.states.front().state.load;
    const auto t0 = std::chrono::steady_clock::now();
    long solves = 0;
    locate_failure(model, branch, {start, settings.load_end, settings.bracket_width}, out.row, solves,
                   &out.crossing_states);
    if (progress && out.row.failure_load)
      progress(fmt::format("  {:.6g} rad/s: {} [{} steady solves, {:.1f} s]", model.speed(), out.row.failure, solves,
                           elapsed_ms(t0) / 1000.0));
  }
  out.counts.klu_factorizations = SparseLu::thread_counts().factored_since(before) + out.counts.ida_factorizations;
  return out;
}

}  // namespace twb
