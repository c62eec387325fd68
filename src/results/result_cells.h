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

}  // namespace twb::cells
