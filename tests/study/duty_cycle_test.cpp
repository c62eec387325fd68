// The duty cycle (study/duty_cycle.h, docs/physics.md section 19): the schedule's inputs
// in time, a held point's end at the point study's steady state, the bodies' heat
// capacities delaying an ambient ramp, and the thermo-viscous runaway recognised on a
// ramp past W_d and not on one that stops short of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "solver/relaxation_time.h"
#include "study/searches/distress_search.h"
#include "study/time/operating_schedule.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"
#include "twb/results/cycle_state.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

// The paper's washer on a coarse mesh (the march's behaviour, not its mesh error, is
// under test) with a duty cycle of the given schedule (YAML).
Scene cycle_scene(const std::string& schedule, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "operating.load=100 N",
                                     "study={type: duty_cycle, schedule: " + schedule + "}"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", overrides);
}

// A duty cycle scene's schedule.
const std::vector<SchedulePoint>& schedule_of(const Scene& scene) {
  return std::get<DutyCycleSettings>(scene.study.settings).schedule;
}

// What only a duty cycle gives back: its events, end and heat balance.
const DutyCycleOutcome& cycle_of(const StudyOutcome& out) { return std::get<DutyCycleOutcome>(out.own); }

SchedulePoint point(double t, double load, double speed, double ambient, double tilt) {
  SchedulePoint p;
  p.time = t, p.load = load, p.speed = speed, p.ambient = ambient, p.tilt = tilt;
  return p;
}

// The heat over the cycle: generated = conducted + carried + stored (physics §19). The
// integrals follow the state with IDA's formula and its relative tolerance, 1e-6 a step:
// their balance closes to a few times that of the heat generated, and 1e-5 allows ten.
// (Without the ambient's rate on the bodies' rows, their content would jump with the
// ambient with no heat to account for it.)
void expect_heat_balance(const StudyOutcome& out) {
  ASSERT_TRUE(cycle_of(out).heat);
  const CycleHeat& h = *cycle_of(out).heat;
  EXPECT_GT(h.generated, 0.0);
  EXPECT_LT(std::abs(h.error()), 1e-5 * h.generated)
      << "generated " << h.generated << " J, to the ambient " << h.to_ambient << " J, carried " << h.carried
      << " J, stored " << h.stored << " J";
}

TEST(OperatingSchedule, StraightLinesBetweenThePointsHeldOutside) {
  const OperatingSchedule s({point(0, 100, 500, 300, 1e-3), point(10, 200, 300, 320, 2e-3), point(30, 200, -100, 320, 0)});
  EXPECT_EQ(s.segments(), 2u);
  EXPECT_EQ(s.segment_at(-1.0), 0u);
  EXPECT_EQ(s.segment_at(5.0), 0u);
  EXPECT_EQ(s.segment_at(10.0), 1u);
  EXPECT_EQ(s.segment_at(99.0), 1u);
  const SchedulePoint a = s.at(2.5);
  EXPECT_DOUBLE_EQ(a.load, 125.0);
  EXPECT_DOUBLE_EQ(a.speed, 450.0);
  EXPECT_DOUBLE_EQ(a.ambient, 305.0);
  EXPECT_DOUBLE_EQ(a.tilt, 1.25e-3);
  EXPECT_DOUBLE_EQ(s.at(20.0).speed, 100.0);  // through zero on the second segment
  EXPECT_DOUBLE_EQ(s.at(-5.0).load, 100.0);   // the first point's before the schedule
  EXPECT_DOUBLE_EQ(s.at(50.0).speed, -100.0);  // the last's after it
  // Both segments give the point between them.
  EXPECT_DOUBLE_EQ(s.on_segment(0, 10.0).speed, s.on_segment(1, 10.0).speed);
  EXPECT_DOUBLE_EQ(s.ambient_rate(0), 2.0);
  EXPECT_DOUBLE_EQ(s.ambient_rate(1), 0.0);
  EXPECT_THROW(OperatingSchedule({point(0, 100, 500, 300, 0)}), std::invalid_argument);
  EXPECT_THROW(OperatingSchedule({point(1, 100, 500, 300, 0), point(1, 100, 500, 300, 0)}), std::invalid_argument);
}

