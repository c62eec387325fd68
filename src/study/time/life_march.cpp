#include "study/time/life_march.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/failure_margins.h"
#include "model/limit_thresholds.h"
#include "model/wear_effect.h"
#include "solver/ida_transient.h"
#include "study/searches/distress_search.h"
#include "study/searches/operating_point.h"
#include "study/study_support.h"
#include "study/time/cycle_life.h"

namespace twb {
namespace {

constexpr double kHour = 3600.0;  // IDA's time in slow time is in hours (the rows' σ_ref per hour)
// study.tolerance bounds the depths' error at the end of the life. IDA controls each
// step's local error, and a wearing washer keeps what a step got wrong (an error of depth
// does not decay), so the global error grows with the steps: on the paper's washer over
// 1000 h it measured 3 to 20 local tolerances for 13 to 87 steps (benchmarks/README.md,
// "What a life costs"). IDA's local tolerance is a thirtieth of the study's.
constexpr double kLocalShare = 1.0 / 30.0;

// The rate of a face as the state reports it (µm/h), in m/s.
double reported_rate(const BearingState& s, const char* column) {
  return s.reported_value(column).value_or(0.0) * 1e-6 / kHour;
}

class LifeMarch {
 public:
  LifeMarch(BearingModel& model, StudyOutcome& out, const ProgressReport& progress)
      : model_(model),
        out_(out),
        progress_(progress),
        settings_(std::get<LifeSettings>(model.scene().study.settings)),
        wear_(*model.effect<WearEffect>()) {}

  void run(std::vector<double> u);

 private:
  // Records the washer at state u, time t_h (hours), with how the life ended there: its
  // state (states.csv) and its row (life.csv), the row from the state described as `s`.
  void record(std::span<const double> u, double t_h, const std::string& event);
  void add_row(std::span<const double> u, double t_h, const std::string& event, const BearingState& s);
  // The state at t_h within IDA's last step, the bearing solved again at its depths
  // (the interpolated algebraic unknowns only start Newton).
  std::vector<double> settled_at(const IdaTransient& ida, double t_h) const;
  // The steady bearing at state u's depths, Newton from u; none where it finds none.
  std::optional<std::vector<double>> steady_at_depths(std::span<const double> u) const;
  double deepest(std::span<const double> u) const {
    const auto worn = wear_.worn(u);
    return std::max(worn[0].deepest, worn[1].deepest);
  }
  // The washer's margins to the failure criteria at its operating point at state u.
  FailureMargins margins(std::span<const double> u) const {
    return FailureMargins(LimitValues::of(model_.describe(u), model_.scene().effects.thermal), limits_);
  }
  // Where within IDA's last step, from `before`, a condition first holds that holds at
  // its end and not at `before` (a depth reaching the allowance, the operating point
  // passing a criterion's limit), asked of a time: bisection to a millionth of the step,
  // the later end of the last bracket.
  template <class Holds>
  double first_time(const IdaTransient& ida, double before, Holds holds) const {
    double low = before, high = ida.time();
    while (high - low > 1e-6 * (ida.time() - before)) {
      const double mid = 0.5 * (low + high);
      (holds(mid) ? high : low) = mid;
    }
    return high;
  }
  TransientSettings march_settings() const;
  // The failure load of the washer worn to state u (study.failure_load), into the last
  // row and distress.csv.
  void failure_at(std::span<const double> u, double t_h);
  void summarize(const std::string& ending);
  void count_work(const IdaTransient& ida);

