// The consistent start of a transient in real time (ida_transient.h) as a system KINSOL
// solves: with the differential unknowns y_d held, the algebraic unknowns y_a and the
// rates y'_d such that
//
//     G(y, y') = C·(y' + r) + F(y, y') = 0,
//
// F the system's residual with its rate terms (SteadySystem::evaluate_in_time), r the
// rate of the reference its capacities' unknowns are measured from. The unknowns z are
// y_k where k is algebraic and y'_k where it is differential; the Jacobian in z is
// exact: ∂G/∂y on algebraic columns, ∂G/∂y' on differential ones.
//
// Why not IDACalcIC: its Newton iterates y'_d with the matrix ∂G/∂y + c_j·∂G/∂y', in
// which the ∂G/∂y_d part is spurious (y_d is held) and must be small against c_j·∂G/∂y'.
// For a body's temperature it is (c_j·C beats the conduction for a short trial step),
// but the bearing's force balances have no rate at all while their slopes in the rigid
// unknowns are the contact's stiffness: there the spurious part is the whole column,
// and CalcIC's iteration wanders off (docs/physics.md section 19, "The DAE and its index").
#pragma once

#include <span>
#include <vector>

#include "system/steady_system.h"

namespace twb {

class ConsistentRates final : public SteadySystem {
 public:
  // y the state whose differential unknowns are held (its algebraic ones are only the
  // guess's); capacities and differential as the transient's.
  ConsistentRates(const SteadySystem& system, std::span<const double> y, const std::vector<double>& capacities,
                  const std::vector<char>& differential, double reference_rate);

  Index size() const override { return system_.size(); }
  const SparsePattern& pattern() const override { return system_.pattern(); }
  void evaluate(std::span<const double> z, std::span<double> residual, std::span<double> jacobian) const override;

  // z of a state and its rates, and back.
  std::vector<double> unknowns_of(std::span<const double> y, std::span<const double> rate) const;
  void state_of(std::span<const double> z, std::vector<double>& y, std::vector<double>& rate) const;

  double parameter() const override { return system_.parameter(); }
  void set_parameter(double) override;
  void parameter_derivative(std::span<const double> z, std::span<double> derivative) const override;
  std::vector<double> capacities() const override { return std::vector<double>(std::size_t(size()), 0.0); }
  // KINSOL caps a Newton step in these units: the system's own for the algebraic
  // unknowns, 1e-3 for a rate (as for a field: a step may move it by 1e3 times the cap,
  // 2e4 of its scaled units a second with the default cap of 20).
  std::vector<double> step_weights() const override;
  // The system's rows in the form it is in (a march's Newton form, steady_system.h), and
  // the tolerance that form's residual must meet.
  bool newton_form() const override { return system_.newton_form(); }
  double newton_form_tolerance_ratio() const override { return system_.newton_form_tolerance_ratio(); }
  std::string block_name(Index k) const override { return system_.block_name(k); }
  std::string describe_row(Index k) const override { return system_.describe_row(k); }

 private:
  const SteadySystem& system_;
  std::vector<double> held_, capacities_;
  std::vector<char> differential_;
  double reference_rate_;
  std::vector<Index> diagonal_;  // position of (k, k) in the pattern, −1 where absent
  mutable std::vector<double> y_, rate_, scratch_, matrix_at_unit_cj_;
};

}  // namespace twb
