#include "study/time/cycle_start.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "study/searches/operating_point.h"
#include "study/searches/steady_solver.h"
#include "study/study_support.h"

namespace twb {

namespace {

// The unknowns of an earlier cycle's end, checked to be this bearing's and to end where
// this schedule starts (std::invalid_argument saying what differs).
std::vector<double> continued_state(const BearingModel& model, const CycleState& end, const SchedulePoint& first,
                                    const std::string& bearing) {
  if (end.bearing != bearing) {
    std::istringstream a(end.bearing), b(bearing);
    std::string la, lb;
    while (std::getline(a, la) && std::getline(b, lb) && la == lb) {
    }
    throw std::invalid_argument(fmt::format("the cycle continued from belongs to another bearing: it has '{}' where "
                                            "this scene has '{}'",
                                            la, lb));
  }
  if (end.unknowns.size() != std::size_t(model.size()))
    throw std::invalid_argument(fmt::format("the cycle continued from has {} unknowns, this bearing {}",
                                            end.unknowns.size(), model.size()));
  // Within a millionth: a schedule's values written to ten digits (cycle_events.csv's) are the end's.
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)); };
  if (!same(end.time, first.time) || !same(end.load, first.load) || !same(end.speed, first.speed) ||
      !same(end.ambient, first.ambient) || !same(end.tilt, first.tilt))
    throw std::invalid_argument(fmt::format(
        "the cycle continued from ended at t = {:.10g} s, {:.10g} N, {:.10g} rad/s, ambient {:.10g} K, tilt {:.10g} rad; "
        "this schedule's first point is t = {:.10g} s, {:.10g} N, {:.10g} rad/s, {:.10g} K, {:.10g} rad: a continued "
        "cycle starts where the last one ended (its inputs are continuous in time)",
        end.time, end.load, end.speed, end.ambient, end.tilt, first.time, first.load, first.speed, first.ambient,
        first.tilt));
  return end.unknowns;
}

// How far into the first segment the march of a washer starting from rest under load
// begins its film: a millionth, as the rests of physics section 19.
constexpr double kTurning = 1e-6;

}  // namespace

std::optional<std::vector<double>> cycle_start(BearingModel& model, const OperatingSchedule& schedule,
                                               const NewtonSettings& newton, const CycleState* start,
                                               const std::string& bearing, StudyOutcome& out,
                                               const ProgressReport& progress) {
  const SchedulePoint first = schedule.points().front();
  OperatingSchedule::apply(model, first);
  std::vector<double> u;
  if (start) {
    u = continued_state(model, *start, first, bearing);
    SolvedState row = solved_state(model, u);
    row.converged = false;  // a point of a trajectory, not a steady state
    out.states.push_back(std::move(row));
    return u;
  }
  SteadySolver steady(model, newton);
  const SteadyReport rep = steady.solve_cold(u);
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("duty cycle: no steady state at the schedule's start ({:.6g} N, {:.6g} rad/s): {}",
                              first.load, first.speed, rep.message);
    return std::nullopt;
  }
  out.states.push_back(recorded_state(model, u, rep));
  out.timings.newton_iterations += rep.iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  if (!(first.speed == 0.0 && first.load > 0.0)) return u;

  // At rest under load: the film as it starts to turn (cycle_start.h).
  const SchedulePoint& next = schedule.points()[1];
  const SchedulePoint turning = schedule.on_segment(0, first.time + kTurning * (next.time - first.time));
  OperatingSchedule::apply(model, turning);
  std::vector<double> v = u;
  const SteadyReport moving = SteadySolver(model, newton).solve(v);
  OperatingSchedule::apply(model, first);
  out.timings.newton_iterations += moving.iterations;
  out.timings.jacobian_evaluations += moving.jacobian_evaluations;
  if (!moving.converged) {
    out.summary.push_back(fmt::format("duty cycle: no steady state of the film starting to turn ({:.6g} rad/s at "
                                      "t = {:.6g} s), the march starts from the state at rest: {}",
                                      turning.speed, turning.time, moving.message));
    return u;
  }
  if (progress)
    progress(fmt::format("duty cycle: at rest under load; the march starts from the film turning at {:.3g} rad/s",
                         turning.speed));
  return v;
}

}  // namespace twb
