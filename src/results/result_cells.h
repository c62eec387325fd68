// Cell formatting shared by the CSV tables: results never carry NaN or infinity (a
// non-finite value means a bug upstream, so it throws rather than being written).
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace twb::cells {

constexpr double kelvin_offset = 273.15;

inline double finite(double v, const char* name) {
  if (!std::isfinite(v)) throw std::runtime_error(std::string("non-finite result value for ") + name);
  return v;
}

inline std::string number(double v, const char* name) { return fmt::format("{:.10g}", finite(v, name)); }

// An absent value is an empty cell.
inline std::string number(const std::optional<double>& v, const char* name) {
  return v ? number(*v, name) : std::string();
}

// The columns that tell a study's runs apart: the parameter's value and the sliding film.
inline std::string run_header(const std::string& parameter_column, bool sliding_column) {
  return (parameter_column.empty() ? std::string() : parameter_column + ",") + (sliding_column ? "sliding," : "");
}
inline std::string run_cells(const std::string& parameter_column, bool sliding_column,
                             const std::optional<double>& parameter, const std::string& sliding) {
  return (parameter_column.empty() ? std::string() : number(parameter, "parameter") + ",") +
         (sliding_column ? sliding + "," : std::string());
}

}  // namespace twb::cells
