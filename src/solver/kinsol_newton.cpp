#include "twb/solver/kinsol_newton.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "twb/solver/sparse_matrix_fill.h"

namespace twb {

double max_norm(std::span<const double> v) {
  double m = 0.0;
  for (double x : v) {
    if (!std::isfinite(x)) return INFINITY;
    m = std::max(m, std::abs(x));
  }
  return m;
}

struct KinsolNewton::Callbacks {
  const SteadySystem* model;
  std::vector<double> jac_values;
  std::string last_error;      // KINSOL's own message
  std::string callback_error;  // what a callback threw
  const PseudoTimeShift* shift = nullptr;
  std::vector<Index> diagonal;  // position of (k, k) in the pattern
};

namespace {

// Trampolines: no exception may cross into C. A non-finite residual is recoverable
// (the line search shortens the step); anything else thrown is unrecoverable and its
// message is kept for the report.
int residual_fn(N_Vector y, N_Vector f, void* data) {
  auto* cb = static_cast<KinsolNewton::Callbacks*>(data);
  try {
    const auto n = std::size_t(N_VGetLength(y));
    std::span<const double> u(N_VGetArrayPointer(y), n);
    std::span<double> r(N_VGetArrayPointer(f), n);
    cb->model->evaluate(u, r, {});
    if (cb->shift)
      for (std::size_t k = 0; k < n; ++k) r[k] += cb->shift->coefficient(k) * (u[k] - cb->shift->anchor[k]);
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(r[k])) {
        return 1;
      }
    return 0;
  } catch (const std::exception& e) {
    cb->callback_error = e.what();
    return -1;
  }
}

int jacobian_fn(N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector) {
  auto* cb = static_cast<KinsolNewton::Callbacks*>(data);
  try {
    const SteadySystem& m = *cb->model;
    const SparsePattern& p = m.pattern();
    const auto n = std::size_t(N_VGetLength(y));
    std::vector<double> r(n);
    cb->jac_values.resize(std::size_t(p.nnz()));
    m.evaluate(std::span<const double>(N_VGetArrayPointer(y), n), r, cb->jac_values);
    if (cb->shift)
      for (std::size_t k = 0; k < cb->diagonal.size(); ++k)
        cb->jac_values[std::size_t(cb->diagonal[k])] += cb->shift->coefficient(k);
    return fill_sparse_matrix(J, p, cb->jac_values) ? 0 : 1;
  } catch (const std::exception& e) {
    cb->callback_error = e.what();
    return -1;
  }
}

void error_handler(int, const char*, const char*, char* msg, void* data) {
  static_cast<KinsolNewton::Callbacks*>(data)->last_error = msg;
}

}  // namespace

KinsolNewton::KinsolNewton(const SteadySystem& model)
    : model_(model), ctx_(make_context()), callbacks_(std::make_unique<Callbacks>()) {
  callbacks_->model = &model_;
  for (Index k = 0; k < model_.size(); ++k) callbacks_->diagonal.push_back(model_.pattern().find(k, k));
  const sunindextype n = model_.size();
  y_.reset(N_VNew_Serial(n, ctx_.get()));
  scale_.reset(N_VNew_Serial(n, ctx_.get()));
  const std::vector<double> weights = model_.step_weights();
  std::copy(weights.begin(), weights.end(), N_VGetArrayPointer(scale_.get()));
  residual_scale_.reset(N_VNew_Serial(n, ctx_.get()));
  N_VConst(1.0, residual_scale_.get());
  jac_.reset(SUNSparseMatrix(n, n, model_.pattern().nnz(), CSR_MAT, ctx_.get()));
  klu_.reset(SUNLinSol_KLU(y_.get(), jac_.get(), ctx_.get()));
  if (!y_ || !scale_ || !jac_ || !klu_) throw SolverFailure("could not allocate the Newton solver", -1);
  // SUNDIALS defaults KLU to COLAMD, which fills the factors of this arrow-shaped matrix
  // (dense rigid-body border) about six-fold; AMD on A + Aᵀ orders the border last.
  check_flag(SUNLinSol_KLUSetOrdering(klu_.get(), 0), "SUNLinSol_KLUSetOrdering");
  kin_ = KINCreate(ctx_.get());
  if (!kin_) throw SolverFailure("KINCreate failed", -1);
  check_flag(KINInit(kin_, residual_fn, y_.get()), "KINInit");
  check_flag(KINSetUserData(kin_, callbacks_.get()), "KINSetUserData");
  check_flag(KINSetErrHandlerFn(kin_, error_handler, callbacks_.get()), "KINSetErrHandlerFn");
  check_flag(KINSetLinearSolver(kin_, klu_.get(), jac_.get()), "KINSetLinearSolver");
  check_flag(KINSetJacFn(kin_, jacobian_fn), "KINSetJacFn");
  // A fresh exact Jacobian every iteration: quadratic convergence is worth one KLU
  // refactorization per step on this small system.
  check_flag(KINSetMaxSetupCalls(kin_, 1), "KINSetMaxSetupCalls");
  // TWB_KINSOL_PRINT=1..3 shows KINSOL's own iteration log on stdout (diagnostics).
  if (const char* level = std::getenv("TWB_KINSOL_PRINT")) KINSetPrintLevel(kin_, std::atoi(level));
}

