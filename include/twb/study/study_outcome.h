// What a study gives back: solved states, distress rows, the transient's trajectory, and
// what only its type gives (a fold curve, probabilities, a cycle's events, ...), with what
// the run cost; how to run it (threads, where its searches run); the progress callback.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "twb/error_family.h"
#include "twb/results/calibration_table.h"
#include "twb/results/cycle_state.h"
#include "twb/results/cycle_table.h"
#include "twb/results/distress_table.h"
#include "twb/results/fold_curve_table.h"
#include "twb/results/life_table.h"
#include "twb/results/reliability_table.h"
#include "twb/results/run_timings.h"
#include "twb/results/sensitivity_table.h"
#include "twb/results/sliding_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "twb/results/worn_washer.h"
#include "twb/scene/scene.h"

namespace twb {

class SearchScheduler;

// What a study type gives back beyond what every type shares, one struct per type that
// has any (point, load_sweep, distress_map and transient have none).

// sliding_choice: both configurations at every grid load.
struct SlidingChoiceOutcome {
  std::vector<SlidingRow> rows;
};

// distress_curve: the fold along the curve parameter (fold_curve.csv), and the column
// that holds the parameter.
struct DistressCurveOutcome {
  std::vector<FoldCurveRow> rows;
  std::string column;
};

// sensitivity: each quantity against each input.
struct SensitivityOutcome {
  std::vector<SensitivityRow> rows;
};

struct ReliabilityOutcome {
  std::vector<ReliabilityRow> rows;           // each probability of failure
  std::vector<DesignPointRow> design_points;  // the inputs at each design point
};

struct CalibrationOutcome {
  std::vector<CalibrationRow> fitted;        // each fitted input
  std::vector<CorrelationRow> correlations;  // each pair of fitted inputs
  std::vector<CalibrationPointRow> points;   // each measured value
};

struct DutyCycleOutcome {
  std::vector<CycleEvent> events;  // crossings, runaway, the worst moment, the end
  std::optional<CycleState> end;   // where a completed cycle ended, to go on from
  std::optional<CycleHeat> heat;   // the heat balance over the march
};

// life: the washer at every reported time of its slow time, the last row saying how its
// life ended (the duration, the wear allowance or distress).
struct LifeOutcome {
  std::vector<LifeRow> rows;
  // The washer at each row's time (worn_profile.csv); the last is worn_washer.json.
  std::vector<WornWasher> worn;
};

// The outcome of the type that ran, where it has one of its own (monostate for the
// others): the alternative its runner made.
using OwnOutcome = std::variant<std::monostate, SlidingChoiceOutcome, DistressCurveOutcome, SensitivityOutcome,
                                ReliabilityOutcome, CalibrationOutcome, DutyCycleOutcome, LifeOutcome>;

struct StudyOutcome {
  std::vector<SolvedState> states;
  std::vector<DistressRow> distress;  // load_sweep, distress_map, sliding_choice: one row per search
  std::vector<std::string> parameter_columns;  // the study's axes (run_axes.h), e.g. "friction_coefficient"
  bool sliding_column = false;        // sliding_choice: rows name their sliding film
  // transient; load_sweep, sliding_choice: the first step past distress of each search;
  // duty_cycle: the bearing along the cycle
  std::vector<TrajectorySample> trajectory;
  // What only the type that ran gives back. Code that knows the type reads it with
  // std::get (its runner made it, so it is there); code that does not, with the
  // accessors below.
  OwnOutcome own;
  std::vector<std::string> summary;  // lines for the end of the run's output (e.g. the cusp)
  bool speeds_in_rpm = false;        // the scene gave its speeds in rpm: the summaries say rpm
  // The solvers' own words where a search went on regardless (twb run --verbose).
  std::vector<std::string> diagnostics;
  bool solver_failed = false;  // a state the study needed could not be solved
  bool stopped = false;        // RunOptions::stop ended it early: some searches are missing
  std::string message;
  RunTimings timings;

  // Each type's own outcome, nullptr for a study of another type.
  const SlidingChoiceOutcome* sliding_choice() const { return std::get_if<SlidingChoiceOutcome>(&own); }
  const DistressCurveOutcome* distress_curve() const { return std::get_if<DistressCurveOutcome>(&own); }
  const SensitivityOutcome* sensitivity() const { return std::get_if<SensitivityOutcome>(&own); }
  const ReliabilityOutcome* reliability() const { return std::get_if<ReliabilityOutcome>(&own); }
  const CalibrationOutcome* calibration() const { return std::get_if<CalibrationOutcome>(&own); }
  const DutyCycleOutcome* duty_cycle() const { return std::get_if<DutyCycleOutcome>(&own); }
  const LifeOutcome* life() const { return std::get_if<LifeOutcome>(&own); }

