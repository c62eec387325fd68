#include "study/study_runner.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "solver/sparse_lu.h"
#include "study/accuracy/state_error.h"
#include "study/study_kind.h"
#include "study/study_support.h"

namespace twb {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

StudyOutcome run_study(BearingModel& model, const ProgressReport& progress, const RunOptions& options,
                       const SearchJournal* journal) {
  // The public API's own check (the command line's option checks the same).
  if (options.threads < 0)
    throw std::invalid_argument(
        fmt::format("threads must be 0 (one per core) or a positive count, not {}", options.threads));
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  const Running how{threads, journal, options.scheduler, options.stop};
  const StudyKind& kind = study_kind(model.scene().study.type());
  if (options.cycle_start) check_continuable(model.scene().study, "RunOptions::cycle_start");
  StudyOutcome out;
  out.speeds_in_rpm = model.scene().study.speeds_in_rpm;
  const auto t0 = Clock::now();
  const SparseLu::Counts klu_before = SparseLu::thread_counts();
  kind.run(model, out, StudyRun{.progress = progress, .threads = threads, .how = how, .cycle_start = options.cycle_start});
  // Searches run on worker threads count their own (run_searches); the rest ran here.
  if (!kind.searches_count_their_work)
    out.timings.klu_factorizations =
        SparseLu::thread_counts().factored_since(klu_before) + out.timings.ida_factorizations;
  if (options.stop && options.stop->load() && has_independent_searches(model.scene().study)) {
    out.stopped = true;
    out.message += (out.message.empty() ? "" : "; ") + std::string("stopped before the study's end: searches are missing");
  }
  if (const ErrorBarSettings* bars = model.scene().study.error_bars();
      bars && bars->estimate == ErrorEstimate::every_state) {
    const std::vector<std::string> lines = state_error_lines(model.scene(), out.states);
    out.summary.insert(out.summary.end(), lines.begin(), lines.end());
  }
  out.timings.states = int(out.states.size());
  // Continuation and distress searches count their work in states, transients and
  // factorizations; their Newton iterations are those that solved the reported states.
  if (kind.searches_count_their_work)
    for (const SolvedState& s : out.states) out.timings.newton_iterations += s.iterations;
  out.timings.solve_ms = elapsed_ms(t0);
  return out;
}

}  // namespace twb
