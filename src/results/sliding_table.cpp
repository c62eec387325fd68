#include "twb/results/sliding_table.h"

#include "result_cells.h"

namespace twb {

ResultTable sliding_table(const std::vector<SlidingRow>& rows) {
  ResultTable t;
  const auto speed = t.number("speed_rad_s"), load = t.number("load_N"), sliding = t.text("sliding"),
             area = t.number("film_area_m2"), fluid_force = t.number("fluid_force_N"),
             fluid = t.number("fluid_share"), contact = t.number("contact_share"), torque = t.number("torque_Nm"),
             f_eff = t.number("f_eff"), hmin = t.number("hmin_over_sigma"), t_mean = t.number("T_mean_C"),
             chosen = t.count("chosen");
  for (const SlidingRow& r : rows) {
    const BearingState& s = r.solved.state;
    t.put_number(speed, s.speed);
    t.put_number(load, s.load);
    t.put_text(sliding, cells::film_name(r.solved.sliding));
    t.put_number(area, r.film_area);
    t.put_number(fluid_force, s.fluid_force);
    t.put_number(fluid, s.fluid_share);
    t.put_number(contact, s.contact_share);
    t.put_number(torque, s.torque);
    t.put_number(f_eff, s.f_eff);
    t.put_number(hmin, s.hmin_over_sigma);
    t.put_number(t_mean, s.washer_mean_temperature - cells::kelvin_offset);
    t.put_count(chosen, r.chosen ? 1 : 0);
  }
  return t;
}

std::string sliding_csv(const std::vector<SlidingRow>& rows) { return sliding_table(rows).csv(); }

}  // namespace twb
