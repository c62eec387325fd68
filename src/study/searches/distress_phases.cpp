// The distress search's run and its phases 2-7 (distress_phases.h).
#include "study/searches/distress_phases.h"

#include <algorithm>

#include <fmt/format.h>

#include "study/searches/load_step_march.h"
#include "study/study_support.h"
#include "solver/runaway.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

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

NewtonSettings in_basin(NewtonSettings newton) {
  newton.max_iterations = 12;
  newton.line_search = false;
  return newton;
}

// Only the first turning point: the step whose tangent turns back in load has passed
// the fold and located it, and the rest of the S is not needed (nor is the middle
// branch below the fold: a bound 2 % below the start stops a continuation that turns
// without a located fold).
ArclengthReport round_the_fold(BearingModel& model, std::span<const double> state, double load, double load_end,
                               const NewtonSettings& newton, BranchStates* cool_side) {
  ArclengthSettings arc;
  arc.newton = newton;
  arc.newton.max_iterations = 12;
  arc.parameter_scale = load;
  arc.initial_step = 0.002;
  arc.max_step = 0.05;
  arc.lambda_min = 0.98 * load;
  arc.lambda_max = load_end;
  arc.max_points = 200;
  return continue_by_arclength(model, state, load, arc, [&](const BranchPoint& p) {
    const bool turned = !p.tangent.empty() && p.tangent.back() < 0.0;
    if (cool_side && !turned && p.index > 0) cool_side->emplace_back(p.lambda, std::vector<double>(p.u.begin(), p.u.end()));
    return !turned;
  });
}

DistressSearchPhases::DistressSearchPhases(BearingModel& model, const DistressSearchSettings& settings,
                                           const SearchProgress& progress, BranchStates& cool, BranchStates& approach)
    : model_(model),
      settings_(settings),
      progress_(progress),
      started_(std::chrono::steady_clock::now()),
      newton_(newton_settings(model.scene())),
      detector_(distress_detector(model.scene(), settings.bracket_width)),
      cool_(cool),
      approach_(approach) {
  out_.row.speed = model.speed();
  out_.searched_to = searched_to_ = settings.load_end;
  const std::vector<double> capacity = model.capacities();
  dynamics_ = std::any_of(capacity.begin(), capacity.end(), [](double c) { return c > 0.0; });
  transient_ = dynamics_ && !settings.fold_only;
  // Through the requested grid, and never more than 15 % of the load at once, since a
  // longer step can land on the hot branch beyond a fold before the jump shows.
  std::vector<double> stops = settings.grid;
  std::erase_if(stops, [&](double w) { return w <= settings.load_start || w > settings.load_end; });
  if (stops.empty() || stops.back() < settings.load_end) stops.push_back(settings.load_end);
  double at = settings.load_start;
  if (!(at > 0.0)) throw InternalError("DistressSearchPhases: the search must start at a positive load");
  for (double stop : stops) {
    while (at * 1.15 < stop) targets_.push_back(at *= 1.15);
    targets_.push_back(at = stop);
  }
  natural_.newton = in_basin(newton_);
  // Natural continuation only has to bring the branch near its end: the fold is located
  // by arclength. Creeping closer than a bracket width costs slow corrections (the
  // Jacobian turns singular).
  natural_.min_step = settings.bracket_width * settings.load_start;
}

void DistressSearchPhases::say(const std::string& line) const {
  if (progress_) progress_(fmt::format("{} [{:.1f} s]", line, elapsed_ms(started_) / 1000.0));
}

void DistressSearchPhases::keep(double load, std::span<const double> v, long iterations, double wall_ms) {
  model_.set_load(load);
  out_.states.push_back(record(model_, v, iterations, wall_ms));
  if (settings_.keep_state_vectors) out_.state_vectors.emplace_back(v.begin(), v.end());
}

DistressSearch DistressSearchPhases::run(std::vector<double> u, const SteadyReport& first) {
  keep(settings_.load_start, u, first.iterations, first.wall_ms);
  low_ = settings_.load_start;
  low_state_ = u;
  bound_past_failure(0);  // the start itself may be past a criterion
  cool_ = {{low_, low_state_}};
  approach_.clear();

  const CoolBranchEnd end = continue_cool_branch();
  out_.cool_states = out_.states.size();
  if (end == CoolBranchEnd::load_end) {
    report_no_distress();
    return std::move(out_);
  }
  if (end == CoolBranchEnd::bounded) {
    out_.row.verdict = DistressVerdict::bounded;
    out_.row.method = fmt::format("no fold up to {:.6g} N (not searched further: {:g} times the first failure at "
                                  "{:.6g} N, study.search_past_failure)",
                                  searched_to_, settings_.search_past_failure, first_failure_.value_or(0.0));
    return std::move(out_);
  }
  if (!transient_) {
    report_steady_fold();
    return std::move(out_);
  }
  if (!locate_and_prove_fold(end, u)) return std::move(out_);
  // (past distress u is the state at the bracket's upper end, where the march went)
  if (settings_.continue_past_distress) sweep_hot_branch(std::move(u), out_.row.bracket_high.value());
  return std::move(out_);
}

