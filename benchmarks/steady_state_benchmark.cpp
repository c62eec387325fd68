// What one steady state of the paper's bearing costs (issue: cold start < 50 ms, warm
// start from a neighbouring load < 10 ms on the paper's 9×66 mesh, all effects on).
// Reported as medians over repetitions, with the Newton iterations, Jacobian
// evaluations and KLU factorizations per state as counters. Every Newton iteration
// evaluates the exact Jacobian once and refactors it once (KINSOL max setup calls = 1;
// the symbolic analysis is done once per solver), so factorizations = Jacobians.
//
//   ./build/benchmarks/steady_state_benchmark --benchmark_repetitions=5
//   (add --benchmark_report_aggregates_only=true for medians only)
#include <benchmark/benchmark.h>

#include <stdexcept>

#include "twb/model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "twb/solver/steady_solver.h"

namespace {

twb::Scene paper_scene(double load) {
  twb::Scene s = twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml");
  s.operating.load = load;
  return s;
}

void report(benchmark::State& state, long iterations, long jacobians, int solves) {
  state.counters["newton_iterations"] = benchmark::Counter(double(iterations) / solves);
  state.counters["jacobians"] = benchmark::Counter(double(jacobians) / solves);
  state.counters["klu_factorizations"] = benchmark::Counter(double(jacobians) / solves);
}

void BM_ColdStart(benchmark::State& state) {
  twb::BearingModel model(paper_scene(double(state.range(0))));
  twb::SteadySolver solver(model, {});
  long iterations = 0, jacobians = 0;
  int solves = 0;
  for (auto _ : state) {
    std::vector<double> u;
    const twb::SteadyReport rep = solver.solve_cold(u);
    if (!rep.converged) throw std::runtime_error("cold start did not converge: " + rep.message);
    iterations += rep.iterations;
    jacobians += rep.jacobian_evaluations;
    ++solves;
  }
  report(state, iterations, jacobians, solves);
}
BENCHMARK(BM_ColdStart)->Arg(500)->Unit(benchmark::kMillisecond);

void BM_WarmStartNeighbouringLoad(benchmark::State& state) {
  const double load = double(state.range(0));
  twb::BearingModel model(paper_scene(load));
  twb::SteadySolver solver(model, {});
  std::vector<double> base;
  if (!solver.solve_cold(base).converged) throw std::runtime_error("no base state");
  long iterations = 0, jacobians = 0;
  int solves = 0;
  for (auto _ : state) {
    model.set_load(load * 1.02);
    std::vector<double> u = base;
    const twb::SteadyReport rep = solver.solve(u);
    if (!rep.converged) throw std::runtime_error("warm start did not converge: " + rep.message);
    iterations += rep.iterations;
    jacobians += rep.jacobian_evaluations;
    ++solves;
  }
  report(state, iterations, jacobians, solves);
}
BENCHMARK(BM_WarmStartNeighbouringLoad)->Arg(500)->Arg(120)->Unit(benchmark::kMillisecond);

void BM_ResidualAndJacobian(benchmark::State& state) {
  twb::BearingModel model(paper_scene(500));
  twb::SteadySolver solver(model, {});
  std::vector<double> u;
  solver.solve_cold(u);
  std::vector<double> r(u.size()), jac(std::size_t(model.pattern().nnz()));
  for (auto _ : state) {
    model.evaluate(u, r, jac);
    benchmark::DoNotOptimize(jac.data());
  }
}
BENCHMARK(BM_ResidualAndJacobian)->Unit(benchmark::kMillisecond);

void BM_Residual(benchmark::State& state) {
  twb::BearingModel model(paper_scene(500));
  twb::SteadySolver solver(model, {});
  std::vector<double> u;
  solver.solve_cold(u);
  std::vector<double> r(u.size());
  for (auto _ : state) {
    model.evaluate(u, r, {});
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_Residual)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
