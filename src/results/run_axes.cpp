#include "twb/results/run_axes.h"

#include <fmt/format.h>

namespace twb {

std::string run_axes_text(const std::vector<std::string>& columns, const std::vector<double>& values) {
  std::string out;
  for (std::size_t k = 0; k < values.size(); ++k)
    out += fmt::format(", {} = {:.6g}", k < columns.size() && !columns[k].empty() ? columns[k] : "parameter", values[k]);
  return out;
}

}  // namespace twb
