// The film at a point between its nodes (film_point.h; docs/physics.md sections 7, 8).
#include "model/film_point.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/tools/toms748_solve.hpp>

#include "model/assembly_totals.h"
#include "physics/average_gap.h"

namespace twb {

namespace {
// Where (r, θ) lies on a film's grid: cell (i, j) and the fractions s (radial) and t
// (circumferential) across it, r clamped to the annulus.
struct CellPlace {
  int i = 0, j = 0;
  double s = 0.0, t = 0.0;
};
CellPlace place(const FilmMesh& m, double r, double theta) {
  CellPlace c;
  const double x = std::clamp((r - m.inner_radius()) / m.dr(), 0.0, double(m.radial_nodes() - 1));
  c.i = std::min(int(x), m.radial_nodes() - 2);
  c.s = x - c.i;
  const double y = theta / m.dtheta();
  const double jf = std::floor(y);
  c.j = m.wrap(int(jf));
  c.t = y - jf;
  return c;
}
// Bilinear in the cell's four nodes, corners (i, j), (i+1, j), (i, j+1), (i+1, j+1).
double bilinear(const std::vector<double>& at_node, const FilmMesh& m, const CellPlace& c) {
  const auto v = [&](int di, int dj) { return at_node[std::size_t(m.node(c.i + di, c.j + dj))]; };
  return (1 - c.s) * (1 - c.t) * v(0, 0) + c.s * (1 - c.t) * v(1, 0) + (1 - c.s) * c.t * v(0, 1) +
         c.s * c.t * v(1, 1);
}
}  // namespace

FilmPointReader::FilmPointReader(const BearingModel& model, std::span<const double> u,
                                 std::span<const FilmTotals> totals)
    : model_(model), u_(u) {
  const auto& films = model.films();
  for (std::size_t f = 0; f < films.size(); ++f)
    if (films[f].sliding && f < totals.size()) friction_coefficient_ = totals[f].friction_coefficient;
  for (const Film& film : films) gaps_.emplace_back(model, u, film);
  for (const Film& film : films) roughness_.emplace_back(model, u, film);
  const Scene& scene = model.scene();
  const std::array<const Material*, 3> materials{&scene.carrier.material, &scene.washer.material, &scene.gear.material};
  for (std::size_t b = 0; b < 3; ++b) yield_strength_[b] = materials[b]->yield_strength;
  for (std::size_t b = 0; b < 3; ++b)
    flash_bodies_[b] = {materials[b]->conductivity,
                        materials[b]->conductivity / (materials[b]->density * materials[b]->specific_heat), 0.0};
  if (model.scene().effects.convection && model.scene().effects.thermal)
    for (std::size_t f = 0; f < films.size(); ++f) advected_.push_back(node_advection(films[f], totals[f]));
}

namespace {
// The point's heat paths (physics §7): Tf to each body through half the mean gap's oil and
// the body's own part (half the washer's thickness, nothing for carrier and gear).
struct HeatPaths {
  std::array<double, 2> body{}, resistance{}, own{};
};
}  // namespace

FilmPoint FilmPointReader::at(const Film& film, double r, double theta) const {
  const FilmMesh& m = film.mesh;
  const CellPlace c = place(m, r, theta);
  FilmPoint p;
  const double h = gaps_[std::size_t(film.number - 1)].at_point(r, theta, c.i, c.j, c.s, c.t);
  p.gap = h;
  // σ at the point, bilinear in its cell's corners' Rqs where the faces run in (section 20).
  const FilmRoughness& roughness = roughness_[std::size_t(film.number - 1)];
  const PointRoughness rough = roughness.in_cell(
      {m.node(c.i, c.j), m.node(c.i + 1, c.j), m.node(c.i, c.j + 1), m.node(c.i + 1, c.j + 1)}, c.s, c.t);
  const double scale = rough.sigma / roughness.uniform().sigma;
  p.mean_gap = average_gap(h, rough.sigma).value;
  if (model_.contact() && h <= model_.contact_cutoff())
    p.contact_pressure = roughness.varies() ? model_.scaled_contact()->pressure(h, scale).value
                                            : model_.contact()->pressure(h).value;

  const Scene& scene = model_.scene();
  p.sliding_speed = film.sliding ? std::abs(scene.operating.speed) * r : 0.0;
  p.flash_rise = flash_rise(film, h, scale, p.contact_pressure, p.sliding_speed);
  const double ambient = scene.operating.ambient;
  if (!scene.effects.thermal) {
    p.film_temperature = ambient;
    p.body_temperature = p.face_temperature = {ambient, ambient};
    p.contact_temperature = ambient + p.flash_rise;
    return p;
  }
  HeatPaths paths;
  const std::array<ComponentId, 2> sides{film.lower, film.upper};
  for (std::size_t k = 0; k < 2; ++k) {
    const double before = model_.face_temperature(u_, sides[k], r, c.j, nullptr);
    const double after = model_.face_temperature(u_, sides[k], r, c.j + 1, nullptr);
    paths.body[k] = (1 - c.t) * before + c.t * after;
    paths.own[k] = model_.body_resistance(sides[k]);
    paths.resistance[k] = model_.heat_path(p.mean_gap, sides[k]);
  }
  p.body_temperature = paths.body;
  const double conductance = 1.0 / paths.resistance[0] + 1.0 / paths.resistance[1];
  const double from_bodies = paths.body[0] / paths.resistance[0] + paths.body[1] / paths.resistance[1];
  const double advected = advected_.empty() ? 0.0 : bilinear(advected_[std::size_t(film.number - 1)], m, c);

  const double friction_heat = friction_coefficient_ * p.contact_pressure * p.sliding_speed;
  const auto heat_at = [&](double viscosity_temperature) {
    return friction_heat +
           model_.viscosity(viscosity_temperature).value * p.sliding_speed * p.sliding_speed / p.mean_gap;
  };
  // Tf balances q − (advected) = Σ (Tf − T_k)/R_k.
  if (scene.effects.viscosity_temperature != ViscosityTemperature::film_node) {
    p.heat = heat_at(0.5 * (paths.body[0] + paths.body[1]));
    p.film_temperature = (p.heat - advected + from_bodies) / conductance;
  } else {
    // μ at Tf itself: the balance's left side falls as Tf rises and its right side grows,
    // so one root, bracketed by the bodies' range widened by what the heat can lift.
    const double reach = (heat_at(std::min(paths.body[0], paths.body[1])) + std::abs(advected)) / conductance;
    const double low = std::min(paths.body[0], paths.body[1]) - std::abs(advected) / conductance - 1.0;
    const double high = std::max(paths.body[0], paths.body[1]) + reach + 1.0;
    const auto balance = [&](double tf) { return heat_at(tf) - advected - (conductance * tf - from_bodies); };
    std::uintmax_t iterations = 60;
    const auto root = boost::math::tools::toms748_solve(
        balance, low, high, [](double a, double b) { return std::abs(b - a) <= 1e-9; }, iterations);
    p.film_temperature = 0.5 * (root.first + root.second);
    p.heat = heat_at(p.film_temperature);
  }
  for (std::size_t k = 0; k < 2; ++k)
    p.face_temperature[k] =
        paths.body[k] + (p.film_temperature - paths.body[k]) * paths.own[k] / paths.resistance[k];
  p.contact_temperature = 0.5 * (p.face_temperature[0] + p.face_temperature[1]) + p.flash_rise;
  return p;
}

// The mean summit contact at the point (docs/physics.md section 8, scuffing): n contacts
// per unit area of real area A_r share the contact pressure, so each has the radius
// sqrt(A_r/(π n)) and the mean real pressure p_cont/A_r, and its friction heat is
// f·(p_cont/A_r)·V per unit of real area. The junction rides on the softer face's summits
// (a stationary source there) and sweeps over the other face at V.
double FilmPointReader::flash_rise(const Film& film, double gap, double scale, double contact_pressure,
                                   double sliding_speed) const {
  if (!film.sliding || !(contact_pressure > 0.0) || !(sliding_speed > 0.0)) return 0.0;
  const StatisticalContact::SummitContacts c = roughness_[std::size_t(film.number - 1)].varies()
                                                   ? model_.scaled_contact()->contacts(gap, scale)
                                                   : model_.contact()->contacts(gap);
  if (!(c.count > 0.0) || !(c.area_fraction > 0.0)) return 0.0;
  const double radius = std::sqrt(c.area_fraction / (std::numbers::pi * c.count));
  const double flux = friction_coefficient_ * contact_pressure / c.area_fraction * sliding_speed;
  FlashBody lower = flash_bodies_[std::size_t(film.lower)], upper = flash_bodies_[std::size_t(film.upper)];
  const bool lower_softer = yield_strength_[std::size_t(film.lower)] <= yield_strength_[std::size_t(film.upper)];
  (lower_softer ? upper : lower).speed = sliding_speed;
  return flash_temperature_rise(flux, radius, lower, upper);
}

// The node's balance of physics §15: generated = conducted to the faces + advected, so
// its advection is the generation less the conduction, with the conduction summed over
// the parts of a node on a relief's edge as the heat balance sums it.
std::vector<double> FilmPointReader::node_advection(const Film& film, const FilmTotals& totals) const {
  const FilmMesh& m = film.mesh;
  std::vector<double> out(std::size_t(m.node_count()), 0.0);
  if (!film.sliding) return out;
  const std::array<ComponentId, 2> sides{film.lower, film.upper};
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const int n = m.node(i, j);
      const double area = m.node_area(i);
      double generated = 0.0;
      if (!totals.contact_power.empty()) generated += friction_coefficient_ * totals.contact_power[std::size_t(n)];
      if (!totals.viscous_power.empty()) generated += totals.viscous_power[std::size_t(n)];
      const FilmGap& gap = gaps_[std::size_t(film.number - 1)];
      const double smooth = gap.smooth(i, j);
      const FaceRelief::NodeParts parts = gap.parts(i, j);
      const double sigma = roughness_[std::size_t(film.number - 1)].at_node(n).sigma;
      const double tf = model_.temperature_of(u_, film.temperature_row(n));
      double conducted = 0.0;
      for (std::size_t k = 0; k < 2; ++k) {
        const double body = model_.face_temperature(u_, sides[k], m.radius(i), j, nullptr);
        for (int part = 0; part < parts.count; ++part) {
          const double gap = average_gap(smooth + parts.relief[std::size_t(part)], sigma).value;
          conducted += area * parts.share[std::size_t(part)] * (tf - body) / model_.heat_path(gap, sides[k]);
        }
      }
      out[std::size_t(n)] = (generated - conducted) / area;
    }
  return out;
}

}  // namespace twb
