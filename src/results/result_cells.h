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

// The columns that tell a study's runs apart: the parameter's value (e.g.
// friction_coefficient) and the sliding film, each only when the study has it.
struct RunColumns {
  std::optional<ResultTable::Column> parameter, sliding;

  RunColumns(ResultTable& table, const std::string& parameter_column, bool sliding_column) {
    if (!parameter_column.empty()) parameter = table.number(parameter_column);
    if (sliding_column) sliding = table.text("sliding");
  }
  void put(ResultTable& table, const std::optional<double>& value, const std::optional<SlidingFilm>& film) const {
    if (parameter) table.put_number(*parameter, value);
    if (sliding) table.put_text(*sliding, film_name(film));
  }
};

}  // namespace twb::cells
