// The duty cycle's march: IDA's starts and steps, each step's sample, the heat banked,
// and step 3, a crossing located in time (duty_cycle_march.h).
#include "study/time/duty_cycle_march.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "model/convection_effect.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// IDA restarts at a kink of the model (contact or cavitation switching on) before a
// failure to go on is read as the trajectory's end.
constexpr int kRestarts = 3;

// The cycle's heat integrals (generated, to the ambient, carried off), the quadratures'
// first; the integrands' follow.
constexpr std::size_t kHeatIntegrals = 3;

double lowest_ambient(const OperatingSchedule& schedule) {
  double lowest = schedule.points().front().ambient;
  for (const SchedulePoint& p : schedule.points()) lowest = std::min(lowest, p.ambient);
  return lowest;
}

}  // namespace

DutyCycleMarch::DutyCycleMarch(BearingModel& model, const OperatingSchedule& schedule,
                               const DutyCycleSettings& settings, std::vector<double> u, StudyOutcome& out,
                               const ProgressReport& progress, CycleIntegrands integrands)
    : model_(model),
      schedule_(schedule),
      u_(std::move(u)),
      out_(out),
      cycle_(out.own_part<DutyCycleOutcome>()),
      progress_(progress),
      settings_(settings),
      integrands_(std::move(integrands)),
      integrals_(integrands_.count, 0.0),
      content_at_start_(heat_content(model, u_, schedule.points().front().ambient)),
      ida_(model, transient_settings()),
      march_form_(std::in_place, model),
      between_(std::size_t(model.size())),
      watch_(model, out, lowest_ambient(schedule),
             [this](double a, double b, LimitKind kind) { return locate_crossing(a, b, kind); }),
      runaway_(model) {}

bool DutyCycleMarch::run(const std::string& bearing) {
  if (ran_) throw InternalError("duty cycle: the march is run once only");
  ran_ = true;
  follow_schedule();
  if (!check_started()) return false;
  record_end(bearing);
  worst_moment();
  std::stable_sort(cycle_.events.begin(), cycle_.events.end(),
                   [](const CycleEvent& a, const CycleEvent& b) { return a.time < b.time; });
  return true;
}

// Real time: the film's squeeze is on, the rigid body moves at its rate (physics §19).
// The heat generated, conducted to the ambient and carried off is integrated with the
// state (the cycle's energy balance, physics §19).
TransientSettings DutyCycleMarch::transient_settings() {
  TransientSettings settings;
  settings.real_time = true;
  settings.relative_tolerance = settings_.march_tolerance;
  settings.inputs_at = [this](double t) {
    OperatingSchedule::apply(model_, schedule_.on_segment(segment_, t));
    model_.set_imposed_tilt_rate(schedule_.tilt_rate(segment_));
    return schedule_.ambient_rate(segment_);
  };
  settings.quadrature_count = int(kHeatIntegrals + integrands_.count);
  settings.quadrature_rates = [this](double t, std::span<const double> state, std::span<double> rates) {
    const BearingState& s = describe_at(t, state);
    rates[0] = s.heat_generated;
    rates[1] = s.heat_to_ambient;
    rates[2] = s.reported_value(ConvectionEffect::kHeatCarried).value_or(0.0);
    if (integrands_.count > 0) integrands_.rates(state, rates.subspan(kHeatIntegrals));
  };
  return settings;
}

double DutyCycleMarch::heat_content(const BearingModel& model, std::span<const double> u, double ambient) {
  const std::vector<double> capacity = model.heat_capacities();
  double e = 0.0;
  for (std::size_t k = 0; k < capacity.size(); ++k)
    if (capacity[k] > 0.0) e += capacity[k] * (ambient + u[k]);
  return e;
}

const BearingState& DutyCycleMarch::describe_at(double t, std::span<const double> state) {
  if (described_.t != t ||
      !std::equal(state.begin(), state.end(), described_.u.begin(), described_.u.end())) {
    // The balances' errors a state reports are its own rows' (the march runs in Newton's).
    const NewtonForm own_rows(model_, false);
    described_.state = model_.describe(state);
    described_.t = t;
    described_.u.assign(state.begin(), state.end());
  }
  return described_.state;
}

