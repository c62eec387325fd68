// What the solvers need from a problem: a square sparse system F(u; λ) = 0 in one
// continuation parameter λ, its exact Jacobian ∂F/∂u in a fixed pattern, the exact
// ∂F/∂λ, and the capacities of the pseudo-time transient
//
//     C · du/dt = −F(u; λ),   C diagonal, C_k = 0 for an algebraic unknown,
//
// whose steady states are the roots of F. Rows are oriented so that the diagonal of
// ∂F/∂u is positive where the physics is stable (u' = −F relaxes).
//
// The bearing (BearingModel, λ = load in N) implements it, and so do the model
// problems with known critical points (Semenov, Bratu) that prove the continuation
// and runaway machinery on the same code path.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "system/newton_step_solver.h"
#include "system/sparse_pattern.h"

namespace twb {

class SteadySystem {
 public:
  virtual ~SteadySystem() = default;

  virtual Index size() const = 0;
  virtual const SparsePattern& pattern() const = 0;
  // Residual and, if jacobian is non-empty, ∂F/∂u in pattern() order.
  virtual void evaluate(std::span<const double> u, std::span<double> residual,
                        std::span<double> jacobian) const = 0;

  virtual double parameter() const = 0;
  virtual void set_parameter(double value) = 0;
  // ∂F/∂λ at u and the current λ.
  virtual void parameter_derivative(std::span<const double> u, std::span<double> derivative) const = 0;
  // The same when F(u) is at hand: a system whose ∂F/∂λ follows from F (the bearing's
  // load enters its force balance as F_ext/λ) saves an evaluation; the default ignores it.
  virtual void parameter_derivative_given(std::span<const double> u, std::span<const double> /*residual*/,
                                          std::span<double> derivative) const {
    parameter_derivative(u, derivative);
  }

  // Diagonal of C (time units of the transient); 0 marks an algebraic unknown.
  virtual std::vector<double> capacities() const = 0;

  // The transient in real time (a duty cycle, docs/physics.md section 19) may read the
  // rates of unknowns beyond C·u': the bearing's film squeeze, the rigid body's rates in
  // the Reynolds rows. rate_unknowns() marks the unknowns whose rates those terms read
  // (differential in the DAE beside those with C_k > 0; empty: none); evaluate_in_time
  // gives the residual with them at u' = rate and, with a jacobian, the iteration matrix
  // ∂/∂u + c_j·∂/∂u' of everything but C·u' in pattern(), which must hold its entries.
  virtual std::vector<char> rate_unknowns() const { return {}; }
  virtual void evaluate_in_time(std::span<const double> u, std::span<const double> /*rate*/, double /*cj*/,
                                std::span<double> residual, std::span<double> jacobian) const {
    evaluate(u, residual, jacobian);
  }

  // Unknowns whose rows hold at every pseudo-time step instead of relaxing towards it
  // (pseudo_transient.h puts no shift on them): a body that answers its loads at once, as
  // the bearing's elastic washer does, whose own mixed-form rows have no stable
  // relaxation of their own. Empty: every row relaxes.
  virtual std::vector<char> held_in_pseudo_time() const { return {}; }
  // Weights KINSOL measures a Newton step with (its maximum step is in these units).
  virtual std::vector<double> step_weights() const { return std::vector<double>(std::size_t(size()), 1.0); }
  // Name of the group of unknowns holding unknown k, for failure reports.
  virtual std::string block_name(Index) const { return "unknowns"; }
  // What residual row k balances, and where, in the physics' words (for failure
  // reports: which balance, which film, which node); the block's name by default.
  virtual std::string describe_row(Index k) const { return block_name(k); }

  // Newton's form: rows with the same roots that Newton converges on faster from a
  // close start, but whose slopes jump where a march (pseudo-time, a transient) or a
  // differentiated system (a fold's) needs them continuous: the bearing's cavitation
  // rows as min(λ·p̂, ŵ) and the gear's stop's as min(ŝ, R̂) instead of
  // Fischer–Burmeister (CavitationRow, docs/physics.md sections 3 and 19). Off unless a
  // NewtonForm scope is open; a system without such rows ignores it. (A duty cycle's IDA
  // opens one for its Newton, which starts every step close, from its predictor: IDA
  // needs only the roots, its error test reads the differential unknowns.)
  virtual void set_newton_form(bool) {}
  virtual bool newton_form() const { return false; }
  // Newton's form must meet the tolerance tighter by this ratio for the system's own
  // rows to meet it too (states are checked in the own form afterwards); KinsolNewton
  // applies it to every solve in Newton's form.
  virtual double newton_form_tolerance_ratio() const { return 1.0; }
  // Newton's linear solves from factors the system holds itself (newton_step_solver.h);
  // null: KINSOL's KLU factors the Jacobian as assembled.
  virtual NewtonStepSolver* step_solver() const { return nullptr; }
};

// Newton's form of a system's rows while the scope lives (or, with on = false, its own
// form); the form it found afterwards.
class NewtonForm {
 public:
  explicit NewtonForm(SteadySystem& system, bool on = true) : system_(system), kept_(system.newton_form()) {
    system_.set_newton_form(on);
  }
  ~NewtonForm() { system_.set_newton_form(kept_); }
  NewtonForm(const NewtonForm&) = delete;
  NewtonForm& operator=(const NewtonForm&) = delete;

 private:
  SteadySystem& system_;
  bool kept_;
};

// The system's parameter (the bearing's load) for the scope: set to `value` if given,
// and back to the value it had when the scope ends, whatever the solvers inside set it
// to. A study takes one at its entry, so that its caller's model is the model it gave.
class ParameterScope {
 public:
  explicit ParameterScope(SteadySystem& system) : system_(system), entered_(system.parameter()) {}
  ParameterScope(SteadySystem& system, double value) : ParameterScope(system) { system.set_parameter(value); }
  // The value was the system's own when the scope began, so setting it back cannot fail.
  ~ParameterScope() { system_.set_parameter(entered_); }
  ParameterScope(const ParameterScope&) = delete;
  ParameterScope& operator=(const ParameterScope&) = delete;

 private:
  SteadySystem& system_;
  double entered_;
};

}  // namespace twb
