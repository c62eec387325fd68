// The reported quantities of a solved state (docs/physics.md section 9).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "model/limit_thresholds.h"
#include "model/assembly_totals.h"
#include "model/film_point.h"
#include "model/film_roughness.h"
#include "model/located_maximum.h"

namespace twb {

namespace {

// What the bodies' temperature fields report: the washer's area-weighted mean rise above
// the ambient (K) and the heat the bodies lose to the ambient (W), in the bodies' order.
struct BodiesHeat {
  double washer_mean_rise = 0.0;
  double to_ambient = 0.0;
};

BodiesHeat bodies_heat(const std::vector<ComponentHeat>& components, std::span<const double> u) {
  BodiesHeat out;
  for (const ComponentHeat& comp : components) {
    double sum = 0, area = 0, loss = 0;
    const int nt = comp.axisymmetric ? 1 : comp.grid.circumferential_nodes();
    for (int i = 0; i < comp.grid.radial_nodes(); ++i)
      for (int j = 0; j < nt; ++j) {
        const double tk = u[comp.offset + i * nt + j];
        sum += comp.node_area(i) * tk;
        area += comp.node_area(i);
        if (comp.loses_to_ambient) loss += comp.node_area(i) * comp.conductivity / comp.thickness * tk;
      }
    if (comp.id == ComponentId::washer) out.washer_mean_rise = sum / area;
    out.to_ambient += loss;
  }
  return out;
}

// Where the sliding film's faces run in (docs/physics.md section 20) σ and the summits vary
// over it: its least h/σ and largest contact pressure, each over its nodes.
struct RunInExtremes {
  double least_ratio = INFINITY, greatest_pressure = 0.0;
};
RunInExtremes run_in_extremes(const BearingModel& model, std::span<const double> u, const Film& film,
                              const FilmRoughness& roughness) {
  RunInExtremes out;
  const FilmGap gap(model, u, film);
  const FilmMesh& m = film.mesh;
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const double h = gap.smooth(i, j) + (film.relief.flat() ? 0.0 : film.relief.least_at_node(i, j));
      const double sigma = roughness.at_node(m.node(i, j)).sigma;
      out.least_ratio = std::min(out.least_ratio, h / sigma);
      if (h <= model.contact_cutoff())
        out.greatest_pressure = std::max(
            out.greatest_pressure, model.scaled_contact()->pressure(h, sigma / roughness.uniform().sigma).value);
    }
  return out;
}

}  // namespace

void BearingModel::gather_totals(std::span<const double> u, AssemblyTotals& totals) const {
  std::vector<double> residual(size());
  Assembler a(&pattern_, residual, {});
  assemble(u, a, &totals);
}

