#include "twb/results/life_table.h"

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

ResultTable life_table(const std::vector<LifeRow>& rows) {
  constexpr double um = 1e6, mm3 = 1e9, hour = 3600.0;
  ResultTable t;
  const auto time = t.number(kLifeTimeColumn);
  struct Face {
    ResultTable::Column deepest, mean, volume, rq;
  };
  auto face = [&](const char* name) {
    return Face{t.number(std::string("worn_depth_") + name + "_max_um"),
                t.number(std::string("worn_depth_") + name + "_mean_um"),
                t.number(std::string("worn_volume_") + name + "_mm3"), t.number(std::string("rq_") + name + "_um")};
  };
  const Face rest = face("rest"), turn = face("turn");
  const auto rest_rate = t.number("wear_rate_rest_um_h"), turn_rate = t.number("wear_rate_turn_um_h");
  const auto torque = t.number("torque_Nm"), f_eff = t.number("f_eff"), t_max = t.number("T_max_C"),
             hmin = t.number("hmin_over_sigma"), contact = t.number("contact_share");
  const auto failure_load = t.number("W_fail_N");
  const auto failure_criterion = t.text("failure_criterion"), event = t.text("event");
  for (const LifeRow& r : rows) {
    t.put_number(time, r.time / hour);
    for (const auto& [columns, wear] : {std::pair{rest, r.rest}, std::pair{turn, r.turn}}) {
      t.put_number(columns.deepest, um * wear.deepest);
      t.put_number(columns.mean, um * wear.mean);
      t.put_number(columns.volume, mm3 * wear.volume);
      t.put_number(columns.rq, um * wear.rq);
    }
    t.put_number(rest_rate, um * hour * r.rest_rate);
    t.put_number(turn_rate, um * hour * r.turn_rate);
    t.put_number(torque, r.torque);
    t.put_number(f_eff, r.f_eff);
    t.put_number(t_max, r.max_temperature - kelvin_offset);
    t.put_number(hmin, r.hmin_over_sigma);
    t.put_number(contact, r.contact_share);
    t.put_number(failure_load, r.failure_load);
    t.put_text(failure_criterion, r.failure_criterion ? criterion_name(*r.failure_criterion) : std::string());
    t.put_text(event, r.event);
  }
  return t;
}

}  // namespace twb
