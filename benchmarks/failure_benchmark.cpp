// What a failure load costs on a washer that is not the paper's (issue: a failure load
// for every washer): the bronze washer of configs/washers/bronze_cusn8.yaml on its 9×66
// mesh, each run 3 times; quote the medians (CPU time) and compare within one run: the
// machine is noisy. Targets:
//   BM_BronzePoint / BM_BronzePointWithErrorBar   300 N, 3000 rpm: the point with its
//                        error bar on 17×132                          < 3× the point alone
//   BM_BronzeFailureMap  W_fail at 3000 rpm, every criterion located, with error bars
//   BM_BronzeSafeRegion  the safe region over 1000-6000 rpm: the fold curve and every
//                        criterion's limit curve, error bars off
//   BM_BronzeSafeRegionWithErrorBars  the same with every fold's error bar, on one thread
//   BM_BronzeSafeRegionOnTwoThreads   the same on both cores (the ends searched at once,
//                        the fold's bars in two chains and the limit curves spread)  (issue: < 5 s)
// Counters: states, transients, KLU factorizations. Times are CPU time on one thread and
// wall time (UseRealTime) on two.
//
//   ./build/benchmarks/failure_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"

namespace {

void run_bronze(benchmark::State& state, const std::vector<std::string>& overrides, int threads = 1) {
  const twb::Scene s =
      twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml", overrides);
  twb::RunTimings last;
  for (auto _ : state) {
    twb::BearingModel model(s);
    const twb::StudyOutcome out = twb::run_study(model, {}, twb::RunOptions{.threads = threads});
    last = out.timings;
  }
  state.counters["states"] = double(last.states);
  state.counters["transients"] = double(last.transients);
  state.counters["klu_factorizations"] = double(last.klu_factorizations);
}

const std::string kCurve =
    "study={type: distress_curve, parameter: speed, from: 1000 rpm, to: 6000 rpm, load_start: 100 N, load_end: "
    "4000 N";

void BM_BronzePoint(benchmark::State& state) {
  run_bronze(state, {"study={type: point, error_estimate: none}", "operating.load=300 N"});
}
void BM_BronzePointWithErrorBar(benchmark::State& state) {
  run_bronze(state, {"study={type: point}", "operating.load=300 N"});
}
void BM_BronzeFailureMap(benchmark::State& state) { run_bronze(state, {}); }
void BM_BronzeSafeRegion(benchmark::State& state) { run_bronze(state, {kCurve + ", error_estimate: none}"}); }
void BM_BronzeSafeRegionWithErrorBars(benchmark::State& state) { run_bronze(state, {kCurve + "}"}); }
void BM_BronzeSafeRegionOnTwoThreads(benchmark::State& state) { run_bronze(state, {kCurve + "}"}, 2); }

}  // namespace

BENCHMARK(BM_BronzePoint)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BronzePointWithErrorBar)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BronzeFailureMap)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BronzeSafeRegion)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BronzeSafeRegionWithErrorBars)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BronzeSafeRegionOnTwoThreads)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
