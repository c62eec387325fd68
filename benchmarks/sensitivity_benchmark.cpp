// What the derivatives of the answers cost (issue: every input a parameter): the paper's
// scene on its 9x66 mesh at 545 rad/s.
//   BM_PaperFailureLoad         W_d alone: the distress search 100-400 N, no error bar
//   BM_PaperSensitivities/N     the sensitivity study: the state at 150 N, the same search,
//                               and the derivatives of the state and of W_d in the first
//                               N inputs the scene writes (41 in all)
// Target (issue): the sensitivities of W_d to ~25 inputs < 2x the cost of W_d itself,
// i.e. BM_PaperSensitivities/25 − BM_PaperFailureLoad − the state < 2 BM_PaperFailureLoad.
// CPU time on one thread.
//
//   ./build/benchmarks/sensitivity_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"

namespace {

const std::string kScene = std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml";

void run(benchmark::State& state, const std::string& study) {
  const twb::Scene s = twb::load_scene(kScene, {"operating.load=150 N", "study=" + study});
  for (auto _ : state) {
    twb::BearingModel model(s);
    benchmark::DoNotOptimize(twb::run_study(model, {}, twb::RunOptions{.threads = 1}));
  }
}

void BM_PaperFailureLoad(benchmark::State& state) {
  run(state, "{type: distress_map, speeds: [545 rad/s], load_start: 100 N, load_end: 400 N, error_estimate: none}");
}

void BM_PaperSensitivities(benchmark::State& state) {
  const twb::Scene s = twb::load_scene(kScene);
  std::string paths;
  for (std::size_t k = 0; k < s.inputs.size() && k < std::size_t(state.range(0)); ++k)
    paths += (paths.empty() ? "" : ", ") + s.inputs[k].path;
  run(state, "{type: sensitivity, load_start: 100 N, load_end: 400 N, parameters: [" + paths + "]}");
  state.counters["inputs"] = double(std::min<std::size_t>(s.inputs.size(), std::size_t(state.range(0))));
}

}  // namespace

BENCHMARK(BM_PaperFailureLoad)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PaperSensitivities)->Arg(1)->Arg(25)->Arg(41)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