// Where an unloaded washer's speed turns back the march adds a point of rest (physics
// §19), on the schedule's line: the speed exactly zero there, the ambient and tilt the
// line's; nowhere else, and at an end where the zero rounds onto it.
TEST(OperatingSchedule, AnUnloadedWasherTurningBackRestsAtTheZero) {
  const std::vector<SchedulePoint> rests = OperatingSchedule::with_rests(
      {point(0, 100, 500, 300, 0), point(2, 0, 500, 300, 0), point(6, 0, -300, 340, 4e-3), point(8, 50, 100, 340, 0)});
  ASSERT_EQ(rests.size(), 5u);
  const SchedulePoint& rest = rests[2];
  EXPECT_DOUBLE_EQ(rest.time, 4.5);  // 500 of the 800 rad/s in 4 s
  EXPECT_EQ(rest.load, 0.0);
  EXPECT_EQ(rest.speed, 0.0);
  EXPECT_DOUBLE_EQ(rest.ambient, 325.0);
  EXPECT_DOUBLE_EQ(rest.tilt, 2.5e-3);
  EXPECT_TRUE(OperatingSchedule::unloaded_at_rest(rest));
  // Loaded where it turns back (the last segment), or unloaded at one end only: no rest.
  EXPECT_EQ(OperatingSchedule::with_rests({point(0, 100, 500, 300, 0), point(2, 100, -500, 300, 0)}).size(), 2u);
  EXPECT_EQ(OperatingSchedule::with_rests({point(0, 100, 500, 300, 0), point(2, 0, -500, 300, 0)}).size(), 2u);
  // A zero a rounding from the segment's start: the start is the rest.
  const std::vector<SchedulePoint> at_start =
      OperatingSchedule::with_rests({point(0, 100, 500, 300, 0), point(1000, 0, 1e-300, 300, 0), point(2000, 0, -545, 300, 0)});
  ASSERT_EQ(at_start.size(), 3u);
  EXPECT_TRUE(OperatingSchedule::unloaded_at_rest(at_start[1]));
}

// A schedule held at its last point (from the point before to its end): the march, and
// its end against the point study's steady state there. Held long enough, the cycle ends at the point's
// steady state: the slowest mode's share of the start's distance is then below e^−40,
// and what is left is IDA's error, a few times its relative tolerance (1e-6) of the
// temperatures (a contractive march does not accumulate it): 1e-4 K and 1e-5 of h_min/σ
// allow a hundred times that.
void expect_at_steady_state(const BearingState& end, const BearingState& steady) {
  EXPECT_NEAR(end.washer_mean_temperature, steady.washer_mean_temperature, 1e-4);
  EXPECT_NEAR(end.max_film_temperature, steady.max_film_temperature, 1e-4);
  EXPECT_NEAR(end.hmin_over_sigma, steady.hmin_over_sigma, 1e-5 * steady.hmin_over_sigma);
}

struct HeldCycle {
  StudyOutcome out;
  BearingState steady;
};
HeldCycle held_cycle(const std::string& schedule, const std::vector<std::string>& more = {}) {
  const Scene scene = cycle_scene(schedule, more);
  const std::vector<SchedulePoint>& points = schedule_of(scene);
  const double hold = points.back().time, held_from = points[points.size() - 2].time;
  BearingModel model(scene);
  HeldCycle held{run_study(model, {}), {}};
  EXPECT_FALSE(held.out.solver_failed) << held.out.message;
  BearingModel point(scene);
  OperatingSchedule::apply(point, schedule_of(scene).back());
  std::vector<double> u;
  EXPECT_TRUE(SteadySolver(point, newton_settings(scene)).solve_cold(u).converged);
  EXPECT_LT(40.0 * slowest_relaxation_time(point, u, 20), hold - held_from) << "hold the point longer";
  held.steady = point.describe(u);
  if (held.out.trajectory.empty()) return held;
  const TrajectorySample& end = held.out.trajectory.back();
  EXPECT_DOUBLE_EQ(end.time, hold);
  expect_at_steady_state(end.state, held.steady);
  return held;
}

TEST(DutyCycle, HeldAtAPointItEndsAtThePointsSteadyState) {
  const HeldCycle held =
      held_cycle("[{t: 0 s, load: 100 N}, {t: 5 s, load: 130 N, ambient: 30 degC}, {t: 600 s}]");
  ASSERT_FALSE(held.out.trajectory.empty());
  EXPECT_NEAR(*held.out.trajectory.back().ambient, 303.15, 1e-12);
  // No criterion was crossed and the bearing did not run away.
  for (const CycleEvent& e : cycle_of(held.out).events) EXPECT_TRUE(e.event == "end" || e.event == "worst") << e.event;
}

// A washer starting from rest under load, the most common start there is: 100 N at rest,
// run up to 545 rad/s in 5 s and held. The steady state at rest has no film pressure
// (every cavitation row at its kink), where the march once failed a few microseconds in;
// it starts from the film turning a millionth of the ramp on (cycle_start.h) and runs
// through to the point study's steady state at the end, the heat balance closed. The
// first sample is the rest: speed 0, no heat.
TEST(DutyCycle, AWasherStartsTurningFromRestUnderLoad) {
  const HeldCycle held = held_cycle("[{t: 0 s, load: 100 N, speed: 0 rad/s}, {t: 5 s, speed: 545 rad/s}, {t: 600 s}]");
  ASSERT_FALSE(held.out.trajectory.empty());
  const TrajectorySample& first = held.out.trajectory.front();
  EXPECT_EQ(first.time, 0.0);
  EXPECT_EQ(first.state.speed, 0.0);
  EXPECT_EQ(first.state.heat_generated, 0.0);
  expect_heat_balance(held.out);
}

