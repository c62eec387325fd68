#include "solver/kinsol_newton.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>
#include <limits>
#include <optional>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "solver/pattern_klu.h"
#include "solver/sparse_lu.h"
#include "solver/sparse_matrix_fill.h"
#include "solver/callback_guard.h"
#include "twb/error_family.h"

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
  std::string last_error;      // KINSOL's own message
  // What a callback threw (callback_guard.h): an internal error is carried across the
  // C solver and thrown again once it returns.
  CallbackFailure failure;
  const PseudoTimeShift* shift = nullptr;
  std::vector<Index> diagonal;  // position of (k, k) in the pattern

  // One assembly serves both callbacks. KINSOL asks for the Jacobian at the point its
  // line search has just accepted, usually the full Newton step, the first point
  // whose residual it asks for after a Jacobian. So that residual is assembled with its
  // Jacobian (one pass costs about 1.4 residual-only passes, against 2.4 for a
  // residual and then both) and both are kept with the point, unshifted; the points of
  // a backtracking line search get the residual alone. The system does not change
  // during one solve, so the cache is cleared at the start of each.
  std::vector<double> point, point_residual, point_jacobian;
  bool point_has_jacobian = false;
  bool next_with_jacobian = true;
  // The last Newton point needs no Jacobian: it meets the tolerance and KINSOL stops.
  // Where Newton converges quadratically, ‖F_k+1‖ ≈ C‖F_k‖² with C = ‖F_k‖/‖F_k−1‖²
  // from the last two points; when that guess is 100× below the tolerance the next
  // point gets the residual alone (if the guess was wrong, KINSOL's Jacobian request
  // assembles the point again: slower, never wrong).
  std::vector<double> step_norms;  // ‖F‖∞ at the points assembled for a Jacobian
  // NewtonSettings::watched: the last Newton point's value of that unknown, and whether a
  // point met the watched criterion (KINSOL is then stopped by a failed residual call,
  // and `point` holds that point).
  Index watched = -1;
  double watched_step = 0.0, watched_residual = 0.0;
  NewtonSettings::WatchedQuantities quantities;
  std::optional<double> last_watched;
  NewtonSettings::QuantityReads reads;
  std::vector<double> settled_point;  // where the quantities settled, unassembled
  bool watched_settled = false;
  bool full_steps = false;  // KINSOL runs without a line search
  double tolerance = 0.0;
  // The full steps converge: the residual down a thousandfold over the run and by at
  // least half at each of its last two steps.
  bool converging() const {
    const std::size_t k = step_norms.size();
    if (k < 3) return false;
    return step_norms[k - 1] <= 1e-3 * step_norms.front() && step_norms[k - 1] <= 0.5 * step_norms[k - 2] &&
           step_norms[k - 2] <= 0.5 * step_norms[k - 3];
  }
  bool expects_convergence() const {
    const std::size_t k = step_norms.size();
    if (k < 2 || !(step_norms[k - 2] > 0.0)) return false;
    const double rate = step_norms[k - 1] / (step_norms[k - 2] * step_norms[k - 2]);
    return rate * step_norms[k - 1] * step_norms[k - 1] <= 1e-2 * tolerance;
  }
  bool holds(std::span<const double> u) const {
    return point.size() == u.size() && std::equal(u.begin(), u.end(), point.begin());
  }
  void assemble_at(std::span<const double> u, bool with_jacobian) {
    if (holds(u) && (point_has_jacobian || !with_jacobian)) return;
    point.clear();  // invalid until the assembly below succeeds
    point_residual.resize(u.size());
    point_jacobian.resize(with_jacobian ? std::size_t(model->pattern().nnz()) : 0);
    model->evaluate(u, point_residual, point_jacobian);
    point.assign(u.begin(), u.end());
    point_has_jacobian = with_jacobian;
  }
  void forget() {
    point.clear();
    step_norms.clear();
    next_with_jacobian = true;
    last_watched.reset();
    reads = {};
    settled_point.clear();
    watched_settled = false;
  }
  // At a new Newton point u: true when the step to it settled the watched unknown.
  bool settles_watched(std::span<const double> u) {
    if (watched < 0) return false;
    const double value = u[std::size_t(watched)];
    const bool small_step = last_watched && std::abs(value - *last_watched) <= watched_step;
    last_watched = value;
    if (!small_step) return false;
    assemble_at(u, false);
    watched_settled = max_norm(point_residual) <= watched_residual;
    return watched_settled;
  }
  // At a Newton point u, before it is assembled: true when the caller's quantities
  // settled there (kept in `settled_point`). Only on the full steps, where each point is
  // the next iterate (a line search's first trial may be rejected, and a bound on
  // consecutive iterates says nothing about trials). The start is skipped: where a
  // caller carries a state over (another mesh's), its quantities are the ones it carried.
  bool settles_quantities(std::span<const double> u) {
    if (!quantities.at || shift || !full_steps || step_norms.empty()) return false;
    reads.values.push_back(quantities.at(u));
    const std::size_t k = step_norms.size();
    reads.residual_contraction = k >= 2 ? step_norms[k - 1] / step_norms[k - 2] : NAN;
    watched_settled = quantities.settled(reads);
    if (watched_settled) settled_point.assign(u.begin(), u.end());
    return watched_settled;
  }
};

