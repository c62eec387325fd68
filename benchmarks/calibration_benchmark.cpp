// What calibration to measurements costs (issue: every input a parameter): the shipped
// example, configs/washers/bronze_calibration.yaml, the bronze washer on its 9x66 mesh with
// three inputs (gear tilt, washer roughness, the oil's kv40) fitted to 40 readings
// (torque and mean temperature) at 20 operating points.
//   BM_BronzeCalibration/T   the study on T threads (the measured speeds spread over them)
// Target (issue): 3 parameters, 20 points < 30 s. Wall time of one run each.
//
//   ./build/benchmarks/calibration_benchmark
#include <benchmark/benchmark.h>

#include <string>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"

namespace {

void BM_BronzeCalibration(benchmark::State& state) {
  const twb::Scene s = twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_calibration.yaml");
  twb::StudyOutcome last;
  for (auto _ : state) {
    twb::BearingModel model(s);
    last = twb::run_study(model, {}, twb::RunOptions{.threads = int(state.range(0))});
  }
  if (last.solver_failed) state.SkipWithError(last.message.c_str());
  state.counters["states"] = double(last.states.size());
}

}  // namespace

BENCHMARK(BM_BronzeCalibration)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
