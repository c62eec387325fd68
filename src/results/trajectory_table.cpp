#include "twb/results/trajectory_table.h"

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

ResultTable trajectory_table(const std::vector<TrajectorySample>& samples, const std::vector<std::string>& parameter_columns,
                             bool sliding_column) {
  ResultTable t;
  const auto time = t.number("t_s"), t_mean = t.number("T_mean_C"), t_max = t.number("T_max_C"),
             hmin = t.number("hmin_over_sigma"), contact = t.number("contact_share"), f_eff = t.number("f_eff"),
             load = t.number("load_N"), speed = t.number("speed_rad_s");
  const cells::RunColumns run(t, parameter_columns, sliding_column);
  for (const TrajectorySample& p : samples) {
    const BearingState& s = p.state;
    t.put_number(time, p.time);
    t.put_number(t_mean, s.washer_mean_temperature - kelvin_offset);
    t.put_number(t_max, s.max_film_temperature - kelvin_offset);
    t.put_number(hmin, s.hmin_over_sigma);
    t.put_number(contact, s.contact_share);
    t.put_number(f_eff, s.f_eff);
    t.put_number(load, s.load);
    t.put_number(speed, s.speed);
    run.put(t, p.parameters, p.sliding);
  }
  return t;
}

std::string trajectory_csv(const std::vector<TrajectorySample>& samples, const std::vector<std::string>& parameter_columns,
                           bool sliding_column) {
  return trajectory_table(samples, parameter_columns, sliding_column).csv();
}

}  // namespace twb
