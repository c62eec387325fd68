#include "twb/results/run_axes.h"

#include <numbers>

#include <fmt/format.h>

namespace twb {

std::string run_axes_text(const std::vector<std::string>& columns, const std::vector<double>& values) {
  std::string out;
  for (std::size_t k = 0; k < values.size(); ++k)
    out += fmt::format(", {} = {:.6g}", k < columns.size() && !columns[k].empty() ? columns[k] : "parameter", values[k]);
  return out;
}

std::string speed_text(double rad_per_s, bool in_rpm) {
  return in_rpm ? fmt::format("{:.6g} rpm", rad_per_s * 30.0 / std::numbers::pi) : fmt::format("{:.6g} rad/s", rad_per_s);
}

}  // namespace twb
