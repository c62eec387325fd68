#include "study/time/cycle_life.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "model/wear_effect.h"
#include "study/time/life_march.h"
#include "study/study_support.h"
#include "study/time/cycle_start.h"
#include "study/time/duty_cycle_march.h"
#include "study/time/operating_schedule.h"
#include "twb/error_family.h"
#include "twb/results/cycle_state.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

constexpr double kHour = 3600.0;
// study.tolerance bounds the depths' error at the end of the life; each step's error
// estimate (Euler's against Heun's, first order) is held to a third of it. Measured on
// the paper's washer on 5x24 through a 10-s cycle over 0.5 h (wear rates of 1.4e-15
// m³/(N·m), 1.1 µm deep at the end): at 1, 10 and 100 nm the depths ended 0.86, 1.8 and
// 3.3 nm from every cycle marched, in 99, 60 and 47 marches against 180 cycles
// (docs/physics.md section 20).
constexpr double kLocalShare = 1.0 / 3.0;
// A step grows by at most this factor, and shrinks to at least this share, at a time.
constexpr double kMostGrowth = 4.0, kLeastShrink = 0.2;

// What one cycle marched at frozen depths did.
struct MarchedCycle {
  std::vector<double> wear;  // the depth each node lost over the cycle (m): the face at rest's, then the turning face's
  std::vector<double> end;   // the state it ended in, the next cycle's start
  // Where it passed a failure criterion or ran away (s into the cycle), and which; none
  // where it did neither.
  std::optional<double> failed_at;
  std::string failure;  // "failure" or "distress"
  std::string why;
  // Over the cycle: the time means of torque, f_eff and the contact's share, the hottest
  // film node, the least h_min/σ; the deepest rate (m/s) of each face.
  double torque = 0.0, f_eff = 0.0, contact_share = 0.0, max_temperature = 0.0, hmin_over_sigma = 0.0;
  double rest_rate = 0.0, turn_rate = 0.0;
  // At the cycle's worst moment, where searched: its failure load and the search.
  std::optional<double> failure_load, worst_load;
  std::optional<FailureCriterion> failure_criterion;
  std::optional<DistressRow> search;
  bool failed() const { return failed_at.has_value(); }
};

// Time means over a trajectory's samples (the trapezoid between them).
struct CycleMeans {
  double torque = 0.0, f_eff = 0.0, contact_share = 0.0;
};
CycleMeans means_of(const std::vector<TrajectorySample>& samples) {
  CycleMeans m;
  const double span = samples.back().time - samples.front().time;
  if (samples.size() < 2 || !(span > 0.0)) {
    const BearingState& s = samples.front().state;
    return {s.torque, s.f_eff, s.contact_share};
  }
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const double dt = samples[k].time - samples[k - 1].time;
    const BearingState &a = samples[k - 1].state, &b = samples[k].state;
    m.torque += 0.5 * dt * (a.torque + b.torque);
    m.f_eff += 0.5 * dt * (a.f_eff + b.f_eff);
    m.contact_share += 0.5 * dt * (a.contact_share + b.contact_share);
  }
  return {m.torque / span, m.f_eff / span, m.contact_share / span};
}

// A washer at rest under load has no film a march can start from (cycle_start.h): the new
// washer's first cycle could start a millionth into the first segment, but every later
// cycle starts from the last one's end, at rest with the cycle's heat in the bodies. A
// schedule that starts so is marched from its first point where the washer turns instead:
// the same periodic cycle, shifted by that point's time, so that each march starts and
// ends on a turning film. Returns the points and the shift (s).
std::pair<std::vector<SchedulePoint>, double> from_turning(const std::vector<SchedulePoint>& points) {
  const SchedulePoint& first = points.front();
  if (!(first.speed == 0.0 && first.load > 0.0)) return {points, 0.0};
  const auto turning = std::find_if(points.begin(), points.end(), [](const SchedulePoint& p) { return p.speed != 0.0; });
  if (turning == points.end()) return {points, 0.0};
  const double shift = turning->time - first.time, period = points.back().time - first.time;
  std::vector<SchedulePoint> shifted;
  for (auto p = turning; p != points.end(); ++p) {
    shifted.push_back(*p);
    shifted.back().time -= shift;
  }
  for (auto p = points.begin() + 1; p <= turning; ++p) {
    shifted.push_back(*p);
    shifted.back().time += period - shift;
  }
  return {shifted, shift};
}

