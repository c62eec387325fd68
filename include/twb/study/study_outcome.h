// What a study gives back: solved states, distress rows, the transient's trajectory,
// fold curves, with what the run cost; how to run it (threads, resume journal); the
// progress callback.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "twb/results/calibration_table.h"
#include "twb/results/cycle_state.h"
#include "twb/results/cycle_table.h"
#include "twb/results/distress_table.h"
#include "twb/results/fold_curve_table.h"
#include "twb/results/reliability_table.h"
#include "twb/results/run_timings.h"
#include "twb/results/sensitivity_table.h"
#include "twb/results/sliding_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "twb/scene/scene.h"

namespace twb {

struct StudyOutcome {
  std::vector<SolvedState> states;
  std::vector<DistressRow> distress;  // load_sweep, distress_map, sliding_choice: one row per search
  std::vector<std::string> parameter_columns;  // the study's axes (run_axes.h), e.g. "friction_coefficient"
  bool sliding_column = false;        // sliding_choice: rows name their sliding film
  // transient; load_sweep, sliding_choice: the first step past distress of each search;
  // duty_cycle: the bearing along the cycle
  std::vector<TrajectorySample> trajectory;
  std::vector<SlidingRow> sliding;    // sliding_choice: both configurations at every grid load
  // distress_curve: the fold along the curve parameter (fold_curve.csv) and its column
  std::vector<FoldCurveRow> fold_curve;
  std::string fold_curve_column;
  std::vector<SensitivityRow> sensitivity;  // sensitivity: each quantity against each input
  std::vector<ReliabilityRow> reliability;   // reliability: each probability of failure
  std::vector<DesignPointRow> design_points;  // reliability: the inputs at each design point
  std::vector<CalibrationRow> calibration;             // calibration: each fitted input
  std::vector<CorrelationRow> correlations;            // calibration: each pair of fitted inputs
  std::vector<CalibrationPointRow> calibration_points;  // calibration: each measured value
  std::vector<CycleEvent> cycle_events;  // duty_cycle: crossings, runaway, the worst moment, the end
  std::optional<CycleState> cycle_end;   // duty_cycle: where a completed cycle ended, to go on from
  std::optional<CycleHeat> cycle_heat;   // duty_cycle: the heat balance over the march
  std::vector<std::string> summary;  // lines for the end of the run's output (e.g. the cusp)
  bool speeds_in_rpm = false;        // the scene gave its speeds in rpm: the summaries say rpm
  // The solvers' own words where a search went on regardless (twb run --verbose).
  std::vector<std::string> diagnostics;
  bool solver_failed = false;  // a state the study needed could not be solved
  bool stopped = false;        // RunOptions::stop ended it early: some searches are missing
  std::string message;
  RunTimings timings;
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
  // A duty cycle continued from where an earlier one ended (its StudyOutcome::cycle_end,
  // or twb run --continue-from DIR): the march starts from that state instead of the
  // steady state at the schedule's start, whose first point must be the end's time and
  // inputs (std::invalid_argument otherwise, for another bearing's state, or for a study
  // of another type: check_continuable).
  const CycleState* cycle_start = nullptr;
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

}  // namespace twb
