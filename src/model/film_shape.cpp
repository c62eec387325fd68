// Thermal deformation of the films (docs/physics.md section 11): carrier and gear faces
// displaced by their through-thickness expansion, the washer dished by the heat
// crossing it. Only the gaps change: the effect registers its shape as a part of the
// films' gap (gap_contribution.h), which every kernel reads through film_gap.h.
//
// A uniform part of the displacement is absorbed by the clearances z_w, z_g (the
// unknowns); the shape is what changes the physics.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/deformation_effect.h"

#include "model/bearing_model.h"
#include "physics/thermal_deformation.h"

namespace twb {

namespace {

// The carrier's and gear's face expansion and the washer's dishing as a part of the
// films' gap (gap_contribution.h).
class ThermalShape final : public GapContribution {
 public:
  std::string name() const override { return "thermal deformation"; }
  void add_node_forms(const BearingModel& model, const Film& film, double scale,
                      std::vector<LinearForm>& forms) const override;
};

void ThermalShape::add_node_forms(const BearingModel& model, const Film& film, double scale,
                                  std::vector<LinearForm>& forms) const {
  const Scene& scene = model.scene();
  const bool constrained = scene.effects.face_expansion == FaceExpansion::constrained;
  const std::vector<double> zero(std::size_t(model.layout().size()), 0.0);
  const double ri = scene.washer.inner_radius, ro = scene.washer.outer_radius;
  const WasherDishing& dishing = model.washer_dishing();
  const FilmMesh& m = film.mesh;
  for (int i = 0; i < m.radial_nodes(); ++i) {
    const double r = m.radius(i);
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      LinearForm& form = forms[std::size_t(m.node(i, j))];
      // A thick body's face moves towards the film by u = c_ν α t (T − T0)/2: the gap closes.
      for (const ComponentId side : {film.lower, film.upper}) {
        if (side == ComponentId::washer) continue;
        const Component& body = side == ComponentId::carrier ? scene.carrier : scene.gear;
        const double per_kelvin = face_expansion_per_kelvin(body.material.thermal_expansion, body.thickness,
                                                            body.material.poisson_ratio, constrained);
        LinearForm face;
        model.face_temperature(zero, side, r, j, &face);
        for (const auto& [k, w] : face.terms)
          if (w != 0.0) form.add(k, -scale * per_kelvin * w);
      }
      // The dished washer's mid-surface rises by w(r) towards film 2: film 1 (washer
      // above) opens by w, film 2 (washer below) closes by w.
      // A washer that bends as a plate takes its thermal curvature in its deflection
      // (docs/physics.md section 21), of which this dish is the uniform part.
      if (model.washer_plate().elastic()) continue;
      const double towards = film.upper == ComponentId::washer ? 1.0 : -1.0;
      form.add(dishing.unknown, scale * towards * dishing.curvature_ref * dishing_shape(r, ri, ro));
    }
  }
}

}  // namespace

// κ̂ = κ̄/curvature_ref is one unknown with its own row (the washer's mean through-
// thickness flux), so the curvature couples the films through one column, not a dense
// block.
DeformationEffect::DeformationEffect(ModelSetup& setup) : model_(setup.model) {
  const Scene& scene = setup.model.scene();
  if (!scene.effects.thermal) throw std::invalid_argument("thermal_deformation needs the thermal effect");
  setup.dishing.unknown = setup.layout.add("washer dishing curvature", BlockEffect::thermal_deformation, 1);
  // κ̂ = 1 lifts the washer's rim by σ_ref.
  setup.dishing.curvature_ref = setup.model.clearance_scale() /
                                dishing_shape(scene.washer.outer_radius, scene.washer.inner_radius,
                                              scene.washer.outer_radius);
  setup.gap_parts.push_back(std::make_unique<ThermalShape>());
}

// The row is assembled as (what the state implies − the unknown) and negated with the
// others by orient_rows: κ̂ − κ(u)/κ_ref, with +1 on the diagonal. What the state implies
// is added by the heat balance (the flux crossing the washer).
void DeformationEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals&) const {
  const Index dishing = model_.washer_dishing().unknown;
  a.add_residual(dishing, -u[std::size_t(dishing)]);
  a.add_derivative(dishing, dishing, -1.0);
}

void DeformationEffect::carry_from(const BearingModel& source, const EffectAssembler&, std::span<const double> u,
                                   std::span<double> out) const {
  const WasherDishing& dishing = model_.washer_dishing();
  out[std::size_t(dishing.unknown)] = source.dishing_curvature(u) / dishing.curvature_ref;
}

double BearingModel::dishing_curvature(std::span<const double> u) const {
  return deforms() ? dishing_.curvature_ref * u[std::size_t(dishing_.unknown)] : 0.0;
}

// κ̄ = α/K_w · q̄_w with q̄_w the washer's area-mean flux from its film-1 face to its
// film-2 face: half of what enters through film 1 minus half of what enters through
// film 2 (the antisymmetric part of the two faces' fluxes is what crosses the
// mid-plane), over the washer's area.
double BearingModel::dishing_row_weight(const Film& film) const {
  const double ri = scene_.washer.inner_radius, ro = scene_.washer.outer_radius;
  const double area = std::numbers::pi * (ro * ro - ri * ri);
  const Material& steel = scene_.washer.material;
  const double from_film_1 = film.upper == ComponentId::washer ? 1.0 : -1.0;
  return from_film_1 * dishing_curvature_per_flux(steel.thermal_expansion, steel.conductivity) /
         (2.0 * area * dishing_.curvature_ref);
}

}  // namespace twb
