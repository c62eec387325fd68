// The pseudo-time transient of a SteadySystem, C·u' = −F(u; λ), integrated by SUNDIALS
// IDA (IDAS, its edition with quadratures) as the DAE residual
//
//     G(t, u, u') = C·u' + F(u; λ) = 0,       ∂G/∂u + c_j·∂G/∂u' = ∂F/∂u + c_j·C,
//
// with the system's exact sparse Jacobian factored by KLU. Unknowns with C_k = 0 are
// algebraic (on the bearing: pressures, film-node temperatures, rigid body; physics §7):
// IDA keeps them on the constraint manifold F_alg = 0 at every step. In real time
// (TransientSettings::real_time) F also holds the system's terms in u' (the film's
// squeeze, physics §19), and the unknowns whose rates they read are differential too.
//
// A change of λ (a load step) is a discontinuity of the right-hand side: restart with
// start(), which re-initializes IDA and recomputes consistent initial conditions. Inputs
// that move in time (TransientSettings::inputs_at) are set at every evaluation's time.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "system/steady_system.h"
#include "solver/sundials_context.h"

namespace twb {

struct TransientSettings {
  // IDA's local error test is ‖e‖_WRMS ≤ 1 with weights 1/(rtol·|u_k| + atol_k).
  // 1e-6 relative: the runaway detector reads the trajectory's slow drift near a
  // saddle-node's ghost, where an error δ in u acts like a shift of λ of relative size
  // O(δ); 1e-6 keeps that three orders below a 2e-3 bracket width, and the state a
  // step settles to is polished by Newton anyway. (The distress search ties it to its
  // bracket width: distress_detector.)
  double relative_tolerance = 1e-6;
  // twb's unknowns are O(1) (scaled pressures, clearances in σ) to O(100) (temperature
  // rises in K): 1e-8 lets the relative tolerance govern except where an unknown
  // passes through zero.
  double absolute_tolerance = 1e-8;
  // Per unknown; replaces absolute_tolerance when not empty.
  std::vector<double> absolute_tolerances;
  // A transient in real time whose inputs change with it (a duty cycle, docs/physics.md
  // section 19): called before every evaluation at t, it sets the system's inputs there
  // and returns the rate r(t) at which the reference the differential unknowns are
  // measured from moves (the bearing's temperatures are rises above the ambient, which
  // the schedule moves), so that the residual is C·(u' + r) + F(u; t). Empty: λ fixed,
  // r = 0. The inputs must be smooth between the stop times the caller restarts at.
  std::function<double(double t)> inputs_at;
  // A transient in physical time: the system's terms in the state's rates beyond C·u'
  // (SteadySystem::rate_unknowns, the bearing's film squeeze) are on, and the unknowns
  // they read are differential. A pseudo-time transient, which only decides which steady
  // state a step reaches, leaves them off.
  bool real_time = false;
  // Whether IDA's error test reads the algebraic unknowns too. Off in real time (below),
  // and where the error that matters is the differential unknowns' alone (a washer's
  // worn depths in slow time, docs/physics.md section 20), the algebraic ones following
  // them through the constraints.
  bool algebraic_error_test = true;
  // Integrals of functions of the state along the march (IDAS's quadratures: the same
  // BDF formula as the state, kept out of the error test, so they are as accurate as the
  // state is): `count` of them, whose rates at (t, u) `rates` writes (the inputs set at t
  // first). Read with IdaTransient::quadratures(), from zero at each start().
  int quadrature_count = 0;
  std::function<void(double t, std::span<const double> u, std::span<double> rates)> quadrature_rates;
};

// A failure of IDA is data, not an exception: a finite-time blow-up ends in
// IDA_ERR_FAIL, IDA_CONV_FAIL or a step too small, and the caller reads it as such.
struct TransientStatus {
  bool ok = true;
  bool reached_stop = false;  // the step ended exactly at the requested stop time
  int flag = 0;
  std::string flag_name;      // IDA's name of flag, e.g. "IDA_ERR_FAIL"
  std::string message;        // IDA's own error text, and what a callback threw
};

struct TransientStatistics {
  long steps = 0;
  long residual_evaluations = 0;
  long jacobian_evaluations = 0;
  long linear_setups = 0;  // each a KLU factorization of ∂F/∂u + c_j·C
  long nonlinear_iterations = 0;
  long error_test_failures = 0;
  long convergence_failures = 0;
  double last_step = 0.0;
};

// Called at every internal step of IDA with the time and the state there (the bearing
// writes its trajectory rows from it).
using TransientObserver = std::function<void(double t, std::span<const double> u)>;

class IdaTransient {
 public:
  IdaTransient(const SteadySystem& system, TransientSettings settings);
  ~IdaTransient();
  IdaTransient(const IdaTransient&) = delete;
  IdaTransient& operator=(const IdaTransient&) = delete;

