#include "twb/results/trajectory_table.h"

#include "result_cells.h"

namespace twb {

std::string trajectory_csv(const std::vector<TrajectorySample>& samples) {
  std::string out = "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N\n";
  for (const TrajectorySample& p : samples) {
    const BearingState& s = p.state;
    out += fmt::format("{},{},{},{},{},{},{}\n", cells::number(p.time, "t"),
                       cells::number(s.washer_mean_temperature - cells::kelvin_offset, "T_mean"),
                       cells::number(s.max_film_temperature - cells::kelvin_offset, "T_max"),
                       cells::number(s.hmin_over_sigma, "hmin_over_sigma"),
                       cells::number(s.contact_share, "contact_share"), cells::number(s.f_eff, "f_eff"),
                       cells::number(s.load, "load"));
  }
  return out;
}

}  // namespace twb
