#include "twb/results/distress_table.h"

#include "result_cells.h"

namespace twb {

namespace {
// RFC 4180: a text cell holding a comma, a quote or a line break is quoted, quotes doubled.
std::string text_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}
}  // namespace

std::string distress_csv(const std::vector<DistressRow>& rows, const std::string& parameter_column,
                         bool sliding_column) {
  std::string out = "speed_rad_s," + cells::run_header(parameter_column, sliding_column) +
                    "W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,W_d_extrapolated_N,W_d_error_N,method\n";
  for (const DistressRow& r : rows) {
    out += cells::number(r.speed, "speed") + "," + cells::run_cells(parameter_column, sliding_column, r.parameter, r.sliding);
    out += fmt::format("{},{},{},{},{},{},{},{}\n", cells::number(r.distress_load, "W_d"),
                       cells::number(r.bracket_low, "bracket_low"), cells::number(r.bracket_high, "bracket_high"),
                       cells::number(r.fold_load, "fold"), cells::number(r.fine_fold_load, "W_d_fine"),
                       cells::number(r.extrapolated_load, "W_d_extrapolated"),
                       cells::number(r.discretization_error, "W_d_error"), text_cell(r.method));
  }
  return out;
}

}  // namespace twb
