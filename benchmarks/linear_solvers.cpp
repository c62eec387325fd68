// The Newton system's linear solve, by the solvers a reader would try: KLU with AMD (what
// twb uses) and with COLAMD (SUNDIALS' default), a full factorization and a
// refactorization with the kept pivots; Eigen's SparseLU; Eigen's dense partial-pivoting
// LU (up to 9×66). The matrix is the bearing's Jacobian at the converged state of the
// paper's case (545 rad/s, 150 N); each solve's relative residual ‖J·x − b‖∞/‖b‖∞ is
// reported beside its time, so a fast solver that loses digits shows.
//
//   ./build/benchmarks/linear_solvers --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <klu.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "twb/model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "twb/solver/steady_solver.h"

namespace {

struct System {
  twb::SparsePattern pattern;
  std::vector<double> values, rhs;
};

// The Jacobian at the converged state of one mesh, and a right-hand side (the residual's
// parameter derivative: a Newton tangent's system).
const System& system_for(int radial, int circumferential) {
  static std::map<std::pair<int, int>, System> systems;
  auto [it, fresh] = systems.try_emplace({radial, circumferential});
  if (!fresh) return it->second;
  const twb::Scene scene = twb::load_scene(
      std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
      {"study={type: point}", "operating.load=150 N", "mesh.radial_nodes=" + std::to_string(radial),
       "mesh.circumferential_nodes=" + std::to_string(circumferential)});
  twb::BearingModel model(scene);
  std::vector<double> u;
  twb::SteadySolver(model, twb::NewtonSettings{}).solve_cold(u);
  System& s = it->second;
  s.pattern = model.pattern();
  std::vector<double> r(u.size());
  s.values.resize(std::size_t(s.pattern.nnz()));
  model.evaluate(u, r, s.values);
  s.rhs.resize(u.size());
  model.parameter_derivative(u, s.rhs);
  return s;
}

// ‖J·x − b‖∞ / ‖b‖∞ in the row-compressed pattern.
double relative_residual(const System& s, const std::vector<double>& x) {
  double worst = 0.0, scale = 0.0;
  for (std::size_t k = 0; k + 1 < s.pattern.row_start.size(); ++k) {
    double sum = -s.rhs[k];
    for (auto e = s.pattern.row_start[k]; e < s.pattern.row_start[k + 1]; ++e)
      sum += s.values[std::size_t(e)] * x[std::size_t(s.pattern.column[std::size_t(e)])];
    worst = std::max(worst, std::abs(sum));
    scale = std::max(scale, std::abs(s.rhs[k]));
  }
  return worst / scale;
}

// KLU reads column-compressed arrays: handed the row-compressed Jacobian it factors Jᵀ,
// so tsolve solves with J (as twb's SparseLu does).
void klu(benchmark::State& state, int ordering, bool refactor) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  std::vector<long> ap(s.pattern.row_start.begin(), s.pattern.row_start.end());
  std::vector<long> ai(s.pattern.column.begin(), s.pattern.column.end());
  std::vector<double> values = s.values, x;
  klu_l_common common;
  klu_l_defaults(&common);
  common.ordering = ordering;
  klu_l_symbolic* symbolic = klu_l_analyze(long(s.rhs.size()), ap.data(), ai.data(), &common);
  klu_l_numeric* numeric = refactor ? klu_l_factor(ap.data(), ai.data(), values.data(), symbolic, &common) : nullptr;
  for (auto _ : state) {
    if (refactor) {
      klu_l_refactor(ap.data(), ai.data(), values.data(), symbolic, numeric, &common);
    } else {
      if (numeric) klu_l_free_numeric(&numeric, &common);
      numeric = klu_l_factor(ap.data(), ai.data(), values.data(), symbolic, &common);
    }
    x = s.rhs;
    klu_l_tsolve(symbolic, numeric, long(x.size()), 1, x.data(), &common);
  }
  state.counters["factor_nnz"] = double(numeric->lnz + numeric->unz);
  state.counters["matrix_nnz"] = double(s.pattern.nnz());
  state.counters["relative_residual"] = relative_residual(s, x);
  klu_l_free_numeric(&numeric, &common);
  klu_l_free_symbolic(&symbolic, &common);
}

Eigen::SparseMatrix<double> eigen_matrix(const System& s) {
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t k = 0; k + 1 < s.pattern.row_start.size(); ++k)
    for (auto e = s.pattern.row_start[k]; e < s.pattern.row_start[k + 1]; ++e)
      entries.emplace_back(int(k), int(s.pattern.column[std::size_t(e)]), s.values[std::size_t(e)]);
  Eigen::SparseMatrix<double> m(int(s.rhs.size()), int(s.rhs.size()));
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

void BM_KluAmdFactor(benchmark::State& state) { klu(state, 0, false); }
void BM_KluAmdRefactor(benchmark::State& state) { klu(state, 0, true); }
void BM_KluColamdRefactor(benchmark::State& state) { klu(state, 1, true); }

void BM_EigenSparseLu(benchmark::State& state) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  const Eigen::SparseMatrix<double> m = eigen_matrix(s);
  const Eigen::Map<const Eigen::VectorXd> b(s.rhs.data(), Eigen::Index(s.rhs.size()));
  Eigen::VectorXd x;
  for (auto _ : state) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu(m);
    x = lu.solve(b);
  }
  state.counters["relative_residual"] = relative_residual(s, std::vector<double>(x.data(), x.data() + x.size()));
}

void BM_EigenDenseLu(benchmark::State& state) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  const Eigen::MatrixXd m = Eigen::MatrixXd(eigen_matrix(s));
  const Eigen::Map<const Eigen::VectorXd> b(s.rhs.data(), Eigen::Index(s.rhs.size()));
  Eigen::VectorXd x;
  for (auto _ : state) x = m.partialPivLu().solve(b);
  state.counters["relative_residual"] = relative_residual(s, std::vector<double>(x.data(), x.data() + x.size()));
}

#define TWB_MESHES(b) b->Args({5, 24})->Args({9, 66})->Args({17, 132})->Args({33, 264})
TWB_MESHES(BENCHMARK(BM_KluAmdFactor))->Unit(benchmark::kMillisecond)->Repetitions(3);
TWB_MESHES(BENCHMARK(BM_KluAmdRefactor))->Unit(benchmark::kMillisecond)->Repetitions(3);
// COLAMD fills 19-37 times the matrix: 33×264 takes 10 s a refactorization, left out.
BENCHMARK(BM_KluColamdRefactor)->Args({5, 24})->Args({9, 66})->Args({17, 132})->Unit(benchmark::kMillisecond)->Repetitions(3);
TWB_MESHES(BENCHMARK(BM_EigenSparseLu))->Unit(benchmark::kMillisecond)->Repetitions(3);
BENCHMARK(BM_EigenDenseLu)->Args({5, 24})->Args({9, 66})->Unit(benchmark::kMillisecond)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
