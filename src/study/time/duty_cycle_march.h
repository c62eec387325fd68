// The duty cycle (duty_cycle.h) as its steps, with the march's state in one place. From
// the state at the schedule's first point (the start: cycle_start.h):
//   1. segment       IDA from one point of the schedule to the next, every step
//                    recorded, its margins and the runaway watched (cycle_watch.h,
//                    runaway_watch.h), a kink of the model passed by a restart
//   2. rest          an unloaded washer at rest held where it came to rest, and its
//                    balances given back as it leaves (cycle_segment.cpp: 1 and 2)
//   3. crossing      where between two steps a criterion's margin is zero, on IDA's
//                    interpolating polynomial (duty_cycle_march.cpp, with IDA's starts,
//                    steps and the heat they bank)
//   4. end           the trajectory's last state, the heat stored, why it ended early
//   5. worst moment  the least allowance left, and the failure load there
//                    (cycle_end.cpp: 4 and 5)
// The summary of what the cycle did is cycle_summary.h.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/ida_transient.h"
#include "study/time/cycle_watch.h"
#include "study/time/operating_schedule.h"
#include "study/time/runaway_watch.h"
#include "system/steady_system.h"
#include "twb/results/cycle_table.h"
#include "twb/study/study_outcome.h"

namespace twb {

// What a march integrates along the cycle besides its heat: `count` functions of the state
// (a life's wear rate at every depth node: cycle_life.h), integrated as the heat is, by
// IDA's own formula on its steps, from the cycle's start.
struct CycleIntegrands {
  std::size_t count = 0;
  std::function<void(std::span<const double> u, std::span<double> rates)> rates;
};

class DutyCycleMarch {
 public:
  // From u, the state at the schedule's first point, the model set to its inputs, as
  // `settings` say (the study's, or a life's repeated cycle's). The march keeps
  // references to model, schedule, settings, out and progress: they must outlive it.
  DutyCycleMarch(BearingModel& model, const OperatingSchedule& schedule, const DutyCycleSettings& settings,
                 std::vector<double> u, StudyOutcome& out, const ProgressReport& progress,
                 CycleIntegrands integrands = {});
  // The washer's balances given back, however the march ended.
  ~DutyCycleMarch() { model_.hold_at_rest({}); }
  DutyCycleMarch(const DutyCycleMarch&) = delete;
  DutyCycleMarch& operator=(const DutyCycleMarch&) = delete;
  DutyCycleMarch(DutyCycleMarch&&) = delete;  // the watch and IDA's settings refer to this
  DutyCycleMarch& operator=(DutyCycleMarch&&) = delete;

  // Steps 1-5 in turn, once, the cycle's events then in time order (`bearing`: this
  // one's, for the state the cycle ends in). False where the march did not start (out
  // says so).
  bool run(const std::string& bearing);
  // The integrands' integrals over the march (CycleIntegrands), once run.
  const std::vector<double>& integrals() const { return integrals_; }

 private:
  // Steps 1-3: every segment in turn, until the schedule's end or a segment that ends
  // the march; the model then quasi-steady (no rest held, no tilt rate, its own rows).
  void follow_schedule();
  // Whether the march started (a first state recorded); out says so where it did not.
  bool check_started();
  // Step 4, once the march started.
  void record_end(const std::string& bearing);
  // Step 5.
  void worst_moment();

  // The segment being marched (cycle_segment.cpp): its march from a to b, and the rest
  // at its start a (held from a, and the balances given back a little after it).
  void march_segment();
  void rest_at_start(const SchedulePoint& a, const SchedulePoint& b, double span, bool rest_b);

  // IDA started at (t, u_), consistent values computed afresh: at every point of the
  // schedule (the inputs' rates jump there, and so do the state's) and where the rest
  // begins or ends. (`kink`: a restart inside a segment, after IDA failed at a kink of
  // the model, where the inputs' rates do not jump: the runaway watch keeps its trend.)
  TransientStatus start_at(double t, bool kink = false);
  // IDA's steps from its time to `to`, each recorded, u_ the state reached: why it
  // stopped short, empty where it did not. A kink of the model (contact or cavitation
  // switching on) is passed by one restart; a march that fails again and again has ended.
  std::string step_to(double to);
  // The step's sample at (t, state): its margins, crossings and any runaway.
  void record(double t, std::span<const double> state);
  // The heat and work IDA holds since its last start, added to the cycle's.
  void bank();
  // Step 3: where between the steps at a and b the criterion's margin is zero.
  std::optional<SchedulePoint> locate_crossing(double a, double b, LimitKind kind);
  // The state at (t, state) described, once for every use IDA's step makes of it.
  const BearingState& describe_at(double t, std::span<const double> state);
  void rest_event(bool held, double t);
  TransientSettings transient_settings();
  TransientStatus start_in_own_rows(double t);
  // The bodies' heat content (J) at state u and ambient T_a: Σ ρ·c·t·A·(T_a + ϑ) over
  // every body node (the capacities of physics §7, in physical units).
  static double heat_content(const BearingModel& model, std::span<const double> u, double ambient);

  BearingModel& model_;
  const OperatingSchedule& schedule_;
  std::vector<double> u_;
  StudyOutcome& out_;
  DutyCycleOutcome& cycle_;  // out_'s own part: the events, the end, the heat balance
  const ProgressReport& progress_;
  const DutyCycleSettings& settings_;
  const CycleIntegrands integrands_;
  std::vector<double> integrals_;

  // The inputs on the segment being marched, set at every evaluation's time.
  std::size_t segment_ = 0;
  // IDAS evaluates the heat's rates once a step, at the state the step ends on: the
  // state described there is the step's sample too (described once).
  struct Described {
    double t = 0.0;
    std::vector<double> u;
    BearingState state;
  } described_;
  CycleHeat heat_;
  const double content_at_start_;
  IdaTransient ida_;
  // IDA's Newton starts each step from its predictor, close: it works on the Newton form
  // of the model's complementarity rows (the minimum, piecewise linear, as continuation's
  // correctors do), whose roots are the model's own. Fischer–Burmeister's curvature at
  // the cavitation boundary failed its iterations over and over where a lightly loaded
  // washer lifts: a ramp from 100 to 1 N and a hold took 6802 steps, 201 in this form.
  // The consistent starts (KINSOL from rates of zero, not close) keep the model's own
  // rows. Held from construction to the schedule's end.
  std::optional<NewtonForm> march_form_;
  // Whether IDA holds heat and work since its last start that bank() has not taken: a
  // start that fails leaves IDA as it was, already banked.
  bool unbanked_ = false;
  std::vector<double> between_;  // the state inside a step, where a crossing is sought
  CycleWatch watch_;
  RunawayWatch runaway_;
  std::string ended_;  // why the march ended before the schedule did
  // Whether IDA has started once: its first consistent state is the trajectory's first
  // sample (recorded by the first start, never again).
  bool started_ = false;
  bool ran_ = false;  // run() is called once only
};

}  // namespace twb
