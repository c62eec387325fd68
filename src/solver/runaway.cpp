#include "solver/runaway.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/relaxation_time.h"

namespace twb {

namespace {

// The verdict machinery of one step: the trajectory, its rate history and Newton.
class StepJudge {
 public:
  StepJudge(SteadySystem& system, const RunawaySettings& settings, StepOutcome& out)
      : system_(system), s_(settings), out_(out), ida_(system, settings.transient), newton_(system),
        residual_(std::size_t(system.size())) {}

  void run(std::span<const double> start_state, const TransientObserver& observer) {
    const TransientStatus begun = ida_.start(0.0, start_state);
    if (!begun.ok) {
      out_.final_state.assign(start_state.begin(), start_state.end());
      return conclude(StepVerdict::runaway, StepEvidence::no_consistent_start,
                      "no consistent initial state at the new parameter: " + begun.message);
    }
    start_.assign(ida_.state().begin(), ida_.state().end());
    if (observer) observer(0.0, ida_.state());
    double rate = sample();
    double minimum = rate, previous = rate;
    minimum_state_ = start_;
    double next_test = rate / s_.slowdown_factor;
    // Already steady to Newton's tolerance (no step at all): only Newton can tell.
    if (rate <= s_.newton.residual_tolerance && settled_here()) return;
    for (;;) {
      const TransientStatus st = ida_.step(out_.horizon);
      if (!st.ok) {
        // IDA also stumbles where the model is only once differentiable (asperity
        // contact and cavitation switching on at a node), with no blow-up at all:
        // restart there with fresh consistent values a few times, and before calling
        // the failure a runaway let Newton look for a steady state next to it.
        if (restarts_ < max_restarts) {
          ++restarts_;
          const std::vector<double> here(ida_.state().begin(), ida_.state().end());
          if (ida_.start(ida_.time(), here).ok) {
            if (ida_.time() >= out_.horizon) break;  // a fallback start may step past it
            continue;
          }
        }
        if (settled_here(last_look)) return;
        keep_state();
        return conclude(StepVerdict::runaway, StepEvidence::integration_failure,
                        fmt::format("the transient could not continue at t = {:.6g} ({} restarts): {}", ida_.time(),
                                    restarts_, st.message));
      }
      if (observer) observer(ida_.time(), ida_.state());
      rate = sample();
      if (!std::isfinite(rate)) {
        keep_state();
        return conclude(StepVerdict::runaway, StepEvidence::integration_failure,
                        fmt::format("the rate is not finite at t = {:.6g}", ida_.time()));
      }
      if (rate < minimum) {
        minimum = rate;
        minimum_state_.assign(ida_.state().begin(), ida_.state().end());
        minimum_from_residual_ = false;
      }
      // A rate under Newton's residual tolerance is a steady state's: it sinks to the
      // rounding level of F (1e-12 on Bratu) and wanders there by factors of 2-3, which
      // is no acceleration.
      auto accelerated = [&](double now) {
        return now > s_.acceleration_factor * std::max(minimum, s_.newton.residual_tolerance);
      };
      if (accelerated(rate)) {
        // The verdict is read from the residual itself, here and at the minimum: where
        // the rate is small against IDA's tolerance its u' is mostly error, and a
        // minimum read from it can lie below the true one. A confirmed minimum replaces
        // the interpolant's, so an unconfirmed rise is not asked about again.
        if (!minimum_from_residual_) {
          minimum = residual_rate(minimum_state_);
          minimum_from_residual_ = true;
        }
        rate = residual_rate(ida_.state());
        if (accelerated(rate)) {
          keep_state();
          return conclude(StepVerdict::runaway, StepEvidence::acceleration,
                          fmt::format("the rate grew from its minimum {:.3g} to {:.3g} by t = {:.6g}", minimum, rate,
                                      ida_.time()));
        }
      }
      const bool falling = rate < previous;
      previous = rate;
      if (st.reached_stop) break;
      if ((falling && rate <= next_test) || rate <= s_.newton.residual_tolerance) {
        if (settled_here()) return;
        next_test = rate / s_.slowdown_factor;
      }
    }
    if (settled_here(last_look)) return;
    keep_state();
    conclude(StepVerdict::runaway, StepEvidence::no_steady_state_nearby,
             fmt::format("no steady state near the trajectory at the horizon t = {:.6g} ({})", ida_.time(),
                         last_newton_));
  }

