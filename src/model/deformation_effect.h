// Thermal deformation (docs/physics.md section 11): the washer's dishing curvature as an
// unknown of its own, and its row, and the carrier's, gear's and washer's shape as a part
// of the films' gap (gap_contribution.h, film_shape.cpp), which every effect reads.
#pragma once

#include "model/effect_assembler.h"

namespace twb {

class DeformationEffect final : public EffectAssembler {
 public:
  explicit DeformationEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;
  // The dishing curvature, in physical units.
  void carry_from(const BearingModel& source, const EffectAssembler& mine_there, std::span<const double> u,
                  std::span<double> out) const override;

 private:
  const BearingModel& model_;
};

}  // namespace twb
