// The washer as an elastic plate (docs/physics.md section 21): a Kirchhoff annulus with
// free edges in the mixed form [E1]-[E3] (physics/elastic_annulus.h) on the washer's grid
// (film 1's), its deflection w a part of both films' gaps (film 1 opens by w, film 2
// closes by w), its load the difference of the films' pressures, fluid and contact.
//
// Unknowns: ŵ = w/σ_ref and m̂ = m·D/F_ref at every node of the washer's grid, then the
// multipliers of the three conditions that measure w from the rigid plane (λ0, λ1, λ2 in
// F_ref/A, F_ref/(A·r_o), F_ref/(A·r_o), A the washer's area). Rows: the operator's,
// scaled to read in σ_ref (w rows), in F_ref (m rows) and in σ_ref·A (the conditions).
// Each film's force at a node enters the m rows in the film loads' scatter
// (film_loads.cpp), the heat crossing the washer the w rows in the heat balance's
// (heat_balance.cpp, with thermal_deformation: the thermal curvature κ_T).
//
// A washer whose material has a modulus over temperature (physics §23) bends with the
// rigidity D(T) of its mid-plane temperature at each node: the m rows' fluxes are those of
// D·m, D at the node each flux's m belongs to (the edges' [E3] at the edge node), scaled
// by E(T)/E_ref from the operator's constant D_ref.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "model/effect_assembler.h"
#include "physics/elastic_annulus.h"
#include "physics/modulus_curve.h"

namespace twb {

class ElasticWasherEffect final : public EffectAssembler {
 public:
  static constexpr ReportedQuantity kReported[] = {
      {"washer_bending_um", "µm",
       "with elastic_washer: the washer's bending, its greatest deflection towards film 2 less its greatest towards "
       "film 1 (from its rigid plane)"}};

  explicit ElasticWasherEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;
  void carry_from(const BearingModel& source, const EffectAssembler& mine_there, std::span<const double> u,
                  std::span<double> out) const override;
  void report(std::span<const double> u, const AssemblyTotals& totals, std::vector<ReportedValue>& out) const override;

  // The deflection w (m) and the curvature sum m (1/m) at every node of the washer's grid,
  // and the multipliers (Pa, Pa/m, Pa/m): the plate's balance, of the discretization's
  // order at a solution (physics §21).
  std::vector<double> deflection(std::span<const double> u) const;
  std::vector<double> curvature_sum(std::span<const double> u) const;
  std::array<double, 3> multipliers(std::span<const double> u) const;
  const ElasticAnnulus& annulus() const { return annulus_; }

 private:
  // The physical value of local unknown k (the operator's numbering) per scaled unit, and
  // the factor local row k's balance is scaled by.
  double column_ref(int k) const;
  double row_scale(int k) const;
  Index global(int k) const;
  // The operator's rows with D(T): E(T)/E_ref at each node and its slope in the washer's
  // temperature unknowns.
  void add_terms_with_modulus_curve(std::span<const double> u, Assembler& a) const;

  const BearingModel& model_;
  ElasticAnnulus annulus_;
  Index multipliers_ = -1;
  double deflection_ref_ = 0, moment_ref_ = 0, load_ref_ = 0, area_ = 0, outer_ = 0;
  WasherPlate plate_;  // a copy of what the model holds
  std::optional<ModulusCurve> modulus_;  // the washer's E(T); none: constant
  double reference_modulus_ = 0;         // Pa, the E of the operator's D_ref
  // The plate's twisting terms (physics §23 [M2]-[M3]), where the modulus has a curve.
  std::vector<ElasticAnnulus::TwistingTerm> twisting_;
};

}  // namespace twb