 private:
  // The rate of the transient, ‖C·u'‖∞ over the differential rows, from the u' IDA
  // holds at the step: along the trajectory C·u' = −F(u), to IDA's nonlinear tolerance
  // (on the bearing the two agree to 0.4 % from the step's first instant to a runaway,
  // and to 1e-5 in the slow passage), without a residual evaluation per step. The
  // algebraic rows are left out: they are constraints, not motion.
  double sample() {
    const std::span<const double> rate_of_change = ida_.rate();
    const std::vector<double>& c = ida_.capacities();
    const double rate = largest_motion([&](std::size_t k) { return c[k] * rate_of_change[k]; });
    out_.samples.push_back({ida_.time(), rate});
    return rate;
  }

  // The same rate from the residual, max |F_k| over the differential rows: a runaway
  // verdict is read from the equations themselves, not from IDA's interpolant.
  double residual_rate(std::span<const double> u) {
    system_.evaluate(u, residual_, {});
    return largest_motion([&](std::size_t k) { return residual_[k]; });
  }

  // max |row(k)| over the differential rows; inf where any row is not finite.
  template <class Row>
  double largest_motion(const Row& row) const {
    const std::vector<double>& c = ida_.capacities();
    double rate = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const double value = row(k);
      if (!std::isfinite(value)) return INFINITY;
      if (c[k] > 0.0) rate = std::max(rate, std::abs(value));
    }
    return rate;
  }

  // The settle test: Newton from u(t) must converge to a steady state u* no farther
  // from u(t) than closeness × the way u(t) has come (at least the tolerance). While
  // the trajectory goes on, u(t) is tried as a point of Newton's quadratic basin (full
  // steps only): one that has slowed near a stable state is, and one near a ghost,
  // where no root exists, then fails in a few steps instead of a line search's many.
  // The last look, when the trajectory can go no further, gets the globalized Newton.
  static constexpr bool last_look = true;
  bool settled_here(bool last = false) {
    ++out_.newton_attempts;
    std::vector<double> candidate(ida_.state().begin(), ida_.state().end());
    NewtonSettings newton = s_.newton;
    newton.line_search = newton.line_search && last;
    const NewtonReport rep = newton_.solve(candidate, newton);
    if (!rep.converged) {
      last_newton_ = "Newton: " + rep.message;
      return false;
    }
    const double gap = ida_.differential_distance(candidate, ida_.state());
    const double travel = ida_.differential_distance(ida_.state(), start_);
    if (!(gap <= s_.closeness * std::max(travel, 1.0))) {
      last_newton_ = fmt::format("Newton converged {:.3g} tolerance units away after a travel of {:.3g}", gap, travel);
      return false;
    }
    out_.final_state = std::move(candidate);
    conclude(StepVerdict::settled, StepEvidence::steady_state_found,
             fmt::format("steady state found at t = {:.6g}, {:.3g} tolerance units from the trajectory", ida_.time(),
                         gap));
    return true;
  }

  void keep_state() { out_.final_state.assign(ida_.state().begin(), ida_.state().end()); }

  void conclude(StepVerdict verdict, StepEvidence evidence, std::string reason) {
    out_.verdict = verdict;
    out_.evidence = evidence;
    out_.time = ida_.time();
    out_.reason = std::move(reason);
    out_.statistics = ida_.statistics();
  }

