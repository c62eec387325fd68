// A study run to its failure load as a benchmark's timed loop: the model built and the
// study run on each iteration, the last run's states and KLU factorizations as counters.
#pragma once

#include <benchmark/benchmark.h>

#include "model/bearing_model.h"
#include "study/study_runner.h"

namespace twb::bench {

inline void run_failure_study(benchmark::State& state, const Scene& s, int threads = 1) {
  RunTimings last;
  for (auto _ : state) {
    BearingModel model(s);
    const StudyOutcome out = run_study(model, {}, RunOptions{.threads = threads});
    if (out.distress.size() != 1 || !out.distress.front().failure_load) {
      state.SkipWithError("no failure load");
      return;
    }
    last = out.timings;
  }
  state.counters["states"] = double(last.states);
  state.counters["klu_factorizations"] = double(last.klu_factorizations);
}

}  // namespace twb::bench