// Nearly unloaded, the washer lifts off its film: ramped from 100 N to 1 N in 5 s and held,
// it rises from h_min/σ ≈ 6 to about 100 at the rate film 1's squeeze allows (the squeeze
// falls as h⁻³, the lift as h⁻²: fast at the end of the ramp) and ends at the point
// study's steady state at 1 N, within what the held point allows.
TEST(DutyCycle, UnloadedTo1NTheWasherLiftsToTheLightSteadyState) {
  const HeldCycle held = held_cycle("[{t: 0 s, load: 100 N}, {t: 5 s, load: 1 N}, {t: 600 s}]");
  ASSERT_FALSE(held.out.trajectory.empty());
  // The march itself lifted the washer: its film at the end ten times its start's.
  EXPECT_GT(held.out.trajectory.back().state.hmin_over_sigma, 10.0 * held.out.trajectory.front().state.hmin_over_sigma);
  expect_heat_balance(held.out);
}

// Unloaded to zero while turning (physics §19, "A load of zero"): the washer lifts off
// its film until the gear, riding on it, meets its stop at its axial play (100 µm); held
// unloaded, then loaded again, the cycle ends at the point study's steady state at 100 N,
// within what the held point allows. At zero load the stop's reaction presses the washer
// between its films: what film 1 carries (its pressure) is the stop's, the shares and
// f_eff are over it, and nothing is left undefined.
TEST(DutyCycle, UnloadedToZeroTheGearRestsOnItsStopAndComesBack) {
  const HeldCycle held =
      held_cycle("[{t: 0 s, load: 100 N}, {t: 5 s, load: 0 N}, {t: 10 s}, {t: 15 s, load: 100 N}, {t: 600 s}]",
                 {"geometry.gear.axial_play=100 um"});
  ASSERT_FALSE(held.out.trajectory.empty());
  int unloaded = 0;
  for (const TrajectorySample& p : held.out.trajectory) {
    if (p.state.load != 0.0) continue;
    ++unloaded;
    EXPECT_GT(p.state.hmin_over_sigma, 10.0 * held.out.trajectory.front().state.hmin_over_sigma) << "t = " << p.time;
    EXPECT_TRUE(std::isfinite(p.state.f_eff) && p.state.f_eff > 0.0) << "t = " << p.time;
    ASSERT_TRUE(p.state.stop_reaction) << "t = " << p.time;
    EXPECT_GT(*p.state.stop_reaction, 0.0) << "t = " << p.time << ": unloaded, the gear is on its stop";
  }
  EXPECT_GT(unloaded, 2) << "the march did not hold the washer unloaded";
  // Loaded again, the gear is back on its films.
  EXPECT_EQ(held.out.trajectory.back().state.stop_reaction, 0.0);
  expect_heat_balance(held.out);
}

// Held unloaded, the cycle ends at the steady state at zero load (Newton from its end:
// the steady solver's own start climbs from a load). There the stop's reaction is all
// film 1 carries, to the washer's row's tolerance (1e-10 of the force scale, 100 N); the
// march's end is within what a held point allows (held_cycle's reasons), its reaction,
// which follows film 2's gap through the asperities' tail (a log-slope of a few per σ at
// the few σ it sits at, on gaps held to 1e-6 of themselves), within 1e-4 of itself.
TEST(DutyCycle, HeldUnloadedItEndsAtTheSteadyStateOnTheStop) {
  const Scene scene = cycle_scene("[{t: 0 s, load: 100 N}, {t: 5 s, load: 0 N}, {t: 300 s}]",
                                  {"geometry.gear.axial_play=100 um"});
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  ASSERT_TRUE(cycle_of(out).end);
  BearingModel point(scene);
  OperatingSchedule::apply(point, schedule_of(scene).back());
  std::vector<double> u = cycle_of(out).end->unknowns;
  ASSERT_TRUE(SteadySolver(point, newton_settings(scene)).solve(u).converged);
  EXPECT_LT(40.0 * slowest_relaxation_time(point, u, 20), 295.0) << "hold the point longer";
  const BearingState steady = point.describe(u);
  ASSERT_TRUE(steady.stop_reaction);
  EXPECT_NEAR(*steady.stop_reaction, steady.fluid_force + steady.contact_force, 1e-9 * scene.operating.load);
  const BearingState& end = out.trajectory.back().state;
  expect_at_steady_state(end, steady);
  ASSERT_TRUE(end.stop_reaction);
  EXPECT_NEAR(*end.stop_reaction, *steady.stop_reaction, 1e-4 * *steady.stop_reaction);
  expect_heat_balance(out);
}

