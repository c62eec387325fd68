// Thermal deformation of the films (docs/physics.md section 11): carrier and gear faces
// displaced by their through-thickness expansion, the washer dished by the heat
// crossing it. Only the gaps change: every place that evaluates a film's gap adds the
// node values δ of shape_form (interpolated bilinearly inside a cell, linearly along a
// face) to the gap plane, and their forms to its gradient.
//
// A uniform part of the displacement is absorbed by the clearances z_w, z_g (the
// unknowns); the shape is what changes the physics.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/deformation_effect.h"

#include "model/bearing_model.h"
#include "model/film_gap.h"
#include "physics/thermal_deformation.h"

namespace twb {

// κ̂ = κ̄/curvature_ref is one unknown with its own row (the washer's mean through-
// thickness flux), so the curvature couples the films through one column, not a dense
// block. With the empirical friction law the sliding film's total contact force, which
// every δ moves, is one unknown too (F̂c = F_c/contact_force_ref), for the same reason.
DeformationEffect::DeformationEffect(ModelSetup& setup) : model_(setup.model) {
  const Scene& scene = setup.model.scene();
  if (!scene.effects.thermal) throw std::invalid_argument("thermal_deformation needs the thermal effect");
  ShapeUnknowns& shape = setup.shape;
  shape.dishing = setup.layout.add("washer dishing curvature", BlockEffect::thermal_deformation, 1);
  // Every δ moves the sliding film's contact force, which sets f in every heat row.
  if (scene.effects.asperity_contact && scene.friction.law == FrictionLaw::empirical)
    shape.contact_force = setup.layout.add("sliding film contact force", BlockEffect::thermal_deformation, 1);
  // κ̂ = 1 lifts the washer's rim by σ_ref; F̂c = 1 is the scene's load (fixed, unlike
  // the rigid rows' F_ext, so that the load enters no other row).
  shape.curvature_ref = setup.model.clearance_scale() /
                         dishing_shape(scene.washer.outer_radius, scene.washer.inner_radius, scene.washer.outer_radius);
  shape.contact_force_ref = scene.operating.load;
}

// Rows are assembled as (what the state implies − the unknown) and negated with the
// others by orient_rows: κ̂ − κ(u)/κ_ref, F̂c − F_c(u)/F_ref, with +1 on the diagonal.
// What the state implies is added by the heat balance (the flux crossing the washer)
// and the film loads (the contact force).
void DeformationEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals&) const {
  const ShapeUnknowns& shape = model_.shape_unknowns();
  a.add_residual(shape.dishing, -u[std::size_t(shape.dishing)]);
  a.add_derivative(shape.dishing, shape.dishing, -1.0);
  if (shape.contact_force < 0) return;
  a.add_residual(shape.contact_force, -u[std::size_t(shape.contact_force)]);
  a.add_derivative(shape.contact_force, shape.contact_force, -1.0);
}

void BearingModel::build_shape_forms() {
  shape_forms_.assign(films_.size(), {});
  for (const Film& film : films_) shape_forms_[std::size_t(film.number - 1)].resize(std::size_t(film.mesh.node_count()));
  if (!deforms()) return;
  const bool constrained = scene_.effects.face_expansion == FaceExpansion::constrained;
  const std::vector<double> zero(std::size_t(layout_.size()), 0.0);
  const double ri = scene_.washer.inner_radius, ro = scene_.washer.outer_radius;
  for (const Film& film : films_) {
    const FilmMesh& m = film.mesh;
    for (int i = 0; i < m.radial_nodes(); ++i) {
      const double r = m.radius(i);
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        LinearForm& form = shape_forms_[std::size_t(film.number - 1)][std::size_t(m.node(i, j))];
        // A thick body's face moves towards the film by u = c_ν α t (T − T0)/2: the gap closes.
        for (const ComponentId side : {film.lower, film.upper}) {
          if (side == ComponentId::washer) continue;
          const Component& body = side == ComponentId::carrier ? scene_.carrier : scene_.gear;
          const double per_kelvin = face_expansion_per_kelvin(body.material.thermal_expansion, body.thickness,
                                                              body.material.poisson_ratio, constrained);
          LinearForm face;
          face_temperature(zero, side, r, j, &face);
          for (const auto& [k, w] : face.terms)
            if (w != 0.0) form.add(k, -deformation_scale_ * per_kelvin * w);
        }
        // The dished washer's mid-surface rises by w(r) towards film 2: film 1 (washer
        // above) opens by w, film 2 (washer below) closes by w.
        const double towards = film.upper == ComponentId::washer ? 1.0 : -1.0;
        form.add(shape_.dishing, deformation_scale_ * towards * shape_.curvature_ref * dishing_shape(r, ri, ro));
      }
    }
  }
}

void BearingModel::set_deformation_scale(double s) {
  if (s == deformation_scale_) return;
  deformation_scale_ = s;
  // The same terms with other coefficients: the pattern and its slot tape still hold.
  build_shape_forms();
}

double BearingModel::shape_at(std::span<const double> u, const Film& film, int node) const {
  double delta = 0.0;
  for (const auto& [k, c] : shape_form(film, node).terms) delta += c * u[std::size_t(k)];
  return delta;
}

std::vector<double> BearingModel::node_shapes(std::span<const double> u, const Film& film) const {
  std::vector<double> delta(deforms() ? std::size_t(film.mesh.node_count()) : 0);
  for (std::size_t n = 0; n < delta.size(); ++n) delta[n] = shape_at(u, film, int(n));
  return delta;
}

double BearingModel::least_gap(std::span<const double> u, const Film& film) const {
  return NodeGaps(*this, u, film).least();
}

double BearingModel::dishing_curvature(std::span<const double> u) const {
  return deforms() ? shape_.curvature_ref * u[std::size_t(shape_.dishing)] : 0.0;
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
         (2.0 * area * shape_.curvature_ref);
}

}  // namespace twb
