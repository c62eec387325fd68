#include "twb/results/distress_table.h"

#include "result_cells.h"

namespace twb {

std::string distress_csv(const std::vector<DistressRow>& rows, const std::string& parameter_column) {
  const bool with_parameter = !parameter_column.empty();
  std::string out = "speed_rad_s," + (with_parameter ? parameter_column + "," : std::string()) +
                    "W_d_N,bracket_low_N,bracket_high_N,fold_N,method\n";
  for (const DistressRow& r : rows) {
    out += cells::number(r.speed, "speed") + ",";
    if (with_parameter) out += cells::number(r.parameter, "parameter") + ",";
    out += fmt::format("{},{},{},{},{}\n", cells::number(r.distress_load, "W_d"),
                       cells::number(r.bracket_low, "bracket_low"), cells::number(r.bracket_high, "bracket_high"),
                       cells::number(r.fold_load, "fold"), r.method);
  }
  return out;
}

}  // namespace twb
