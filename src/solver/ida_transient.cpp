#include "solver/ida_transient.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>
#include <cstdlib>
#include <stdexcept>

#include <idas/idas.h>  // IDA with quadratures (a duty cycle's heat integrals)
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "solver/consistent_rates.h"
#include "solver/kinsol_newton.h"
#include "solver/sparse_matrix_fill.h"
#include "solver/callback_guard.h"
#include "twb/error_family.h"

namespace twb {

struct IdaTransient::Callbacks {
  const SteadySystem* system;
  const std::vector<double>* capacities;
  const std::function<double(double)>* inputs_at;  // may be empty
  const TransientSettings* settings;
  // The system's G(u, u') − C·u' (its rate terms in real time) and its iteration matrix
  // without c_j·C.
  void evaluate(std::span<const double> y, std::span<const double> yp, double cj, std::span<double> r,
                std::span<double> jac) const {
    if (settings->real_time)
      system->evaluate_in_time(y, yp, cj, r, jac);
    else
      system->evaluate(y, r, jac);
  }
  // The inputs at t; the rate of the differential unknowns' reference there.
  double set_inputs(double t) const { return *inputs_at ? (*inputs_at)(t) : 0.0; }
  // IDA's Jacobian needs (k, k) wherever C_k > 0; the system's pattern may lack it, so
  // IDA works on the union and the system's entries are scattered into it.
  SparsePattern pattern;
  std::vector<Index> from_system;  // position in `pattern` of each entry of the system's pattern
  std::vector<Index> diagonal;     // position of (k, k) in `pattern`, -1 where C_k = 0 and absent
  std::vector<double> system_values, values, scratch;
  std::string last_error;      // IDA's own message
  // What a callback threw (callback_guard.h): an internal error is carried across the
  // C solver and thrown again once it returns.
  CallbackFailure failure;
};

namespace {

// The system's pattern plus the diagonal of every differential row.
SparsePattern with_capacity_diagonal(const SparsePattern& p, const std::vector<double>& capacities) {
  SparsePattern u;
  u.rows = p.rows;
  u.cols = p.cols;
  u.prefers_nested_dissection = p.prefers_nested_dissection;
  u.row_start.push_back(0);
  for (Index r = 0; r < p.rows; ++r) {
    std::vector<Index> row(p.column.begin() + p.row_start[std::size_t(r)],
                           p.column.begin() + p.row_start[std::size_t(r + 1)]);
    const auto at = std::lower_bound(row.begin(), row.end(), r);
    if (capacities[std::size_t(r)] > 0.0 && (at == row.end() || *at != r)) row.insert(at, r);
    u.column.insert(u.column.end(), row.begin(), row.end());
    u.row_start.push_back(Index(u.column.size()));
  }
  return u;
}

// Trampolines: no exception may cross into C. A non-finite residual is recoverable
// (IDA retries with a smaller step, and a blow-up then ends in a step failure the
// caller reads); anything thrown is unrecoverable and its message kept.
int residual_fn(double t, N_Vector y, N_Vector yp, N_Vector g, void* data) {
  auto* cb = static_cast<IdaTransient::Callbacks*>(data);
  return guarded_callback(cb->failure, [&]() -> int {
    const auto n = std::size_t(N_VGetLength(y));
    const double* up = N_VGetArrayPointer(yp);
    std::span<double> r(N_VGetArrayPointer(g), n);
    const double reference_rate = cb->set_inputs(t);
    cb->evaluate(std::span<const double>(N_VGetArrayPointer(y), n), std::span<const double>(up, n), 0.0, r, {});
    const std::vector<double>& c = *cb->capacities;
    for (std::size_t k = 0; k < n; ++k) r[k] += c[k] * (up[k] + reference_rate);
    for (double v : r)
      if (!std::isfinite(v)) return 1;
    return 0;
  });
}

int jacobian_fn(double t, double cj, N_Vector y, N_Vector yp, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
                N_Vector) {
  auto* cb = static_cast<IdaTransient::Callbacks*>(data);
  return guarded_callback(cb->failure, [&]() -> int {
    const auto n = std::size_t(N_VGetLength(y));
    cb->set_inputs(t);
    const std::span<const double> state(N_VGetArrayPointer(y), n), rate(N_VGetArrayPointer(yp), n);
    cb->evaluate(state, rate, cj, cb->scratch, cb->system_values);
    std::fill(cb->values.begin(), cb->values.end(), 0.0);
    for (std::size_t e = 0; e < cb->from_system.size(); ++e)
      cb->values[std::size_t(cb->from_system[e])] = cb->system_values[e];
    const std::vector<double>& c = *cb->capacities;
    for (std::size_t k = 0; k < n; ++k)
      if (c[k] > 0.0) cb->values[std::size_t(cb->diagonal[k])] += cj * c[k];
    return fill_sparse_matrix(J, cb->pattern, cb->values) ? 0 : 1;
  });
}

int quadrature_fn(double t, N_Vector y, N_Vector, N_Vector rates, void* data) {
  auto* cb = static_cast<IdaTransient::Callbacks*>(data);
  return guarded_callback(cb->failure, [&]() -> int {
    const auto n = std::size_t(N_VGetLength(y));
    cb->set_inputs(t);
    std::span<double> q(N_VGetArrayPointer(rates), std::size_t(N_VGetLength(rates)));
    cb->settings->quadrature_rates(t, std::span<const double>(N_VGetArrayPointer(y), n), q);
    for (double v : q)
      if (!std::isfinite(v)) return 1;
    return 0;
  });
}

void error_handler(int, const char*, const char*, char* msg, void* data) {
  try {
    static_cast<IdaTransient::Callbacks*>(data)->last_error = msg;
  } catch (...) {
    // The message is lost (no memory for it); the solver's flag still says what failed.
  }
}

}  // namespace

IdaTransient::IdaTransient(const SteadySystem& system, TransientSettings settings)
    : system_(system),
      settings_(std::move(settings)),
      capacities_(system.capacities()),
      ctx_(make_context()),
      callbacks_(std::make_unique<Callbacks>()) {
  const Index n = system_.size();
  if (Index(capacities_.size()) != n) throw InternalError("IdaTransient: capacities() has the wrong size");
  for (double c : capacities_)
    if (!(c >= 0.0)) throw InternalError("IdaTransient: a capacity is negative or not a number");
  absolute_ = settings_.absolute_tolerances.empty()
                  ? std::vector<double>(std::size_t(n), settings_.absolute_tolerance)
                  : settings_.absolute_tolerances;
  if (Index(absolute_.size()) != n) throw InternalError("IdaTransient: one absolute tolerance per unknown");
  differential_.assign(std::size_t(n), 0);
  const std::vector<char> rates_read = settings_.real_time ? system_.rate_unknowns() : std::vector<char>{};
  if (!rates_read.empty() && Index(rates_read.size()) != n)
    throw InternalError("IdaTransient: rate_unknowns() has the wrong size");
  for (std::size_t k = 0; k < std::size_t(n); ++k)
    differential_[k] = capacities_[k] > 0.0 || (!rates_read.empty() && rates_read[k]);

  Callbacks& cb = *callbacks_;
  cb.system = &system_;
  cb.capacities = &capacities_;
  cb.inputs_at = &settings_.inputs_at;
  cb.settings = &settings_;
  const SparsePattern& own = system_.pattern();
  cb.pattern = with_capacity_diagonal(own, capacities_);
  for (Index r = 0; r < n; ++r)
    for (Index e = own.row_start[std::size_t(r)]; e < own.row_start[std::size_t(r + 1)]; ++e)
      cb.from_system.push_back(cb.pattern.find(r, own.column[std::size_t(e)]));
  for (Index k = 0; k < n; ++k) cb.diagonal.push_back(cb.pattern.find(k, k));
  cb.system_values.resize(std::size_t(own.nnz()));
  cb.values.resize(std::size_t(cb.pattern.nnz()));
  cb.scratch.resize(std::size_t(n));

  y_.reset(N_VNew_Serial(n, ctx_.get()));
  yp_.reset(N_VNew_Serial(n, ctx_.get()));
  id_.reset(N_VNew_Serial(n, ctx_.get()));
  atol_.reset(N_VNew_Serial(n, ctx_.get()));
  jac_.reset(SUNSparseMatrix(n, n, cb.pattern.nnz(), CSR_MAT, ctx_.get()));
  if (!y_ || !yp_ || !id_ || !atol_ || !jac_) throw SolverFailure("could not allocate the transient solver", -1);
  N_VConst(0.0, y_.get());
  N_VConst(0.0, yp_.get());
  for (std::size_t k = 0; k < std::size_t(n); ++k) {
    N_VGetArrayPointer(id_.get())[k] = differential_[k] ? 1.0 : 0.0;
    N_VGetArrayPointer(atol_.get())[k] = absolute_[k];
  }
  klu_.reset(SUNLinSol_KLU(y_.get(), jac_.get(), ctx_.get()));
  if (!klu_) throw SolverFailure("could not allocate KLU for the transient solver", -1);
  // AMD rather than SUNDIALS' default COLAMD: see kinsol_newton.cpp (the bearing's
  // dense rigid-body border).
  check_flag(SUNLinSol_KLUSetOrdering(klu_.get(), 0), "SUNLinSol_KLUSetOrdering");

  ida_.reset(IDACreate(ctx_.get()));
  if (!ida_) throw SolverFailure("IDACreate failed", -1);
  check_flag(IDAInit(ida_.get(), residual_fn, 0.0, y_.get(), yp_.get()), "IDAInit");
  check_flag(IDASVtolerances(ida_.get(), settings_.relative_tolerance, atol_.get()), "IDASVtolerances");
  check_flag(IDASetUserData(ida_.get(), callbacks_.get()), "IDASetUserData");
  check_flag(IDASetErrHandlerFn(ida_.get(), error_handler, callbacks_.get()), "IDASetErrHandlerFn");
  check_flag(IDASetLinearSolver(ida_.get(), klu_.get(), jac_.get()), "IDASetLinearSolver");
  check_flag(IDASetJacFn(ida_.get(), jacobian_fn), "IDASetJacFn");
  check_flag(IDASetId(ida_.get(), id_.get()), "IDASetId");
  // In real time the pressures switch between full film and cavitation node by node,
  // each switch a kink in them that IDA's error test would resolve with steps of
  // microseconds; an index-one DAE's algebraic unknowns follow the differential ones
  // through the constraints, so their error needs no test of its own (on the
  // speed-through-zero cycle: 1461 steps instead of 6384).
  if (settings_.real_time || !settings_.algebraic_error_test)
    check_flag(IDASetSuppressAlg(ida_.get(), SUNTRUE), "IDASetSuppressAlg");
  if (settings_.quadrature_count > 0) {
    if (!settings_.quadrature_rates) throw InternalError("IdaTransient: quadratures without their rates");
    quadrature_.reset(N_VNew_Serial(settings_.quadrature_count, ctx_.get()));
    if (!quadrature_) throw SolverFailure("could not allocate the transient's quadratures", -1);
    N_VConst(0.0, quadrature_.get());
    check_flag(IDAQuadInit(ida_.get(), quadrature_fn, quadrature_.get()), "IDAQuadInit");
  }
}

IdaTransient::~IdaTransient() = default;

TransientStatus IdaTransient::status_from(int flag, const char* call) const {
  callbacks_->failure.rethrow_internal();
  TransientStatus s;
  s.flag = flag;
  s.ok = flag >= 0;
  s.reached_stop = flag == IDA_TSTOP_RETURN;
  if (!s.ok) {
    char* name = IDAGetReturnFlagName(flag);
    s.flag_name = name ? name : "IDA failure";
    free(name);
    s.message = std::string(call) + ": " + s.flag_name +
                (callbacks_->last_error.empty() ? "" : ": " + callbacks_->last_error) +
                (callbacks_->failure.message.empty() ? "" : " (" + callbacks_->failure.message + ")");
  }
  return s;
}

// IDACalcIC takes a trial step of 0.001·(tout1 − t0) and iterates for u' with the
// matrix ∂F/∂u + C/h: the iteration contracts by about ‖(∂F/∂u + C/h)⁻¹ ∂F/∂u‖, so h
// must be short against the fastest relaxation, not the span to be integrated (with a
// long span, CalcIC fails on stiff conduction grids near a fold). The fastest local
// relaxation time is min C_k/|∂F_k/∂u_k|; C_k itself (a time, steady_system.h) stands in
// where no row has a diagonal.
double IdaTransient::fastest_time(std::span<const double> u) const {
  double smallest_capacity = INFINITY;
  for (double c : capacities_)
    if (c > 0.0) smallest_capacity = std::min(smallest_capacity, c);
  if (!std::isfinite(smallest_capacity)) smallest_capacity = 1.0;
  Callbacks& cb = *callbacks_;
  try {
    system_.evaluate(u, cb.scratch, cb.system_values);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception&) {
    return smallest_capacity;  // CalcIC will meet the same failure and report it
  }
  double fastest = INFINITY;
  const SparsePattern& own = system_.pattern();
  for (std::size_t k = 0; k < capacities_.size(); ++k) {
    const Index at = own.find(Index(k), Index(k));
    const double diagonal = at >= 0 ? std::abs(cb.system_values[std::size_t(at)]) : 0.0;
    if (capacities_[k] > 0.0 && diagonal > 0.0) fastest = std::min(fastest, capacities_[k] / diagonal);
  }
  return std::isfinite(fastest) ? fastest : smallest_capacity;
}

TransientStatus IdaTransient::reinitialize(double t0, std::span<const double> u0, std::span<const double> rate0) {
  std::copy(u0.begin(), u0.end(), N_VGetArrayPointer(y_.get()));
  if (rate0.empty())
    N_VConst(0.0, yp_.get());
  else
    std::copy(rate0.begin(), rate0.end(), N_VGetArrayPointer(yp_.get()));
  callbacks_->last_error.clear();
  callbacks_->failure.message.clear();
  time_ = t0;
  stepped_ = false;
  int flag = IDAReInit(ida_.get(), t0, y_.get(), yp_.get());
  if (flag < 0) return status_from(flag, "IDAReInit");
  if (quadrature_) {
    N_VConst(0.0, quadrature_.get());
    flag = IDAQuadReInit(ida_.get(), quadrature_.get());
    if (flag < 0) return status_from(flag, "IDAQuadReInit");
  }
  return status_from(flag, "IDAReInit");
}

TransientStatus IdaTransient::consistent_start(double t0, std::span<const double> u0, double fastest) {
  // u' = 0 is only a guess: CalcIC computes it for the differential unknowns.
  const TransientStatus s = reinitialize(t0, u0, {});
  if (!s.ok) return s;
  const int flag = IDACalcIC(ida_.get(), IDA_YA_YDP_INIT, t0 + fastest);
  if (flag < 0) return status_from(flag, "IDACalcIC");
  return status_from(IDAGetConsistentIC(ida_.get(), y_.get(), yp_.get()), "IDAGetConsistentIC");
}

TransientStatus IdaTransient::start(double t0, std::span<const double> u0) {
  if (Index(u0.size()) != system_.size()) throw InternalError("IdaTransient::start: state has the wrong size");
  const std::vector<double> held(u0.begin(), u0.end());  // u0 may be our own state()
  const double reference_rate = callbacks_->set_inputs(t0);
  if (settings_.real_time) return start_in_real_time(t0, held, reference_rate);
  const double fastest = fastest_time(held);
  TransientStatus s = consistent_start(t0, held, fastest);
  if (s.ok) return s;
  // CalcIC's Newton is plain (a few Jacobians, no step bound): after a large load step
  // the bearing's film and rigid body can be out of its reach. KINSOL's line search
  // with a bounded step reaches them as one implicit Euler step of the transient,
  // F(u) + C·(u − u0)/Δτ = 0 with Δτ the trial step CalcIC took; IDA starts again from
  // that point of the trajectory, at t0 + Δτ.
  const double dtau = 1e-3 * fastest;
  std::vector<double> stepped = held;
  // C·((u − u0)/Δτ + r): the anchor moved back by the reference's move over the step.
  std::vector<double> anchor = held;
  for (std::size_t k = 0; k < anchor.size(); ++k)
    if (capacities_[k] > 0.0) anchor[k] -= reference_rate * dtau;
  const PseudoTimeShift euler{1.0 / dtau, anchor, capacities_};
  NewtonReport rep;
  try {
    // From the start itself, a step this short is well inside Newton's quadratic basin
    // whenever its algebraic part has a root at all; where it has none (the film's
    // equilibrium lost at an impasse of the DAE) more iterations only churn.
    rep = KinsolNewton(system_).solve(stepped, NewtonSettings{.max_iterations = 25}, &euler);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    rep.message = e.what();  // e.g. a differential row without a diagonal entry
  }
  if (!rep.converged) {
    s.message += "; an implicit Euler start by KINSOL failed too: " + rep.message;
    return s;
  }
  TransientStatus again = consistent_start(t0 + dtau, stepped, fastest);
  if (!again.ok) again.message = s.message + "; again after an implicit Euler start: " + again.message;
  return again;
}

// The algebraic unknowns and the rates by KINSOL, the exact Newton of ConsistentRates
// (consistent_rates.h says why not IDACalcIC); IDA then starts from them as they are.
// Newton starts from rates of zero, not from those the march had: the start is then a
// function of the state alone, so that a cycle continued from a saved state restarts
// as the whole cycle does, to the bit.
TransientStatus IdaTransient::start_in_real_time(double t0, const std::vector<double>& held, double reference_rate) {
  const ConsistentRates consistent(system_, held, capacities_, differential_, reference_rate);
  std::vector<double> z = consistent.unknowns_of(held, std::vector<double>(held.size(), 0.0));
  NewtonReport rep;
  try {
    rep = KinsolNewton(consistent).solve(z, NewtonSettings{.max_iterations = 50});
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    rep.message = e.what();
  }
  if (!rep.converged) {
    TransientStatus s;
    s.ok = false;
    s.flag = -1;
    s.flag_name = "no consistent start";
    s.message = "the algebraic unknowns and the rates at the start: " + rep.message;
    return s;
  }
  std::vector<double> y, rate0;
  consistent.state_of(z, y, rate0);
  return reinitialize(t0, y, rate0);
}

TransientStatus IdaTransient::step(double t_stop) {
  if (!(t_stop > time_)) throw InternalError("IdaTransient::step: stop time not ahead of the current time");
  callbacks_->last_error.clear();
  callbacks_->failure.message.clear();
  int flag = IDASetStopTime(ida_.get(), t_stop);
  if (flag < 0) return status_from(flag, "IDASetStopTime");
  double reached = time_;
  flag = IDASolve(ida_.get(), t_stop, &reached, y_.get(), yp_.get(), IDA_ONE_STEP);
  if (flag >= 0) {
    time_ = reached;
    stepped_ = true;
  }
  return status_from(flag, "IDASolve");
}

TransientStatus IdaTransient::advance(double t_out, const TransientObserver& observer) {
  TransientStatus s;
  while (time_ < t_out) {
    s = step(t_out);
    if (!s.ok) return s;
    if (observer) observer(time_, state());
    if (s.reached_stop) break;
  }
  return s;
}

std::span<const double> IdaTransient::state() const {
  return {N_VGetArrayPointer(y_.get()), std::size_t(system_.size())};
}

std::span<const double> IdaTransient::rate() const {
  return {N_VGetArrayPointer(yp_.get()), std::size_t(system_.size())};
}

bool IdaTransient::state_at(double t, std::span<double> out) const {
  if (Index(out.size()) != system_.size()) throw InternalError("IdaTransient::state_at: state has the wrong size");
  // IDAGetDky extrapolates past the last step, and after a restart returns the start.
  if (!stepped_ || !(t <= time_)) return false;
  // A vector over the caller's array (IDA writes into it; destroying it leaves the array).
  const Vector at(N_VMake_Serial(system_.size(), out.data(), ctx_.get()));
  if (!at) throw SolverFailure("could not allocate the transient's interpolation", -1);
  return IDAGetDky(ida_.get(), t, 0, at.get()) == IDA_SUCCESS;
}

double IdaTransient::differential_distance(std::span<const double> a, std::span<const double> b) const {
  double d = 0.0;
  for (std::size_t k = 0; k < capacities_.size(); ++k) {
    if (!differential_[k]) continue;
    const double scaled = std::abs(a[k] - b[k]) / (settings_.relative_tolerance * std::abs(b[k]) + absolute_[k]);
    if (!std::isfinite(scaled)) return INFINITY;
    d = std::max(d, scaled);
  }
  return d;
}

std::vector<double> IdaTransient::quadratures() const {
  if (!quadrature_) return {};
  double t = time_;
  // Before the first step IDAS has no quadrature history: the integrals are zero.
  if (IDAGetQuad(ida_.get(), &t, quadrature_.get()) < 0) N_VConst(0.0, quadrature_.get());
  const double* q = N_VGetArrayPointer(quadrature_.get());
  return {q, q + settings_.quadrature_count};
}

TransientStatistics IdaTransient::statistics() const {
  TransientStatistics s;
  IDAGetNumSteps(ida_.get(), &s.steps);
  IDAGetNumResEvals(ida_.get(), &s.residual_evaluations);
  IDAGetNumJacEvals(ida_.get(), &s.jacobian_evaluations);
  IDAGetNumLinSolvSetups(ida_.get(), &s.linear_setups);
  IDAGetNumNonlinSolvIters(ida_.get(), &s.nonlinear_iterations);
  IDAGetNumErrTestFails(ida_.get(), &s.error_test_failures);
  IDAGetNumNonlinSolvConvFails(ida_.get(), &s.convergence_failures);
  IDAGetLastStep(ida_.get(), &s.last_step);
  return s;
}

}  // namespace twb