void DistressSearchPhases::report_no_distress() {
  const double load_end = settings_.load_end;
  if (!transient_) {
    out_.row.verdict = DistressVerdict::no_heating;
    out_.row.method = fmt::format("no fold up to {:.6g} N (no thermal effect: no thermo-viscous distress)", load_end);
  } else if (model_.scene().lubricant.viscosity_model == ViscosityModel::constant) {
    out_.row.verdict = DistressVerdict::no_heating;
    out_.row.method = fmt::format("no fold up to {:.6g} N (the oil's viscosity does not depend on temperature: no "
                                  "thermo-viscous distress)",
                                  load_end);
  } else {
    const double steepest = steepest_sensitivity(out_.states);
    out_.row.verdict = DistressVerdict::gradual_heating;
    out_.row.method = fmt::format("no fold up to {:.6g} N (gradual heating); steepest rise of T_mean at {:.6g} N",
                                  load_end, steepest);
  }
}

void DistressSearchPhases::report_steady_fold() {
  const ArclengthReport around =
      around_fold_ ? *around_fold_ : round_the_fold(model_, low_state_, low_, settings_.load_end, newton_);
  if (!around.folds.empty()) {
    out_.row.fold_load = around.folds.front().lambda;
    out_.fold = around.folds.front();
  }
  if (settings_.fold_only) {
    out_.row.verdict = DistressVerdict::fold_only;
    out_.row.method = out_.row.fold_load ? "fold only" : "no fold located: " + around.message;
    return;
  }
  out_.row.verdict = DistressVerdict::steady_fold;
  out_.row.method = out_.row.fold_load
                        ? fmt::format("no thermal effect, so no transient to bracket W_d: the steady branch folds at "
                                      "{:.6g} N",
                                      *out_.row.fold_load)
                        : "no thermal effect, so no transient to bracket W_d; the steady branch ends near " +
                              fmt::format("{:.6g} N without a located fold: {}", low_, around.message);
}

bool DistressSearchPhases::locate_and_prove_fold(CoolBranchEnd end, std::vector<double>& u) {
  const bool ran_away = end == CoolBranchEnd::runaway;
  try {
    // The fold first: pseudo-arclength continuation round the branch's end locates it
    // (minimally augmented Newton); two transients then prove it.
    std::optional<FoldPoint> fold;
    FoldProof proof;
    std::string disagreement;
    if (!ran_away) {
      if (!around_fold_) {
        say(fmt::format("  locating the fold by arclength continuation from {:.2f} N", low_));
        around_fold_ = round_the_fold(model_, low_state_, low_, settings_.load_end, newton_, &approach_);
      }
      const ArclengthReport& around = *around_fold_;
      if (!around.folds.empty()) {
        fold = around.folds.front();
        out_.row.fold_load = fold->lambda;
        proof = prove_fold(model_, cool_, approach_, fold->lambda, detector_, settings_.march_past_distress,
                           out_.counts, [this](const std::string& s) { say(s); });
        if (!proof.bracket.valid) disagreement = proof.bracket.message;
      }
    }
    if (!proof.bracket.valid && !bisect(ran_away, proof, fold, disagreement)) return false;

    const Bracket& bracket = proof.bracket;
    out_.fold = fold;
    out_.bracket_state = bracket.low_state;
    out_.row.bracket_low = bracket.low;
    out_.row.bracket_high = bracket.high;
    if (fold && disagreement.empty()) {
      // The bracket is centred on the fold: W_d is the fold, proven to the bracket's width.
      out_.fold_proven = !ran_away;
      out_.row.distress_load = fold->lambda;
      out_.row.verdict = DistressVerdict::fold_proven;
      out_.row.method = fmt::format("runaway; fold at {:.6g} N ({}), proven by transients: the step to {:.6g} N "
                                    "settles, to {:.6g} N runs away",
                                    fold->lambda, to_string(fold->method), bracket.low, bracket.high);
    } else {
      out_.row.distress_load = bracket.critical_estimate();
      out_.row.verdict = DistressVerdict::bisection;
      if (fold) {
        const double gap = (*out_.row.distress_load - fold->lambda) / fold->lambda;
        out_.row.method = fmt::format("runaway bracketed by bisection; fold at {:.6g} N ({}), {:+.2f} % from W_d ({})",
                                      fold->lambda, to_string(fold->method), -100.0 * gap, disagreement);
      } else {
        out_.row.method = "runaway bracketed by bisection; " + disagreement;
      }
    }
    say(fmt::format("  distress between {:.2f} and {:.2f} N", bracket.low, bracket.high));
    return march_past(proof, u);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    // A singular Jacobian under the detector or the march, at the fold itself: what
    // was found so far stays, and the row says why the search stopped.
    if (!out_.row.distress_load) out_.row.method = std::string("distress search stopped: ") + e.what();
    out_.message = std::string("distress search stopped: ") + e.what();
    return false;
  }
}