KinsolNewton::~KinsolNewton() { KINFree(&kin_); }

NewtonReport KinsolNewton::solve(std::vector<double>& u, const NewtonSettings& s, const PseudoTimeShift* shift) {
  NewtonReport rep;
  const std::size_t n = u.size();
  std::copy(u.begin(), u.end(), N_VGetArrayPointer(y_.get()));
  check_flag(KINSetFuncNormTol(kin_, s.residual_tolerance), "KINSetFuncNormTol");
  check_flag(KINSetScaledStepTol(kin_, s.step_tolerance), "KINSetScaledStepTol");
  check_flag(KINSetNumMaxIters(kin_, s.max_iterations), "KINSetNumMaxIters");
  if (s.max_step > 0) check_flag(KINSetMaxNewtonStep(kin_, s.max_step), "KINSetMaxNewtonStep");
  callbacks_->last_error.clear();
  callbacks_->callback_error.clear();
  // The shift adds to the diagonal: a row whose pattern lacks (k, k) cannot take it.
  if (shift)
    for (std::size_t k = 0; k < n; ++k)
      if (shift->coefficient(k) != 0.0 && callbacks_->diagonal[k] < 0)
        throw std::invalid_argument(fmt::format("pseudo-time shift on row {}, which has no diagonal entry", k));
  callbacks_->shift = shift;

  const int flag = KINSol(kin_, y_.get(), KIN_LINESEARCH, scale_.get(), residual_scale_.get());
  rep.flag = flag;
  KINGetNumNonlinSolvIters(kin_, &rep.iterations);
  KINGetNumFuncEvals(kin_, &rep.residual_evaluations);
  KINGetNumJacEvals(kin_, &rep.jacobian_evaluations);
  KINGetNumBacktrackOps(kin_, &rep.backtracks);

  std::vector<double> trial(N_VGetArrayPointer(y_.get()), N_VGetArrayPointer(y_.get()) + n);
  std::vector<double> r(n);
  try {
    model_.evaluate(trial, r, {});
    if (shift)
      for (std::size_t k = 0; k < n; ++k) r[k] += shift->coefficient(k) * (trial[k] - shift->anchor[k]);
    rep.residual_norm = max_norm(r);
  } catch (const std::exception&) {
    rep.residual_norm = INFINITY;
  }
  // KIN_STEP_LT_STPTOL may be a stall: only the residual says whether it converged.
  rep.converged = flag >= 0 && rep.residual_norm <= s.residual_tolerance;
  u = trial;  // the final iterate, converged or not: callers keep their own copies
  if (!rep.converged) {
    // Say where the residual is largest: the block names the physics that failed.
    std::size_t worst = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (!(std::abs(r[k]) <= std::abs(r[worst]))) worst = k;
    rep.worst_block = model_.block_name(Index(worst));
    rep.worst_row = Index(worst);
    char* name = KINGetReturnFlagName(flag);
    rep.message = std::string(name ? name : "KINSOL failure") +
                  fmt::format(" (largest residual {:.3g} in {}, row {})", r[worst], rep.worst_block, worst) +
                  (callbacks_->last_error.empty() ? "" : ": " + callbacks_->last_error) +
                  (callbacks_->callback_error.empty() ? "" : " (" + callbacks_->callback_error + ")");
    free(name);
  }
  return rep;
}

}  // namespace twb
