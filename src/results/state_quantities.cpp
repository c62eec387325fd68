#include "twb/results/state_quantities.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "model/reported_quantity.h"
#include "result_cells.h"

namespace twb {

namespace {

using cells::kelvin_offset;
using Kind = ResultColumn::Kind;
using Style = ResultColumn::Style;

constexpr double kLitresPerMinute = 1e3 * 60.0; // l/min in one m³/s

StateCell number(std::optional<double> v) { return StateCell{v, 0, {}}; }
std::optional<double> celsius(std::optional<double> kelvin) {
  return kelvin ? std::optional<double>(*kelvin - kelvin_offset) : std::nullopt;
}

// A state quantity of BearingState.
StateQuantity
of_state(std::string column, std::string_view unit, std::string_view meaning,
         std::function<std::optional<double>(const BearingState &)> get,
         Style style = Style::general,
         std::function<bool(const SolvedState &)> where = {}) {
  return {std::move(column),
          unit,
          meaning,
          Kind::number,
          style,
          [get](const SolvedState &r) { return number(get(r.state)); },
          std::move(where)};
}

// A quantity of the solve or of the row's place in a study (SolvedState).
StateQuantity of_solve(std::string column, std::string_view unit,
                       std::string_view meaning, Kind kind, Style style,
                       std::function<StateCell(const SolvedState &)> value) {
  return {std::move(column), unit, meaning, kind, style, std::move(value), {}};
}

// The sliding film's flows, m³/s and l/min (docs/physics.md section 14).
void add_flows(std::vector<StateQuantity> &q) {
  struct Flow {
    const char *m3_s;
    const char *l_min;
    std::string_view meaning;
    double FilmFlows::*member;
  };
  static constexpr std::array<Flow, 4> flows{{
      {"Q_supply_m3_s", "Q_supply_l_min",
       "oil into the sliding film from every fed boundary (bore and grooves)",
       &FilmFlows::supplied},
      {"Q_inner_m3_s", "Q_inner_l_min",
       "oil leaving the sliding film at its inner radius (negative: entering)",
       &FilmFlows::inner},
      {"Q_outer_m3_s", "Q_outer_l_min",
       "oil leaving the sliding film at its outer radius", &FilmFlows::outer},
      {"Q_grooves_m3_s", "Q_grooves_l_min",
       "oil out of the fed grooves into the lands and across the rims",
       &FilmFlows::grooves},
  }};
  const auto has_flows = [](const SolvedState &r) {
    return r.state.flows.has_value();
  };
  for (const Flow &f : flows) {
    const auto member = f.member;
    q.push_back(of_state(
        f.m3_s, "m³/s", f.meaning,
        [member](const BearingState &s) {
          return s.flows ? std::optional<double>((*s.flows).*member)
                         : std::nullopt;
        },
        Style::scientific, has_flows));
    q.push_back(of_state(
        f.l_min, "l/min", "the same in litres per minute",
        [member](const BearingState &s) {
          return s.flows ? std::optional<double>((*s.flows).*member *
                                                 kLitresPerMinute)
                         : std::nullopt;
        },
        Style::general, has_flows));
  }
}

// The quantities the effects report of their own (model/reported_quantity.h), each
// written only where some state's effects report it.
void add_effect_quantities(std::vector<StateQuantity> &q) {
  for (const ReportedQuantity &e : effect_quantities()) {
    const std::string_view column = e.column;
    q.push_back(of_state(
        std::string(column), e.unit, e.meaning,
        [column](const BearingState &s) { return s.reported_value(column); },
        Style::general, [column](const SolvedState &r) {
          return r.state.reported_value(column).has_value();
        }));
  }
}

// Each error-bar quantity's Richardson extrapolation and error (docs/physics.md
// section 8).
void add_mesh_errors(std::vector<StateQuantity> &q) {
  for (std::size_t k = 0; k < std::size(kMeshErrorQuantities); ++k) {
    for (const bool error : {false, true}) {
      const std::size_t at = 2 * k + (error ? 1 : 0);
      q.push_back(
          {std::string(kMeshErrorQuantities[k]) +
               (error ? "_error" : "_extrapolated"),
           "as the quantity",
           error ? "its discretization error bar (the state again on the mesh "
                   "refined by two)"
                 : "its Richardson extrapolation to the converged mesh",
           Kind::number, Style::general,
           [at](const SolvedState &r) {
             return number(at < r.mesh_errors.size()
                               ? std::optional<double>(r.mesh_errors[at])
                               : std::nullopt);
           },
           [](const SolvedState &r) { return !r.mesh_errors.empty(); }});
    }
  }
}

std::vector<StateQuantity> make_quantities() {
  std::vector<StateQuantity> q;
  q.push_back(of_state("load_N", "N", "the load on the gear",
                       [](const BearingState &s) { return s.load; }));
  q.push_back(of_state("speed_rad_s", "rad/s", "the sliding speed",
                       [](const BearingState &s) { return s.speed; }));
  q.push_back(of_state("T_mean_C", "°C",
                       "the washer's area-weighted mean temperature",
                       [](const BearingState &s) {
                         return s.washer_mean_temperature - kelvin_offset;
                       }));
  q.push_back(of_state("T_max_C", "°C", "the hottest film node",
                       [](const BearingState &s) {
                         return s.max_film_temperature - kelvin_offset;
                       }));
  q.push_back(of_state(
      "T_oil_peak_C", "°C",
      "the oil's peak temperature, located between the nodes (physics §8)",
      [](const BearingState &s) {
        return s.oil_peak_temperature - kelvin_offset;
      }));
  q.push_back(of_state(
      "T_contact_max_C", "°C",
      "the asperities' hottest contact: face plus Blok's flash temperature "
      "(physics §8); empty "
      "without the contact model",
      [](const BearingState &s) { return celsius(s.contact_temperature); }));
  q.push_back(of_state("T_carrier_max_C", "°C", "the carrier's hottest face",
                       [](const BearingState &s) {
                         return s.carrier_max_temperature - kelvin_offset;
                       }));
  q.push_back(of_state("T_washer_max_C", "°C", "the washer's hottest face",
                       [](const BearingState &s) {
                         return s.washer_max_temperature - kelvin_offset;
                       }));
  q.push_back(of_state("T_gear_max_C", "°C", "the gear's hottest face",
                       [](const BearingState &s) {
                         return s.gear_max_temperature - kelvin_offset;
                       }));
  q.push_back(
      of_state("hmin_over_sigma", "1",
               "the sliding film's least gap over the combined roughness σ",
               [](const BearingState &s) { return s.hmin_over_sigma; }));
  q.push_back(of_state("gamma_x_ratio", "1",
                       "the washer's tilt about x over the gear's tilt",
                       [](const BearingState &s) { return s.gamma_x_ratio; }));
  q.push_back(of_state("gamma_y_ratio", "1",
                       "the washer's tilt about y over the gear's tilt",
                       [](const BearingState &s) { return s.gamma_y_ratio; }));
  q.push_back(of_state("fluid_share", "1",
                       "the share of the load the sliding film's oil carries",
                       [](const BearingState &s) { return s.fluid_share; }));
  q.push_back(
      of_state("contact_share", "1",
               "the share of the load the sliding film's asperities carry",
               [](const BearingState &s) { return s.contact_share; }));
  q.push_back(of_state("torque_Nm", "N·m",
                       "the running friction torque the sliding dissipates (physics §6); 0 at rest",
                       [](const BearingState &s) { return s.torque; }));
  q.push_back(of_state("f_eff", "1",
                       "the effective friction coefficient, torque over load "
                       "and mean radius (eq. [43])",
                       [](const BearingState &s) { return s.f_eff; }));
  q.push_back(of_state("stribeck", "Pa·s·rev/s/Pa", "the Stribeck number Z·N/P (physics §9)",
                       [](const BearingState &s) { return s.stribeck; }));
  q.push_back(
      of_solve("converged", "", "1 where Newton met its tolerance", Kind::count,
               Style::general, [](const SolvedState &r) {
                 return StateCell{std::nullopt, r.converged ? 1 : 0, {}};
               }));
  q.push_back(of_solve("iterations", "", "Newton iterations", Kind::count,
                       Style::general, [](const SolvedState &r) {
                         return StateCell{std::nullopt, r.iterations, {}};
                       }));
  q.push_back(
      of_solve("residual", "1", "the max-norm of the scaled residual",
               Kind::number, Style::scientific,
               [](const SolvedState &r) { return number(r.residual); }));
  q.push_back(of_state(
      "energy_error", "1", "the relative error of the energy balance",
      [](const BearingState &s) { return s.energy_error; }, Style::scientific));
  q.push_back(of_solve("wall_ms", "ms", "the wall time of the solve",
                       Kind::number, Style::fixed,
                       [](const SolvedState &r) { return number(r.wall_ms); }));
  q.push_back(
      of_solve("branch", "",
               "the steady branch: cool (before distress), hot (past it), "
               "empty for none",
               Kind::text, Style::general, [](const SolvedState &r) {
                 return StateCell{std::nullopt, 0, branch_name(r.branch)};
               }));
  // A state past a failure criterion says so beside its branch: "cool" alone is
  // never a verdict of safety.
  q.push_back(of_solve(
      "fails_by", "", "the failure criteria the state is past", Kind::text,
      Style::general, [](const SolvedState &r) {
        return StateCell{std::nullopt, 0, failure_names(r.state.limits)};
      }));
  q.push_back(of_solve(
      "limits", "", "the limits of the model and the oil the state exceeds",
      Kind::text, Style::general, [](const SolvedState &r) {
        return StateCell{std::nullopt, 0, limit_names(r.state.limits)};
      }));
  add_flows(q);
  add_effect_quantities(q);
  add_mesh_errors(q);
  return q;
}

} // namespace

std::span<const StateQuantity> state_quantities() {
  static const std::vector<StateQuantity> quantities = make_quantities();
  return quantities;
}

const StateQuantity &state_quantity(std::string_view column) {
  for (const StateQuantity &q : state_quantities())
    if (q.column == column)
      return q;
  throw std::invalid_argument(
      fmt::format("no state quantity is called {}", column));
}

std::string state_quantities_markdown() {
  std::string out = "| column | unit | meaning |\n|---|---|---|\n";
  for (const StateQuantity &q : state_quantities())
    out += fmt::format("| `{}` | {} | {}{} |\n", q.column,
                       q.unit.empty() ? "–" : q.unit, q.meaning,
                       q.where ? " (only where some state has it)" : "");
  return out;
}

} // namespace twb
