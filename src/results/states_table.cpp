#include "twb/results/states_table.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

namespace {
constexpr double kLitresPerMinute = 1e3 * 60.0;  // l/min in one m³/s
}  // namespace

ResultTable states_table(const std::vector<SolvedState>& rows, const std::vector<std::string>& parameter_columns,
                         bool sliding_column) {
  ResultTable t;
  using Style = ResultColumn::Style;
  const auto load = t.number("load_N"), speed = t.number("speed_rad_s");
  const cells::RunColumns run(t, parameter_columns, sliding_column);
  const auto t_mean = t.number("T_mean_C"), t_max = t.number("T_max_C"), t_peak = t.number("T_oil_peak_C"),
             t_contact = t.number("T_contact_max_C"),
             t_carrier = t.number("T_carrier_max_C"),
             t_washer = t.number("T_washer_max_C"), t_gear = t.number("T_gear_max_C"), hmin = t.number("hmin_over_sigma"),
             gx = t.number("gamma_x_ratio"), gy = t.number("gamma_y_ratio"), fluid = t.number("fluid_share"),
             contact = t.number("contact_share"), torque = t.number("torque_Nm"), f_eff = t.number("f_eff"),
             stribeck = t.number("stribeck"), converged = t.count("converged"), iterations = t.count("iterations"),
             residual = t.number("residual", Style::scientific),
             energy = t.number("energy_error", Style::scientific), wall = t.number("wall_ms", Style::fixed),
             branch = t.text("branch"), fails_by = t.text("fails_by"), limits = t.text("limits");
  // The oil's flows where the film has hydrodynamics, in m³/s and in l/min.
  std::vector<ResultTable::Column> flows;
  if (std::any_of(rows.begin(), rows.end(), [](const SolvedState& r) { return r.state.flows.has_value(); }))
    for (const char* q : {"Q_supply", "Q_inner", "Q_outer", "Q_grooves"}) {
      flows.push_back(t.number(std::string(q) + "_m3_s", Style::scientific));
      flows.push_back(t.number(std::string(q) + "_l_min"));
    }
  // The heat the oil carries where some state has convection.
  std::optional<ResultTable::Column> carried;
  if (std::any_of(rows.begin(), rows.end(), [](const SolvedState& r) { return r.state.heat_carried.has_value(); }))
    carried = t.number("heat_carried_W");
  // The error bars' columns only where some state has them.
  std::vector<ResultTable::Column> errors;
  if (std::any_of(rows.begin(), rows.end(), [](const SolvedState& r) { return !r.mesh_errors.empty(); }))
    for (const char* q : kMeshErrorQuantities) {
      errors.push_back(t.number(std::string(q) + "_extrapolated"));
      errors.push_back(t.number(std::string(q) + "_error"));
    }
  for (const SolvedState& r : rows) {
    const BearingState& s = r.state;
    t.put_number(load, s.load);
    t.put_number(speed, s.speed);
    run.put(t, r.parameters, r.sliding);
    t.put_number(t_mean, s.washer_mean_temperature - kelvin_offset);
    t.put_number(t_max, s.max_film_temperature - kelvin_offset);
    t.put_number(t_peak, s.oil_peak_temperature - kelvin_offset);
    t.put_number(t_contact, s.contact_temperature ? std::optional<double>(*s.contact_temperature - kelvin_offset)
                                                  : std::nullopt);
    t.put_number(t_carrier, s.carrier_max_temperature - kelvin_offset);
    t.put_number(t_washer, s.washer_max_temperature - kelvin_offset);
    t.put_number(t_gear, s.gear_max_temperature - kelvin_offset);
    t.put_number(hmin, s.hmin_over_sigma);
    t.put_number(gx, s.gamma_x_ratio);
    t.put_number(gy, s.gamma_y_ratio);
    t.put_number(fluid, s.fluid_share);
    t.put_number(contact, s.contact_share);
    t.put_number(torque, s.torque);
    t.put_number(f_eff, s.f_eff);
    t.put_number(stribeck, s.stribeck);
    t.put_count(converged, r.converged ? 1 : 0);
    t.put_count(iterations, r.iterations);
    t.put_number(residual, r.residual);
    t.put_number(energy, s.energy_error);
    t.put_number(wall, r.wall_ms);
    t.put_text(branch, branch_name(r.branch));
    // A state past a failure criterion says so beside its branch: "cool" alone is
    // never a verdict of safety.
    t.put_text(fails_by, failure_names(s.limits));
    t.put_text(limits, limit_names(s.limits));
    if (carried) t.put_number(*carried, s.heat_carried);
    if (!flows.empty()) {
      const std::optional<FilmFlows>& q = s.flows;
      const std::array<double, 4> m3_s =
          q ? std::array<double, 4>{q->supplied, q->inner, q->outer, q->grooves} : std::array<double, 4>{};
      for (std::size_t k = 0; k < m3_s.size(); ++k) {
        t.put_number(flows[2 * k], q ? std::optional<double>(m3_s[k]) : std::nullopt);
        t.put_number(flows[2 * k + 1], q ? std::optional<double>(m3_s[k] * kLitresPerMinute) : std::nullopt);
      }
    }
    for (std::size_t k = 0; k < errors.size(); ++k)
      t.put_number(errors[k], k < r.mesh_errors.size() ? std::optional<double>(r.mesh_errors[k]) : std::nullopt);
  }
  return t;
}

std::vector<double> mesh_error_quantities(const BearingState& s) {
  return {s.washer_mean_temperature - kelvin_offset, s.max_film_temperature - kelvin_offset,
          s.oil_peak_temperature - kelvin_offset, s.hmin_over_sigma, s.torque, s.f_eff};
}

std::string states_csv(const std::vector<SolvedState>& rows, const std::vector<std::string>& parameter_columns,
                       bool sliding_column) {
  return states_table(rows, parameter_columns, sliding_column).csv();
}

std::string states_summary(const std::vector<SolvedState>& rows) {
  std::string out = fmt::format("{:>9} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7} {:>7} {:>9} {:>7} {:>4} {:>8}\n",
                                "load N", "speed r/s", "Tmean C", "Tmax C", "hmin/sig", "gx/gt", "gy/gt",
                                "fluid", "contact", "torque Nm", "f_eff", "iter", "ms");
  for (const SolvedState& r : rows) {
    const BearingState& s = r.state;
    out += fmt::format("{:9.1f} {:9.1f} {:8.2f} {:8.2f} {:8.3f} {:8.4f} {:8.4f} {:7.4f} {:7.4f} {:9.3e} {:7.4f} {:4} {:8.1f}{}{}{}\n",
                       s.load, s.speed, s.washer_mean_temperature - kelvin_offset,
                       s.max_film_temperature - kelvin_offset, s.hmin_over_sigma, s.gamma_x_ratio, s.gamma_y_ratio,
                       s.fluid_share, s.contact_share, s.torque, s.f_eff, r.iterations, r.wall_ms,
                       r.converged ? "" : "  NOT CONVERGED",
                       failure_names(s.limits).empty() ? "" : "  FAILS BY " + failure_names(s.limits),
                       s.limits.empty() ? "" : "  limits: " + limit_names(s.limits));
  }
  return out;
}

}  // namespace twb
