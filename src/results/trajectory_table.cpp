#include "twb/results/trajectory_table.h"

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

Regime regime_of(const BearingState& state) {
  if (state.load == 0.0 && state.speed == 0.0) return Regime::at_rest;
  if (state.contact_share < 0.01) return Regime::full_film;
  if (state.fluid_share < 0.1) return Regime::boundary;
  return Regime::mixed;
}

std::string_view regime_name(Regime regime) {
  switch (regime) {
    case Regime::full_film: return "full_film";
    case Regime::mixed: return "mixed";
    case Regime::boundary: return "boundary";
    case Regime::at_rest: return "at_rest";
  }
  return "";
}

ResultTable trajectory_table(const std::vector<TrajectorySample>& samples, const std::vector<std::string>& parameter_columns,
                             bool sliding_column, bool cycle) {
  ResultTable t;
  const auto time = t.number("t_s"), t_mean = t.number("T_mean_C"), t_max = t.number("T_max_C"),
             hmin = t.number("hmin_over_sigma"), contact = t.number("contact_share"), f_eff = t.number("f_eff"),
             load = t.number("load_N"), speed = t.number("speed_rad_s"), torque = t.number("torque_Nm"),
             fluid = t.number("fluid_share");
  const auto regime = t.text("regime");
  const auto generated = t.number("heat_generated_W"), to_ambient = t.number("heat_to_ambient_W");
  const cells::ReportedColumns reported(
      t, samples, [](const TrajectorySample& p) -> const BearingState& { return p.state; }, true);
  std::optional<ResultTable::Column> ambient, tilt, margin, criterion, stop;
  if (cycle) {
    ambient = t.number("ambient_C"), tilt = t.number("tilt_rad"), margin = t.number("least_margin");
    criterion = t.text("least_margin_criterion");
    stop = t.number("stop_reaction_N");  // empty without the gear's stop
  }
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
    t.put_number(torque, s.torque);
    t.put_number(fluid, s.fluid_share);
    t.put_text(regime, std::string(regime_name(regime_of(s))));
    t.put_number(generated, s.heat_generated);
    t.put_number(to_ambient, s.heat_to_ambient);
    reported.put(t, s);
    if (cycle) {
      t.put_number(*ambient, p.ambient ? std::optional<double>(*p.ambient - kelvin_offset) : std::nullopt);
      t.put_number(*tilt, p.tilt);
      t.put_number(*margin, p.least_margin);
      t.put_text(*criterion, p.least_criterion ? std::string(limit_name(*p.least_criterion)) : std::string());
      t.put_number(*stop, s.stop_reaction);
    }
    run.put(t, p.parameters, p.sliding);
  }
  return t;
}

std::string trajectory_csv(const std::vector<TrajectorySample>& samples, const std::vector<std::string>& parameter_columns,
                           bool sliding_column) {
  return trajectory_table(samples, parameter_columns, sliding_column).csv();
}

}  // namespace twb
