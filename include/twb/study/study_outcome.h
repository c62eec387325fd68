// What a study gives back: solved states, distress rows, the transient's trajectory,
// fold curves, with what the run cost; how to run it (threads, resume journal); the
// progress callback.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "twb/results/distress_table.h"
#include "twb/results/fold_curve_table.h"
#include "twb/results/run_timings.h"
#include "twb/results/sliding_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "twb/scene/scene.h"

namespace twb {

struct StudyOutcome {
  std::vector<SolvedState> states;
  std::vector<DistressRow> distress;  // load_sweep, distress_map, sliding_choice: one row per search
  std::string parameter_column;       // the study's second axis, e.g. "friction_coefficient"
  bool sliding_column = false;        // sliding_choice: rows name their sliding film
  // transient; load_sweep, sliding_choice: the first step past distress of each search
  std::vector<TrajectorySample> trajectory;
  std::vector<SlidingRow> sliding;    // sliding_choice: both configurations at every grid load
  // distress_curve: the fold along the curve parameter (fold_curve.csv) and its column
  std::vector<FoldCurveRow> fold_curve;
  std::string fold_curve_column;
  std::vector<std::string> summary;  // lines for the end of the run's output (e.g. the cusp)
  // The solvers' own words where a search went on regardless (twb run --verbose).
  std::vector<std::string> diagnostics;
  bool solver_failed = false;  // a state the study needed could not be solved
  std::string message;
  RunTimings timings;
};

using ProgressReport = std::function<void(const std::string&)>;

class SearchJournal;
class SearchScheduler;

struct RunOptions {
  // Threads for the study's independent searches (speeds, parameter values, sliding
  // films); 0: one per core. The results do not depend on it.
  int threads = 1;
  // Where each finished search is written at once and, on resume, read instead of run
  // (search_journal.h); none: nothing journaled.
  const SearchJournal* journal = nullptr;
  // Where the study's independent searches run (search_scheduler.h: MPI ranks, a slice of
  // a job array); none: on `threads` threads here. Like the journal, twb's command's own.
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

}  // namespace twb
