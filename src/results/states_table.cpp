#include "twb/results/states_table.h"

#include "result_cells.h"

namespace twb {

using cells::finite;
using cells::kelvin_offset;

std::string states_csv(const std::vector<SolvedState>& rows, const std::string& parameter_column,
                       bool sliding_column) {
  std::string out =
      "load_N,speed_rad_s," + cells::run_header(parameter_column, sliding_column) +
      "T_mean_C,T_max_C,hmin_over_sigma,gamma_x_ratio,gamma_y_ratio,fluid_share,"
      "contact_share,torque_Nm,f_eff,stribeck,converged,iterations,residual,energy_error,wall_ms,branch,limits\n";
  for (const SolvedState& r : rows) {
    const BearingState& s = r.state;
    out += fmt::format("{:.10g},{:.10g},", finite(s.load, "load"), finite(s.speed, "speed")) +
           cells::run_cells(parameter_column, sliding_column, r.parameter, r.sliding);
    out += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},"
                       "{:.10g},{:.10g},{},{},{:.3e},{:.3e},{:.3f},{},{}\n",
                       finite(s.washer_mean_temperature - kelvin_offset, "T_mean"),
                       finite(s.max_film_temperature - kelvin_offset, "T_max"),
                       finite(s.hmin_over_sigma, "hmin_over_sigma"), finite(s.gamma_x_ratio, "gamma_x_ratio"),
                       finite(s.gamma_y_ratio, "gamma_y_ratio"), finite(s.fluid_share, "fluid_share"),
                       finite(s.contact_share, "contact_share"), finite(s.torque, "torque"),
                       finite(s.f_eff, "f_eff"), finite(s.stribeck, "stribeck"), r.converged ? 1 : 0,
                       r.iterations, finite(r.residual, "residual"), finite(s.energy_error, "energy_error"),
                       finite(r.wall_ms, "wall_ms"), r.branch, limit_names(s.limits));
  }
  return out;
}

std::string states_summary(const std::vector<SolvedState>& rows) {
  std::string out = fmt::format("{:>9} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7} {:>7} {:>9} {:>7} {:>4} {:>8}\n",
                                "load N", "speed r/s", "Tmean C", "Tmax C", "hmin/sig", "gx/gt", "gy/gt",
                                "fluid", "contact", "torque Nm", "f_eff", "iter", "ms");
  for (const SolvedState& r : rows) {
    const BearingState& s = r.state;
    out += fmt::format("{:9.1f} {:9.1f} {:8.2f} {:8.2f} {:8.3f} {:8.4f} {:8.4f} {:7.4f} {:7.4f} {:9.3e} {:7.4f} {:4} {:8.1f}{}{}\n",
                       s.load, s.speed, s.washer_mean_temperature - kelvin_offset,
                       s.max_film_temperature - kelvin_offset, s.hmin_over_sigma, s.gamma_x_ratio, s.gamma_y_ratio,
                       s.fluid_share, s.contact_share, s.torque, s.f_eff, r.iterations, r.wall_ms,
                       r.converged ? "" : "  NOT CONVERGED", s.limits.empty() ? "" : "  limits: " + limit_names(s.limits));
  }
  return out;
}

}  // namespace twb
