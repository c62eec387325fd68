// Thermal deformation (docs/physics.md section 11): the washer's dishing curvature and,
// with the empirical friction law, the sliding film's contact force as unknowns of
// their own, and their rows (film_shape.cpp). The shapes δ themselves are the films'
// geometry (BearingModel::shape_form), which every effect reads.
#pragma once

#include "model/effect_assembler.h"

namespace twb {

class DeformationEffect final : public EffectAssembler {
 public:
  explicit DeformationEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;

 private:
  const BearingModel& model_;
};

}  // namespace twb
