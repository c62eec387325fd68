#include "twb/results/states_table.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "result_cells.h"
#include "twb/results/state_quantities.h"

namespace twb {

using cells::kelvin_offset;

// The columns of the quantities (state_quantities.h) in their order, the run's
// columns after the operating point's; a column written only where some state
// has it is left out where none has.
ResultTable states_table(const std::vector<SolvedState> &rows,
                         const std::vector<std::string> &parameter_columns,
                         bool sliding_column) {
  ResultTable t;
  const std::span<const StateQuantity> quantities = state_quantities();
  std::vector<std::optional<ResultTable::Column>> columns(quantities.size());
  auto declare = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const StateQuantity &q = quantities[k];
      if (q.where && std::none_of(rows.begin(), rows.end(), q.where))
        continue;
      columns[k] = q.kind == ResultColumn::Kind::count ? t.count(q.column)
                   : q.kind == ResultColumn::Kind::text
                       ? t.text(q.column)
                       : t.number(q.column, q.style);
    }
  };
  auto put = [&](const SolvedState &r, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      if (!columns[k])
        continue;
      const StateCell c = quantities[k].value(r);
      switch (quantities[k].kind) {
      case ResultColumn::Kind::count:
        t.put_count(*columns[k], c.count);
        break;
      case ResultColumn::Kind::text:
        t.put_text(*columns[k], c.text);
        break;
      case ResultColumn::Kind::number:
        t.put_number(*columns[k], c.number);
        break;
      }
    }
  };
  declare(0, kOperatingPointQuantities);
  const cells::RunColumns run(t, parameter_columns, sliding_column);
  declare(kOperatingPointQuantities, quantities.size());
  // An effect's quantity not among the registered effects' is written too, last.
  const cells::ReportedColumns unlisted(
      t, rows, [](const SolvedState &r) -> const BearingState & { return r.state; }, false);
  for (const SolvedState &r : rows) {
    put(r, 0, kOperatingPointQuantities);
    run.put(t, r.parameters, r.sliding);
    put(r, kOperatingPointQuantities, quantities.size());
    unlisted.put(t, r.state);
  }
  return t;
}

std::vector<double> mesh_error_quantities(const BearingState &s) {
  SolvedState r;
  r.state = s;
  std::vector<double> values;
  for (const char *q : kMeshErrorQuantities)
    values.push_back(*state_quantity(q).value(r).number);
  return values;
}

std::string states_csv(const std::vector<SolvedState> &rows,
                       const std::vector<std::string> &parameter_columns,
                       bool sliding_column) {
  return states_table(rows, parameter_columns, sliding_column).csv();
}

std::string states_summary(const std::vector<SolvedState> &rows) {
  std::string out = fmt::format("{:>9} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} "
                                "{:>7} {:>7} {:>9} {:>7} {:>4} {:>8}\n",
                                "load N", "speed r/s", "Tmean C", "Tmax C",
                                "hmin/sig", "gx/gt", "gy/gt", "fluid",
                                "contact", "torque Nm", "f_eff", "iter", "ms");
  for (const SolvedState &r : rows) {
    const BearingState &s = r.state;
    out += fmt::format(
        "{:9.1f} {:9.1f} {:8.2f} {:8.2f} {:8.3f} {:8.4f} {:8.4f} {:7.4f} "
        "{:7.4f} {:9.3e} {:7.4f} {:4} {:8.1f}{}{}{}\n",
        s.load, s.speed, s.washer_mean_temperature - kelvin_offset,
        s.max_film_temperature - kelvin_offset, s.hmin_over_sigma,
        s.gamma_x_ratio, s.gamma_y_ratio, s.fluid_share, s.contact_share,
        s.torque, s.f_eff, r.iterations, r.wall_ms,
        r.converged ? "" : "  NOT CONVERGED",
        failure_names(s.limits).empty()
            ? ""
            : "  FAILS BY " + failure_names(s.limits),
        s.limits.empty() ? "" : "  limits: " + limit_names(s.limits));
  }
  return out;
}

} // namespace twb