class CycleLife {
 public:
  CycleLife(BearingModel& model, StudyOutcome& out, const ProgressReport& progress)
      : model_(model),
        out_(out),
        progress_(progress),
        settings_(std::get<LifeSettings>(model.scene().study.settings)),
        wear_(*model.effect<WearEffect>()),
        phase_(from_turning(settings_.cycle->schedule).second),
        schedule_(OperatingSchedule::with_rests(from_turning(settings_.cycle->schedule).first)),
        period_(schedule_.end() - schedule_.start()),
        bearing_(bearing_of(describe_scene(model.scene()))),
        rest_nodes_(wear_.rest_depths(std::vector<double>(std::size_t(model.size()))).size()) {}

  void run();

 private:
  // The cycle marched from state `from` with the depths `d` frozen (a failure search at
  // its worst moment where `search`).
  MarchedCycle march(const std::vector<double>& d, std::vector<double> from, bool search);
  // The depths of state u, the face at rest's then the turning face's (m).
  std::vector<double> depths_of(std::span<const double> u) const;
  // u with its depth unknowns set to d, and d held by the model.
  void set_depths(const std::vector<double>& d, std::vector<double>& u) const;
  double deepest(const std::vector<double>& d) const { return std::max(0.0, *std::max_element(d.begin(), d.end())); }
  // Records the washer with depths d at `cycles` into the life (time start_ + cycles·T),
  // its cycle's quantities `c`, how the life ended there (`event`).
  void record(const std::vector<double>& d, const std::vector<double>& start, double cycles, const MarchedCycle& c,
              const std::string& event);
  // Within the step from d0 (cycles n0) to d1 (n0 + steps), the depths taken linear in
  // the cycles: the first whole cycle m in [1, steps] whose march fails, by bisection;
  // `last` is the march at d1, which failed. Returns m and its march.
  std::pair<long, MarchedCycle> first_failing(const std::vector<double>& d0, const std::vector<double>& d1, long steps,
                                              const std::vector<double>& from, MarchedCycle last);
  std::vector<double> along(const std::vector<double>& d0, const std::vector<double>& d1, double share) const;
  std::string ended_by(const MarchedCycle& c, double cycles) const;
  // Whether the failure load at a searched cycle's worst moment has come down to the load there.
  static bool come_down(const MarchedCycle& c) {
    return c.failure_load && c.worst_load && *c.failure_load <= *c.worst_load;
  }
  void summarize(const std::string& ending);
  double hours(double cycles) const { return (start_ + cycles * period_) / kHour; }

  BearingModel& model_;
  StudyOutcome& out_;
  const ProgressReport& progress_;
  const LifeSettings& settings_;
  WearEffect& wear_;
  const double phase_;  // s: where in the scene's schedule the marched cycle starts (from_turning)
  const OperatingSchedule schedule_;
  const double period_;
  const std::string bearing_;
  const std::size_t rest_nodes_;
  double start_ = 0.0;  // s: a new washer's 0, a worn one's time
  long marches_ = 0;
};

std::vector<double> CycleLife::depths_of(std::span<const double> u) const {
  std::vector<double> d = wear_.rest_depths(u);
  const std::vector<double> turn = wear_.turn_depths(u);
  d.insert(d.end(), turn.begin(), turn.end());
  return d;
}

void CycleLife::set_depths(const std::vector<double>& d, std::vector<double>& u) const {
  const std::span<const double> rest(d.data(), rest_nodes_), turn(d.data() + rest_nodes_, d.size() - rest_nodes_);
  wear_.hold(rest, turn);
  const double scale = model_.clearance_scale();
  for (std::size_t n = 0; n < rest.size(); ++n) u[std::size_t(wear_.rest_offset()) + n] = rest[n] / scale;
  for (std::size_t i = 0; i < turn.size(); ++i) u[std::size_t(wear_.turn_offset()) + i] = turn[i] / scale;
}

