// What the results tables share: temperatures in the tables are °C (the column names say
// _C), and the columns that tell a study's runs apart.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/reported_quantity.h"
#include "twb/model/bearing_state.h"
#include "twb/results/distress_table.h"
#include "twb/results/result_table.h"
#include "twb/scene/scene.h"
#include "twb/scene/scene_loader.h"

namespace twb::cells {

constexpr double kelvin_offset = 273.15;

// The sliding column's cell: the configuration's scene name, empty for none.
inline std::string film_name(const std::optional<SlidingFilm>& film) {
  return film ? std::string(scene_name(*film)) : std::string();
}

// The columns that tell a study's runs apart: its axes' values (e.g.
// friction_coefficient; run_axes.h) and the sliding film, each only when the study has it.
struct RunColumns {
  std::vector<ResultTable::Column> parameters;
  std::optional<ResultTable::Column> sliding;

  RunColumns(ResultTable& table, const std::vector<std::string>& parameter_columns, bool sliding_column) {
    for (const std::string& c : parameter_columns) parameters.push_back(table.number(c));
    if (sliding_column) sliding = table.text("sliding");
  }
  // A row's values, one per axis; none (empty cells) for a row of no run of them.
  void put(ResultTable& table, const std::vector<double>& values, const std::optional<SlidingFilm>& film) const {
    for (std::size_t k = 0; k < parameters.size(); ++k)
      table.put_number(parameters[k], k < values.size() ? std::optional<double>(values[k]) : std::nullopt);
    if (sliding) table.put_text(*sliding, film_name(film));
  }
};

// How a mesh-converged load was reached (LoadConvergence): <prefix>_meshes, <prefix>_order
// and, with `met`, <prefix>_tolerance_met ("yes", "no"; empty without a tolerance).
struct ConvergenceColumns {
  ResultTable::Column meshes, order;
  std::optional<ResultTable::Column> met;

  ConvergenceColumns(ResultTable& table, const std::string& prefix, bool with_met)
      : meshes(table.text(prefix + "_meshes")), order(table.number(prefix + "_order")) {
    if (with_met) met = table.text(prefix + "_tolerance_met");
  }
  void put(ResultTable& table, const LoadConvergence& c) const {
    table.put_text(meshes, c.meshes);
    table.put_number(order, c.order);
    if (met) table.put_text(*met, c.tolerance_met ? (*c.tolerance_met ? "yes" : "no") : "");
  }
};

// The columns of the quantities the effects report of their own (model/reported_quantity.h)
// that some row's state has: the registered effects' in their order (unless the table
// writes those among its own quantities, `registered` false), then any other (a test's
// own effect) in the order the rows first report it.
struct ReportedColumns {
  std::vector<std::pair<std::string, ResultTable::Column>> columns;

  template <class Rows, class StateOf>
  ReportedColumns(ResultTable& table, const Rows& rows, StateOf state_of, bool registered) {
    const auto reports = [&](std::string_view column) {
      return std::any_of(rows.begin(), rows.end(),
                         [&](const auto& r) { return state_of(r).reported_value(column).has_value(); });
    };
    const auto listed = [&](std::string_view column) {
      const auto quantities = effect_quantities();
      return std::any_of(quantities.begin(), quantities.end(),
                         [&](const ReportedQuantity& q) { return q.column == column; });
    };
    if (registered)
      for (const ReportedQuantity& q : effect_quantities())
        if (reports(q.column)) columns.emplace_back(std::string(q.column), table.number(std::string(q.column)));
    for (const auto& r : rows)
      for (const ReportedValue& v : state_of(r).reported)
        if (!listed(v.column) && std::none_of(columns.begin(), columns.end(),
                                              [&](const auto& c) { return c.first == v.column; }))
          columns.emplace_back(v.column, table.number(v.column));
  }
  void put(ResultTable& table, const BearingState& state) const {
    for (const auto& [column, at] : columns) table.put_number(at, state.reported_value(column));
  }
};

}  // namespace twb::cells