// Unloaded and at rest together (physics §19, "Unloaded at rest"): nothing holds the
// massless washer and gear, and the march holds them where they came to rest, from a
// millionth of the segment before the point to a millionth after the inputs leave it.
// Checked over a cycle: the events at those times; the rigid body held (its rows leave
// the differential unknowns at their predictor, constant over a held march, so h_min/σ
// is the rest's to rounding); no heat generated without speed, so the bearing cools at
// rest; and loaded and turning again, the cycle ends at the point study's steady state.
// `samples_at_rest`: how many samples at least have load and speed zero exactly.
void expect_rest_between(const StudyOutcome& out, double rest, double resume, int samples_at_rest) {
  std::vector<const CycleEvent*> events;
  for (const CycleEvent& e : cycle_of(out).events)
    if (e.event == "rest" || e.event == "resume") events.push_back(&e);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0]->event, "rest");
  EXPECT_NEAR(events[0]->time, rest, 1e-12 * rest);
  EXPECT_EQ(events[1]->event, "resume");
  EXPECT_NEAR(events[1]->time, resume, 1e-12 * resume);
  const auto at_rest_start = std::find_if(out.trajectory.begin(), out.trajectory.end(),
                                          [&](const TrajectorySample& p) { return p.time >= events[0]->time; });
  ASSERT_NE(at_rest_start, out.trajectory.end());
  EXPECT_DOUBLE_EQ(at_rest_start->time, events[0]->time) << "a sample where the rest begins";
  const BearingState& held = at_rest_start->state;
  int at_rest = 0;
  double mean_before = held.washer_mean_temperature;
  for (auto p = at_rest_start; p != out.trajectory.end() && p->time <= events[1]->time; ++p) {
    EXPECT_NEAR(p->state.hmin_over_sigma, held.hmin_over_sigma, 1e-12 * held.hmin_over_sigma) << "t = " << p->time;
    EXPECT_NEAR(p->state.gamma_x_ratio, held.gamma_x_ratio, 1e-12) << "t = " << p->time;
    EXPECT_TRUE(std::isfinite(p->state.f_eff) && std::isfinite(p->state.torque)) << "t = " << p->time;
    if (p->state.load != 0.0 || p->state.speed != 0.0) continue;
    ++at_rest;
    EXPECT_EQ(regime_of(p->state), Regime::at_rest);
    EXPECT_EQ(p->state.heat_generated, 0.0) << "t = " << p->time << ": heat without sliding";
    EXPECT_LE(p->state.washer_mean_temperature, mean_before) << "t = " << p->time << ": at rest the washer cools";
    mean_before = p->state.washer_mean_temperature;
  }
  EXPECT_GE(at_rest, samples_at_rest) << "the march did not hold the washer at rest";
}

TEST(DutyCycle, UnloadedAtRestTheBearingIsHeldCoolsAndStartsAgain) {
  const HeldCycle held = held_cycle("[{t: 0 s, load: 100 N}, {t: 5 s, load: 0 N, speed: 0 rad/s}, {t: 35 s}, "
                                    "{t: 40 s, load: 100 N, speed: 545 rad/s}, {t: 600 s}]",
                                    {"geometry.gear.axial_play=100 um"});
  ASSERT_FALSE(held.out.trajectory.empty());
  expect_rest_between(held.out, 5.0 - 5e-6, 35.0 + 5e-6, 3);
  // Cooled at rest: thirty seconds are five of the carrier's and gear's time constants
  // through their thickness (6.1 s, physics §19), e^−5 = 0.7 % of the washer's rise above
  // the ambient in that mode; slower paths in the bodies' planes leave more, and a tenth
  // allows them. (With heat generated at rest, or the temperatures held, it stays high.)
  const auto rise_at = [&](double t) {
    const auto p = std::find_if(held.out.trajectory.begin(), held.out.trajectory.end(),
                                [&](const TrajectorySample& s) { return s.time >= t; });
    return p->state.washer_mean_temperature - *p->ambient;
  };
  EXPECT_LT(rise_at(35.0), 0.1 * rise_at(5.0 - 5e-6));
  expect_heat_balance(held.out);
}