  // (Re)starts at (t0, u0) under the system's current λ: IDAReInit, then
  // IDACalcIC(IDA_YA_YDP_INIT) solves the algebraic unknowns and u' with the
  // differential unknowns held at u0. Should CalcIC fail, one implicit Euler step by
  // KINSOL supplies the algebraic unknowns and the transient starts there, a
  // thousandth of the fastest relaxation time later (time() says when). In real time
  // KINSOL solves for them directly (consistent_rates.h), from rates of zero (a restart
  // is a function of the state alone), and the transient starts at t0.
  TransientStatus start(double t0, std::span<const double> u0);
  // One internal step of IDA, never past t_stop (> time()).
  TransientStatus step(double t_stop);
  // Internal steps until t_out, calling the observer after each.
  TransientStatus advance(double t_out, const TransientObserver& observer = {});

  double time() const { return time_; }
  std::span<const double> state() const;
  std::span<const double> rate() const;  // u'
  // The state at t within the last step, [time() − its length, time()], on IDA's
  // interpolating polynomial (IDAGetDky): what the march computed between its steps. The
  // algebraic unknowns there are the polynomial's too, not re-solved, and with the real
  // time's suppressed algebraic error test nothing bounds their interpolation but the
  // differential unknowns they follow. False outside that interval or before a step
  // since the last start.
  bool state_at(double t, std::span<double> out) const;
  const std::vector<double>& capacities() const { return capacities_; }
  // Whether unknown k is differential: a capacity, or a rate the system's terms read.
  bool differential(std::size_t k) const { return differential_[k] != 0; }
  // max over differential unknowns of |a_k − b_k| / (rtol·|b_k| + atol_k): a distance in
  // units of the integration tolerance (1 = what IDA cannot resolve).
  double differential_distance(std::span<const double> a, std::span<const double> b) const;
  TransientStatistics statistics() const;
  // The quadratures' integrals from the last start() to time() (TransientSettings).
  std::vector<double> quadratures() const;

  // Callback state, public for the C trampolines.
  struct Callbacks;

 private:
  TransientStatus status_from(int flag, const char* call) const;
  double fastest_time(std::span<const double> u) const;
  TransientStatus consistent_start(double t0, std::span<const double> u0, double fastest);
  TransientStatus reinitialize(double t0, std::span<const double> u0, std::span<const double> rate0);
  TransientStatus start_in_real_time(double t0, const std::vector<double>& held, double reference_rate);

  const SteadySystem& system_;
  TransientSettings settings_;
  std::vector<double> capacities_, absolute_;
  std::vector<char> differential_;
  SundialsContext ctx_;
  Vector y_, yp_, id_, atol_, quadrature_;
  Matrix jac_;
  LinearSolver klu_;
  IdaMemory ida_;
  std::unique_ptr<Callbacks> callbacks_;
  double time_ = 0.0;
  bool stepped_ = false;  // a step since the last start: IDA's polynomial is the step's
};

}  // namespace twb
