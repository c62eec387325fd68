// What a grooved washer's failure load costs (issue: grooved washers fed and cooled by
// the oil): configs/studies/grooved/eight_grooves.yaml, the paper's washer with eight
// radial grooves at 545 rad/s on 9×96 (three cells across each groove, nine on each
// land), searched from 50 to 3000 N. It fails by the flash point near 87 N and has no
// fold up to 3000 N (gradual heating), so its answer is W_fail with the error bar of
// every criterion crossed (the flash point's and the oil's maximum temperature's, each
// again on 17×192). Each run 3 times; quote the medians and compare within one run: the
// machine is noisy. Targets:
//   BM_EightGroovesFailureLoad              without error bars, one thread
//   BM_EightGroovesFailureLoadWithErrorBars with them, one thread
//   BM_EightGroovesOnTwoThreads             with them on both cores (the start's check
//                        beside the branch, the two crossings' bars at once)   (issue: < 3 s)
// Counters: states, KLU factorizations. Times are CPU time on one thread and wall time
// (UseRealTime) on two.
//
//   ./build/benchmarks/grooved_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "failure_run.h"
#include "twb/scene/scene_loader.h"

namespace {

void run_eight_grooves(benchmark::State& state, const std::vector<std::string>& overrides, int threads = 1) {
  twb::bench::run_failure_study(
      state, twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/studies/grooved/eight_grooves.yaml", overrides),
      threads);
}

void BM_EightGroovesFailureLoad(benchmark::State& state) {
  run_eight_grooves(state, {"study.error_estimate=none"});
}
void BM_EightGroovesFailureLoadWithErrorBars(benchmark::State& state) { run_eight_grooves(state, {}); }
void BM_EightGroovesOnTwoThreads(benchmark::State& state) { run_eight_grooves(state, {}, 2); }

}  // namespace

BENCHMARK(BM_EightGroovesFailureLoad)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_EightGroovesFailureLoadWithErrorBars)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_EightGroovesOnTwoThreads)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
