// The loads the films put on their bodies (docs/physics.md sections 3, 4, 6): fluid and
// asperity contact forces and moments into the rigid-body rows, viscous and friction
// heat into the film-node heat rows, the contact force into its own row where the gap
// has a part (bearing_model.h, contact_force_unknown; film_loads.cpp, cell by cell:
// film_load_pass.h). Always on: the films
// carry the load whichever effects fill them.
#pragma once

#include "model/effect_assembler.h"
#include "model/gauss_rule.h"

namespace twb {

struct FilmTotals;

// The Gauss rules of a film's cells: a fixed one for the smooth fluid terms, a high
// order one where contact varies steeply, and a cheaper one where it varies little.
struct FilmLoadRules {
  GaussRule smooth, contact, flat_contact;
};

class FilmLoadsEffect final : public EffectAssembler {
 public:
  explicit FilmLoadsEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;

 private:
  void add_film(std::span<const double> u, const Film& film, Assembler& a, FilmTotals& totals) const;

  const BearingModel& model_;
  FilmLoadRules rules_;
};

}  // namespace twb