TransientStatus DutyCycleMarch::start_in_own_rows(double t) {
  const NewtonForm own_rows(model_, false);
  TransientStatus status = ida_.start(t, u_);
  if (status.ok) unbanked_ = true;
  return status;
}

TransientStatus DutyCycleMarch::start_at(double t, bool kink) {
  bank();
  if (!kink) runaway_.restart();
  const TransientStatus status = start_in_own_rows(t);
  if (status.ok && !started_) record(ida_.time(), ida_.state());
  started_ = started_ || status.ok;
  return status;
}

std::string DutyCycleMarch::step_to(double to) {
  int restarts = 0;
  std::string why, restart_failed;
  while (ida_.time() < to) {
    const TransientStatus status = ida_.step(to);
    if (!status.ok && restarts < kRestarts) {
      ++restarts;
      u_.assign(ida_.state().begin(), ida_.state().end());
      const TransientStatus again = start_at(ida_.time(), true);
      if (again.ok) continue;
      restart_failed = "; starting again there: " + again.message;
    }
    if (!status.ok) {
      why = fmt::format("IDA could not go on at t = {:.6g} s ({}, {} restarts in a row){}", ida_.time(),
                        status.flag_name, restarts, restart_failed);
      break;
    }
    restarts = 0;
    record(ida_.time(), ida_.state());
  }
  u_.assign(ida_.state().begin(), ida_.state().end());
  return why;
}

void DutyCycleMarch::record(double t, std::span<const double> state) {
  const SchedulePoint inputs = schedule_.on_segment(segment_, t);
  OperatingSchedule::apply(model_, inputs);
  watch_.sample(t, inputs, describe_at(t, state));
  switch (runaway_.at(t, out_.trajectory.back().state.max_film_temperature, state)) {
    case RunawayWatch::Change::runs_away:
      watch_.event("runaway", t, inputs).margin = out_.trajectory.back().least_margin;
      if (progress_) progress_(fmt::format("duty cycle: thermo-viscous runaway at t = {:.6g} s", t));
      break;
    case RunawayWatch::Change::settles:
      watch_.event("settled", t, inputs).margin = out_.trajectory.back().least_margin;
      break;
    case RunawayWatch::Change::none:
      break;
  }
}

void DutyCycleMarch::bank() {
  if (!unbanked_) return;
  unbanked_ = false;
  const std::vector<double> q = ida_.quadratures();
  heat_.generated += q[0];
  heat_.to_ambient += q[1];
  heat_.carried += q[2];
  for (std::size_t k = 0; k < integrals_.size(); ++k) integrals_[k] += q[kHeatIntegrals + k];
  const TransientStatistics s = ida_.statistics();
  out_.timings.ida_steps += s.steps;
  out_.timings.ida_factorizations += s.linear_setups;
}

// The root of the margin of the state on IDA's interpolating polynomial over the step
// (IDAS's own root finding does the same, on every step; this searches only the steps
// whose ends differ in sign), to 1e-12 of the time (1e-12 s below a second); a margin
// that is not a number, or a search that does not close, leaves the straight line
// between the step's ends.
std::optional<SchedulePoint> DutyCycleMarch::locate_crossing(double a, double b, LimitKind kind) {
  const auto margin_at = [&](double t) -> double {
    if (!ida_.state_at(t, between_)) throw std::domain_error("outside the step");
    OperatingSchedule::apply(model_, schedule_.on_segment(segment_, t));
    const LimitValues values = LimitValues::of(model_.describe(between_), model_.scene().effects.thermal);
    const double m = failure_margin(kind, values, watch_.limits()).value_or(NAN);
    if (!std::isfinite(m)) throw std::domain_error("no margin there");
    return m;
  };
  std::optional<SchedulePoint> at;
  try {
    const double ma = margin_at(a), mb = margin_at(b);
    if ((ma >= 0.0) != (mb >= 0.0)) {
      constexpr std::uintmax_t kMost = 60;
      std::uintmax_t iterations = kMost;
      const auto [lo, hi] = boost::math::tools::toms748_solve(
          margin_at, a, b, ma, mb,
          [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); }, iterations);
      if (iterations < kMost) at = schedule_.on_segment(segment_, 0.5 * (lo + hi));
    }
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception&) {
    at.reset();  // the straight line between the steps instead
  }
  OperatingSchedule::apply(model_, schedule_.on_segment(segment_, b));
  return at;
}

}  // namespace twb
