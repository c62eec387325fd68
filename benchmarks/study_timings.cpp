// Whole-study timings of the shipped scenes, so that a regression shows: every scene of
// configs/ and configs/studies/, its study run as `twb run` runs it (on the machine's
// threads, the default; writing the results, milliseconds, is left out), 3 times each;
// quote the medians of the wall time and of the process's CPU time.
//
//   ./build/benchmarks/study_timings --benchmark_report_aggregates_only=true
//
// Measured: see benchmarks/README.md ("Whole studies").
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/study_runner.h"

namespace {

namespace fs = std::filesystem;

void run_scene(benchmark::State& state, const fs::path& path) {
  const twb::Scene scene = twb::load_scene(path.string(), {});
  for (auto _ : state) {
    twb::BearingModel model(scene);
    const twb::StudyOutcome outcome =
        twb::run_study(model, {}, twb::RunOptions{.threads = int(std::max(1u, std::thread::hardware_concurrency()))});
    if (outcome.solver_failed) state.SkipWithError(outcome.message.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<fs::path> scenes{fs::path(TWB_SOURCE_DIR) / "configs" / "jackson_green_2006.yaml"};
  for (const auto& entry : fs::directory_iterator(fs::path(TWB_SOURCE_DIR) / "configs" / "studies"))
    // The 200-search design map is timed by scripts/scaling_study.sh (docs/scaling.md), on
    // 1 and 2 threads and 2 ranks: a minute a run would dwarf the rest here.
    if (entry.path().extension() == ".yaml" && entry.path().stem() != "design_map") scenes.push_back(entry.path());
  std::sort(scenes.begin() + 1, scenes.end());
  for (const fs::path& scene : scenes)
    benchmark::RegisterBenchmark(scene.stem().string().c_str(), [scene](benchmark::State& s) { run_scene(s, scene); })
        ->Unit(benchmark::kSecond)
        ->Iterations(1)
        ->Repetitions(3)
        ->MeasureProcessCPUTime()
        ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