namespace {

// Trampolines: no exception may cross into C. A non-finite residual is recoverable
// (the line search shortens the step); anything else thrown is unrecoverable and its
// message is kept for the report.
int residual_fn(N_Vector y, N_Vector f, void* data) {
  auto* cb = static_cast<KinsolNewton::Callbacks*>(data);
  return guarded_callback(cb->failure, [&]() -> int {
    const auto n = std::size_t(N_VGetLength(y));
    std::span<const double> u(N_VGetArrayPointer(y), n);
    std::span<double> r(N_VGetArrayPointer(f), n);
    const bool newton_point = cb->next_with_jacobian;
    // Every call of a full-step run is at a new iterate (a line search's are trials); a
    // failed call stops KINSOL, and solve() takes the point from the cache.
    if ((newton_point || cb->full_steps) && (cb->settles_watched(u) || cb->settles_quantities(u))) return -1;
    cb->assemble_at(u, newton_point && !cb->expects_convergence());
    cb->next_with_jacobian = false;
    std::copy(cb->point_residual.begin(), cb->point_residual.end(), r.begin());
    if (cb->shift)
      for (std::size_t k = 0; k < n; ++k) r[k] += cb->shift->coefficient(k) * (u[k] - cb->shift->anchor[k]);
    const double norm = max_norm(r);
    if (!std::isfinite(norm)) return 1;
    if (newton_point) cb->step_norms.push_back(norm);
    return 0;
  });
}

int jacobian_fn(N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector) {
  auto* cb = static_cast<KinsolNewton::Callbacks*>(data);
  return guarded_callback(cb->failure, [&]() -> int {
    const SparsePattern& p = cb->model->pattern();
    const auto n = std::size_t(N_VGetLength(y));
    cb->assemble_at(std::span<const double>(N_VGetArrayPointer(y), n), true);
    cb->next_with_jacobian = true;
    if (!fill_sparse_matrix(J, p, cb->point_jacobian)) return 1;
    if (cb->shift) {
      double* vals = SUNSparseMatrix_Data(J);
      // solve() has refused a shift on a row without a diagonal entry.
      for (std::size_t k = 0; k < cb->diagonal.size(); ++k)
        if (cb->diagonal[k] >= 0) vals[cb->diagonal[k]] += cb->shift->coefficient(k);
    }
    return 0;
  });
}

void error_handler(int, const char*, const char*, char* msg, void* data) {
  try {
    static_cast<KinsolNewton::Callbacks*>(data)->last_error = msg;
  } catch (...) {
    // The message is lost (no memory for it); the solver's flag still says what failed.
  }
}

// Undamped Newton steps tried before the line search (see solve()).
constexpr int full_step_budget = 8;

}  // namespace

