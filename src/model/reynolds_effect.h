// Hydrodynamics (docs/physics.md sections 3 and 12): the sliding film's pressure, and
// with mass-conserving cavitation its content, and their rows (reynolds_film.cpp).
#pragma once

#include <vector>

#include "model/effect_assembler.h"

namespace twb {

struct FilmTotals;
class FilmFaceFlows;

class ReynoldsEffect final : public EffectAssembler {
 public:
  // Declares the pressure block (and the content block) of every sliding film.
  explicit ReynoldsEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;
  // With the film's squeeze (docs/physics.md section 19).
  void add_terms_in_time(std::span<const double> u, const StateRates& rates, Assembler& a,
                         AssemblyTotals& totals) const override;

 private:
  void add_film(std::span<const double> u, const StateRates* rates, const Film& film, Assembler& a,
                FilmTotals& totals) const;
  void add_squeeze(const StateRates& rates, const Film& film, const FilmFaceFlows& flows,
                   Assembler& a) const;

  const BearingModel& model_;
  // Per interior node: p_ref times the Poiseuille diagonal of a uniform reference
  // film, so that the flow balance ŵ = w / scale reads like p̂.
  std::vector<double> flow_scale_;
};

}  // namespace twb
