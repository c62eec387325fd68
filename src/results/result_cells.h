// What the results tables share: temperatures in the tables are °C (the column names say
// _C), and the columns that tell a study's runs apart.
#pragma once

#include <optional>
#include <string>

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

}  // namespace twb::cells