BearingState BearingModel::describe(std::span<const double> u) const {
  std::vector<double> residual(size());
  Assembler a(&pattern_, residual, {});
  AssemblyTotals t;
  assemble(u, a, &t);

  BearingState s;
  s.load = load_;
  s.speed = scene_.operating.speed;
  s.position = position(u);
  const std::size_t fs = films_[0].sliding ? 0 : 1;
  const Film& film = films_[fs];
  const FilmTotals& ft = t.film[fs];

  const double sliding_least_gap = least_gap(u, film);
  s.hmin_over_sigma = sliding_least_gap / film.sigma;
  const FilmRoughness roughness(*this, u, film);
  const RunInExtremes run_in = roughness.varies() ? run_in_extremes(*this, u, film, roughness) : RunInExtremes{};
  if (roughness.varies()) s.hmin_over_sigma = run_in.least_ratio;
  const double tilt = scene_.gear.tilt > 0 ? scene_.gear.tilt : 1.0;
  s.gamma_x_ratio = s.position.gamma_x / tilt;
  s.gamma_y_ratio = s.position.gamma_y / tilt;

  s.fluid_force = ft.fluid_force;
  s.contact_force = ft.contact_force;
  // What the sliding film carries: the load, and with the gear's stop the stop's reaction
  // too (the washer pressed between the films when unloaded, docs/physics.md section 19).
  const double carried = gear_stop() && ft.fluid_force + ft.contact_force > 0.0 ? ft.fluid_force + ft.contact_force : load_;
  // Off its stop where the stop's row reads the balance (R̂ below ŝ, as Newton's form
  // selects): R̂ is then zero to the tolerance, and its rounding is no reaction.
  if (gear_stop()) s.stop_reaction = t.stop_reaction > t.stop_gap ? t.stop_reaction * force_scale() : 0.0;
  // Unloaded at rest with the films parted (physics §19) nothing is carried: the shares,
  // f_eff and the Stribeck number over it are written as 0.
  const auto over_carried = [&](double x) { return carried > 0.0 ? x / carried : 0.0; };
  s.fluid_share = over_carried(ft.fluid_force);
  s.contact_share = over_carried(ft.contact_force);
  s.friction_coefficient = ft.friction_coefficient;
  s.friction_clamped = ft.friction_clamped;
  // At rest nothing slides (physics §9): the contacts' friction is then static, the torque
  // that would start the washer turning, which dissipates nothing; the running torque
  // twb reports, and f_eff with it, is nought.
  s.torque = s.speed == 0.0 ? 0.0 : ft.friction_coefficient * ft.contact_torque_per_f + ft.viscous_torque;
  // Eq [43] with the washer's radii.
  const double ri = scene_.washer.inner_radius, ro = scene_.washer.outer_radius;
  s.f_eff = carried > 0.0 ? 1.5 * s.torque * (ro * ro - ri * ri) / (carried * (ro * ro * ro - ri * ri * ri)) : 0.0;

  // Temperatures.
  const double t0 = scene_.operating.ambient;
  s.washer_mean_temperature = t0;
  s.max_film_temperature = t0;
  s.oil_peak_temperature = t0;
  double mean_visc_t = 0.0, area_sum = 0.0;
  const FilmMesh& m = film.mesh;
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      mean_visc_t += m.node_area(i) * viscosity_temperature(u, film, i, j, nullptr);
      area_sum += m.node_area(i);
    }
  mean_visc_t /= area_sum;
  // The oil's peak and the asperities' hottest contact, located between the nodes
  // (docs/physics.md section 8).
  const FilmPointReader points(*this, u, t.film);
  if (scene_.effects.thermal) {
    for (const Film& f : films_)
      for (int n = 0; n < f.mesh.node_count(); ++n)
        s.max_film_temperature = std::max(s.max_film_temperature, temperature_of(u, f.temperature_row(n)));
    s.oil_peak_temperature =
        locate_maximum(
            films_, [&](const Film& f, double r, double theta) { return points.at(f, r, theta).film_temperature; },
            [](const Film&) { return true; })
            .value;
  }
  if (contact_)
    s.contact_temperature =
        locate_maximum(
            films_, [&](const Film& f, double r, double theta) { return points.at(f, r, theta).contact_temperature; },
            [](const Film& f) { return f.sliding; })
            .value;
  if (scene_.effects.thermal) {
    const BodiesHeat bodies = bodies_heat(components_, u);
    s.washer_mean_temperature = t0 + bodies.washer_mean_rise;
    s.heat_to_ambient = bodies.to_ambient;
  }
  s.heat_generated = ft.viscous_heat + ft.friction_heat;
  // Generated = conducted to ambient (+ carried out by the oil, with convection).
  if (scene_.effects.thermal)
    s.energy_error =
        std::abs(s.heat_generated - s.heat_to_ambient - (scene_.effects.convection ? ft.convected_heat : 0.0)) /
        std::max(s.heat_generated, 1e-300);

  // Stribeck number Z·N/P: viscosity at the mean film temperature, N in rev/s, P the
  // load over the washer area (docs/physics.md section 9).
  const double washer_area = std::numbers::pi * (ro * ro - ri * ri);
  s.stribeck = carried > 0.0 ? viscosity(mean_visc_t).value * (std::abs(s.speed) / (2 * std::numbers::pi)) /
                                    (carried / washer_area)
                              : 0.0;

  // Balances, from the residual rows (forces scaled by the load, or with the gear's stop by
  // the scene's load; the gear's row is then the stop's complementarity).
  s.force_balance_error = std::max(std::abs(residual[rigid_offset_ + 0]), std::abs(residual[rigid_offset_ + 3]));
  s.moment_balance_error = std::max(std::abs(residual[rigid_offset_ + 1]), std::abs(residual[rigid_offset_ + 2]));
  if (film.pressure_offset >= 0)
    for (Index k = film.pressure_offset; k < film.pressure_offset + film.mesh.interior_count(); ++k)
      s.complementarity_error = std::max(s.complementarity_error, std::abs(residual[k]));

  if (film.pressure_offset >= 0) {
    // A fed bore's inflow is supply; the grooves' outflow is supply wherever they are fed.
    const bool fed_bore = scene_.lubricant.supply && scene_.lubricant.supply->feeds_bore();
    s.flows = FilmFlows{ft.groove_flow - (fed_bore ? ft.inner_flow : 0.0), ft.inner_flow, ft.outer_flow,
                        ft.groove_flow};
  }

  // The contact pressure falls with the gap, so each film's largest is at its least gap.
  if (contact_)
    for (const Film& f : films_) {
      const double least = f.number == film.number ? sliding_least_gap : least_gap(u, f);
      if (f.number == film.number && roughness.varies())
        s.max_contact_pressure = std::max(s.max_contact_pressure, run_in.greatest_pressure);
      else if (least <= contact_cutoff_)
        s.max_contact_pressure = std::max(s.max_contact_pressure, contact_->pressure(least).value);
    }
  // Each body's hottest face, its material's temperature (physics §8): its hottest node,
  // or hotter, a face beside a film, on the heat path from the film's temperature there,
  // located between the film nodes as the oil's peak is. (The hottest film node's face
  // jumps as the hot spot passes from node to node, and its film temperature is the
  // node's control-volume mean, which lags the rim's heat.)
  const auto hottest_face = [&](ComponentId id) {
    const double hottest = hottest_node_temperature(u, id);
    // (A body without resistance of its own has its faces at its nodes' temperatures,
    // piecewise linear between them: the hottest node is its hottest face.)
    if (!scene_.effects.thermal || body_resistance(id) <= 0.0) return hottest;
    const LocatedMaximum face = locate_maximum(
        films_,
        [&](const Film& f, double r, double theta) {
          return points.at(f, r, theta).face_temperature[f.lower == id ? 0 : 1];
        },
        [&](const Film& f) { return f.lower == id || f.upper == id; });
    return face.film != 0 ? std::max(hottest, face.value) : hottest;
  };
  s.carrier_max_temperature = hottest_face(ComponentId::carrier);
  s.washer_max_temperature = hottest_face(ComponentId::washer);
  s.gear_max_temperature = hottest_face(ComponentId::gear);
  s.limits = exceeded_limits(LimitValues::of(s, scene_.effects.thermal), OperatingLimits::of(scene_));
  for (const auto& effect : effects_) effect->report(u, t, s.reported);
  return s;
}

}  // namespace twb
