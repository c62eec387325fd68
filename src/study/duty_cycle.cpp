#include "study/duty_cycle.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "model/limit_thresholds.h"
#include "solver/ida_transient.h"
#include "study/cycle_start.h"
#include "study/cycle_watch.h"
#include "study/distress_search.h"
#include "study/operating_point.h"
#include "study/operating_schedule.h"
#include "study/runaway_watch.h"
#include "study/steady_solver.h"
#include "study/study_support.h"
#include "system/steady_system.h"
#include "twb/error_family.h"
#include "twb/results/cycle_state.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

// IDA restarts at a kink of the model (contact or cavitation switching on) before a
// failure to go on is read as the trajectory's end.
constexpr int kRestarts = 3;

// W_fail at the worst moment's speed, ambient and tilt: how close the operating point
// came to the quasi-steady failure load.
void failure_at_worst(BearingModel& model, StudyOutcome& out, const TrajectorySample& worst, double largest_load,
                      CycleEvent& e) {
  SchedulePoint p;
  p.load = worst.state.load;
  p.speed = worst.state.speed;
  p.ambient = *worst.ambient;
  p.tilt = *worst.tilt;
  OperatingSchedule::apply(model, p);
  DistressSearchSettings settings;
  // From a quarter of the load there, or of the cycle's largest where the washer was
  // unloaded (the search climbs from a load the films carry).
  settings.load_start = 0.25 * (p.load > 0.0 ? p.load : largest_load);
  settings.load_end = 10.0 * largest_load;
  settings.march_past_distress = false;
  try {
    DistressSearch found = search_distress(model, settings, {});
    add_search_work(out.timings, found.counts);
    if (found.row.failure_load) {
      e.failure_load = found.row.failure_load;
      e.failure_criterion = found.row.criterion;
    }
    out.distress.push_back(std::move(found.row));
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception& ex) {
    out.summary.push_back(fmt::format("duty cycle: no failure load at the worst moment: {}", ex.what()));
  }
}

// The hottest film temperature (K) of the trajectory's step at t.
double hottest_at(const std::vector<TrajectorySample>& trajectory, double t) {
  const auto at = std::lower_bound(trajectory.begin(), trajectory.end(), t,
                                   [](const TrajectorySample& s, double time) { return s.time < time; });
  return (at == trajectory.end() ? trajectory.back() : *at).state.max_film_temperature;
}

// The bodies' heat content (J) at state u and ambient T_a: Σ ρ·c·t·A·(T_a + ϑ) over every
// body node (the capacities of physics §7, in physical units).
double heat_content(const BearingModel& model, std::span<const double> u, double ambient) {
  const std::vector<double> capacity = model.heat_capacities();
  double e = 0.0;
  for (std::size_t k = 0; k < capacity.size(); ++k)
    if (capacity[k] > 0.0) e += capacity[k] * (ambient + u[k]);
  return e;
}

}  // namespace

