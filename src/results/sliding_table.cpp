#include "twb/results/sliding_table.h"

#include "result_cells.h"

namespace twb {

std::string sliding_csv(const std::vector<SlidingRow>& rows) {
  std::string out =
      "speed_rad_s,load_N,sliding,film_area_m2,fluid_force_N,fluid_share,contact_share,torque_Nm,f_eff,"
      "hmin_over_sigma,T_mean_C,chosen\n";
  for (const SlidingRow& r : rows) {
    const BearingState& s = r.solved.state;
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", cells::number(s.speed, "speed"),
                       cells::number(s.load, "load"), r.solved.sliding, cells::number(r.film_area, "film_area"),
                       cells::number(s.fluid_force, "fluid_force"), cells::number(s.fluid_share, "fluid_share"),
                       cells::number(s.contact_share, "contact_share"), cells::number(s.torque, "torque"),
                       cells::number(s.f_eff, "f_eff"), cells::number(s.hmin_over_sigma, "hmin_over_sigma"),
                       cells::number(s.washer_mean_temperature - cells::kelvin_offset, "T_mean"),
                       r.chosen ? 1 : 0);
  }
  return out;
}

}  // namespace twb