MarchedCycle CycleLife::march(const std::vector<double>& d, std::vector<double> from, bool search) {
  ++marches_;
  set_depths(d, from);
  OperatingSchedule::apply(model_, schedule_.points().front());
  DutyCycleSettings settings = *settings_.cycle;
  settings.failure_load_at_worst = search;
  const CycleIntegrands integrands{.count = d.size(), .rates = [this](std::span<const double> u, std::span<double> r) {
                                     const WearEffect::Rates rates = wear_.rates_at(u);
                                     std::copy(rates.rest.begin(), rates.rest.end(), r.begin());
                                     std::copy(rates.turn.begin(), rates.turn.end(), r.begin() + rates.rest.size());
                                   }};
  StudyOutcome cycle;
  static const ProgressReport quiet;
  MarchedCycle c;
  {
    DutyCycleMarch marched(model_, schedule_, settings, std::move(from), cycle, quiet, integrands);
    const bool started = marched.run(bearing_);
    c.wear = marched.integrals();
    if (!started) throw SolverFailure("life: a cycle's march did not start: " + cycle.message, -1);
  }
  out_.timings.ida_steps += cycle.timings.ida_steps;
  out_.timings.ida_factorizations += cycle.timings.ida_factorizations;
  out_.timings.transients += cycle.timings.transients + 1;
  out_.timings.newton_iterations += cycle.timings.newton_iterations;
  const DutyCycleOutcome& own = std::get<DutyCycleOutcome>(cycle.own);
  for (const CycleEvent& e : own.events) {
    const bool runaway = e.event == "runaway", crossing = e.event == "crossing";
    if (!(runaway || crossing) || c.failed()) continue;
    c.failed_at = e.time - schedule_.start();
    c.failure = runaway ? "distress" : "failure";
    c.why = runaway ? "the bearing runs away thermo-viscously"
                    : fmt::format("the bearing passes the {} limit", limit_name(*e.criterion));
  }
  const TrajectorySample& first = cycle.trajectory.front();
  if (!c.failed() && first.least_margin && *first.least_margin < 0.0) {
    c.failed_at = 0.0;
    c.failure = "failure";
    c.why = fmt::format("the bearing is past the {} limit where the cycle starts", limit_name(*first.least_criterion));
  }
  if (!own.end && !c.failed()) {
    // The march ended early without a runaway: the solver's, not the washer's failure.
    throw SolverFailure("life: a cycle's march ended early: " + cycle.message, -1);
  }
  if (own.end) c.end = own.end->unknowns;
  const CycleMeans m = means_of(cycle.trajectory);
  c.torque = m.torque;
  c.f_eff = m.f_eff;
  c.contact_share = m.contact_share;
  c.hmin_over_sigma = first.state.hmin_over_sigma;
  for (const TrajectorySample& s : cycle.trajectory) {
    c.max_temperature = std::max(c.max_temperature, s.state.max_film_temperature);
    c.hmin_over_sigma = std::min(c.hmin_over_sigma, s.state.hmin_over_sigma);
  }
  for (std::size_t k = 0; k < c.wear.size(); ++k)
    (k < rest_nodes_ ? c.rest_rate : c.turn_rate) =
        std::max(k < rest_nodes_ ? c.rest_rate : c.turn_rate, c.wear[k] / period_);
  for (const CycleEvent& e : own.events)
    if (e.event == "worst" && e.failure_load) {
      c.failure_load = e.failure_load;
      c.failure_criterion = e.failure_criterion;
      c.worst_load = e.load;
    }
  if (!cycle.distress.empty()) c.search = std::move(cycle.distress.back());
  return c;
}

void CycleLife::record(const std::vector<double>& d, const std::vector<double>& start, double cycles,
                       const MarchedCycle& c, const std::string& event) {
  const double t_h = hours(cycles);
  std::vector<double> u = start;
  set_depths(d, u);
  OperatingSchedule::apply(model_, schedule_.points().front());
  SolvedState solved = solved_state(model_, u);
  // The state the cycle before ended in, consistent to IDA's Newton tolerance: a state of
  // the bearing as any recorded (not a steady one: the heat is the cycle's).
  solved.converged = true;
  solved.parameters = {t_h};
  out_.states.push_back(std::move(solved));
  const auto worn = wear_.worn(u);
  LifeRow row;
  row.time = t_h * kHour;
  row.rest = face_wear(worn[0]);
  row.turn = face_wear(worn[1]);
  row.rest_rate = c.rest_rate;
  row.turn_rate = c.turn_rate;
  row.torque = c.torque;
  row.f_eff = c.f_eff;
  row.max_temperature = c.max_temperature;
  row.hmin_over_sigma = c.hmin_over_sigma;
  row.contact_share = c.contact_share;
  row.failure_load = c.failure_load;
  row.failure_criterion = c.failure_criterion;
  row.event = event;
  if (c.search) {
    DistressRow search = *c.search;
    search.parameters = {t_h};
    out_.distress.push_back(std::move(search));
  }
  out_.own_part<LifeOutcome>().rows.push_back(row);
  out_.own_part<LifeOutcome>().worn.push_back(wear_.worn_washer(u, row.time));
  if (progress_)
    progress_(fmt::format("life: {:.6g} h of {:.6g} h ({:.0f} cycles), deepest wear {:.4g} um", t_h,
                          settings_.duration / kHour, cycles, 1e6 * std::max(row.rest.deepest, row.turn.deepest)));
}