void run_duty_cycle(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, const CycleState* start) {
  const auto t0 = std::chrono::steady_clock::now();
  // The scene's schedule, with a point where an unloaded washer's speed turns back.
  const OperatingSchedule schedule(OperatingSchedule::with_rests(model.scene().study.schedule));
  const NewtonSettings newton = newton_settings(model.scene());
  const std::string bearing = bearing_of(describe_scene(model.scene()));

  // The steady state at the schedule's start, or where the cycle continued from ended.
  const SchedulePoint first = schedule.points().front();
  std::optional<std::vector<double>> begun = cycle_start(model, schedule, newton, start, bearing, out, progress);
  if (!begun) return;
  std::vector<double> u = std::move(*begun);

  // The inputs on the segment being marched, set at every evaluation's time.
  std::size_t segment = 0;
  // Real time: the film's squeeze is on, the rigid body moves at its rate (physics §19).
  TransientSettings settings;
  settings.real_time = true;
  settings.relative_tolerance = model.scene().study.march_tolerance;
  settings.inputs_at = [&](double t) {
    OperatingSchedule::apply(model, schedule.on_segment(segment, t));
    model.set_imposed_tilt_rate(schedule.tilt_rate(segment));
    return schedule.ambient_rate(segment);
  };
  // The heat generated, conducted to the ambient and carried off, integrated with the
  // state (the cycle's energy balance, physics §19).
  // IDAS evaluates them once a step, at the state the step ends on: the state described
  // there is the step's sample too (described once).
  struct Described {
    double t = 0.0;
    std::vector<double> u;
    BearingState state;
  } described;
  const auto describe_at = [&](double t, std::span<const double> state) -> const BearingState& {
    if (described.t != t || !std::equal(state.begin(), state.end(), described.u.begin(), described.u.end())) {
      // The balances' errors a state reports are its own rows' (the march runs in Newton's).
      const NewtonForm own_rows(model, false);
      described.state = model.describe(state);
      described.t = t;
      described.u.assign(state.begin(), state.end());
    }
    return described.state;
  };
  settings.quadrature_count = 3;
  settings.quadrature_rates = [&](double t, std::span<const double> state, std::span<double> rates) {
    const BearingState& s = describe_at(t, state);
    rates[0] = s.heat_generated;
    rates[1] = s.heat_to_ambient;
    rates[2] = s.heat_carried.value_or(0.0);
  };
  CycleHeat heat;
  const double content_at_start = heat_content(model, u, first.ambient);
  IdaTransient ida(model, settings);
  // IDA's Newton starts each step from its predictor, close: it works on the Newton form
  // of the model's complementarity rows (the minimum, piecewise linear, as continuation's
  // correctors do), whose roots are the model's own. Fischer–Burmeister's curvature at the
  // cavitation boundary failed its iterations over and over where a lightly loaded washer
  // lifts: a ramp from 100 to 1 N and a hold took 6802 steps, 201 in this form. The
  // consistent starts (KINSOL from rates of zero, not close) keep the model's own rows.
  std::optional<NewtonForm> march_form;
  march_form.emplace(model);
  // Whether IDA holds heat and work since its last start that bank() has not taken: a
  // start that fails leaves IDA as it was, already banked.
  bool unbanked = false;
  const auto start_in_own_rows = [&](double t, std::span<const double> state) {
    const NewtonForm own_rows(model, false);
    TransientStatus status = ida.start(t, state);
    if (status.ok) unbanked = true;
    return status;
  };
  double lowest_ambient = first.ambient;
  for (const SchedulePoint& p : schedule.points()) lowest_ambient = std::min(lowest_ambient, p.ambient);
  // A crossing's time: the root of the margin of the state on IDA's interpolating
  // polynomial over the step (IDAS's own root finding does the same, on every step; this
  // searches only the steps whose ends differ in sign), to 1e-12 of the time (1e-12 s
  // below a second); a margin that is not a number, or a search that does not close,
  // leaves the straight line between the step's ends.
  std::vector<double> between(std::size_t(model.size()));
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  const CrossingLocator locate = [&](double a, double b, LimitKind kind) -> std::optional<SchedulePoint> {
    const auto margin_at = [&](double t) -> double {
      if (!ida.state_at(t, between)) throw std::domain_error("outside the step");
      OperatingSchedule::apply(model, schedule.on_segment(segment, t));
      const double m =
          failure_margin(kind, LimitValues::of(model.describe(between), model.scene().effects.thermal), limits)
              .value_or(NAN);
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
            margin_at, a, b, ma, mb, [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); },
            iterations);
        if (iterations < kMost) at = schedule.on_segment(segment, 0.5 * (lo + hi));
      }
    } catch (const InternalError&) {
      throw;
    } catch (const std::exception&) {
      at.reset();  // the straight line between the steps instead
    }
    OperatingSchedule::apply(model, schedule.on_segment(segment, b));
    return at;
  };
  CycleWatch watch(model, out, lowest_ambient, locate);
  RunawayWatch runaway(model);
  std::string ended;  // why the march ended before the schedule did
  auto bank = [&] {
    if (!unbanked) return;
    unbanked = false;
    const std::vector<double> q = ida.quadratures();
    heat.generated += q[0];
    heat.to_ambient += q[1];
    heat.carried += q[2];
    const TransientStatistics s = ida.statistics();
    out.timings.ida_steps += s.steps;
    out.timings.ida_factorizations += s.linear_setups;
  };
  auto record = [&](double t, std::span<const double> state) {
    const SchedulePoint inputs = schedule.on_segment(segment, t);
    OperatingSchedule::apply(model, inputs);
    watch.sample(t, inputs, describe_at(t, state));
    switch (runaway.at(t, out.trajectory.back().state.max_film_temperature, state)) {
      case RunawayWatch::Change::runs_away:
        watch.event("runaway", t, inputs).margin = out.trajectory.back().least_margin;
        if (progress) progress(fmt::format("duty cycle: thermo-viscous runaway at t = {:.6g} s", t));
        break;
      case RunawayWatch::Change::settles:
        watch.event("settled", t, inputs).margin = out.trajectory.back().least_margin;
        break;
      case RunawayWatch::Change::none:
        break;
    }
  };

  // The washer unloaded at rest (load and speed both zero) is held where it came to rest
  // (BearingModel::hold_at_rest, physics §19), from a millionth of the segment before the
  // point where it comes to rest to a millionth of the segment after it leaves: the
  // massless bodies' positions have a limit as the load and the speed go to zero, none at
  // the zero itself (the free gear climbs up film 2's asperity tail without end). Where
  // the march cannot follow them that close to the zero (IDA's Newton fails on the film
  // of a load and a speed a millionth of their ramps), the rest begins where it stopped
  // and ends where the balances find a consistent state, within a thousandth.
  constexpr double kRestMargin = 1e-6, kRestReach = 1e-3;
  struct RestGivenBack {
    BearingModel& model;
    ~RestGivenBack() { model.hold_at_rest({}); }
  } rest_given_back{model};
  bool started = false;
  const auto rest_event = [&](bool held, double t) {
    watch.event(held ? "rest" : "resume", t, schedule.on_segment(segment, t));
    if (progress)
      progress(fmt::format("duty cycle: {} at t = {:.6g} s",
                           held ? "unloaded at rest, the washer and gear held" : "the washer and gear balanced again", t));
  };
  // IDA started at (t, u), consistent values computed afresh: at every point of the
  // schedule (the inputs' rates jump there, and so do the state's) and where the rest
  // begins or ends.
  // (`kink`: a restart inside a segment, after IDA failed at a kink of the model, where
  // the inputs' rates do not jump: the runaway watch keeps its trend.)
  const auto start_at = [&](double t, bool kink = false) {
    bank();
    if (!kink) runaway.restart();
    const TransientStatus status = start_in_own_rows(t, u);
    if (status.ok && !started) record(ida.time(), ida.state());
    started = started || status.ok;
    return status;
  };
  // IDA's steps from its time to `to`, each recorded, u the state reached: why it stopped
  // short, empty where it did not. A kink of the model (contact or cavitation switching
  // on) is passed by one restart; a march that fails again and again has ended.
  const auto step_to = [&](double to) -> std::string {
    int restarts = 0;
    std::string why, restart_failed;
    while (ida.time() < to) {
      const TransientStatus status = ida.step(to);
      if (!status.ok && restarts < kRestarts) {
        ++restarts;
        u.assign(ida.state().begin(), ida.state().end());
        const TransientStatus again = start_at(ida.time(), true);
        if (again.ok) continue;
        restart_failed = "; starting again there: " + again.message;
      }
      if (!status.ok) {
        why = fmt::format("IDA could not go on at t = {:.6g} s ({}, {} restarts in a row){}", ida.time(),
                          status.flag_name, restarts, restart_failed);
        break;
      }
      restarts = 0;
      record(ida.time(), ida.state());
    }
    u.assign(ida.state().begin(), ida.state().end());
    return why;
  };
  const auto no_start = [](double t, const TransientStatus& status) {
    return fmt::format("no consistent state at t = {:.6g} s: {}", t, status.message);
  };
  for (; segment < schedule.segments() && ended.empty(); ++segment) {
    const SchedulePoint& a = schedule.points()[segment];
    const SchedulePoint& b = schedule.points()[segment + 1];
    if (progress)
      progress(fmt::format("duty cycle: segment {} of {}, {:.6g} s to {:.6g} s", segment + 1, schedule.segments(),
                           a.time, b.time));
    const double span = b.time - a.time;
    const bool rest_a = OperatingSchedule::unloaded_at_rest(a), rest_b = OperatingSchedule::unloaded_at_rest(b);
    double from = a.time;
    if (rest_a) {
      // Held a millionth of the segment, then balanced again; where the balances find no
      // consistent state that close to the zero, held a decade longer, up to a thousandth.
      // (Held since the segment before came to rest: a schedule does not start at rest.)
      if (!model.held_at_rest()) {
        model.hold_at_rest(u);
        rest_event(true, from);
      }
      std::string why;
      for (double reach = kRestMargin; why.empty(); reach *= 10.0) {
        const TransientStatus held = start_at(from);
        if (!held.ok) {
          ended = no_start(from, held);
          break;
        }
        const double until = rest_b ? b.time : a.time + reach * span;
        if (const std::string stopped = step_to(until); !stopped.empty()) {
          ended = stopped;
          break;
        }
        from = until;
        if (rest_b) break;
        model.hold_at_rest({});
        const TransientStatus balanced = start_at(from);
        if (balanced.ok) {
          rest_event(false, from);
          break;
        }
        model.hold_at_rest(u);  // the rigid unknowns held are the rest's still
        if (reach * 10.0 > kRestReach * (1.0 + 1e-9)) {
          why = no_start(from, balanced);
          // Unloaded, a free gear leaves nothing to press the turning washer down (physics §19).
          if (b.load == 0.0)
            why += "; the washer left its rest with the speed alone, unloaded: bring the load back first, or with the "
                   "speed";
        }
      }
      if (!why.empty()) ended = why;
      if (!ended.empty() || rest_b) continue;
    } else if (const TransientStatus status = start_at(from); !status.ok) {
      ended = no_start(from, status);
      continue;
    }
    const std::string stopped = step_to(rest_b ? b.time - kRestMargin * span : b.time);
    // Coming to rest, within the last thousandth of the segment: the rest begins there.
    if (!stopped.empty() && !(rest_b && ida.time() >= b.time - kRestReach * span)) {
      ended = stopped;
      continue;
    }
    if (!rest_b) continue;
    from = ida.time();
    model.hold_at_rest(u);
    rest_event(true, from);
    if (const TransientStatus held = start_at(from); !held.ok) {
      ended = no_start(from, held);
      continue;
    }
    if (const std::string held_short = step_to(b.time); !held_short.empty()) ended = held_short;
  }
  bank();
  model.hold_at_rest({});
  model.set_imposed_tilt_rate(0.0);  // quasi-steady from here on (the worst moment's search)
  march_form.reset();
  if (out.trajectory.empty()) {
    out.solver_failed = true;
    out.message = "duty cycle: the march did not start: " + ended;
    return;
  }

  const TrajectorySample& last = out.trajectory.back();
  CycleEvent& end = watch.event("end", last.time, schedule.at(last.time));
  end.margin = last.least_margin;
  if (ended.empty()) {
    const SchedulePoint at = schedule.at(last.time);
    out.cycle_end = CycleState{last.time, at.load, at.speed, at.ambient, at.tilt, u, bearing};
  }
  heat.stored = heat_content(model, u, schedule.at(last.time).ambient) - content_at_start;
  out.cycle_heat = heat;
  if (!ended.empty()) {
    // A blow-up (IDA stopped by temperatures running away) is the runaway itself; any
    // other end is the solver's failure.
    if (runaway.running_away()) {
      out.message = fmt::format("duty cycle: the trajectory blew up after the runaway: {}", ended);
    } else {
      out.solver_failed = true;
      out.message = "duty cycle: the march ended early: " + ended;
    }
  }

  double largest_load = 0.0;
  for (const SchedulePoint& p : schedule.points()) largest_load = std::max(largest_load, p.load);
  if (const std::optional<std::size_t> w = watch.worst()) {
    const TrajectorySample worst = out.trajectory[*w];
    CycleEvent& e = watch.event("worst", worst.time, schedule.at(worst.time));
    e.criterion = worst.least_criterion;
    e.margin = worst.least_margin;
    if (model.scene().study.failure_load_at_worst) {
      if (progress) progress(fmt::format("duty cycle: the failure load at the worst moment, t = {:.6g} s", worst.time));
      CycleEvent found = e;
      failure_at_worst(model, out, worst, largest_load, found);
      out.cycle_events.back() = found;
    }
  }
  std::stable_sort(out.cycle_events.begin(), out.cycle_events.end(),
                   [](const CycleEvent& a, const CycleEvent& b) { return a.time < b.time; });

  // The summary: what the cycle did.
  out.summary.push_back(fmt::format("duty cycle: {} segments, {:.6g} s to {:.6g} s, {} steps ({:.1f} s)",
                                    model.scene().study.schedule.size() - 1, schedule.start(), last.time, out.trajectory.size() - 1,
                                    elapsed_ms(t0) / 1000.0));
  out.summary.push_back(fmt::format(
      "duty cycle: heat: {:.6g} J generated = {:.6g} J to the ambient + {:.6g} J carried by the oil + {:.6g} J stored in "
      "the bodies, to {:.2g} J ({:.2g} of the generated)",
      heat.generated, heat.to_ambient, heat.carried, heat.stored, heat.error(),
      std::abs(heat.error()) / std::max(heat.generated, 1e-300)));
  for (const CycleEvent& e : out.cycle_events) {
    if (e.event == "crossing" || e.event == "recovery")
      out.summary.push_back(fmt::format("duty cycle: {} {} at t = {:.6g} s ({:.6g} N, {:.6g} rad/s)",
                                        e.event == "crossing" ? "crosses" : "recovers from",
                                        criterion_phrase(*e.criterion), e.time, e.load, e.speed));
    else if (e.event == "runaway")
      out.summary.push_back(fmt::format("duty cycle: thermo-viscous runaway at t = {:.6g} s ({:.6g} N, {:.6g} rad/s)",
                                        e.time, e.load, e.speed));
    else if (e.event == "settled")
      out.summary.push_back(fmt::format("duty cycle: the runaway is over at t = {:.6g} s ({:.6g} N, {:.6g} rad/s): "
                                        "the slow thermal mode is stable again, the hottest film at {:.4g} degC",
                                        e.time, e.load, e.speed, hottest_at(out.trajectory, e.time) - 273.15));
    else if (e.event == "rest")
      out.summary.push_back(fmt::format("duty cycle: unloaded at rest from t = {:.6g} s ({:.3g} N, {:.3g} rad/s): the "
                                        "washer and gear held where they came to rest",
                                        e.time, e.load, e.speed));
    else if (e.event == "resume")
      out.summary.push_back(fmt::format("duty cycle: the washer and gear balanced again from t = {:.6g} s ({:.3g} N, "
                                        "{:.3g} rad/s)",
                                        e.time, e.load, e.speed));
    else if (e.event == "worst")
      out.summary.push_back(fmt::format(
          "duty cycle: the worst moment is t = {:.6g} s ({:.6g} N, {:.6g} rad/s): {:.3g} of {}'s allowance left{}",
          e.time, e.load, e.speed, e.margin.value_or(0.0), e.criterion ? criterion_phrase(*e.criterion) : "",
          e.failure_load ? fmt::format("; it would fail there at {:.6g} N by {}", *e.failure_load,
                                       e.failure_criterion ? criterion_name(*e.failure_criterion) : "")
                         : ""));
  }
  out.timings.transients += 1;
}

}  // namespace twb
