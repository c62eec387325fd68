// A quantity an effect reports of each solved state, declared beside the effect's terms
// (docs/architecture.md, "A result column"): its column in states.csv, its unit and
// what it means. The effect declares its list (a static array, kReported) and fills the
// values in EffectAssembler::report; effect_registry.cpp names each registered effect's
// list once, and from that list states.csv, `twb columns` (so the Python module's column
// lists) and the docs' table take the column. A new quantity of an effect touches the
// effect's own file, and nothing in BearingState, the journal or the tables.
#pragma once

#include <span>
#include <string_view>

namespace twb {

struct ReportedQuantity {
  std::string_view column;   // as states.csv names it, its unit in the name ("heat_carried_W")
  std::string_view unit;     // "W", "µm", "1" (a ratio)
  std::string_view meaning;  // what it is, for the docs' table
};

// Every registered effect's reported quantities, in the order the effects are registered
// (effect_registry.cpp): the columns states.csv writes for them, each only where some
// state has it.
std::span<const ReportedQuantity> effect_quantities();

}  // namespace twb