// No fold in range, a runaway continuation did not expect, or dynamics that disagree
// with the fold. From the last cool state, find a step that runs away (in increments
// of 1 %, or 4 bracket widths), then bisect.
bool DistressSearchPhases::bisect(bool ran_away, FoldProof& proof, std::optional<FoldPoint>& fold,
                                  std::string& disagreement) {
  say(fmt::format("  bisecting by transients from {:.2f} N", low_));
  const double widen = std::max(4.0 * settings_.bracket_width, 0.01);
  double high = ran_away ? runaway_load_ : std::min(low_ * (1.0 + widen), settings_.load_end);
  for (int attempt = 0; !ran_away && attempt < 400 && low_ < settings_.load_end; ++attempt) {
    const StepOutcome step = classify_step(model_, low_state_, low_, high, detector_);
    out_.counts.add(step);
    if (!step.settled()) break;
    low_ = high;
    low_state_ = step.final_state;
    keep(low_, low_state_, step.newton_attempts, 0.0);
    cool_.emplace_back(low_, low_state_);
    ++out_.cool_states;
    say(fmt::format("  the step to {:.2f} N settles", low_));
    high = std::min(low_ * (1.0 + widen), settings_.load_end);
  }
  if (!ran_away && low_ >= settings_.load_end) {
    out_.row.verdict = DistressVerdict::settled;
    out_.row.method =
        fmt::format("no distress up to {:.6g} N: every load step settled on the branch", settings_.load_end);
    return false;
  }
  Bracket& bracket = proof.bracket;
  bracket = bracket_critical(model_, low_, low_state_, high, detector_, [&](const BracketStep& step) {
    say(fmt::format("  the step to {:.2f} N {}", step.parameter,
                    step.verdict == StepVerdict::settled ? "settles" : "runs away"));
  });
  out_.counts.transients += long(bracket.steps.size());
  out_.counts.ida_steps += bracket.ida_steps;
  out_.counts.ida_factorizations += bracket.ida_factorizations;
  if (!bracket.valid) {
    out_.row.verdict = DistressVerdict::no_bracket;
    out_.row.method = "no distress bracket: " + bracket.message;
    out_.message = out_.row.method;
    return false;
  }
  if (!fold) {
    const ArclengthReport around = round_the_fold(model_, bracket.low_state, bracket.low, settings_.load_end, newton_);
    if (!around.folds.empty()) {
      fold = around.folds.front();
      out_.row.fold_load = fold->lambda;
    } else {
      disagreement = "no fold: " + around.message;
    }
  }
  return true;
}

// Past W_d: the first runaway step marched to where it goes, its trajectory kept (after
// a proof, on from where the step above the fold was judged a runaway).
bool DistressSearchPhases::march_past(FoldProof& proof, std::vector<double>& u) {
  const RunawaySettings& runaway = detector_;
  const Bracket& bracket = proof.bracket;
  StepMarch hot;
  if (!proof.runaway_state.empty() && !settings_.march_past_distress) {
    // W_d and its proof only (the proof kept no trajectory: nothing marches on).
    out_.runaway = std::move(proof.runaway);
    return false;
  }
  if (!proof.runaway_state.empty()) {
    hot = march_load_step(model_, proof.runaway_state, bracket.high, bracket.high, runaway.transient, runaway.newton, 0.0,
                          proof.runaway_time);
    out_.runaway = std::move(proof.runaway);
    // (the march's first sample is the proof's last; a march that could not start has none)
    if (hot.trajectory.size() > 1) out_.runaway.insert(out_.runaway.end(), hot.trajectory.begin() + 1, hot.trajectory.end());
  } else {
    hot = march_load_step(model_, bracket.low_state, bracket.low, bracket.high, runaway.transient, runaway.newton);
    out_.runaway = std::move(hot.trajectory);
  }
  say(fmt::format("  the step to {:.2f} N: {}", bracket.high, hot.message));
  if (!hot.settled) {
    out_.message = "past distress: " + hot.message;
    return false;
  }
  keep(bracket.high, hot.state, hot.newton_iterations, hot.wall_ms);
  u = hot.state;
  return true;
}

// Load sweep: the hot branch on to load_end, from the state the runaway reached.
void DistressSearchPhases::sweep_hot_branch(std::vector<double> u, double load) {
  auto t0 = std::chrono::steady_clock::now();
  for (double target : targets_) {
    if (target <= load) continue;
    natural_.initial_step = natural_.max_step = target - load;
    const NaturalReport rep = continue_in_parameter(model_, u, load, target, natural_, [&](const BranchPoint& p) {
      if (p.index == 0) return true;
      keep(p.lambda, p.u, p.corrector_iterations, elapsed_ms(t0));
      t0 = std::chrono::steady_clock::now();
      say(fmt::format("  {}: {:.1f} N past distress ({:.2f} C mean)",
                      speed_text(model_.speed(), model_.scene().study.speeds_in_rpm), p.lambda,
                      out_.states.back().state.washer_mean_temperature - 273.15));
      return true;
    });
    if (!rep.reached_target) {
      out_.message = fmt::format("past distress the branch was lost at {:.6g} N: {}", rep.lambda, rep.message);
      break;
    }
    load = rep.lambda;
  }
}

}  // namespace twb
