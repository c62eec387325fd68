// What a duty cycle costs (issue: duty cycles in real time), on the paper's scene and its
// 9x66 mesh:
//   BM_TenMinuteCycle        600 s of 20 segments (ten ramps of 5 s between 100 and 175 N
//                            and 450 to 800 rad/s, each held 55 s), the failure search at
//                            the worst moment included; counters: IDA steps, the worst
//                            moment's failure load
//   BM_SlowRamp/D            the load ramped from 100 to 180 N over D seconds at 545 rad/s,
//                            then held as long again; counters: the largest difference of
//                            the trajectory's T_mean and T_max from the steady branch at
//                            the trajectory's own loads (K), and IDA's steps
//   BM_BranchByContinuation  the same branch traced by continuation (a load sweep from
//                            100 to 180 N in 41 states), the cost the slow ramp is held to
//   BM_LightLoadLift         100 to 1 N in 5 s, held to 60 s: the washer lifting off its
//                            film; counter: IDA's steps
// Targets (issue): the ten-minute cycle < 10 s; the slow-ramp limit equal to the steady
// branch to the solver's tolerance at no more than 2x the continuation's cost. Wall time of
// one run each; compare the ratios within one invocation.
//
//   ./build/benchmarks/duty_cycle_benchmark
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "study/time/operating_schedule.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"
#include "twb/scene/scene_loader.h"

namespace {

const std::string kScene = std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml";

twb::StudyOutcome run(const std::string& study) {
  const twb::Scene s = twb::load_scene(kScene, {"operating.load=100 N", "study=" + study});
  twb::BearingModel model(s);
  return twb::run_study(model, {});
}

std::string ten_minute_schedule() {
  const double loads[] = {140, 120, 170, 110, 160, 130, 175, 100, 150, 120};
  const double speeds[] = {545, 700, 800, 600, 450, 545, 800, 700, 500, 545};
  std::string points = "{t: 0 s, load: 100 N, speed: 545 rad/s}";
  double t = 0.0;
  for (int k = 0; k < 10; ++k) {
    t += 5.0;
    points += fmt::format(", {{t: {} s, load: {} N, speed: {} rad/s}}", t, loads[k], speeds[k]);
    t += 55.0;
    points += fmt::format(", {{t: {} s}}", t);
  }
  return "[" + points + "]";
}

void BM_TenMinuteCycle(benchmark::State& state) {
  const std::string study = "{type: duty_cycle, schedule: " + ten_minute_schedule() + "}";
  for (auto _ : state) {
    const twb::StudyOutcome out = run(study);
    state.counters["ida_steps"] = double(out.timings.ida_steps);
    for (const twb::CycleEvent& e : std::get<twb::DutyCycleOutcome>(out.own).events)
      if (e.event == "worst" && e.failure_load) state.counters["W_fail_worst_N"] = *e.failure_load;
    if (out.solver_failed) state.SkipWithError(out.message.c_str());
  }
}

// The steady branch at 545 rad/s by continuation, 100 to 180 N.
const char* const kSweep =
    "{type: load_sweep, speeds: [545 rad/s], load_start: 100 N, load_end: 180 N, load_steps: 41, error_estimate: none}";

void BM_SlowRamp(benchmark::State& state) {
  const double duration = double(state.range(0));
  const std::string study = fmt::format(
      "{{type: duty_cycle, failure_load_at_worst: false, schedule: [{{t: 0 s, load: 100 N}}, {{t: {} s, load: 180 N}}, "
      "{{t: {} s}}]}}",
      duration, 2.0 * duration);
  twb::StudyOutcome out;
  for (auto _ : state) out = run(study);
  state.counters["ida_steps"] = double(out.timings.ida_steps);
  // The steady state at each step's load (out of the timing): the branch the slow ramp
  // must trace.
  const twb::Scene s = twb::load_scene(kScene, {"operating.load=100 N"});
  twb::BearingModel model(s);
  twb::SteadySolver solver(model, twb::newton_settings(s));
  std::vector<double> u;
  double worst_mean = 0.0, worst_max = 0.0;
  for (std::size_t k = 0; k < out.trajectory.size(); k += std::max<std::size_t>(1, out.trajectory.size() / 40)) {
    const twb::TrajectorySample& p = out.trajectory[k];
    model.set_load(p.state.load);
    const twb::SteadyReport rep = u.empty() ? solver.solve_cold(u) : solver.solve(u);
    if (!rep.converged) continue;
    const twb::BearingState steady = model.describe(u);
    worst_mean = std::max(worst_mean, std::abs(p.state.washer_mean_temperature - steady.washer_mean_temperature));
    worst_max = std::max(worst_max, std::abs(p.state.max_film_temperature - steady.max_film_temperature));
  }
  state.counters["dT_mean_K"] = worst_mean;
  state.counters["dT_max_K"] = worst_max;
}

// Nearly unloaded: 100 N to 1 N in 5 s at 545 rad/s, held to 60 s; the washer lifts off its
// film at the rate its squeeze allows (h_min/σ from about 6 to 100).
void BM_LightLoadLift(benchmark::State& state) {
  const std::string study =
      "{type: duty_cycle, failure_load_at_worst: false, schedule: [{t: 0 s, load: 100 N}, {t: 5 s, load: 1 N}, "
      "{t: 60 s}]}";
  for (auto _ : state) {
    const twb::StudyOutcome out = run(study);
    state.counters["ida_steps"] = double(out.timings.ida_steps);
    if (out.solver_failed) state.SkipWithError(out.message.c_str());
  }
}

void BM_BranchByContinuation(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(run(kSweep));
}

}  // namespace

BENCHMARK(BM_TenMinuteCycle)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BranchByContinuation)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_LightLoadLift)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SlowRamp)->Arg(1000)->Arg(100000)->Arg(10000000)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
