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
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <functional>
#include <memory>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "solver/nested_dissection.h"
#include "study/searches/steady_solver.h"
#include "solver/sundials_context.h"

namespace {

struct System {
  twb::SparsePattern pattern;
  std::vector<double> values, rhs;
  std::vector<std::pair<int, int>> blocks;  // offset and size of every unknown block (unknown_layout.h)
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
  for (const twb::UnknownBlock& b : model.layout().blocks()) s.blocks.emplace_back(int(b.offset), int(b.size));
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
  if (ordering == 3) common.user_order = twb::nested_dissection_order;
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
void BM_KluNestedDissectionFactor(benchmark::State& state) { klu(state, 3, false); }
void BM_KluNestedDissectionRefactor(benchmark::State& state) { klu(state, 3, true); }

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

// UMFPACK (SuiteSparse's multifrontal LU, dense BLAS kernels on its fronts), through
// Eigen: analysis and factorization every time, as KLU's factor above.
void BM_Umfpack(benchmark::State& state) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  const Eigen::SparseMatrix<double> m = eigen_matrix(s);
  const Eigen::Map<const Eigen::VectorXd> b(s.rhs.data(), Eigen::Index(s.rhs.size()));
  Eigen::VectorXd x;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
  lu.analyzePattern(m);
  for (auto _ : state) {
    lu.factorize(m);
    x = lu.solve(b);
  }
  state.counters["relative_residual"] = relative_residual(s, std::vector<double>(x.data(), x.data() + x.size()));
}

// GMRES (SUNDIALS' SPGMR, restarted after 100 directions, at most 10 restarts) with a
// right preconditioner, to ‖J·x − b‖₂ ≤ 1e-10 ‖b‖₂ as a direct solve gives: the
// preconditioner's construction is timed with the solve, as KLU's factorization is.
struct Krylov {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  std::function<void(const double*, double*)> precondition;  // z = M⁻¹ r
  std::vector<double> scratch;
};

int krylov_times(void* data, N_Vector v, N_Vector z) {
  const auto* k = static_cast<Krylov*>(data);
  const Eigen::Map<const Eigen::VectorXd> x(N_VGetArrayPointer(v), k->matrix.cols());
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(z), k->matrix.rows()) = k->matrix * x;
  return 0;
}

int krylov_precondition(void* data, N_Vector r, N_Vector z, double, int) {
  const auto* k = static_cast<Krylov*>(data);
  k->precondition(N_VGetArrayPointer(r), N_VGetArrayPointer(z));
  return 0;
}

void gmres(benchmark::State& state, const System& s, const std::function<void(Krylov&)>& build_preconditioner) {
  const sunindextype n = sunindextype(s.rhs.size());
  const twb::SundialsContext context = twb::make_context();
  N_Vector x = N_VNew_Serial(n, context.get()), b = N_VNew_Serial(n, context.get());
  std::copy(s.rhs.begin(), s.rhs.end(), N_VGetArrayPointer(b));
  const double b_norm = std::sqrt(N_VDotProd(b, b));
  SUNLinearSolver solver = SUNLinSol_SPGMR(x, SUN_PREC_RIGHT, 100, context.get());
  SUNLinSol_SPGMRSetMaxRestarts(solver, 10);
  Krylov k;
  k.matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>(eigen_matrix(s));
  SUNLinSolSetATimes(solver, &k, krylov_times);
  SUNLinSolSetPreconditioner(solver, &k, nullptr, krylov_precondition);
  SUNLinSolInitialize(solver);
  int iterations = 0, flag = 0;
  for (auto _ : state) {
    build_preconditioner(k);
    N_VConst(0.0, x);
    SUNLinSolSetup(solver, nullptr);
    flag = SUNLinSolSolve(solver, nullptr, x, b, 1e-10 * b_norm);
    iterations = SUNLinSolNumIters(solver);
  }
  const double* xs = N_VGetArrayPointer(x);
  state.counters["iterations"] = iterations;
  state.counters["converged"] = flag == SUNLS_SUCCESS ? 1 : 0;
  state.counters["relative_residual"] = relative_residual(s, std::vector<double>(xs, xs + n));
  SUNLinSolFree(solver);
  N_VDestroy(x);
  N_VDestroy(b);
}

