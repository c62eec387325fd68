// A state carried from one mesh to another of the same scene (the start of a mesh
// sequence, study/steady_solver.cpp). Every field lives on an Nr × Nθ index grid spread
// uniformly over its annulus (docs/physics.md section 10), so a node of the target lies at the
// same fractions of radius span and turn on the source grid, and bilinear interpolation
// there is second-order accurate: the interpolated state differs from the target mesh's
// solution by about the source mesh's own discretization error, well inside Newton's
// basin. Pressures are interpolated with their edge zeros, so the target's edge-adjacent
// nodes see the boundary condition; a cavitated node (p = 0) next to a pressurized one
// takes a value in between, which the complementarity rows then settle.
#include <cmath>
#include <stdexcept>
#include <typeinfo>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "model/grid_map.h"
#include "twb/error_family.h"

namespace twb {

std::vector<double> BearingModel::interpolated_from(const BearingModel& source, std::span<const double> u) const {
  const auto& mine = layout_.blocks();
  const auto& theirs = source.layout().blocks();
  bool same_blocks = mine.size() == theirs.size() && films_.size() == source.films_.size() &&
                     components_.size() == source.components_.size();
  for (std::size_t b = 0; same_blocks && b < mine.size(); ++b) same_blocks = mine[b].name == theirs[b].name;
  // The effects pair up by position (carry_from below), those without unknowns too.
  same_blocks = same_blocks && effects_.size() == source.effects_.size();
  for (std::size_t k = 0; same_blocks && k < effects_.size(); ++k)
    same_blocks = typeid(*effects_[k]) == typeid(*source.effects_[k]);
  if (!same_blocks || Index(u.size()) != source.size())
    throw InternalError("interpolated_from: the source model has other unknowns (not the same scene)");

  // The unknowns are scaled (bearing_model.h); a model built for another load, tilt or
  // roughness has other scales, so values go through physical units.
  std::vector<double> out(size(), 0.0);
  const double clearance = source.sigma_ref_ / sigma_ref_, tilt = source.gamma_ref_ / gamma_ref_;
  const double pressure = source.p_ref_ / p_ref_;
  const double ambient_shift = source.scene_.operating.ambient - scene_.operating.ambient;
  const double* q = u.data() + source.rigid_offset_;
  out[rigid_offset_ + 0] = q[0] * clearance;
  out[rigid_offset_ + 1] = q[1] * tilt;
  out[rigid_offset_ + 2] = q[2] * tilt;
  out[rigid_offset_ + 3] = q[3] * clearance;

  for (std::size_t f = 0; f < films_.size(); ++f) {
    const Film& dst = films_[f];
    const Film& src = source.films_[f];
    const GridMap map{src.mesh.radial_nodes(), src.mesh.circumferential_nodes(), dst.mesh.radial_nodes(),
                      dst.mesh.circumferential_nodes()};
    // A field on the interior nodes (pressure, film content) with its edge value and
    // scale; `column` is the film's (Film::pressure_column, content_column).
    auto carry_interior = [&](Index (Film::*column)(int, int) const, double edge, double scale) {
      auto value = [&](int i, int j) {
        const Index k = (src.*column)(i, j);
        return k < 0 ? edge : scale * u[k];
      };
      for (int i = 1; i < map.dst_nr - 1; ++i)
        for (int j = 0; j < map.dst_nt; ++j) out[(dst.*column)(i, j)] = map.at(i, j, value);
    };
    if (dst.pressure_offset >= 0) carry_interior(&Film::pressure_column, 0.0, pressure);
    // The edges are flooded: full film there.
    if (dst.content_offset >= 0) carry_interior(&Film::content_column, 1.0, 1.0);
    if (dst.temperature_offset >= 0) {
      auto t = [&](int i, int j) { return u[src.temperature_row(src.mesh.node(i, j))] + ambient_shift; };
      for (int i = 0; i < map.dst_nr; ++i)
        for (int j = 0; j < map.dst_nt; ++j) out[dst.temperature_row(dst.mesh.node(i, j))] = map.at(i, j, t);
    }
  }

  for (std::size_t c = 0; c < components_.size(); ++c) {
    const ComponentHeat& dst = components_[c];
    const ComponentHeat& src = source.components_[c];
    const int snt = src.axisymmetric ? 1 : src.grid.circumferential_nodes();
    const int dnt = dst.axisymmetric ? 1 : dst.grid.circumferential_nodes();
    const GridMap map{src.grid.radial_nodes(), snt, dst.grid.radial_nodes(), dnt};
    auto t = [&](int i, int j) { return u[src.offset + Index(i) * snt + j] + ambient_shift; };
    for (int i = 0; i < map.dst_nr; ++i)
      for (int j = 0; j < dnt; ++j) out[dst.offset + Index(i) * dnt + j] = map.at(i, j, t);
  }
  // The effects' own unknowns (the same scene registers the same effects), then the
  // contact force's, in physical units.
  for (std::size_t k = 0; k < effects_.size(); ++k) effects_[k]->carry_from(source, *source.effects_[k], u, out);
  if (contact_force_unknown_ >= 0)
    out[contact_force_unknown_] =
        u[source.contact_force_unknown_] * source.contact_force_scale_ / contact_force_scale_;
  return out;
}

bool BearingModel::resolves_grooves_on(int radial_nodes, int circumferential_nodes) const {
  return !scene_.washer.grooves ||
         grooves_on_grid(*scene_.washer.grooves, {scene_.mesh.radial_nodes, scene_.mesh.circumferential_nodes},
                         {radial_nodes, circumferential_nodes});
}

std::unique_ptr<BearingModel> BearingModel::on_mesh(int radial_nodes, int circumferential_nodes) const {
  // The scene holds every parameter changed since construction except the load, the
  // viscosity scale (set_curve_parameter) and the deformation scale.
  Scene scene = scene_;
  scene.mesh.radial_nodes = radial_nodes;
  scene.mesh.circumferential_nodes = circumferential_nodes;
  if (scene.washer.grooves) {
    const std::optional<Grooves> g =
        grooves_on_grid(*scene.washer.grooves, {scene_.mesh.radial_nodes, scene_.mesh.circumferential_nodes},
                        {radial_nodes, circumferential_nodes});
    if (!g)
      throw InternalError(fmt::format("on_mesh: the grooves cannot lie on a grid of {} × {} nodes "
                                      "(resolves_grooves_on says which can hold them)",
                                      radial_nodes, circumferential_nodes));
    scene.washer.grooves = g;
  }
  auto model = std::make_unique<BearingModel>(scene, more_effects_);
  model->set_load(load_);
  if (viscosity_scale_ != 1.0) model->set_curve_parameter(CurveParameter::viscosity_scale, viscosity_scale_);
  model->set_deformation_scale(deformation_scale_);
  model->set_newton_form(newton_form());
  return model;
}

}  // namespace twb