// On the bronze washer (configs/washers/bronze_cusn8.yaml, 5 × 24) the march cannot
// follow the washer to a millionth of its ramp from the zero: IDA's Newton fails on the
// film there, and the consistent start finds no balance a millionth after it. The rest
// then begins where the march stopped and ends where the balances find a state, each
// within a thousandth of its segment (physics §19), and the cycle goes on.
TEST(DutyCycle, WhereTheMarchCannotFollowToTheZeroTheRestBeginsWhereItStops) {
  const Scene scene =
      load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "geometry.gear.axial_play=100 um",
                  "study={type: duty_cycle, failure_load_at_worst: false, schedule: [{t: 0 s}, {t: 5 s, load: 0 N, "
                  "speed: 0 rad/s}, {t: 20 s}, {t: 25 s, load: 300 N, speed: 300 rad/s}, {t: 40 s}]}"});
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  ASSERT_FALSE(out.trajectory.empty());
  EXPECT_DOUBLE_EQ(out.trajectory.back().time, 40.0);
  double rest = NAN, resume = NAN;
  for (const CycleEvent& e : cycle_of(out).events) {
    if (e.event == "rest") rest = e.time;
    if (e.event == "resume") resume = e.time;
  }
  // The segments are 5 s: a thousandth is 5e-3 s, a millionth 5e-6 s.
  EXPECT_GE(rest, 5.0 - 5e-3);
  EXPECT_LT(rest, 5.0 - 5e-6) << "the march followed the washer to the millionth: no test of the rest's reach";
  EXPECT_GT(resume, 20.0 + 5e-6) << "balanced a millionth after the zero: no test of the rest's reach";
  EXPECT_LE(resume, 20.0 + 5e-3 * (1.0 + 1e-12));
  expect_rest_between(out, rest, resume, 3);
  expect_heat_balance(out);
}

// Unloaded while its speed turns back, the washer is at rest where the speed is zero: a
// point of the march's own (the schedule's line there), held about it as at any rest.
TEST(DutyCycle, UnloadedWhileItsSpeedTurnsBackTheWasherRestsAtTheZero) {
  const HeldCycle held = held_cycle("[{t: 0 s, load: 100 N}, {t: 5 s, load: 0 N}, {t: 10 s, speed: -545 rad/s}, "
                                    "{t: 15 s, load: 100 N}, {t: 600 s}]",
                                    {"geometry.gear.axial_play=100 um"});
  ASSERT_FALSE(held.out.trajectory.empty());
  // The zero halfway along the segment from 5 to 10 s, a sample of its own; the margins
  // are a millionth of the halves, 2.5 s each.
  expect_rest_between(held.out, 7.5 - 2.5e-6, 7.5 + 2.5e-6, 1);
  expect_heat_balance(held.out);
}

// The bodies hold heat: an ambient raised by 20 K in 0.05 s, short against the carrier's
// and gear's time constants (about 6 s through their 10 mm), leaves the washer's mean
// temperature well short of the new ambient's rise at first (its rise above the ambient
// falls by nearly the ambient's step), and it follows over the bodies' time. With the
// temperatures taken as rises above an ambient that moved without them (no moving
// reference), it would jump with the ambient at once.
TEST(DutyCycle, TheBodiesHeatCapacitiesDelayAnAmbientRamp) {
  const Scene scene = cycle_scene("[{t: 0 s, ambient: 24 degC}, {t: 0.05 s, ambient: 44 degC}, {t: 60 s}]");
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const TrajectorySample& start = out.trajectory.front();
  const auto at = [&](double t) {
    return *std::find_if(out.trajectory.begin(), out.trajectory.end(), [&](const TrajectorySample& s) { return s.time >= t; });
  };
  const double moved_at_ramp_end = at(0.05).state.washer_mean_temperature - start.state.washer_mean_temperature;
  const double moved_at_end = out.trajectory.back().state.washer_mean_temperature - start.state.washer_mean_temperature;
  EXPECT_LT(moved_at_ramp_end, 0.5 * 20.0);
  EXPECT_GT(moved_at_end, 0.9 * 20.0);  // after ten time constants, nearly all of it
  expect_heat_balance(out);
}