// Incomplete LU with threshold (Eigen's ILUT, Saad): entries below drop · the row's norm
// are dropped, at most fill · (row's nonzeros) kept per row of L and of U.
void BM_GmresIlut(benchmark::State& state) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  const double drop = std::pow(10.0, -double(state.range(2)));
  const int fill = int(state.range(3));
  auto ilut = std::make_shared<Eigen::IncompleteLUT<double>>();
  const Eigen::SparseMatrix<double> m = eigen_matrix(s);
  gmres(state, s, [&](Krylov& k) {
    ilut->setDroptol(drop);
    ilut->setFillfactor(fill);
    ilut->compute(m);
    k.precondition = [ilut, n = m.rows()](const double* r, double* z) {
      Eigen::Map<Eigen::VectorXd>(z, n) = ilut->solve(Eigen::Map<const Eigen::VectorXd>(r, n));
    };
  });
}

// Block Jacobi over the unknown blocks (the rigid body, each film's pressures and
// temperatures, each component's temperatures), each diagonal block factored exactly
// (Eigen's SparseLU): the coupling between the physics is left to GMRES.
void BM_GmresBlockJacobi(benchmark::State& state) {
  const System& s = system_for(int(state.range(0)), int(state.range(1)));
  const Eigen::SparseMatrix<double> m = eigen_matrix(s);
  using Lu = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;
  auto blocks = std::make_shared<std::vector<std::unique_ptr<Lu>>>();
  gmres(state, s, [&](Krylov& k) {
    blocks->clear();
    for (const auto& [offset, size] : s.blocks) {
      const Eigen::SparseMatrix<double> diagonal = m.block(offset, offset, size, size);
      blocks->push_back(std::make_unique<Lu>(diagonal));
    }
    k.precondition = [blocks, &s](const double* r, double* z) {
      for (std::size_t b = 0; b < s.blocks.size(); ++b) {
        const auto [offset, size] = s.blocks[b];
        Eigen::Map<Eigen::VectorXd>(z + offset, size) =
            (*blocks)[b]->solve(Eigen::Map<const Eigen::VectorXd>(r + offset, size));
      }
    };
  });
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
TWB_MESHES(BENCHMARK(BM_KluAmdRefactor))->Args({65, 528})->Unit(benchmark::kMillisecond)->Repetitions(3);
TWB_MESHES(BENCHMARK(BM_KluNestedDissectionFactor))->Unit(benchmark::kMillisecond)->Repetitions(3);
TWB_MESHES(BENCHMARK(BM_KluNestedDissectionRefactor))->Args({65, 528})->Unit(benchmark::kMillisecond)->Repetitions(3);
// COLAMD fills 19-37 times the matrix: 33×264 takes 10 s a refactorization, left out.
BENCHMARK(BM_KluColamdRefactor)->Args({5, 24})->Args({9, 66})->Args({17, 132})->Unit(benchmark::kMillisecond)->Repetitions(3);
// UMFPACK orders the bordered matrix into dense fronts: 33×264 ran past ten minutes.
BENCHMARK(BM_Umfpack)->Args({5, 24})->Args({9, 66})->Args({17, 132})->Unit(benchmark::kMillisecond)->Repetitions(3);
TWB_MESHES(BENCHMARK(BM_EigenSparseLu))->Unit(benchmark::kMillisecond)->Repetitions(3);
// ILUT at drop tolerances 1e-3 and 1e-5 with fill factor 10 (Eigen's default fill).
BENCHMARK(BM_GmresIlut)->Args({5, 24, 3, 10})->Args({9, 66, 3, 10})->Args({9, 66, 5, 10})->Args({17, 132, 3, 10})
    ->Args({17, 132, 5, 10})->Args({33, 264, 5, 10})->Unit(benchmark::kMillisecond)->Repetitions(3);
BENCHMARK(BM_GmresBlockJacobi)->Args({5, 24})->Args({9, 66})->Args({17, 132})->Unit(benchmark::kMillisecond)
    ->Repetitions(3);
BENCHMARK(BM_EigenDenseLu)->Args({5, 24})->Args({9, 66})->Unit(benchmark::kMillisecond)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