bool settled_by_contraction(const NewtonSettings::QuantityReads& reads,
                            const std::function<double(std::size_t, double)>& within) {
  const std::size_t n = reads.values.size();
  if (n < 3) return false;
  const std::vector<double>&now = reads.values[n - 1], &before = reads.values[n - 2], &earlier = reads.values[n - 3];
  double rho = reads.residual_contraction;
  for (std::size_t k = 0; k < now.size(); ++k) {
    const double step = std::abs(now[k] - before[k]);
    if (step == 0.0) continue;  // a quantity the last step left alone bounds nothing
    const double ratio = step / std::abs(before[k] - earlier[k]);
    if (!(ratio <= rho)) rho = ratio;  // a NaN (a wild read) makes rho NaN: no stop
  }
  if (!(rho < 1.0)) return false;  // not contracting: no bound to lean on
  for (std::size_t k = 0; k < now.size(); ++k)
    if (!(rho / (1.0 - rho) * std::abs(now[k] - before[k]) <= within(k, now[k]))) return false;
  return true;
}

KinsolNewton::KinsolNewton(const SteadySystem& model, SparseLu::Ordering ordering)
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
  klu_.reset(make_pattern_klu(ctx_.get(), model_.pattern(), ordering, model_.step_solver()));
  if (!y_ || !scale_ || !jac_ || !klu_) throw SolverFailure("could not allocate the Newton solver", -1);
  kin_.reset(KINCreate(ctx_.get()));
  if (!kin_) throw SolverFailure("KINCreate failed", -1);
  check_flag(KINInit(kin_.get(), residual_fn, y_.get()), "KINInit");
  check_flag(KINSetUserData(kin_.get(), callbacks_.get()), "KINSetUserData");
  check_flag(KINSetErrHandlerFn(kin_.get(), error_handler, callbacks_.get()), "KINSetErrHandlerFn");
  check_flag(KINSetLinearSolver(kin_.get(), klu_.get(), jac_.get()), "KINSetLinearSolver");
  check_flag(KINSetJacFn(kin_.get(), jacobian_fn), "KINSetJacFn");
  // TWB_KINSOL_PRINT=1..3 shows KINSOL's own iteration log on stdout (diagnostics).
  if (const char* level = std::getenv("TWB_KINSOL_PRINT")) KINSetPrintLevel(kin_.get(), std::atoi(level));
}

KinsolNewton::~KinsolNewton() = default;

bool KinsolNewton::within_rounding(std::span<const double> y, std::span<const double> r, double tolerance) const {
  const SparsePattern& p = model_.pattern();
  std::vector<double> residual(y.size()), jacobian(std::size_t(p.nnz()));
  try {
    model_.evaluate(y, residual, jacobian);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception&) {
    return false;
  }
  constexpr double terms = 64.0;
  const double eps = std::numeric_limits<double>::epsilon();
  for (Index k = 0; k < p.rows; ++k) {
    double size = 0.0;
    for (Index e = p.row_start[std::size_t(k)]; e < p.row_start[std::size_t(k) + 1]; ++e)
      size += std::abs(jacobian[std::size_t(e)] * y[std::size_t(p.column[std::size_t(e)])]);
    if (!(std::abs(r[std::size_t(k)]) <= tolerance + terms * eps * size)) return false;
  }
  return true;
}

SparseLu& KinsolNewton::factorization() {
  PatternKlu& k = pattern_klu(klu_.get());
  if (!k.lu) throw InternalError("KinsolNewton::factorization of a system that solves its own Newton steps");
  return *k.lu;
}

