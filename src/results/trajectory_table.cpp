#include "twb/results/trajectory_table.h"

#include "result_cells.h"

namespace twb {

std::string trajectory_csv(const std::vector<TrajectorySample>& samples, const std::string& parameter_column,
                           bool sliding_column) {
  std::string header = "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s," +
                       cells::run_header(parameter_column, sliding_column);
  header.back() = '\n';
  std::string out = header;
  for (const TrajectorySample& p : samples) {
    const BearingState& s = p.state;
    std::string row = fmt::format("{},{},{},{},{},{},{},{},", cells::number(p.time, "t"),
                       cells::number(s.washer_mean_temperature - cells::kelvin_offset, "T_mean"),
                       cells::number(s.max_film_temperature - cells::kelvin_offset, "T_max"),
                       cells::number(s.hmin_over_sigma, "hmin_over_sigma"),
                       cells::number(s.contact_share, "contact_share"), cells::number(s.f_eff, "f_eff"),
                       cells::number(s.load, "load"), cells::number(s.speed, "speed")) +
                      cells::run_cells(parameter_column, sliding_column, p.parameter, p.sliding);
    row.back() = '\n';
    out += row;
  }
  return out;
}

}  // namespace twb
