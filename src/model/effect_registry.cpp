// The effects a scene turns on, in the order they declare their unknowns and add their
// terms (effect_assembler.h). The order is part of the results: it fixes the unknowns'
// numbering and the order in which terms are summed into a shared row. Below them, the
// quantities they report of their own (reported_quantity.h), in the same order.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "model/bearing_model.h"
#include "model/convection_effect.h"
#include "model/deformation_effect.h"
#include "model/elastic_washer_effect.h"
#include "model/film_loads_effect.h"
#include "model/heat_effect.h"
#include "model/reynolds_effect.h"
#include "model/wear_effect.h"
#include "twb/error_family.h"

namespace twb {

std::string fmt_film_block(int number, const char* what) { return "film " + std::to_string(number) + " " + what; }

void BearingModel::register_effects() {
  // A stack local: an effect or a part keeps what it needs of it, never a reference to it.
  ModelSetup setup{*this, layout_, films_, components_, gap_parts_, dishing_, plate_};
  const Effects& fx = scene_.effects;
  if (fx.hydrodynamics) effects_.push_back(std::make_unique<ReynoldsEffect>(setup));
  effects_.push_back(std::make_unique<FilmLoadsEffect>(setup));  // contact, fluid force, shear and friction heat
  if (fx.thermal) effects_.push_back(std::make_unique<HeatEffect>(setup));
  if (fx.thermal_deformation) effects_.push_back(std::make_unique<DeformationEffect>(setup));
  // Effects beyond the scene's (a test's) before convection, which rewrites the fed
  // grooves' heat rows once every other term is in them; it declares no unknowns, so the
  // numbering is the same either way.
  for (const EffectMaker& make : more_effects_) {
    effects_.push_back(make(setup));
    if (!effects_.back()) throw InternalError("register_effects: an effect maker made no effect");
  }
  if (fx.convection) effects_.push_back(std::make_unique<ConvectionEffect>(setup));  // rewrites the fed grooves' heat rows
  // After convection, which adds no unknowns: the numbering of every scene without wear is
  // as it was. It reads the friction power the film loads gathered.
  if (fx.wear) effects_.push_back(std::make_unique<WearEffect>(setup));
  // After wear, for the same reason: the washer's plate (its loads gathered with the films').
  if (fx.elastic_washer) effects_.push_back(std::make_unique<ElasticWasherEffect>(setup));
  // Once every part of the gap is known: the contact force's own unknown, whose row the
  // film loads assemble (bearing_model.h, contact_force_unknown).
  if (gap_shaped(sliding_film()) && fx.asperity_contact && scene_.friction.law == FrictionLaw::empirical) {
    contact_force_unknown_ = layout_.add("sliding film contact force", BlockEffect::asperity_contact, 1);
    contact_force_scale_ = scene_.operating.load;
  }
}

std::span<const ReportedQuantity> effect_quantities() {
  // One line per effect that reports a quantity of its own: its kReported.
  static const std::vector<ReportedQuantity> quantities = [] {
    std::vector<ReportedQuantity> q;
    for (std::span<const ReportedQuantity> of_effect : std::array<std::span<const ReportedQuantity>, 3>{
             ConvectionEffect::kReported,
             WearEffect::kReported,
             ElasticWasherEffect::kReported,
         })
      q.insert(q.end(), of_effect.begin(), of_effect.end());
    return q;
  }();
  return quantities;
}

}  // namespace twb
