#include "model/bearing_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "model/assembly_totals.h"
#include "model/wear_effect.h"
#include "physics/asperity_contact.h"
#include "physics/contact_table_cache.h"
#include "twb/error_family.h"

namespace twb {

namespace {

double combined_sigma(const Component& a, const Component& b) {
  return std::hypot(a.roughness.rq, b.roughness.rq);
}

}  // namespace

BearingModel::BearingModel(const Scene& scene, std::vector<EffectMaker> more_effects)
    : scene_(scene), load_(scene.operating.load), more_effects_(std::move(more_effects)) {
  const Effects& fx = scene_.effects;
  const int nr = scene_.mesh.radial_nodes, nt = scene_.mesh.circumferential_nodes;
  const bool film1_slides = scene_.operating.sliding == SlidingFilm::carrier_washer;

  // Film 1 covers the washer annulus; film 2 the overlap of washer and gear (docs/physics.md 1).
  const auto [r2_in, r2_out] = film_radii(scene_, 2);
  if (!(r2_out > r2_in)) throw std::invalid_argument("washer and gear annuli do not overlap");

  Film f1{1, FilmMesh(scene_.washer.inner_radius, scene_.washer.outer_radius, nr, nt),
          ComponentId::carrier, ComponentId::washer};
  f1.clearance_unknown = 0;
  f1.sign = 1.0;
  f1.sliding = film1_slides;
  f1.sigma = combined_sigma(scene_.carrier, scene_.washer);
  Film f2{2, FilmMesh(r2_in, r2_out, nr, nt), ComponentId::washer, ComponentId::gear};
  f2.clearance_unknown = 3;
  f2.sign = -1.0;
  f2.imposed_tilt = scene_.gear.tilt;
  f2.sliding = !film1_slides;
  f2.sigma = combined_sigma(scene_.washer, scene_.gear);
  // Eq [3]: the moving surface is "1". In the load frame the carrier is fixed, so on
  // film 1 the washer moves; on film 2 the gear moves against the stuck washer.
  auto weight = [](double moving, double fixed) {
    const double s2 = moving * moving + fixed * fixed;
    return (moving * moving - fixed * fixed) / s2;
  };
  f1.shear_weight = weight(scene_.washer.roughness.rq, scene_.carrier.roughness.rq);
  f2.shear_weight = weight(scene_.gear.roughness.rq, scene_.washer.roughness.rq);
  if (const std::optional<Grooves>& g = scene_.washer.grooves) {
    Film& grooved = g->film == 1 ? f1 : f2;
    grooved.relief = FaceRelief(*g, grooved.mesh);
  }
  if (const std::optional<OilSupply>& supply = scene_.lubricant.supply) {
    Film& fed = film1_slides ? f1 : f2;
    if (supply->feeds_bore()) fed.inner_edge_pressure = supply->pressure;
    // The scene refused a supply into grooves that are not in the sliding film's face.
    if (supply->feeds_grooves()) {
      if (fed.relief.flat()) throw InternalError("BearingModel: oil supplied into grooves the sliding film lacks");
      fed.groove_pressure = supply->pressure;
    }
  }
  films_ = {f1, f2};

  // Reference scales (their values do not depend on the unknowns declared).
  build_contact();
  roelands_ = RoelandsViscosity{scene_.lubricant.mu_infinity, scene_.lubricant.g0, scene_.lubricant.s0};
  sigma_ref_ = films_[0].sigma;
  gamma_ref_ = scene_.gear.tilt > 0 ? scene_.gear.tilt : sigma_ref_ / scene_.washer.outer_radius;
  rigid_offset_ = layout_.add("rigid body (z_w, gamma_x, gamma_y, z_g)", BlockEffect::mechanics, 4);
  for (Film& f : films_) {
    f.rigid_offset = rigid_offset_;
    f.clearance_scale = sigma_ref_;
    f.tilt_scale = gamma_ref_;
  }
  p_ref_ = scene_.operating.load / sliding_film().mesh.area();

  // The effects declare their unknowns in the order they are registered.
  register_effects();
  if (const WearEffect* wear = effect<WearEffect>(); wear && wear->runs_in())
    scaled_contact_ = shared_scaled_contact(contact_key_, wear->run_in_sigma() / sliding_film().sigma);

  // The viscosity temperature's and the shapes' gradients: grids and unknowns only.
  viscosity_forms_.resize(films_.size());
  if (fx.thermal) {
    const std::vector<double> zero(layout_.size(), 0.0);
    for (const Film& f : films_) {
      auto& forms = viscosity_forms_[f.number - 1];
      forms.resize(f.mesh.node_count());
      for (int i = 0; i < nr; ++i)
        for (int j = 0; j < nt; ++j) viscosity_temperature(zero, f, i, j, &forms[f.mesh.node(i, j)]);
    }
  } else {
    for (const Film& f : films_) viscosity_forms_[f.number - 1].resize(f.mesh.node_count());
  }
  build_shape_forms();

  Assembler structure(layout_.size());
  assemble(cold_start(), structure, nullptr);
  pattern_ = structure.finish_structure(&slot_tape_);
  pattern_.prefers_nested_dissection = plate_.elastic();
}

const Film& BearingModel::sliding_film() const { return films_[0].sliding ? films_[0] : films_[1]; }

const ComponentHeat* BearingModel::component(ComponentId id) const {
  for (const auto& c : components_)
    if (c.id == id) return &c;
  return nullptr;
}

void BearingModel::set_load(double load) {
  if (!std::isfinite(load))
    throw std::invalid_argument(fmt::format("load must be a finite number of newtons, not {}", load));
  if (!(load > 0) && !(gear_stop() && load == 0.0))
    throw std::invalid_argument(gear_stop() ? "load must be zero or positive" : "load must be positive");
  load_ = load;
}

void BearingModel::set_speed(double speed) {
  // The sign is the sense of rotation (scenes give a non-negative speed; the model's
  // symmetry under reversal is a property test).
  if (!std::isfinite(speed))
    throw std::invalid_argument(fmt::format("speed must be a finite number of rad/s, not {}", speed));
  scene_.operating.speed = speed;
}

void BearingModel::build_contact() {
  if (!scene_.effects.asperity_contact) return;
  const Material& m1 = scene_.washer.material;
  const Material& m2 = scene_.carrier.material;
  const double e_eff = JacksonGreenAsperity::effective_modulus(m1.youngs_modulus, m1.poisson_ratio,
                                                               m2.youngs_modulus, m2.poisson_ratio);
  // The softer material yields first (docs/physics.md section 4).
  const Material& soft = (m1.yield_strength <= m2.yield_strength) ? m1 : m2;
  contact_key_ = {e_eff, soft.yield_strength, soft.poisson_ratio, scene_.asperities.summit_radius,
                  scene_.asperities.summit_density, scene_.asperities.summit_sigma};
  contact_ = shared_contact_table(contact_key_);
  contact_cutoff_ = contact_->cutoff_gap(1e-20);
}

double BearingModel::curve_parameter(CurveParameter p) const {
  switch (p) {
    case CurveParameter::speed: return scene_.operating.speed;
    case CurveParameter::friction_coefficient: return scene_.friction.coefficient;
    case CurveParameter::gear_tilt: return scene_.gear.tilt;
    case CurveParameter::ambient_temperature: return scene_.operating.ambient;
    case CurveParameter::viscosity_scale: return viscosity_scale_;
    case CurveParameter::roughness: return uniform_roughness_ ? *uniform_roughness_ : scene_.washer.roughness.rq;
  }
  return 0.0;
}

void BearingModel::set_curve_parameter(CurveParameter p, double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("a curve parameter must be finite");
  switch (p) {
    case CurveParameter::speed:
      // A curve in speed ends at rest: past it the sense of rotation, not the speed,
      // would change (a scene's speeds are non-negative).
      if (value < 0) throw std::invalid_argument("a speed curve ends at rest (0 rad/s)");
      set_speed(value);
      break;
    case CurveParameter::friction_coefficient:
      if (scene_.friction.law != FrictionLaw::constant)
        throw std::invalid_argument("the dry friction coefficient is a parameter of the constant friction law only");
      scene_.friction.coefficient = value;
      break;
    case CurveParameter::gear_tilt:
      // Film 2's imposed tilt (docs/physics.md section 1); the tilt scale stays.
      scene_.gear.tilt = value;
      films_[1].imposed_tilt = value;
      break;
    case CurveParameter::ambient_temperature:
      // Temperatures are unknowns relative to ambient; the viscosity scale stays.
      if (!(value > 0)) throw std::invalid_argument("the ambient temperature must be positive (K)");
      scene_.operating.ambient = value;
      break;
    case CurveParameter::viscosity_scale:
      // Roelands' μ∞ is a prefactor: scaling it scales μ(T) and leaves dlnμ/dT alone;
      // the viscosity scale of the unknowns stays.
      if (!(value > 0)) throw std::invalid_argument("the viscosity scale must be positive");
      viscosity_scale_ = value;
      roelands_.mu_infinity = value * scene_.lubricant.mu_infinity;
      break;
    case CurveParameter::roughness:
      // The films' σ and the summit population follow; the clearance scale σ_ref stays.
      if (!(value > 0)) throw std::invalid_argument("the roughness must be positive");
      // A face that runs in has its Rq from its worn depth: one value is not its roughness.
      if (scaled_contact_)
        throw std::invalid_argument("the roughness is not a curve parameter of faces that run in (surfaces.run_in_rq)");
      // Rebuilding the summit population costs; the fold curve sets the same value at
      // every evaluation.
      if (uniform_roughness_ == value) break;
      // Always from the scene's own surfaces, so that a value gives the same bearing
      // whatever values came before (rounding would otherwise accumulate).
      if (!uniform_roughness_) roughness_origin_ = {scene_.carrier, scene_.washer, scene_.gear, scene_.asperities};
      uniform_roughness_ = value;
      std::tie(scene_.carrier, scene_.washer, scene_.gear, scene_.asperities) = roughness_origin_;
      set_roughness(scene_, value);
      films_[0].sigma = combined_sigma(scene_.carrier, scene_.washer);
      films_[1].sigma = combined_sigma(scene_.washer, scene_.gear);
      // A fold curve's ∂/∂p visits p ± h and p at every corrector iteration: the tables
      // of those populations are kept (contact_table_cache.h).
      build_contact();
      break;
  }
}

double BearingModel::body_resistance(ComponentId id) const {
  return id == ComponentId::washer ? scene_.washer.thickness / (2.0 * scene_.washer.material.conductivity) : 0.0;
}

ValueSlope BearingModel::viscosity(double temperature) const {
  if (scene_.lubricant.viscosity_model == ViscosityModel::constant)
    return {viscosity_scale_ * scene_.lubricant.constant_viscosity, 0.0};
  return roelands_(temperature);
}

void BearingModel::viscosity(std::span<const double> temperature, std::span<ValueSlope> out) const {
  if (scene_.lubricant.viscosity_model == ViscosityModel::constant) {
    std::fill(out.begin(), out.end(), ValueSlope{viscosity_scale_ * scene_.lubricant.constant_viscosity, 0.0});
    return;
  }
  roelands_(temperature, out);
}

RigidPosition BearingModel::position(std::span<const double> u) const {
  const double* q = u.data() + rigid_offset_;
  return {q[0] * sigma_ref_, q[1] * gamma_ref_, q[2] * gamma_ref_, q[3] * sigma_ref_};
}

double BearingModel::pressure_at(std::span<const double> u, const Film& film, int i, int j) const {
  const Index k = film.pressure_column(i, j);
  return k >= 0 ? p_ref_ * u[k] : film.edge_pressure(i);
}

double BearingModel::content_at(std::span<const double> u, const Film& film, int i, int j) const {
  const Index k = film.content_column(i, j);
  return k >= 0 ? u[k] : 1.0;
}

double BearingModel::temperature_of(std::span<const double> u, Index k) const {
  return scene_.operating.ambient + u[k];
}

double BearingModel::face_temperature(std::span<const double> u, ComponentId id, double r, int j,
                                      LinearForm* form) const {
  const ComponentHeat* c = component(id);
  if (!c) return scene_.operating.ambient;
  const auto w = c->grid.radial_weights(r);
  const int nt = c->grid.circumferential_nodes();
  const Index k0 = c->offset + (c->axisymmetric ? w.i0 : Index(w.i0) * nt + c->grid.wrap(j));
  const Index k1 = c->offset + (c->axisymmetric ? w.i1 : Index(w.i1) * nt + c->grid.wrap(j));
  if (form) {
    form->add(k0, w.w0);
    form->add(k1, w.w1);
  }
  return scene_.operating.ambient + w.w0 * u[k0] + w.w1 * u[k1];
}

double BearingModel::apply(const LinearForm& form, std::span<const double> u) const {
  double t = scene_.operating.ambient;
  for (const auto& [k, c] : form.terms) t += c * u[k];
  return t;
}

double BearingModel::viscosity_temperature(std::span<const double> u, const Film& film, int i, int j,
                                           LinearForm* form) const {
  if (!scene_.effects.thermal) return scene_.operating.ambient;
  if (scene_.effects.viscosity_temperature == ViscosityTemperature::film_node) {
    const Index k = film.temperature_row(film.mesh.node(i, j));
    if (form) form->add(k, 1.0);
    return temperature_of(u, k);
  }
  // The paper's rule: the mean of the two bounding surfaces (docs/physics.md section 7).
  LinearForm lo, up;
  const double r = film.mesh.radius(i);
  const double t = 0.5 * (face_temperature(u, film.lower, r, j, &lo) + face_temperature(u, film.upper, r, j, &up));
  if (form) {
    for (auto [k, c] : lo.terms) form->add(k, 0.5 * c);
    for (auto [k, c] : up.terms) form->add(k, 0.5 * c);
  }
  return t;
}

SegregatedSystem::Blocks BearingModel::segregated_blocks() const {
  Blocks b;
  for (const UnknownBlock& block : layout_.blocks()) {
    std::vector<Index>* into = block.effect == BlockEffect::mechanics || block.effect == BlockEffect::elastic_washer
                                   ? &b.rigid
                               : block.effect == BlockEffect::hydrodynamics ? &b.pressure
                               : block.effect == BlockEffect::thermal || block.effect == BlockEffect::thermal_deformation ||
                                         block.effect == BlockEffect::asperity_contact || block.effect == BlockEffect::wear
                                   ? &b.temperature
                                                                 : nullptr;
    if (!into) throw InternalError(std::string("segregated_blocks: unknown block of effect ") + effect_name(block.effect));
    for (Index k = 0; k < block.size; ++k) into->push_back(block.offset + k);
  }
  return b;
}

std::array<double, 4> BearingModel::cold_start_rigid() const {
  const double h0 = scene_.solver.cold_start_film;
  const double gamma_y = 0.5 * scene_.gear.tilt;
  // Minimum of a plane c − a·x over an annulus is c − |a|·r_o.
  const double c1 = h0 * films_[0].sigma + std::abs(gamma_y) * films_[0].mesh.outer_radius();
  const double c2 = h0 * films_[1].sigma + std::abs(scene_.gear.tilt - gamma_y) * films_[1].mesh.outer_radius();
  return {c1 / sigma_ref_, 0.0, gamma_y / gamma_ref_, c2 / sigma_ref_};
}

std::vector<double> BearingModel::cold_start() const {
  std::vector<double> u(layout_.size(), 0.0);
  const std::array<double, 4> rigid = cold_start_rigid();
  std::copy(rigid.begin(), rigid.end(), u.begin() + rigid_offset_);
  // A full film everywhere (the cold start has no pressure, so no cavitation yet).
  for (const Film& f : films_)
    if (f.content_offset >= 0)
      std::fill(u.begin() + f.content_offset,
                u.begin() + f.content_offset + f.mesh.interior_count(), 1.0);
  return u;
}

void BearingModel::evaluate(std::span<const double> u, std::span<double> residual,
                            std::span<double> jacobian) const {
  // A pass that leaves the slot tape (sparse_assembly.h: a state that drops or brings
  // terms) leaves the tape of its own sequence for the next, kept once the pass is whole.
  SlotTape retaped;
  Assembler a(&pattern_, residual, jacobian, &slot_tape_, &retaped);
  assemble(u, a, nullptr);
  if (!jacobian.empty() && !a.on_tape()) slot_tape_ = std::move(retaped);
}

void BearingModel::evaluate_in_time(std::span<const double> u, std::span<const double> rate, double cj,
                                    std::span<double> residual, std::span<double> jacobian) const {
  SlotTape retaped;
  Assembler a(&pattern_, residual, jacobian, &rate_slot_tape_, &retaped);
  const StateRates rates{rate, cj, imposed_tilt_rate_};
  assemble(u, a, nullptr, &rates);
  if (!jacobian.empty() && !a.on_tape()) rate_slot_tape_ = std::move(retaped);
}

std::vector<char> BearingModel::rate_unknowns() const {
  std::vector<char> reads(std::size_t(size()), 0);
  for (const Film& f : films_)
    if (f.pressure_offset >= 0)
      for (const Index k : f.rigid_columns()) reads[std::size_t(k)] = 1;
  return reads;
}

double BearingModel::groove_supply_force() const {
  const Film& film = sliding_film();
  if (!film.groove_pressure) return 0.0;
  double area = 0.0;
  for (int i = 1; i < film.mesh.radial_nodes() - 1; ++i)
    for (int j = 0; j < film.mesh.circumferential_nodes(); ++j)
      if (film.fed_node(i, j)) area += film.mesh.node_area(i);
  return *film.groove_pressure * area;
}

double BearingModel::supply_lift_bound() const {
  double most = 0.0;
  for (const Film& film : films_) {
    const double pressure = std::max(film.inner_edge_pressure, film.groove_pressure.value_or(0.0));
    const double ri = film.mesh.inner_radius(), ro = film.mesh.outer_radius();
    most = std::max(most, pressure * std::numbers::pi * (ro * ro - ri * ri));
  }
  return most;
}

void BearingModel::assemble(std::span<const double> u, Assembler& a, AssemblyTotals* totals,
                            const StateRates* rates) const {
  AssemblyTotals local;
  AssemblyTotals& t = totals ? *totals : local;
  t.film.assign(films_.size(), FilmTotals{});
  for (const auto& effect : effects_)
    if (rates)
      effect->add_terms_in_time(u, *rates, a, t);
    else
      effect->add_terms(u, a, t);
  // The films' loads were added with their signs; only the external load remains: eq [37]
  // (−1 exactly where the load is the force scale).
  a.add_residual(rigid_offset_ + 3, -load_ / force_scale());
  if (gear_stop()) add_gear_stop(u, a, t);
  orient_rows(a);
  if (held_at_rest()) add_rest_rows(u, a, rates);
}

// Rows are assembled as "what pushes − what resists" (forces F1 − F2, heat gained −
// heat lost), whose derivatives in their own unknown are negative: a thicker film
// carries less, a hotter node loses more. Negating them makes every diagonal positive,
// so that u' = −F(u) is the stable physical relaxation (pseudo-transient continuation
// relies on it, and it is the sign of ρ c t dT/dt = gains − losses).
void BearingModel::orient_rows(Assembler& a) const {
  if (a.mode() != Assembler::Mode::values) return;
  for (const UnknownBlock& b : layout_.blocks()) {
    if (b.effect == BlockEffect::hydrodynamics) continue;  // complementarity rows already rise with p̂
    for (Index k = b.offset; k < b.offset + b.size; ++k) {
      a.set_residual(k, -a.residual_value(k));
      a.scale_row(k, -1.0);
    }
  }
}

}  // namespace twb
