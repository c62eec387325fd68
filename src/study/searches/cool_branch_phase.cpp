// Phase 1 of the distress search (distress_phases.h): the cool branch by natural
// continuation (secant predictor), segment by segment.
//
// Every state continuation accepts is judged by its linear stability, with the
// corrector's own factors (linear_stability.h). A stable verdict cannot tell a jump to
// the hot branch (stable too): that is natural continuation's own test, which rejects a
// corrected state farther from the tangent's prediction than half the predicted change
// (a jump moves tens of kelvins where a cool step predicts a few), and near the fold,
// where the prediction grows, arclength continuation has taken over. Only where the
// stability test is not conclusive does the transient decide: the load step from the
// previous state must settle, and on that state. Where it settles elsewhere the
// corrector had jumped branches: the transient's state is the one the machine reaches,
// and continuation restarts from it. The first step that runs away ends the cool branch.
#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "study/searches/fold_approach.h"
#include "model/failure_margins.h"
#include "study/searches/distress_phases.h"
#include "study/study_support.h"
#include "solver/linear_stability.h"
#include "solver/runaway.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

namespace twb {

namespace {

// A state natural continuation accepted, waiting for its verdict.
struct Pending {
  std::vector<double> u;
  double load;
  long iterations;
  double wall_ms;
  Stability stability;
  std::string why;
};

// Why a segment of natural continuation stopped before its target.
enum class SegmentStop {
  none,       // at its target, or where continuation itself stopped (its report says)
  near_fold,  // the slowest mode says the fold is near: arclength takes over
  replan,     // a fold foreseen short of the target: plan the segment again
};

// What the transients said of a segment's states.
enum class Acceptance {
  all,       // every state is on the cool branch
  replaced,  // continuation had jumped: the transient's state replaced one, the rest dropped
  runaway,   // a step between two states ran away (or settled off the branch)
  unjudged,  // a step could not be judged (a singular Jacobian near the fold)
};

}  // namespace

DistressSearchPhases::CoolBranchEnd DistressSearchPhases::continue_cool_branch() {
  // (The check against the continuation's own state replaces the detector's branch test here.)
  RunawaySettings runaway = detector_;
  const auto branch_test = runaway.on_branch;
  runaway.on_branch = nullptr;
  FoldApproach approach;
  NaturalContinuation cool_branch(model_);

  for (std::size_t t = 0; t < targets_.size();) {
    if (first_failure_ && low_ >= searched_to_)
      return searched_to_ < settings_.load_end ? CoolBranchEnd::bounded : CoolBranchEnd::load_end;
    // A segment that would cross the fold the slowest mode foresees costs rejected
    // corrections: stop short of it, at 70 % of the way there (the estimate lies beyond
    // the fold, and once within 3 % of it arclength continuation takes over).
    double target = targets_[t];
    const double foreseen = approach.fold_estimate();
    if (std::isfinite(foreseen) && foreseen > low_) target = std::min(target, low_ + 0.7 * (foreseen - low_));
    natural_.initial_step = natural_.max_step = std::max(target - low_, natural_.min_step);

    std::vector<Pending> pending;
    SegmentStop stop = SegmentStop::none;
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> x = low_state_;
    const NaturalReport rep = cool_branch.continue_to(x, low_, target, natural_, [&](const BranchPoint& p) {
      if (p.index > 0) {
        Pending& q = pending.emplace_back(
            Pending{{p.u.begin(), p.u.end()}, p.lambda, p.corrector_iterations, 0.0, Stability::inconclusive, {}});
        if (dynamics_ && p.factors) {
          const StabilityReport st = linear_stability(model_, *p.factors, settings_.stability);
          ++out_.counts.stability_tests;
          q.stability = st.verdict;
          q.why = st.reason;
          if (st.verdict == Stability::stable) approach.add(p.lambda, st.modes.front().real());
        }
        q.wall_ms = elapsed_ms(t0);
        // Near the fold natural continuation only creeps (its Jacobian turns singular):
        // arclength continuation takes over once the fold is near.
        if (approach.near(p.lambda)) {
          stop = SegmentStop::near_fold;
          return false;
        }
        const double ahead = approach.fold_estimate();
        if (std::isfinite(ahead) && ahead < target) {
          stop = SegmentStop::replan;
          return false;
        }
      }
      t0 = std::chrono::steady_clock::now();
      return true;
    });

    // The segment's states in order: each inconclusive one judged by the load step to
    // it from the last accepted state.
    Acceptance acceptance = Acceptance::all;
    for (Pending& p : pending) {
      // A bound set by an earlier state of this segment: the states beyond it are not
      // searched (the next segment ends at the bound).
      if (searched_to_ < settings_.load_end && p.load > searched_to_) break;
      bool replaced = false;
      if (transient_ && p.stability != Stability::stable) {
        say(fmt::format("  {:.2f} N: linear stability {} ({}); the transient decides", p.load,
                        to_string(p.stability), p.why));
        StepOutcome step;
        try {
          step = classify_step(model_, low_state_, low_, p.load, runaway);
        } catch (const InternalError&) {
          throw;  // a bug: no fallback may hide it
        } catch (const std::exception& e) {
          // Near a fold the Jacobian may turn singular under the detector's relaxation
          // estimate: the branch ends here, and the bracket below takes over.
          acceptance = Acceptance::unjudged;
          say(fmt::format("  the step {:.2f} -> {:.2f} N could not be judged: {}", low_, p.load, e.what()));
          break;
        }
        out_.counts.add(step);
        if (!step.settled()) {
          acceptance = Acceptance::runaway;
          runaway_load_ = p.load;
          say(fmt::format("  the step {:.2f} -> {:.2f} N runs away: {}", low_, p.load, step.reason));
          break;
        }
        replaced = !same_state(step.final_state, p.u);
        if (replaced) {
          // Either continuation jumped (the transient's state is the branch's) or the
          // step itself jumped to the hot branch without an acceleration the detector
          // saw: the branch test tells which.
          if (!branch_test(model_, low_state_, low_, step.final_state, p.load)) {
            acceptance = Acceptance::runaway;
            runaway_load_ = p.load;
            say(fmt::format("  the step {:.2f} -> {:.2f} N settles off the branch: a runaway", low_, p.load));
            break;
          }
          say(fmt::format("  at {:.2f} N continuation had jumped to another branch; the transient's state is kept",
                          p.load));
          p.u = step.final_state;
        }
      }
      low_ = p.load;
      low_state_ = p.u;
      cool_.emplace_back(low_, low_state_);
      keep(low_, low_state_, p.iterations, p.wall_ms);
      bound_past_failure(t);
      const double done = (low_ - settings_.load_start) / (searched_to_ - settings_.load_start);
      say(fmt::format("  {}: {:.2f} N on the cool branch ({:.2f} C mean; {:.0f} % of the load range)",
                      speed_text(model_.speed(), model_.scene().study.speeds_in_rpm), low_, out_.states.back().state.washer_mean_temperature - 273.15, 100 * done));
      if (replaced) {
        acceptance = Acceptance::replaced;
        break;
      }
    }
    switch (acceptance) {
      case Acceptance::runaway: return CoolBranchEnd::runaway;
      case Acceptance::unjudged: return CoolBranchEnd::ended;
      case Acceptance::replaced:
        // The states after a replaced one were never accepted: their slow modes must
        // not feed the fold estimate.
        approach.forget();
        continue;
      case Acceptance::all: break;
    }
    if (stop == SegmentStop::near_fold) {
      say(fmt::format("  the slowest thermal mode says a fold is near {:.2f} N; arclength continuation from "
                      "{:.2f} N",
                      approach.fold_estimate(), low_));
      // The estimate lies beyond a fold it sees coming (μ² bends away from its chord): a
      // branch that climbs 10 % past it without turning has no fold there.
      approach_.clear();
      around_fold_ = round_the_fold(model_, low_state_, low_,
                                    std::min(settings_.load_end, 1.1 * std::max(approach.fold_estimate(), low_)),
                                    newton_, &approach_);
      if (!around_fold_->folds.empty()) return CoolBranchEnd::ended;
      // Near a cusp the slowest mode slows without a fold (steep, gradual heating): the
      // estimate is no longer trusted, and natural continuation goes on as without it.
      say("  no fold there: the branch only steepens; natural continuation goes on");
      out_.diagnostics.push_back("arclength found no fold: " + around_fold_->message);
      around_fold_.reset();
      approach_.clear();
      approach.disable();
      continue;
    }
    if (stop == SegmentStop::replan) continue;
    if (!rep.reached_target) {
      say(fmt::format("  the cool branch ends near {:.2f} N", low_));
      out_.diagnostics.push_back(rep.message);
      return CoolBranchEnd::ended;
    }
    if (t < targets_.size() && target == targets_[t]) ++t;
  }
  return searched_to_ < settings_.load_end ? CoolBranchEnd::bounded : CoolBranchEnd::load_end;
}

void DistressSearchPhases::bound_past_failure(std::size_t t) {
  if (!(settings_.search_past_failure > 0.0) || first_failure_) return;
  const LimitValues values = LimitValues::of(out_.states.back().state, model_.scene().effects.thermal);
  const std::optional<LimitKind> past = FailureMargins(values, OperatingLimits::of(model_.scene())).first_past();
  if (!past) return;
  first_failure_ = low_;
  const double bound = settings_.search_past_failure * low_;
  if (bound >= settings_.load_end) return;
  out_.searched_to = searched_to_ = bound;
  targets_.erase(std::remove_if(targets_.begin() + std::ptrdiff_t(t), targets_.end(), [&](double w) { return w > bound; }),
                 targets_.end());
  if (targets_.size() <= t || targets_.back() < bound) targets_.push_back(bound);
  say(fmt::format("  {}: past {} at {:.2f} N; the branch is searched on to {:.2f} N only "
                  "(study.search_past_failure: {:g})",
                  speed_text(model_.speed(), model_.scene().study.speeds_in_rpm), criterion_phrase(*past), low_, bound, settings_.search_past_failure));
}

}  // namespace twb
