// The `effects` list: which physics the model assembles (docs/physics.md sections 3, 4, 7).
#include <fmt/format.h>

#include "key_suggestion.h"
#include "scene_names.h"
#include "scene_sections.h"

namespace twb::scene_io {
namespace {

struct Listed {
  std::string name;
  Node item;
  std::optional<Node> options;
};

// An item is a bare name, or a one-entry map {name: {options}}.
Listed read_item(const Node& item) {
  const std::string allowed = join(kEffectNames);
  if (item.yaml().IsScalar()) return {item.yaml().Scalar(), item, std::nullopt};
  if (!item.yaml().IsMap())
    item.fail(fmt::format("{}: expected an effect name or {{name: {{options}}}}; got {}; allowed: {}",
                          item.path(), item.describe_content(), allowed));
  const MapReader entry(item, {kEffectNames.begin(), kEffectNames.end()});
  const std::vector<std::string> keys = entry.keys();
  if (keys.size() != 1)
    item.fail(fmt::format("{}: each item names one effect (write '- name: {{options}}' per "
                          "effect); got {} names",
                          item.path(), keys.size()));
  return {keys.front(), item, entry.find(keys.front())};
}

}  // namespace

Effects read_effects(const MapReader& scene) {
  const Node list = scene.get("effects", "a list of effects, e.g. [hydrodynamics, asperity_contact]");
  const std::vector<Node> items = list.list(fmt::format("effects ({})", join(kEffectNames)));
  if (items.empty())
    list.fail(fmt::format("effects: the list is empty; at least one of hydrodynamics, "
                          "asperity_contact is needed to carry the load; allowed: {}",
                          join(kEffectNames)));

  Effects effects;
  std::vector<Listed> listed;
  for (const Node& item : items) {
    Listed effect = read_item(item);
    bool known = false;
    for (std::string_view name : kEffectNames) known = known || name == effect.name;
    if (!known) {
      const std::string suggestion = closest_match(effect.name, kEffectNames);
      item.fail(fmt::format("{}: unknown effect '{}'{}", item.path(), effect.name,
                            allowed_after(suggestion, kEffectNames)));
    }
    for (const Listed& earlier : listed)
      if (earlier.name == effect.name)
        item.fail(fmt::format("{}: effect '{}' is listed twice in 'effects'; list each effect once",
                              item.path(), effect.name));

    const Node options_node = effect.options.value_or(
        Node(YAML::Node(), fmt::format("{}.{}", item.path(), effect.name), item.origin(),
             item.mark(), item.provenance()));
    if (effect.name == kHydrodynamics) {
      const MapReader options(options_node, {"cavitation", "cavity_pressure"});
      effects.hydrodynamics = true;
      effects.cavitation = read_choice(options, "cavitation", kCavitationModels, effects.cavitation);
      if (effects.cavitation != CavitationModel::jfo)
        options.restrict_to({"cavitation"}, "with cavitation: reynolds");
      // From ambient down to a vacuum (absolute zero pressure below an atmosphere).
      effects.cavity_pressure = options.quantity(
          "cavity_pressure", si::stress,
          Range{.low = -101325.0, .high = 0.0, .reason = "a gauge pressure from -1 atm (vacuum) to 0 (ambient)"},
          effects.cavity_pressure);
    } else if (effect.name == kThermal) {
      const MapReader options(options_node, {"viscosity_temperature", "carrier_temperature"});
      effects.thermal = true;
      effects.viscosity_temperature = read_choice(options, "viscosity_temperature",
                                                  kViscosityTemperatures, effects.viscosity_temperature);
      effects.carrier_temperature = read_choice(options, "carrier_temperature", kCarrierTemperatures,
                                                effects.carrier_temperature);
    } else if (effect.name == kThermalDeformation) {
      const MapReader options(options_node, {"face_expansion"});
      effects.thermal_deformation = true;
      effects.face_expansion = read_choice(options, "face_expansion", kFaceExpansions, effects.face_expansion);
    } else {
      const MapReader no_options(options_node, {});
      if (effect.name == kFlowFactors) effects.flow_factors = true;
      if (effect.name == kAsperityContact) effects.asperity_contact = true;
      if (effect.name == kConvection) effects.convection = true;
      if (effect.name == kWear) effects.wear = true;
      if (effect.name == kElasticWasher) effects.elastic_washer = true;
    }
    listed.push_back(std::move(effect));
  }

  // Effects that modify another need it: reject what would silently do nothing.
  for (const Listed& effect : listed) {
    if (effect.name == kFlowFactors && !effects.hydrodynamics)
      effect.item.fail(fmt::format(
          "{}: effect 'flow_factors' needs 'hydrodynamics' (flow factors modify the Reynolds "
          "equation); add hydrodynamics to 'effects'",
          effect.item.path()));
    if (effect.name == kThermal && !effects.hydrodynamics && !effects.asperity_contact)
      effect.item.fail(fmt::format(
          "{}: effect 'thermal' needs 'hydrodynamics' or 'asperity_contact': without viscous "
          "shear or contact friction nothing generates heat; add one of them to 'effects'",
          effect.item.path()));
    if (effect.name == kThermalDeformation && !effects.thermal)
      effect.item.fail(fmt::format(
          "{}: effect 'thermal_deformation' needs 'thermal' (the bodies deform with their "
          "temperatures); add thermal to 'effects'",
          effect.item.path()));
    if (effect.name == kConvection && !(effects.thermal && effects.hydrodynamics))
      effect.item.fail(fmt::format(
          "{}: effect 'convection' needs 'thermal' and 'hydrodynamics' (the film's flow carries the film's "
          "temperature); add {} to 'effects'",
          effect.item.path(),
          !effects.thermal && !effects.hydrodynamics ? "both" : effects.thermal ? "hydrodynamics" : "thermal"));
    if (effect.name == kWear && !effects.asperity_contact)
      effect.item.fail(fmt::format(
          "{}: effect 'wear' needs 'asperity_contact' (only the asperities' contact pressure wears a face, "
          "docs/physics.md section 20); add asperity_contact to 'effects'",
          effect.item.path()));
  }
  return effects;
}

}  // namespace twb::scene_io
