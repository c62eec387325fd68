// One block of the model's unknowns: what it holds, where it starts, how many, and the
// effect that brought it. An effect a scene leaves off has none (docs/model.md, "Unknowns").
#pragma once

#include <cstdint>
#include <string>

namespace twb {

struct UnknownBlock {
  std::string name;         // e.g. "film 1 pressure"
  std::string effect;       // the effect that creates it
  std::int64_t offset = 0;
  std::int64_t size = 0;
  bool differential = false;  // has a heat capacity in the pseudo-time transient
};

}  // namespace twb