// A ramp past W_d runs away (the temperatures accelerate with the slowest mode unstable),
// after the ramp has passed W_d (the bodies lag the quasi-steady branch) and before the
// schedule ends; one that stops 5 % short of W_d settles without a runaway or a crossing.
TEST(DutyCycle, ARampPastDistressRunsAwayAndOneShortOfItDoesNot) {
  const Scene base = cycle_scene("[{t: 0 s}, {t: 1 s}]");
  double w_d = 0.0;
  {
    BearingModel model(base);
    DistressSearchSettings settings;
    settings.load_start = 100.0;
    settings.load_end = 400.0;
    settings.march_past_distress = false;
    const DistressSearch found = search_distress(model, settings, {});
    ASSERT_TRUE(found.row.distress_load);
    w_d = *found.row.distress_load;
  }
  const double ramp = 20.0;  // s, from 100 N to the top load
  for (const double top : {1.05 * w_d, 0.95 * w_d}) {
    SCOPED_TRACE(fmt::format("up to {:.6g} N (W_d {:.6g} N)", top, w_d));
    const Scene scene = cycle_scene(fmt::format("[{{t: 0 s, load: 100 N}}, {{t: {} s, load: {} N}}, {{t: 200 s}}]",
                                                ramp, top));
    BearingModel model(scene);
    const StudyOutcome out = run_study(model, {});
    ASSERT_FALSE(out.solver_failed) << out.message;
    const std::vector<CycleEvent>& events = cycle_of(out).events;
    const auto runaway =
        std::find_if(events.begin(), events.end(), [](const CycleEvent& e) { return e.event == "runaway"; });
    if (top > w_d) {
      ASSERT_NE(runaway, events.end());
      const double passes_w_d = ramp * (w_d - 100.0) / (top - 100.0);
      EXPECT_GT(runaway->time, passes_w_d);
      EXPECT_GT(runaway->load, w_d);
      // Held past W_d it ends on the hot branch, where the slow mode is stable again.
      const auto settled =
          std::find_if(runaway, events.end(), [](const CycleEvent& e) { return e.event == "settled"; });
      ASSERT_NE(settled, events.end());
      EXPECT_GT(out.trajectory.back().state.contact_share, 0.5);
      expect_heat_balance(out);  // through the runaway, with much heat stored
    } else {
      EXPECT_EQ(runaway, events.end()) << "at t = " << runaway->time;
      for (const CycleEvent& e : events) EXPECT_NE(e.event, "crossing");
      EXPECT_GT(*out.trajectory.back().least_margin, 0.0);
    }
  }
}

// A step past W_d runs away in the time the fold's slow mode predicts (physics §19). In the
// fold's normal form c·ẋ = −(a·δ + b·x²) (x along the null vector, δ the load past the
// fold W*), the trajectory from the cool branch reaches the ghost's middle, where the slow
// mode turns unstable (the runaway event), after (π/2)·c/√(a·b·δ); below the fold the slow
// mode's rate is μ(λ) = (2/c)·√(a·b·(W* − λ)), so that with τ₁ = 1/μ at a load λ₁ just
// below it the time is π·τ₁·√((W* − λ₁)/δ). The normal form is exact as δ → 0 and off by
// O(√δ) beside it (the cubic terms; the approach from the start adds less): the march's
// time tends to the prediction, its relative error falling about as √δ, by 2 from δ =
// 0.2 % to 0.05 % of W* (measured: 0.16 and 0.05 with the squeeze on). Asserted: within 15 % at
// 0.05 %, and the error at least 1.5 times smaller than at 0.2 %.
TEST(DutyCycle, AStepPastDistressRunsAwayInTheTimeTheFoldsSlowModePredicts) {
  const Scene base = cycle_scene("[{t: 0 s}, {t: 1 s}]");
  BearingModel model(base);
  DistressSearchSettings settings;
  settings.load_start = 100.0;
  settings.load_end = 400.0;
  settings.march_past_distress = false;
  const DistressSearch found = search_distress(model, settings, {});
  ASSERT_TRUE(found.row.fold_load && found.row.bracket_low && !found.bracket_state.empty());
  const double fold = *found.row.fold_load, below = *found.row.bracket_low;
  model.set_load(below);
  const double tau = slowest_relaxation_time(model, found.bracket_state, 20);

  // The march's time to the runaway after a step to W*·(1 + share), against the prediction.
  const auto relative_error = [&](double share) {
    const double delta = share * fold, step_at = 0.5;
    const double predicted = M_PI * tau * std::sqrt((fold - below) / delta);
    const Scene scene = cycle_scene(fmt::format("[{{t: 0 s, load: {} N}}, {{t: {} s, load: {} N}}, {{t: {} s}}]",
                                                0.95 * fold, step_at, fold + delta, step_at + 4.0 * predicted));
    BearingModel cycle(scene);
    const StudyOutcome out = run_study(cycle, {});
    EXPECT_FALSE(out.solver_failed) << out.message;
    const std::vector<CycleEvent>& events = cycle_of(out).events;
    const auto runaway =
        std::find_if(events.begin(), events.end(), [](const CycleEvent& e) { return e.event == "runaway"; });
    if (runaway == events.end()) {
      ADD_FAILURE() << "no runaway " << share << " of W_d past it";
      return 1.0;
    }
    return std::abs(runaway->time - step_at - predicted) / predicted;
  };
  const double nearer = relative_error(0.0005), farther = relative_error(0.002);
  EXPECT_LT(nearer, 0.15) << "τ₁ " << tau << " s at " << below << " N, W_d " << fold << " N";
  EXPECT_LT(1.5 * nearer, farther);
}

