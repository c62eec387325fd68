// Newton's method against chord steps: how many iterations one Jacobian serves
// (NewtonSettings::jacobian_reuse, KINSOL's KINSetMaxSetupCalls), on the paper's case at
// 545 rad/s on 9×66: a state from the paper's cold start at 150 N, and a warm 2 % load
// step from it. Counts beside the times: iterations, residuals, Jacobian assemblies.
//
//   ./build/benchmarks/jacobian_reuse --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/searches/steady_solver.h"

namespace {

twb::Scene scene() {
  return twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                         {"study={type: point}", "operating.load=150 N"});
}

twb::NewtonSettings reusing(int iterations) {
  twb::NewtonSettings s;
  s.jacobian_reuse = iterations;
  return s;
}

void count(benchmark::State& state, const twb::SteadyReport& r) {
  if (!r.converged) state.SkipWithError(r.message.c_str());
  state.counters["iterations"] = double(r.iterations);
  state.counters["residuals"] = double(r.residual_evaluations);
  state.counters["jacobians"] = double(r.jacobian_evaluations);
}

void BM_ColdStart(benchmark::State& state) {
  twb::BearingModel model(scene());
  twb::SteadyReport last;
  for (auto _ : state) {
    std::vector<double> u;
    last = twb::SteadySolver(model, reusing(int(state.range(0)))).solve_cold(u);
  }
  count(state, last);
}

void BM_WarmStep(benchmark::State& state) {
  twb::BearingModel model(scene());
  std::vector<double> start;
  twb::SteadySolver(model, twb::NewtonSettings{}).solve_cold(start);
  model.set_load(153.0);
  twb::SteadyReport last;
  for (auto _ : state) {
    std::vector<double> u = start;
    last = twb::SteadySolver(model, reusing(int(state.range(0)))).solve(u);
  }
  count(state, last);
}

BENCHMARK(BM_ColdStart)->Arg(1)->Arg(2)->Arg(3)->Arg(5)->Arg(10)->Unit(benchmark::kMillisecond)->Repetitions(3);
BENCHMARK(BM_WarmStep)->Arg(1)->Arg(2)->Arg(3)->Arg(5)->Arg(10)->Unit(benchmark::kMillisecond)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
