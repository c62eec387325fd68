// One block of the model's unknowns: what it holds, where it starts, how many, and the
// effect that brought it. An effect a scene leaves off has none (docs/model.md, "Unknowns").
#pragma once

#include <cstdint>
#include <string>

namespace twb {

// The effect behind a block of unknowns: the scene's effect that creates it, or the
// rigid body's mechanics, which every scene has.
enum class BlockEffect { mechanics, hydrodynamics, thermal, thermal_deformation, asperity_contact, wear, elastic_washer };

// The effect's name as scenes and docs/model.md write it.
inline const char* effect_name(BlockEffect e) {
  switch (e) {
    case BlockEffect::mechanics: return "mechanics";
    case BlockEffect::hydrodynamics: return "hydrodynamics";
    case BlockEffect::thermal: return "thermal";
    case BlockEffect::thermal_deformation: return "thermal_deformation";
    case BlockEffect::asperity_contact: return "asperity_contact";
    case BlockEffect::wear: return "wear";
    case BlockEffect::elastic_washer: return "elastic_washer";
  }
  return "?";
}

struct UnknownBlock {
  std::string name;         // e.g. "film 1 pressure"
  BlockEffect effect = BlockEffect::mechanics;  // the effect that creates it
  std::int64_t offset = 0;
  std::int64_t size = 0;
  bool differential = false;  // has a heat capacity in the pseudo-time transient
};

}  // namespace twb