// A washer that stops and turns back (physics §19, "Speed through zero"): the march goes
// through ω = 0, where the film has no lift and the asperities carry the load (boundary),
// and comes back to a film that carries it at the reversed speed; the heat balance
// closes through it.
TEST(DutyCycle, TheSpeedGoesThroughZero) {
  const Scene scene = cycle_scene(
      "[{t: 0 s, speed: 545 rad/s}, {t: 10 s, speed: 0 rad/s}, {t: 20 s, speed: -545 rad/s}, {t: 600 s}]");
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const auto at_rest = std::find_if(out.trajectory.begin(), out.trajectory.end(),
                                    [](const TrajectorySample& s) { return s.time >= 10.0; });
  ASSERT_NE(at_rest, out.trajectory.end());
  EXPECT_EQ(at_rest->state.speed, 0.0);
  EXPECT_EQ(regime_of(at_rest->state), Regime::boundary);
  const TrajectorySample& end = out.trajectory.back();
  EXPECT_EQ(end.state.speed, -545.0);
  EXPECT_EQ(regime_of(end.state), regime_of(out.trajectory.front().state));
  // The washer is symmetric under reversal (a property test of the model): held long
  // enough (the slow mode's share below e^−40) it is back at the state it started from,
  // to IDA's error, as in HeldAtAPointItEndsAtThePointsSteadyState.
  BearingModel start(scene);
  OperatingSchedule::apply(start, schedule_of(scene).front());
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(start, newton_settings(scene)).solve_cold(u).converged);
  ASSERT_LT(40.0 * slowest_relaxation_time(start, u, 20), 600.0 - 20.0) << "hold the reversed speed longer";
  EXPECT_NEAR(end.state.washer_mean_temperature, out.trajectory.front().state.washer_mean_temperature, 1e-4);
  EXPECT_NEAR(end.state.max_film_temperature, out.trajectory.front().state.max_film_temperature, 1e-4);
  expect_heat_balance(out);
}

// A long cycle run in two parts, the second continued from the first's end (through its
// file, as twb run --continue-from reads it), ends where the whole cycle ends, to the
// last bit: the whole march restarts IDA at the same point of the schedule, from the same
// state (the file holds every double exactly).
TEST(DutyCycle, ACycleRunInTwoPartsEndsAsTheWholeCycle) {
  const std::string a = "{t: 0 s, load: 100 N}, {t: 5 s, load: 150 N, speed: 600 rad/s}, {t: 10 s}";
  const std::string b = "{t: 10 s, load: 150 N, speed: 600 rad/s}, {t: 14 s, load: 120 N, ambient: 30 degC}, {t: 20 s}";
  const Scene whole_scene = cycle_scene("[" + a + ", {t: 14 s, load: 120 N, ambient: 30 degC}, {t: 20 s}]");
  BearingModel whole_model(whole_scene);
  const StudyOutcome whole = run_study(whole_model, {});
  ASSERT_FALSE(whole.solver_failed) << whole.message;

  const Scene first_scene = cycle_scene("[" + a + "]");
  BearingModel first_model(first_scene);
  const StudyOutcome first = run_study(first_model, {});
  ASSERT_TRUE(cycle_of(first).end);
  const std::string file = ::testing::TempDir() + "twb_cycle_end_state.json";
  { std::ofstream(file) << cycle_state_json(*cycle_of(first).end); }
  const CycleState end = read_cycle_state(file);
  EXPECT_EQ(end.unknowns, cycle_of(first).end->unknowns);

  const Scene second_scene = cycle_scene("[" + b + "]");
  BearingModel second_model(second_scene);
  const StudyOutcome second = run_study(second_model, {}, RunOptions{.cycle_start = &end});
  ASSERT_FALSE(second.solver_failed) << second.message;
  EXPECT_EQ(second.trajectory.front().time, 10.0);
  const BearingState& w = whole.trajectory.back().state;
  const BearingState& s = second.trajectory.back().state;
  EXPECT_EQ(s.washer_mean_temperature, w.washer_mean_temperature);
  EXPECT_EQ(s.max_film_temperature, w.max_film_temperature);
  EXPECT_EQ(s.hmin_over_sigma, w.hmin_over_sigma);
  EXPECT_EQ(cycle_of(second).end->unknowns, cycle_of(whole).end->unknowns);

  // Refused: a schedule that does not start where the end was, another bearing's state.
  const Scene elsewhere = cycle_scene("[{t: 10 s, load: 160 N, speed: 600 rad/s}, {t: 20 s}]");
  BearingModel elsewhere_model(elsewhere);
  try {
    run_study(elsewhere_model, {}, RunOptions{.cycle_start = &end});
    ADD_FAILURE() << "a schedule starting elsewhere was continued";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("starts where the last one ended"), std::string::npos) << e.what();
  }
  const Scene finer = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                 {"mesh.radial_nodes=9", "mesh.circumferential_nodes=24",
                                  "study={type: duty_cycle, schedule: [" + b + "]}"});
  BearingModel finer_model(finer);
  try {
    run_study(finer_model, {}, RunOptions{.cycle_start = &end});
    ADD_FAILURE() << "another bearing's state was continued";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("another bearing"), std::string::npos) << e.what();
  }
  // The other film sliding is another bearing too (operating.sliding is the bearing's).
  const Scene other_film = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                      {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                       "operating.sliding=washer_gear", "study={type: duty_cycle, schedule: [" + b + "]}"});
  BearingModel other_film_model(other_film);
  EXPECT_THROW(run_study(other_film_model, {}, RunOptions{.cycle_start = &end}), std::invalid_argument);
  // Only a duty cycle goes on from an end: a point study given one says so, not ignores it.
  BearingModel point_model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                      {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study={type: point}"}));
  try {
    run_study(point_model, {}, RunOptions{.cycle_start = &end});
    ADD_FAILURE() << "a point study went on from a cycle's end";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("this scene's study is a point"), std::string::npos) << e.what();
  }
  std::remove(file.c_str());
}