NewtonReport KinsolNewton::solve(std::vector<double>& u, const NewtonSettings& s, const PseudoTimeShift* shift) {
  NewtonReport rep;
  const std::size_t n = u.size();
  std::copy(u.begin(), u.end(), N_VGetArrayPointer(y_.get()));
  // In the system's Newton form the rows must meet a tighter tolerance for its own
  // rows, in which later checks see the state, to meet s.residual_tolerance.
  const double tolerance =
      s.residual_tolerance * (model_.newton_form() ? model_.newton_form_tolerance_ratio() : 1.0);
  check_flag(KINSetFuncNormTol(kin_.get(), tolerance), "KINSetFuncNormTol");
  check_flag(KINSetMaxSetupCalls(kin_.get(), std::max(1, s.jacobian_reuse)), "KINSetMaxSetupCalls");
  check_flag(KINSetScaledStepTol(kin_.get(), s.step_tolerance), "KINSetScaledStepTol");
  if (s.max_step > 0) check_flag(KINSetMaxNewtonStep(kin_.get(), s.max_step), "KINSetMaxNewtonStep");
  callbacks_->last_error.clear();
  callbacks_->failure.message.clear();
  pattern_klu(klu_.get()).failure.message.clear();
  // The shift adds to the diagonal: a row whose pattern lacks (k, k) cannot take it.
  if (shift && model_.step_solver())
    throw InternalError("pseudo-time shift on a system that solves its own Newton steps");
  if (shift)
    for (std::size_t k = 0; k < n; ++k)
      if (shift->coefficient(k) != 0.0 && callbacks_->diagonal[k] < 0)
        throw InternalError(fmt::format("pseudo-time shift on row {}, which has no diagonal entry", k));
  callbacks_->shift = shift;
  callbacks_->tolerance = tolerance;
  callbacks_->watched = s.watched;
  callbacks_->watched_step = s.watched_step;
  callbacks_->watched_residual = s.watched_residual;
  callbacks_->quantities = s.quantities;
  callbacks_->forget();

  auto run = [&](int strategy, int max_iterations) {
    check_flag(KINSetNumMaxIters(kin_.get(), max_iterations), "KINSetNumMaxIters");
    callbacks_->next_with_jacobian = true;  // KINSOL's first request is a Jacobian's point
    callbacks_->step_norms.clear();
    callbacks_->last_watched.reset();
    callbacks_->reads = {};
    callbacks_->settled_point.clear();
    callbacks_->full_steps = strategy == KIN_NONE;
    const int result = KINSol(kin_.get(), y_.get(), strategy, scale_.get(), residual_scale_.get());
    callbacks_->failure.rethrow_internal();
    pattern_klu(klu_.get()).failure.rethrow_internal();
    long count = 0;
    KINGetNumNonlinSolvIters(kin_.get(), &count);
    rep.iterations += count;
    KINGetNumFuncEvals(kin_.get(), &count);
    rep.residual_evaluations += count;
    KINGetNumJacEvals(kin_.get(), &count);
    rep.jacobian_evaluations += count;
    KINGetNumBacktrackOps(kin_.get(), &count);
    rep.backtracks += count;
    return result;
  };
  // The residual (shifted, as solved) at KINSOL's current iterate, into r; true when it
  // meets the tolerance. KIN_STEP_LT_STPTOL may be a stall: only the residual says.
  std::vector<double> r(n);
  auto settled = [&](int result) {
    if (callbacks_->watched_settled) {
      const bool unassembled = !callbacks_->settled_point.empty();
      const std::vector<double>& at = unassembled ? callbacks_->settled_point : callbacks_->point;
      std::copy(at.begin(), at.end(), N_VGetArrayPointer(y_.get()));
      rep.watched_settled = true;
      rep.residual_norm = unassembled ? NAN : max_norm(callbacks_->point_residual);
      return true;
    }
    const std::span<const double> y(N_VGetArrayPointer(y_.get()), n);
    try {
      if (callbacks_->holds(y))
        r = callbacks_->point_residual;
      else
        model_.evaluate(y, r, {});
      if (shift)
        for (std::size_t k = 0; k < n; ++k) r[k] += shift->coefficient(k) * (y[k] - shift->anchor[k]);
      rep.residual_norm = max_norm(r);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception&) {
      rep.residual_norm = INFINITY;
    }
    return result >= 0 && rep.residual_norm <= tolerance;
  };
  // Full Newton steps first. KINSOL's line search asks every step to lower ½‖F‖²; on
  // the hot branch the semismooth Newton direction raises it for a step or two before
  // converging quadratically, and backtracking then costs iterations (a 2 % load step
  // at 500 N: 7 iterations with 6 backtracks, against 4 full steps). So a solve
  // without a pseudo-time shift first takes a few undamped steps (still capped by
  // max_step); when they do not converge it starts again from u with the line search.
  // Pseudo-time steps keep the line search: their Δτ control expects damped steps.
  // Full steps that used their budget while still converging (a start from another
  // mesh's state: the residual down from 710 to 1e-7 in 8 steps, each cutting it five-
  // to tenfold across the kinks of contact and cavitation) go on from where they are:
  // starting again from u with the line search would repeat those steps.
  int flag = -1;
  bool done = false;
  if (!shift && s.max_iterations > 0) {
    long left = s.max_iterations;
    for (;;) {
      const long before = rep.iterations;
      flag = run(KIN_NONE, int(std::min<long>(left, full_step_budget)));
      done = settled(flag);
      left -= rep.iterations - before;
      if (done || flag != KIN_MAXITER_REACHED || left <= 0 || !callbacks_->converging()) break;
    }
    if (!done && s.line_search) std::copy(u.begin(), u.end(), N_VGetArrayPointer(y_.get()));
  }
  if (!done && (s.line_search || shift)) {
    flag = run(KIN_LINESEARCH, s.max_iterations);
    done = settled(flag);
  }
  // A stall (KINSOL's step below its tolerance, or a line search that finds no lower
  // residual) at a residual just above the tolerance is converged when what is left is
  // the rows' own rounding: on states of thousands of kelvin the heat rows sum terms so
  // large that 1e-10 K lies below their floating-point floor (the stability suite's
  // heavy load and steep tilt stalled at 2e-10 and 3.6e-10). A row's rounding is at
  // most about n·ε·Σ_j |J_kj u_j| for a sum of n terms (Higham's γ_n); n = 64 covers the
  // quadrature sums behind a row (four cells of up to 16 Gauss points each).
  if (!done && !shift && (flag == KIN_STEP_LT_STPTOL || flag == KIN_LINESEARCH_NONCONV) &&
      std::isfinite(rep.residual_norm) && rep.residual_norm < 1e3 * tolerance)
    done = within_rounding(std::span<const double>(N_VGetArrayPointer(y_.get()), n), r, tolerance);
  rep.flag = flag;
  std::vector<double> trial(N_VGetArrayPointer(y_.get()), N_VGetArrayPointer(y_.get()) + n);
  rep.converged = done;
  if (std::getenv("TWB_KINSOL_PRINT")) {
    if (const std::optional<SparseLu>& lu = pattern_klu(klu_.get()).lu) {
      const SparseLu::Counts& k = lu->counts();
      fmt::print("[KLU] so far: {} analyses, {} full factorizations, {} refactorizations\n", k.analyses,
                 k.factorizations, k.refactorizations);
    }
  }
  u = trial;  // the final iterate, converged or not: callers keep their own copies
  if (!rep.converged) {
    // Say where the residual is largest: the block names the physics that failed.
    std::size_t worst = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (!(std::abs(r[k]) <= std::abs(r[worst]))) worst = k;
    rep.worst_block = model_.block_name(Index(worst));
    rep.worst_row = Index(worst);
    char* name = KINGetReturnFlagName(flag);
    const std::string& linear_failure = pattern_klu(klu_.get()).failure.message;
    rep.message = std::string(name ? name : "KINSOL failure") +
                  fmt::format(" (largest residual {:.3g} in {})", r[worst], model_.describe_row(Index(worst))) +
                  (callbacks_->last_error.empty() ? "" : ": " + callbacks_->last_error) +
                  (callbacks_->failure.message.empty() ? "" : " (" + callbacks_->failure.message + ")") +
                  (linear_failure.empty() ? "" : " (linear solver: " + linear_failure + ")");
    free(name);
  }
  return rep;
}

}  // namespace twb
