// What the probability of failure costs (issue: every input a parameter): the paper's
// scene on its 9x66 mesh at 545 rad/s with five uncertain inputs (the ambient oil, the
// gear's tilt, the pressure-viscosity constant, the summit radius, the washer's
// conductivity).
//   BM_PaperFailureLoad      the failure search alone, 100-400 N (what every study starts with)
//   BM_PaperForm/T           the reliability study at 150 N without sampling: the search,
//                            then FORM with W_fail's gradients (its inputs on T threads)
//   BM_PaperMonteCarlo/T     at 115 N (P_f ≈ 1e-2), FORM and importance sampling to a 10 %
//                            coefficient of variation, on T threads
// Targets (issue): FORM at one operating point with 5 inputs < 2 s; the Monte Carlo check
// to a 10 % coefficient of variation at P_f ≈ 1e-2 < 60 s on 2 cores. Wall time of one
// run each (the sampling spreads over threads).
//
//   ./build/benchmarks/reliability_benchmark
#include <benchmark/benchmark.h>

#include <string>
#include <variant>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"

namespace {

const std::string kScene = std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml";

const char* const kInputs =
    "inputs: {operating.ambient: {distribution: normal, sd: 3 K},"
    " geometry.gear.tilt: {distribution: truncated_normal, sd: 0.3 mrad, lower: 1 mrad, upper: 3 mrad},"
    " lubricant.viscosity.G0: {distribution: normal, sd: 0.1},"
    " surfaces.asperities.summit_radius: {distribution: lognormal, sd: 4 um},"
    " materials.washer.conductivity: {distribution: uniform, lower: 50 W/(m K), upper: 70 W/(m K)}}";

twb::StudyOutcome run(const std::string& load, const std::string& study, int threads) {
  const twb::Scene s = twb::load_scene(kScene, {"operating.load=" + load, "study=" + study});
  twb::BearingModel model(s);
  return twb::run_study(model, {}, twb::RunOptions{.threads = threads});
}

void BM_PaperFailureLoad(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(
        run("150 N", "{type: distress_map, speeds: [545 rad/s], load_start: 100 N, load_end: 400 N, error_estimate: none}", 1));
}

void BM_PaperForm(benchmark::State& state) {
  for (auto _ : state) {
    const twb::StudyOutcome out = run(
        "150 N", std::string("{type: reliability, load_start: 100 N, load_end: 400 N, monte_carlo: {max_samples: 0}, ") + kInputs + "}",
        int(state.range(0)));
    const std::vector<twb::ReliabilityRow>& rows = std::get<twb::ReliabilityOutcome>(out.own).rows;
    if (!rows.empty()) {
      state.counters["P_f"] = rows[0].probability;
      state.counters["evaluations"] = double(rows[0].evaluations);
    }
  }
}

void BM_PaperMonteCarlo(benchmark::State& state) {
  for (auto _ : state) {
    const twb::StudyOutcome out = run(
        "115 N", std::string("{type: reliability, load_start: 100 N, load_end: 400 N, monte_carlo: {cov: 0.1}, ") + kInputs + "}",
        int(state.range(0)));
    const std::vector<twb::ReliabilityRow>& rows = std::get<twb::ReliabilityOutcome>(out.own).rows;
    if (rows.size() > 1) {
      state.counters["P_f_form"] = rows[0].probability;
      state.counters["P_f_sampled"] = rows[1].probability;
      state.counters["samples"] = double(rows[1].samples.value_or(0));
    }
  }
}

}  // namespace

BENCHMARK(BM_PaperFailureLoad)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PaperForm)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_PaperMonteCarlo)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