// A limit's crossing is where the marched state's margin is zero (physics §19): the
// cycle cut short at a crossing's time ends on the limit. Both marches take the same
// steps until the crossing's, so the cut one's end differs from the whole one's state
// there by the last step's local error and the interpolation's, each within IDA's
// tolerance, 1e-6 of the unknowns (a temperature's rise above the ambient, about 40 K
// here: 4e-5 K; h_min/σ near 3.7: 3.7e-6): ten times that is allowed. Measured: 1.5e-5 K
// and 4.5e-7. (The straight line between the steps either side, where the crossing was
// put before, misses by the margin's curvature over a step: 3.5e-3 K and 2.6e-4 here,
// both past it.)
TEST(DutyCycle, ALimitIsCrossedWhereTheStatesMarginIsZero) {
  const std::string ramp = "{t: 0 s, load: 100 N}, {t: 10 s, load: 170 N}";
  const auto run = [&](const std::string& schedule, const std::vector<std::string>& limits) {
    std::vector<std::string> sets{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "operating.load=100 N",
                                  "study={type: duty_cycle, schedule: [" + schedule + "], failure_load_at_worst: false}"};
    sets.insert(sets.end(), limits.begin(), limits.end());
    BearingModel model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", sets));
    StudyOutcome out = run_study(model, {});
    EXPECT_FALSE(out.solver_failed) << out.message;
    return out;
  };
  // Limits half way between the start's values and the end's.
  const StudyOutcome free = run(ramp + ", {t: 30 s}", {});
  ASSERT_GE(free.trajectory.size(), 2u);
  const BearingState& a = free.trajectory.front().state;
  const BearingState& b = free.trajectory.back().state;
  const double flash = 0.5 * (a.oil_peak_temperature + b.oil_peak_temperature);
  const double ambient = *free.trajectory.front().ambient;
  const double ratio = 0.5 * (a.hmin_over_sigma + b.hmin_over_sigma);
  const std::vector<std::string> limits{fmt::format("lubricant.flash_temperature={:.17g} K", flash),
                                        fmt::format("limits.min_film_ratio={:.17g}", ratio)};
  const StudyOutcome whole = run(ramp + ", {t: 30 s}", limits);
  int crossings = 0;
  for (const CycleEvent& e : cycle_of(whole).events) {
    if (e.event != "crossing") continue;
    ++crossings;
    SCOPED_TRACE(fmt::format("{} at t = {:.12g} s", limit_name(*e.criterion), e.time));
    const std::string cut = e.time < 10.0 ? fmt::format("{{t: 0 s, load: 100 N}}, {{t: {:.17g} s, load: {:.17g} N}}",
                                                        e.time, e.load)
                                          : fmt::format("{}, {{t: {:.17g} s}}", ramp, e.time);
    const StudyOutcome short_of = run(cut, limits);
    ASSERT_FALSE(short_of.trajectory.empty());
    const BearingState& end = short_of.trajectory.back().state;
    if (*e.criterion == LimitKind::oil_peak_temperature)
      EXPECT_NEAR(end.oil_peak_temperature, flash, 10.0 * 1e-6 * (flash - ambient));
    else if (*e.criterion == LimitKind::film_ratio)
      EXPECT_NEAR(end.hmin_over_sigma, ratio, 10.0 * 1e-6 * ratio);
    else
      ADD_FAILURE() << "an unexpected criterion";
  }
  EXPECT_EQ(crossings, 2);
}

}  // namespace
}  // namespace twb