std::vector<double> CycleLife::along(const std::vector<double>& d0, const std::vector<double>& d1,
                                     double share) const {
  std::vector<double> d(d0.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = d0[k] + share * (d1[k] - d0[k]);
  return d;
}

std::pair<long, MarchedCycle> CycleLife::first_failing(const std::vector<double>& d0, const std::vector<double>& d1,
                                                       long steps, const std::vector<double>& from,
                                                       MarchedCycle last) {
  long good = 0, failing = steps;
  while (failing - good > 1) {
    const long mid = good + (failing - good) / 2;
    MarchedCycle c = march(along(d0, d1, double(mid) / double(steps)), from, false);
    if (c.failed()) {
      failing = mid;
      last = std::move(c);
    } else {
      good = mid;
    }
  }
  // The failing cycle once more, with the failure search at its worst moment.
  if (settings_.failure_load) {
    MarchedCycle searched = march(along(d0, d1, double(failing) / double(steps)), from, true);
    if (searched.failed()) last = std::move(searched);
  }
  return {failing, std::move(last)};
}

std::string CycleLife::ended_by(const MarchedCycle& c, double cycles) const {
  const std::string phase =
      phase_ > 0.0 ? fmt::format(", the cycles marched from the schedule's first turning point, t = {:.6g} s", phase_)
                   : std::string();
  return fmt::format("ends {} in cycle {:.0f}, {:.6g} s into it ({:.6g} h{}): {}",
                     c.failure == "distress" ? "by distress" : "by failure", cycles + 1.0, *c.failed_at,
                     hours(cycles) + *c.failed_at / kHour, phase, c.why);
}

void CycleLife::run() {
  start_ = model_.scene().worn ? model_.scene().worn->time : 0.0;
  StudyOutcome begun_out;
  std::optional<std::vector<double>> begun =
      cycle_start(model_, schedule_, newton_settings(model_.scene()), nullptr, bearing_, begun_out, progress_);
  out_.timings.newton_iterations += begun_out.timings.newton_iterations;
  out_.timings.jacobian_evaluations += begun_out.timings.jacobian_evaluations;
  if (!begun) {
    out_.solver_failed = true;
    out_.message = "life: " + begun_out.message;
    return;
  }
  out_.parameter_columns = {kLifeTimeColumn};
  const double every = settings_.report_every > 0.0 ? settings_.report_every : settings_.duration / 20.0;
  const long every_cycles = std::max(1L, std::lround(every / period_));
  const long total = long(std::floor((settings_.duration - start_) / period_ + 1e-9));
  // Reported at whole multiples of report_every's cycles, counted from the life's start
  // (a continued life's as the whole one's).
  const double counted = start_ / period_;
  const auto report_after = [&](long n) {
    const double next = every_cycles * (std::floor((counted + n) / every_cycles + 1e-9) + 1.0) - counted;
    return std::min(total, std::max(n + 1, long(std::lround(next))));
  };

  std::vector<double> d = depths_of(*begun);
  MarchedCycle a = march(d, *begun, settings_.failure_load);
  if (a.failed()) {
    record(d, *begun, 0.0, a, a.failure);
    summarize(ended_by(a, 0.0));
    return;
  }
  record(d, *begun, 0.0, a, total < 1 ? "end" : "");
  if (come_down(a)) {
    out_.own_part<LifeOutcome>().rows.back().event = "failure";
    summarize("ends at its start: the failure load at the cycle's worst moment is below the load there already");
    return;
  }
  if (total < 1) {
    summarize("lasts its duration: no whole cycle is left in it");
    return;
  }
  const double tolerance = kLocalShare * settings_.tolerance;
  const std::optional<double> allowance = model_.scene().limits.wear_depth;
  long n = 0, steps = 1, report = report_after(0);
  std::string ending;
  while (ending.empty()) {
    steps = std::min(steps, report - n);
    std::vector<double> d1(d.size());
    std::optional<MarchedCycle> b;
    double error = 0.0;
    if (steps > 1) {
      std::vector<double> predicted(d.size());
      for (std::size_t k = 0; k < d.size(); ++k) predicted[k] = d[k] + double(steps) * a.wear[k];
      b = march(predicted, a.end, false);
      // A failure within the step: smaller steps find its cycle.
      if (b->failed()) {
        steps = std::max(1L, steps / 4);
        continue;
      }
      for (std::size_t k = 0; k < d.size(); ++k) error = std::max(error, 0.5 * double(steps) * std::abs(b->wear[k] - a.wear[k]));
      if (error > tolerance) {
        steps = std::max(1L, long(double(steps) * std::max(kLeastShrink, 0.9 * std::sqrt(tolerance / error))));
        continue;
      }
      for (std::size_t k = 0; k < d.size(); ++k) d1[k] = d[k] + 0.5 * double(steps) * (a.wear[k] + b->wear[k]);
    } else {
      for (std::size_t k = 0; k < d.size(); ++k) d1[k] = d[k] + a.wear[k];
    }
    const std::vector<double> from = b ? b->end : a.end;
    if (allowance && deepest(d1) >= *allowance) {
      // The depths linear in the cycles within the step: the first whole cycle whose
      // start reaches the allowance.
      long low = 0, high = steps;
      while (high - low > 1) {
        const long mid = low + (high - low) / 2;
        (deepest(along(d, d1, double(mid) / double(steps))) >= *allowance ? high : low) = mid;
      }
      const std::vector<double> reached = along(d, d1, double(high) / double(steps));
      const MarchedCycle c = march(reached, a.end, settings_.failure_load);
      record(reached, a.end, double(n + high), c, "wear_allowance");
      ending = fmt::format("ends at cycle {} ({:.6g} h), where a face reaches the wear allowance of {:.4g} um",
                           n + high, hours(double(n + high)), 1e6 * *allowance);
      break;
    }
    // The next step's first rate: B's, marched at the predicted depths, which differ from
    // the accepted ones by the step's error estimate (Heun's pair with its first stage
    // taken there stays of second order, each step's error O(N³), and costs one march a
    // step instead of two); a reported cycle is marched at the accepted depths, with its
    // failure search.
    const long reached = n + steps;
    const bool searched = settings_.failure_load && reached == report;
    MarchedCycle next = b && reached != report ? std::move(*b) : march(d1, from, searched);
    if (next.failed()) {
      auto [m, c] = first_failing(d, d1, steps, a.end, std::move(next));
      record(along(d, d1, double(m) / double(steps)), a.end, double(n + m), c, c.failure);
      ending = ended_by(c, double(n + m));
      break;
    }
    if (steps == 1) {
      // Every cycle marched: the change of wear from one cycle to the next says what a
      // step of N would err by, N²/2 times it ([W7] with B − A ≈ N·(A' − A)).
      double change = 0.0;
      for (std::size_t k = 0; k < d.size(); ++k) change = std::max(change, std::abs(next.wear[k] - a.wear[k]));
      error = change > 0.0 ? 0.5 * change : tolerance / (kMostGrowth * kMostGrowth);
    }
    d = std::move(d1);
    n = reached;
    a = std::move(next);
    if (progress_) progress_(fmt::format("life: cycle {} of {} ({:.6g} h), {} cycles a step", n, total, hours(double(n)), steps));
    if (n == report) {
      const bool last = n >= total;
      record(d, from, double(n), a, last ? "end" : "");
      if (come_down(a)) {
        out_.own_part<LifeOutcome>().rows.back().event = "failure";
        ending = fmt::format("ends by {:.6g} h, where the failure load at the cycle's worst moment has come down to "
                             "the load there",
                             hours(double(n)));
        break;
      }
      if (last) {
        ending = fmt::format("lasts its {:.6g} h ({} cycles of {:.6g} s)", hours(double(n)), n, period_);
        break;
      }
      report = report_after(n);
    }
    // Euler's error is of the second order in the step: the next step from this one's.
    const double growth =
        error > 0.0 ? std::clamp(0.9 * std::sqrt(tolerance / error), kLeastShrink, kMostGrowth) : kMostGrowth;
    steps = std::max(1L, long(double(steps) * growth));
  }
  summarize(ending);
}

void CycleLife::summarize(const std::string& ending) {
  summarize_life(out_, fmt::format("life through its {:.6g} s cycle", period_), ending);
  out_.summary.push_back(fmt::format("life: {} cycles marched in real time", marches_));
}

}  // namespace

void run_cycle_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  CycleLife(model, out, progress).run();
}

}  // namespace twb
