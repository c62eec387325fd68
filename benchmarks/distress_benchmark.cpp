// What a distress load costs (issue: distress at the speed of continuation). Whole
// studies on the paper's 9×66 mesh, each run 3 times; quote the medians (CPU time, in
// seconds) and compare within one run: the machine is noisy. Targets:
//   BM_DistressMap           the paper's four speeds, error bars off     < 2 s
//   BM_DistressMapTwoThreads the same on two threads (wall time)
//   BM_DistressCurve         W_d(ω) from 2000 down to 136 rad/s, cusp,
//                            error bars off                               < 5 s
//   BM_DistressCurveWithErrorBars  the same with every fold's error bar (the shipped scene)
//   BM_DistressWithErrorBar  W_d at 545 rad/s and its Richardson bar     < 10 s
//   BM_DefaultRun            configs/jackson_green_2006.yaml as shipped < 10 s; W_d to
//                            study.tolerance (1 %)                       < 3× the next
//   BM_DefaultRunWithoutErrorEstimate  the same with study.error_estimate: none
// Counters, per study: transients (IDA load steps), ida_steps, klu_factorizations (every
// KLU factorization or refactorization, twb's own and inside IDA), and per W_d where the
// study finds several.
//
// Measured: docs/model.md, "Distress on the bearing" (all targets met). Contact tables
// are shared within the process: the first repetition builds its one table, ~15 ms, the
// others reuse it.
//
//   ./build/benchmarks/distress_benchmark --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/study_runner.h"

namespace {

void run_scene(benchmark::State& state, const std::string& scene, const std::vector<std::string>& overrides,
               int threads = 1) {
  const twb::Scene s = twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/" + scene, overrides);
  twb::RunTimings last;
  std::size_t found = 0;
  for (auto _ : state) {
    twb::BearingModel model(s);
    const twb::StudyOutcome out = twb::run_study(model, {}, twb::RunOptions{.threads = threads});
    last = out.timings;
    found = 0;
    for (const twb::DistressRow& d : out.distress) found += d.distress_load ? 1 : 0;
  }
  state.counters["transients"] = double(last.transients);
  state.counters["ida_steps"] = double(last.ida_steps);
  state.counters["klu_factorizations"] = double(last.klu_factorizations);
  state.counters["W_d_found"] = double(found);
  if (found > 0) {
    state.counters["ida_steps_per_W_d"] = double(last.ida_steps) / double(found);
    state.counters["klu_per_W_d"] = double(last.klu_factorizations) / double(found);
  }
}

void BM_DistressMap(benchmark::State& state) {
  run_scene(state, "studies/distress_map.yaml", {"study.error_estimate=none"});
}
// The same map with its four searches on two threads: wall time (the CPU time is the
// map's above).
void BM_DistressMapTwoThreads(benchmark::State& state) {
  run_scene(state, "studies/distress_map.yaml", {"study.error_estimate=none"}, 2);
}
void BM_DistressCurve(benchmark::State& state) {
  run_scene(state, "studies/distress_curve.yaml", {"study.error_estimate=none"});
}
void BM_DistressCurveWithErrorBars(benchmark::State& state) { run_scene(state, "studies/distress_curve.yaml", {}); }
void BM_DistressWithErrorBar(benchmark::State& state) {
  run_scene(state, "studies/distress_map.yaml", {"study.speeds=[545 rad/s]"});
}
void BM_DefaultRun(benchmark::State& state) { run_scene(state, "jackson_green_2006.yaml", {}); }
void BM_DefaultRunWithoutErrorEstimate(benchmark::State& state) {
  run_scene(state, "jackson_green_2006.yaml", {"study.error_estimate=none"});
}

#define TWB_WHOLE_STUDY(f) \
  BENCHMARK(f)->Unit(benchmark::kSecond)->Iterations(1)->Repetitions(3)->MeasureProcessCPUTime()
TWB_WHOLE_STUDY(BM_DistressMap);
BENCHMARK(BM_DistressMapTwoThreads)->Unit(benchmark::kSecond)->Iterations(1)->Repetitions(3)->UseRealTime();
TWB_WHOLE_STUDY(BM_DistressCurve);
TWB_WHOLE_STUDY(BM_DistressCurveWithErrorBars);
TWB_WHOLE_STUDY(BM_DistressWithErrorBar);
TWB_WHOLE_STUDY(BM_DefaultRun);
TWB_WHOLE_STUDY(BM_DefaultRunWithoutErrorEstimate);

}  // namespace

BENCHMARK_MAIN();