  BearingModel& model_;
  StudyOutcome& out_;
  const ProgressReport& progress_;
  const LifeSettings& settings_;
  WearEffect& wear_;
  const OperatingLimits limits_ = OperatingLimits::of(model_.scene());
  // What the failure searches solve: a model of the same scene with the march's depths
  // held, so that IDA's model keeps its inputs and IDA its history.
  std::optional<BearingModel> searched_;
};

// The depths' error is IDA's to control, in σ_ref (the unknowns' scale): a share of the
// study's tolerance, absolute, and a relative millionth, which a depth of the washer's thickness
// would still keep below a tenth of a micrometre. The algebraic unknowns follow the depths
// through the steady equations and are left out of the error test.
TransientSettings LifeMarch::march_settings() const {
  TransientSettings t;
  t.relative_tolerance = 1e-6;
  t.absolute_tolerances.assign(std::size_t(model_.size()), t.absolute_tolerance);
  for (const UnknownBlock& b : model_.layout().blocks())
    if (b.effect == BlockEffect::wear)
      std::fill(t.absolute_tolerances.begin() + b.offset, t.absolute_tolerances.begin() + b.offset + b.size,
                kLocalShare * settings_.tolerance / model_.clearance_scale());
  t.algebraic_error_test = false;
  return t;
}

void LifeMarch::record(std::span<const double> u, double t_h, const std::string& event) {
  SolvedState solved = solved_state(model_, u);
  solved.converged = true;
  if (settings_.failure_load) solved.parameters = {t_h};
  out_.states.push_back(std::move(solved));
  add_row(u, t_h, event, out_.states.back().state);
}

void LifeMarch::add_row(std::span<const double> u, double t_h, const std::string& event, const BearingState& s) {
  const auto worn = wear_.worn(u);
  LifeRow row;
  row.time = t_h * kHour;
  row.rest = face_wear(worn[0]);
  row.turn = face_wear(worn[1]);
  row.rest_rate = reported_rate(s, "wear_rate_rest_um_h");
  row.turn_rate = reported_rate(s, "wear_rate_turn_um_h");
  row.torque = s.torque;
  row.f_eff = s.f_eff;
  row.max_temperature = s.max_film_temperature;
  row.hmin_over_sigma = s.hmin_over_sigma;
  row.contact_share = s.contact_share;
  row.event = event;
  out_.own_part<LifeOutcome>().rows.push_back(row);
  out_.own_part<LifeOutcome>().worn.push_back(wear_.worn_washer(u, row.time));
  if (progress_)
    progress_(fmt::format("life: {:.6g} h of {:.6g} h, deepest wear {:.4g} um", t_h, settings_.duration / kHour,
                          1e6 * std::max(row.rest.deepest, row.turn.deepest)));
}

// A search of a copy of the model, its depths held at u's on the heat's time scale
// (life_failure_search).
void LifeMarch::failure_at(std::span<const double> u, double t_h) {
  if (!settings_.failure_load) return;
  if (progress_) progress_(fmt::format("life: the failure load at {:.6g} h", t_h));
  if (!searched_) searched_.emplace(model_.scene());
  searched_->effect<WearEffect>()->hold(wear_.rest_depths(u), wear_.turn_depths(u));
  const DistressSearchSettings search = life_failure_search(model_.load());
  LifeRow& row = out_.own_part<LifeOutcome>().rows.back();
  try {
    DistressSearch found = search_distress(*searched_, search, {});
    add_search_work(out_.timings, found.counts);
    found.row.parameters = {t_h};
    row.failure_load = found.row.failure_load;
    row.failure_criterion = found.row.criterion;
    out_.distress.push_back(std::move(found.row));
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception& e) {
    out_.summary.push_back(fmt::format("life: no failure load at {:.6g} h: {}", t_h, e.what()));
  }
}

std::vector<double> LifeMarch::settled_at(const IdaTransient& ida, double t_h) const {
  std::vector<double> u(std::size_t(model_.size()));
  if (!ida.state_at(t_h, u)) throw InternalError("life: a time outside IDA's last step");
  std::optional<std::vector<double>> settled = steady_at_depths(u);
  return settled ? std::move(*settled) : u;
}

std::optional<std::vector<double>> LifeMarch::steady_at_depths(std::span<const double> u) const {
  wear_.hold(wear_.rest_depths(u), wear_.turn_depths(u));
  model_.set_time_scale(TimeScale::heat);
  std::vector<double> settled(u.begin(), u.end());
  const NewtonReport rep = KinsolNewton(model_).solve(settled, newton_settings(model_.scene()));
  out_.timings.newton_iterations += rep.iterations;
  model_.set_time_scale(TimeScale::wear);
  if (!rep.converged) return std::nullopt;
  return settled;
}

void LifeMarch::run(std::vector<double> u) {
  // A new washer, or the washer an earlier life wore (--continue-from), from its time on.
  const double start = model_.scene().worn ? model_.scene().worn->time / kHour : 0.0;
  add_row(u, start, "", out_.states.back().state);  // solved and recorded
  if (settings_.failure_load) out_.parameter_columns = {kLifeTimeColumn};
  if (settings_.failure_load) out_.states.back().parameters = {start};
  model_.set_time_scale(TimeScale::wear);
  failure_at(u, start);
  if (const std::optional<LimitKind> past = margins(u).first_past()) {
    out_.own_part<LifeOutcome>().rows.back().event = "failure";
    summarize(fmt::format("ends at its start ({:.6g} h): the operating point is past the {} limit already", start,
                          limit_name(*past)));
    model_.set_time_scale(TimeScale::heat);
    return;
  }
  IdaTransient ida(model_, march_settings());
  TransientStatus status = ida.start(start, u);
  if (!status.ok) {
    out_.solver_failed = true;
    out_.message = "life: the march in slow time did not start: " + status.message;
    model_.set_time_scale(TimeScale::heat);
    return;
  }
  const double end = settings_.duration / kHour;
  const double every = (settings_.report_every > 0.0 ? settings_.report_every : settings_.duration / 20.0) / kHour;
  const std::optional<double> allowance = model_.scene().limits.wear_depth;
  // Reported at whole multiples of report_every, a continued life's as the whole one's.
  double next = std::min(end, every * (std::floor(start / every + 1e-9) + 1.0)), before = start;
  std::string ending;
  int fresh_starts = 0;  // IDA started afresh where it last stopped, since it last got on
  double stopped_at = -1.0;
  while (ending.empty()) {
    status = ida.step(next);
    if (!status.ok) {
      // IDA could not go on. Where the steady bearing is lost at the operating load as
      // the faces wore (the fold come down to it), Newton finds no state at the depths
      // IDA reached: distress in slow time, between its last step and the one it could
      // not take. Where Newton finds one, IDA's trouble was its own (its Newton iterations
      // with an old Jacobian across a cavitation boundary): it starts afresh there, up to
      // three times at one place, and a fourth failure there is taken as the fold's.
      fresh_starts = ida.time() > stopped_at ? 0 : fresh_starts;
      stopped_at = ida.time();
      if (fresh_starts < 3) {
        if (std::optional<std::vector<double>> steady = steady_at_depths(ida.state())) {
          ++fresh_starts;
          count_work(ida);
          if (ida.start(stopped_at, *steady).ok) continue;
        }
      }
      record(ida.state(), ida.time(), "distress");
      ending = fmt::format("ends by distress after {:.6g} h: the steady bearing is lost at the operating load as "
                           "the faces wear (IDA: {})",
                           ida.time(), status.flag_name);
      break;
    }
    if (allowance && deepest(ida.state()) >= *allowance) {
      // (the deepest depth grows monotonically within the step; the depths are IDA's
      // differential unknowns: its interpolant holds them to its tolerance)
      std::vector<double> u(std::size_t(model_.size()));
      const double at = first_time(ida, before, [&](double t) {
        ida.state_at(t, u);
        return deepest(u) >= *allowance;
      });
      const std::vector<double> settled = settled_at(ida, at);
      record(settled, at, "wear_allowance");
      failure_at(settled, at);
      ending = fmt::format("ends at {:.6g} h, where a face reaches the wear allowance of {:.4g} um", at,
                           1e6 * *allowance);
      break;
    }
    // A failure criterion passed at the operating point: the failure load has come down
    // to the operating load (the least load at which a criterion is passed), located in
    // time between two steps without a search.
    if (const std::optional<LimitKind> past = margins(ida.state()).first_past()) {
      const std::size_t c = *criterion_index(*past);
      // (the margins of the bearing solved at the interpolant's depths: the interpolated
      // algebraic unknowns are outside IDA's error control)
      const double at = first_time(ida, before, [&](double t) { return margins(settled_at(ida, t)).past(c); });
      const std::vector<double> settled = settled_at(ida, at);
      record(settled, at, "failure");
      failure_at(settled, at);
      ending = fmt::format("ends by {:.6g} h, where the operating point passes the {} limit: its failure load has "
                           "come down to the operating load",
                           at, limit_name(*past));
      break;
    }
    before = ida.time();
    if (!status.reached_stop) continue;
    const bool last = next >= end;
    const std::vector<double> reached(ida.state().begin(), ida.state().end());
    record(reached, next, last ? "end" : "");
    failure_at(reached, next);
    if (const LifeRow& row = out_.own_part<LifeOutcome>().rows.back();
        row.failure_load && *row.failure_load <= model_.load()) {
      out_.own_part<LifeOutcome>().rows.back().event = "failure";
      ending = fmt::format("ends by {:.6g} h, where its failure load has come down to the operating load", next);
      break;
    }
    if (last) ending = fmt::format("lasts its {:.6g} h", end);
    next = std::min(next + every, end);
  }
  count_work(ida);
  out_.timings.transients += 1;
  model_.set_time_scale(TimeScale::heat);
  summarize(ending);
}

// IDA's counts since its start.
void LifeMarch::count_work(const IdaTransient& ida) {
  const TransientStatistics stats = ida.statistics();
  out_.timings.ida_steps += stats.steps;
  out_.timings.ida_factorizations += stats.linear_setups;
}

void LifeMarch::summarize(const std::string& ending) {
  summarize_life(out_, fmt::format("life at {:.6g} N", model_.load()), ending);
}

}  // namespace

DistressSearchSettings life_failure_search(double operating_load) {
  DistressSearchSettings search;
  search.load_start = 0.25 * operating_load;
  search.load_end = 20.0 * operating_load;
  search.march_past_distress = false;
  return search;
}

void summarize_life(StudyOutcome& out, const std::string& subject, const std::string& ending) {
  const LifeRow& last = out.own_part<LifeOutcome>().rows.back();
  out.message = "life: " + ending;
  out.summary.push_back(fmt::format(
      "{}: {}; the face at rest worn {:.4g} um deep (mean {:.4g} um, {:.4g} mm^3), the turning face {:.4g} um (mean "
      "{:.4g} um, {:.4g} mm^3)",
      subject, ending, 1e6 * last.rest.deepest, 1e6 * last.rest.mean, 1e9 * last.rest.volume, 1e6 * last.turn.deepest,
      1e6 * last.turn.mean, 1e9 * last.turn.volume));
  const LifeRow& first = out.own_part<LifeOutcome>().rows.front();
  if (first.failure_load && last.failure_load && &first != &last)
    out.summary.push_back(fmt::format("life: the washer fails at {:.6g} N by {} at {:.6g} h{}, at {:.6g} N by {} at "
                                      "{:.6g} h (on the scene's mesh)",
                                      *first.failure_load, criterion_name(*first.failure_criterion),
                                      first.time / kHour, first.time > 0.0 ? "" : " (new)", *last.failure_load,
                                      criterion_name(*last.failure_criterion), last.time / kHour));
}

void run_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  out.own_part<LifeOutcome>();  // first: life.csv is written (empty) where the life does not start
  if (!model.effect<WearEffect>()) throw InternalError("run_life: a life study of a scene without wear");
  if (std::get<LifeSettings>(model.scene().study.settings).cycle) {
    run_cycle_life(model, out, progress);
    return;
  }
  // The new washer's steady state, the depths held at zero: the life's first state.
  std::vector<double> u;
  if (!solve_operating_point(model, out, u)) return;
  LifeMarch(model, out, progress).run(std::move(u));
}

}  // namespace twb