  SteadySystem& system_;
  const RunawaySettings& s_;
  StepOutcome& out_;
  IdaTransient ida_;
  KinsolNewton newton_;
  std::vector<double> residual_, start_;
  std::vector<double> minimum_state_;  // where the rate was least so far
  bool minimum_from_residual_ = false;
  std::string last_newton_ = "Newton not tried";
  // Restarts after an integration failure: a kink is passed by the first; a blow-up
  // fails again at once, so a few cost little.
  static constexpr int max_restarts = 3;
  int restarts_ = 0;
};

}  // namespace

StepOutcome classify_step(SteadySystem& system, std::span<const double> start_state, double start_parameter,
                          double new_parameter, const RunawaySettings& settings, const TransientObserver& observer) {
  StepOutcome out;
  const ParameterScope at_start(system, start_parameter);
  // The time scale belongs to the machine as it runs before the step (λ still old).
  out.relaxation_time = slowest_relaxation_time(system, start_state, settings.relaxation_iterations);
  out.horizon = settings.horizon_multiple * out.relaxation_time;
  const double old_parameter = start_parameter;
  system.set_parameter(new_parameter);
  StepJudge(system, settings, out).run(start_state, observer);
  if (out.settled() && settings.on_branch &&
      !settings.on_branch(system, start_state, old_parameter, out.final_state, new_parameter)) {
    out.verdict = StepVerdict::runaway;
    out.evidence = StepEvidence::left_branch;
    out.reason = "settled off the branch continued from the start (" + out.reason + ")";
  }
  return out;
}

Bracket bracket_critical(SteadySystem& system, double low_parameter, std::span<const double> low_state,
                         double high_parameter, const RunawaySettings& settings, const BracketObserver& observer) {
  Bracket b;
  b.low = low_parameter;
  b.high = high_parameter;
  b.low_state.assign(low_state.begin(), low_state.end());
  if (!(high_parameter > low_parameter)) {
    b.message = fmt::format("no interval to bisect: high {:.6g} is not above low {:.6g}", high_parameter, low_parameter);
    return b;
  }
  const ParameterScope at_low(system, low_parameter);
  {
    KinsolNewton newton(system);
    const NewtonReport rep = newton.solve(b.low_state, settings.newton);
    if (!rep.converged) {
      b.message = "the start is not a steady state at the low parameter: " + rep.message;
      return b;
    }
  }
  // Until a runaway is proven the upper end is only a target. A step to it that cannot
  // even start (no consistent algebraic state reachable from low) is retried halfway;
  // a settled step raises low and aims at the target again: a walk up, as a load is
  // raised on a rig, until some step runs away.
  bool proven = false;
  double target = high_parameter;
  while (!proven || (b.high - b.low) > settings.relative_width * std::abs(b.high)) {
    const double trial = proven ? 0.5 * (b.low + b.high) : target;
    StepOutcome o = classify_step(system, b.low_state, b.low, trial, settings);
    b.steps.push_back({trial, o.verdict, o.evidence, o.time, o.reason});
    b.ida_steps += o.statistics.steps;
    b.ida_factorizations += o.statistics.linear_setups;
    if (observer) observer(b.steps.back());
    if (o.evidence == StepEvidence::no_consistent_start) {
      const double nearer = 0.5 * (b.low + target);
      if (proven || nearer - b.low <= settings.relative_width * std::abs(nearer)) {
        b.message = fmt::format("the step to {:.6g} could not start: {}", trial, o.reason);
        return b;
      }
      target = nearer;
      continue;
    }
    if (o.settled()) {
      if (!proven && trial == high_parameter) {
        b.message = fmt::format("the step to {:.6g}, the bracket's upper end, settles: no runaway to bracket", trial);
        return b;
      }
      b.low = trial;
      b.low_state = std::move(o.final_state);
      target = high_parameter;
    } else {
      b.high = trial;
      proven = true;
    }
  }
  b.valid = true;
  return b;
}

}  // namespace twb