  // The type's own outcome, for its runner and the code it calls to fill: made empty by
  // the first call (the runner's first step, so that a run that ends early still writes
  // its type's tables), the same one after. Another type's already there is a bug.
  template <class Own>
  Own& own_part() {
    if (std::holds_alternative<std::monostate>(own)) own.emplace<Own>();
    if (Own* part = std::get_if<Own>(&own)) return *part;
    throw InternalError("a study's outcome holds another type's own part");
  }
};

using ProgressReport = std::function<void(const std::string&)>;

struct RunOptions {
  // Threads for the study's independent searches (speeds, parameter values, sliding
  // films); 0: one per core. The results do not depend on it. One by default: a program
  // embedding twb owns its cores (twb run and twb.run use every core unless told).
  int threads = 1;
  // When set (from any thread), the searches not yet begun are not run: the study ends
  // with what it has and StudyOutcome::stopped. A search under way runs to its end, and
  // a study of one piece of work (point, transient, fold curve) is not stopped.
  const std::atomic<bool>* stop = nullptr;
  // A duty cycle continued from where an earlier one ended (its DutyCycleOutcome::end,
  // or twb run --continue-from DIR): the march starts from that state instead of the
  // steady state at the schedule's start, whose first point must be the end's time and
  // inputs (std::invalid_argument otherwise, for another bearing's state, or for a study
  // of another type: check_continuable).
  const CycleState* cycle_start = nullptr;
  // Where the study's independent searches run (twb/study/search_scheduler.h): unset, on
  // `threads` threads here. Studies of one piece of work run here whatever it says.
  SearchScheduler* scheduler = nullptr;
};

// The tables a study writes, named by their file's stem ("states", "distress",
// "sliding", "fold_curve", "trajectory"): the results directory's CSV files and the
// Python module's tables are both made from this list, so they hold the same columns.
// The state fields (output.fields) are per state: fields_table(state.fields).
struct NamedTable {
  std::string name;
  ResultTable table;
};
std::vector<NamedTable> study_tables(const StudyOutcome& outcome, StudyType type);

// The lines a run ends with, as twb run prints them: each search's distress and failure
// line ("distress at 545 rad/s: W_d = ...", "failure at 545 rad/s: fails at ... by ..."),
// then StudyOutcome::summary (the limits' notes follow them: limit_notes.h).
std::vector<std::string> summary_lines(const StudyOutcome& outcome);

// Whether a study is made of independent distress searches (load_sweep, distress_map,
// sliding_choice): what threads, MPI ranks and the slices of a job array share out, and
// what RunOptions::stop can stop between. A followed distress map is one piece of work
// (each combination starts from its neighbour's).
bool has_independent_searches(const Study& study);
// Whether a study's work spreads over the ranks of an MPI job: its independent searches,
// or a reliability study's Monte Carlo samples (whose batches share what they found, so
// that the slices of a job array, which cannot share, do not take them).
bool spreads_over_ranks(const Study& study);
// A study asked to go on from where an earlier run ended (a duty cycle's end state:
// RunOptions::cycle_start, twb run --continue-from, twb.run's continue_from, named by
// `asked_by`): std::invalid_argument unless its type can.
void check_continuable(const Study& study, std::string_view asked_by);
// Where a duty cycle goes on from when asked by a results directory (twb run
// --continue-from DIR, twb.run(continue_from=DIR), named by `asked_by`): the end state an
// earlier run wrote into `from` (cycle_end_state.json), for a run whose results go to
// `out` (empty: none written). std::invalid_argument for a study that cannot go on
// (check_continuable, first), for `out` the directory `from` itself (the new end state
// would replace the one it starts from), and for a directory without an end state.
CycleState cycle_to_continue(const Study& study, const std::string& from, const std::string& out,
                             std::string_view asked_by);
// Where a run goes on from when asked by a results directory (twb run --continue-from DIR,
// twb.run(continue_from=DIR), named by `asked_by`): a duty cycle from the end state an
// earlier cycle wrote into `from` (cycle_to_continue, returned); any study, a duty cycle
// too, from the washer a life wore (`from`/worn_washer.json, set as scene.worn by
// set_worn_washer): a life goes on from its time, every other study holds its depths. std::invalid_argument
// where `from` holds neither, is `out` itself (the results it starts from would be
// replaced), or its washer does not fit the scene.
std::optional<CycleState> continue_from(Scene& scene, const std::string& from, const std::string& out,
                                        std::string_view asked_by);
// Sets scene.worn, checked: the scene has the wear effect (the depths are its unknowns)
// and slides on the film the washer was worn in, of the same annulus (its mesh may
// differ: the depths are interpolated). std::invalid_argument naming `asked_by` and
// where the washer was read from otherwise.
void set_worn_washer(Scene& scene, WornWasher worn, std::string_view asked_by);

}  // namespace twb
