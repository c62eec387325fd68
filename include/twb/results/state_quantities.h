// What a solved state reports, declared once (docs/physics.md section 9): each
// quantity's column in states.csv, its unit, what it means and how it is read
// off a solved state. states.csv's columns, `twb columns` (and so the Python
// module's column lists) and the docs' table of the states' columns (`twb
// columns --markdown`, docs/results.md) are made from this one list, in its
// order: a new reported quantity is one entry here (and its value in
// BearingState, which describe() fills and the search journal keeps).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "twb/results/result_table.h"
#include "twb/results/states_table.h"

namespace twb {

// One cell of a state's row: a number (absent: empty), a count or a text.
struct StateCell {
  std::optional<double> number;
  long long count = 0;
  std::string text;
};

struct StateQuantity {
  std::string
      column; // as states.csv names it, its unit in the name where it has one
  std::string_view unit; // "°C", "N·m", "1" (a ratio), "" (a text or a count)
  std::string_view meaning; // what it is, for the docs' table
  ResultColumn::Kind kind = ResultColumn::Kind::number;
  ResultColumn::Style style = ResultColumn::Style::general;
  std::function<StateCell(const SolvedState &)> value;
  // Set for a column written only where some state has what it reads (a film's
  // flows, the heat the oil carries, the error bars); the others always, empty
  // where a state has no value.
  std::function<bool(const SolvedState &)> where;
};

// Every quantity of states.csv in its column order. The first
// kOperatingPointQuantities (load, speed) come before the columns that tell a
// study's runs apart (states_table).
std::span<const StateQuantity> state_quantities();
inline constexpr std::size_t kOperatingPointQuantities = 2;
// The quantity of that column; std::invalid_argument for a name that is none.
const StateQuantity &state_quantity(std::string_view column);

// The docs' table of the states' columns (Markdown): column, unit, meaning.
std::string state_quantities_markdown();

} // namespace twb
