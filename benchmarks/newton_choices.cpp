// Choices inside the Newton solves, each on the same states of the paper's case
// (545 rad/s, 9×66), with counts beside the times:
//  - the cavitation rows Newton solves (Fischer–Burmeister or the minimum; CavitationRow
//    in bearing_model.h) on a warm start 2 % up in load, on the cool (100 N) and the
//    hot (500 N) branch;
//  - how a load sweep starts each state: from the paper's cold start, from the last
//    state (constant predictor, a warm start), by the secant, by the tangent
//    (natural_continuation.h), on the cool branch 100 → 150 N and on the hot branch
//    500 → 600 N, in ten equal steps.
// Counters per state: newton_iterations (corrector iterations, pseudo-time steps
// included for the cold start), residuals and jacobians (where the solver reports
// them), klu_factorizations (full and refactorizations, SparseLu's own count),
// rejected (continuation steps halved).
//
//   ./build/benchmarks/newton_choices --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "paper_case.h"
#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "solver/kinsol_newton.h"
#include "solver/natural_continuation.h"
#include "solver/sparse_lu.h"
#include "study/searches/steady_solver.h"

namespace {

using twb::bench::converged_state;

twb::Scene paper_scene(double load) { return twb::bench::paper_scene(load, 545.0); }

// Args: row (0 Fischer–Burmeister, 1 minimum), load (N).
void BM_CavitationRow(benchmark::State& state) {
  const bool minimum = state.range(0) == 1;
  const double load = double(state.range(1));
  twb::BearingModel model(paper_scene(load));
  const std::vector<double> base = converged_state(model);
  twb::KinsolNewton newton(model);
  model.set_newton_form(minimum);
  long iterations = 0, residuals = 0, jacobians = 0, states = 0;
  const twb::SparseLu::Counts before = twb::SparseLu::thread_counts();
  for (auto _ : state) {
    model.set_load(1.02 * load);
    std::vector<double> u = base;
    const twb::NewtonReport rep = newton.solve(u, twb::NewtonSettings{});
    if (!rep.converged) throw std::runtime_error("the warm start did not converge: " + rep.message);
    iterations += rep.iterations;
    residuals += rep.residual_evaluations;
    jacobians += rep.jacobian_evaluations;
    ++states;
  }
  const double n = double(states);
  state.counters["newton_iterations"] = double(iterations) / n;
  state.counters["residuals"] = double(residuals) / n;
  state.counters["jacobians"] = double(jacobians) / n;
  state.counters["klu_factorizations"] = double(twb::SparseLu::thread_counts().factored_since(before)) / n;
}
BENCHMARK(BM_CavitationRow)
    ->ArgsProduct({{0, 1}, {100, 500}})
    ->Repetitions(3)
    ->Unit(benchmark::kMillisecond);

// Args: start (0 cold start, 1 constant predictor, 2 secant, 3 tangent), first load (N);
// the sweep goes to 1.5 × (cool) or 1.2 × (hot) that load in ten steps.
void BM_SweepStart(benchmark::State& state) {
  constexpr int steps = 10;
  const int start = int(state.range(0));
  const double load = double(state.range(1));
  const double last = load < 300 ? 1.5 * load : 1.2 * load;
  twb::BearingModel model(paper_scene(load));
  const std::vector<double> base = converged_state(model);
  long iterations = 0, rejected = 0, states = 0;
  const twb::SparseLu::Counts before = twb::SparseLu::thread_counts();
  for (auto _ : state) {
    if (start == 0) {
      twb::SteadySolver solver(model, {});
      for (int k = 1; k <= steps; ++k) {
        model.set_load(load + (last - load) * k / steps);
        std::vector<double> u;
        const twb::SteadyReport rep = solver.solve_cold(u);
        if (!rep.converged) throw std::runtime_error("a cold start failed: " + rep.message);
        iterations += rep.iterations;
      }
    } else {
      twb::NaturalSettings settings;
      settings.predictor = start == 1   ? twb::Predictor::constant
                           : start == 2 ? twb::Predictor::secant
                                        : twb::Predictor::tangent;
      settings.initial_step = settings.max_step = (last - load) / steps;
      model.set_load(load);
      std::vector<double> u = base;
      const twb::NaturalReport rep = twb::continue_in_parameter(model, u, model.parameter(), last, settings);
      if (!rep.reached_target) throw std::runtime_error("the sweep stopped: " + rep.message);
      iterations += rep.corrector_iterations;
      rejected += rep.rejected;
    }
    states += steps;
  }
  const double n = double(states);
  state.counters["s_per_state"] =
      benchmark::Counter(steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["newton_iterations"] = double(iterations) / n;
  state.counters["rejected"] = double(rejected) / n;
  state.counters["klu_factorizations"] = double(twb::SparseLu::thread_counts().factored_since(before)) / n;
}
BENCHMARK(BM_SweepStart)->ArgsProduct({{0, 1, 2, 3}, {100, 500}})->Repetitions(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
