// The modified Reynolds equation [1] on the sliding film (docs/physics.md section 3), finite
// volumes on the polar grid (second order), with the Reynolds cavitation condition as
// the complementarity p ≥ 0, w ≥ 0, p·w = 0 solved inside Newton through a
// semismooth function of the scaled pair (p̂, ŵ): Fischer–Burmeister or the minimum
// (CavitationRow, bearing_model.h). ReynoldsEffect (reynolds_effect.h) declares the
// unknowns and assembles the rows.
//
// w is the net volumetric outflow of a node's control volume: Couette outflow minus
// Poiseuille inflow. Where the film ruptures (p = 0, diverging gap) more oil leaves
// than enters, so w ≥ 0 there, and w = 0 wherever p > 0.
//
// The discretization itself (control volumes, faces, the face flux and which balances
// it enters) is ReynoldsOperator's; this file evaluates the face quantities of the
// bearing's film (conductance, carried gap) with their slopes in the unknowns and
// assembles the chain rule into the Jacobian.
#include <array>
#include <cmath>

#include "model/reynolds_effect.h"

#include "model/assembly_totals.h"
#include "model/reynolds_operator.h"
#include "physics/average_gap.h"
#include "physics/flow_factors.h"

namespace twb {

namespace {

// φ(a, b) and its partial derivatives: Fischer–Burmeister a + b − √(a² + b²) or
// min(a, b). At their kinks (FB at (0, 0), min where a = b) any element of the
// generalized Jacobian serves semismooth Newton.
struct Complementarity {
  double value, da, db;
};
Complementarity complementarity(CavitationRow row, double a, double b) {
  if (row == CavitationRow::minimum) return a <= b ? Complementarity{a, 1.0, 0.0} : Complementarity{b, 0.0, 1.0};
  const double n = std::hypot(a, b);
  if (n == 0.0) return {0.0, 1.0 - std::sqrt(0.5), 1.0 - std::sqrt(0.5)};
  return {a + b - n, 1.0 - a / n, 1.0 - b / n};
}

}  // namespace

ReynoldsEffect::ReynoldsEffect(ModelSetup& setup) : model_(setup.model) {
  const Scene& scene = model_.scene();
  for (Film& f : setup.films) {
    if (!f.sliding) continue;
    f.pressure_offset =
        setup.layout.add(fmt_film_block(f.number, "pressure"), BlockEffect::hydrodynamics, f.mesh.interior_count());
    // The mass-conserving model's second field (docs/physics.md section 12).
    if (scene.effects.cavitation == CavitationModel::jfo)
      f.content_offset = setup.layout.add(fmt_film_block(f.number, "film content"), BlockEffect::hydrodynamics,
                                          f.mesh.interior_count());
    // The Poiseuille diagonal of a uniform reference film: ŵ then reads like p̂.
    // Reference gap: the film's cold-start clearance, a thickness set by the geometry.
    // A σ-based one (3σ) makes smooth surfaces' flux terms 1e8 times the scale, so
    // rounding alone would exceed the solver tolerance.
    const ReynoldsOperator op(f.mesh);
    const double h_flow = model_.cold_start_rigid()[std::size_t(f.clearance_unknown)] * model_.clearance_scale();
    const double g = std::pow(h_flow, 3) / (12.0 * model_.viscosity(scene.operating.ambient).value);
    const double p_ref = model_.pressure_scale();
    flow_scale_.resize(std::size_t(op.interior_count()));
    for (int i = 1; i < f.mesh.radial_nodes() - 1; ++i) {
      const double diag =
          g * (op.radial_geometry(i - 1) + op.radial_geometry(i) + 2.0 * op.circumferential_geometry(i));
      for (int j = 0; j < f.mesh.circumferential_nodes(); ++j) flow_scale_[std::size_t(op.interior_index(i, j))] = p_ref * diag;
    }
  }
}

void ReynoldsEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const {
  for (std::size_t f = 0; f < model_.films().size(); ++f)
    if (model_.films()[f].pressure_offset >= 0) add_film(u, model_.films()[f], a, totals.film[f]);
}

void ReynoldsEffect::add_film(std::span<const double> u, const Film& film, Assembler& a, FilmTotals& totals) const {
  const BearingModel& model = model_;
  const Scene& scene = model.scene();
  const bool jac = a.wants_jacobian();
  const FilmMesh& m = film.mesh;
  const GapPlane plane = film.plane(model.position(u));
  const std::array<Index, 3> rigid_cols = film.rigid_columns();
  const double omega = scene.operating.speed;
  const bool factors = scene.effects.flow_factors;
  const double sigma = film.sigma;
  const double p_ref = model.pressure_scale();

  const ReynoldsOperator op(m);
  // A node on a fed groove holds the supply's pressure, full of oil: like an edge node,
  // a boundary of the lands' flow, whose own rows only say so (docs/physics.md section 14).
  std::vector<char> fed(std::size_t(op.interior_count()), 0);
  if (film.groove_pressure)
    for (int i = 1; i < m.radial_nodes() - 1; ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) fed[std::size_t(op.interior_index(i, j))] = film.fed_node(i, j);
  auto free = [&](int k) { return k >= 0 && !fed[std::size_t(k)]; };
  auto p_col = [&](int k) -> Index { return free(k) ? film.pressure_offset + k : -1; };
  // An edge node holds its edge's pressure (ambient, or the supply's at a fed bore).
  auto p_val = [&](int k, int i) {
    return free(k) ? p_ref * u[p_col(k)] : k >= 0 ? *film.groove_pressure : film.edge_pressure(i);
  };
  // Mass-conserving cavitation (docs/physics.md section 12): the Couette flux carries the film
  // content θ of its upwind node (θ = 1 on the flooded edges and grooves), and the flow
  // balances are rows of their own, the content's; the pressure rows state p̂ ≥ 0, 1 − θ ≥ 0.
  const bool jfo = film.content_offset >= 0;
  auto content_col = [&](int k) -> Index { return jfo && free(k) ? film.content_offset + k : -1; };
  auto content = [&](int k) { return jfo && free(k) ? u[content_col(k)] : 1.0; };
  auto balance_row = [&](int k) -> Index { return jfo ? content_col(k) : p_col(k); };
  // The flows the state reports (m³/s): out of the film at each radius, and out of the fed
  // grooves into it, from the very face fluxes of the balances.
  const bool report = a.mode() == Assembler::Mode::values;
  const int outer = m.radial_nodes() - 1;

  std::vector<double> node_t(m.node_count());
  for (int n = 0; n < m.node_count(); ++n) node_t[n] = model.apply(model.viscosity_temperature_form(film, n), u);
  const std::vector<double> delta = model.node_shapes(u, film);
  const bool deformed = !delta.empty();

  // Poiseuille conductance φ·max(h, 0)³/(12 μ) at a face, and its slopes in h and T.
  struct Conductance { double g, dg_dh, dg_dt; };
  auto conductance = [&](double h, double t_face) {
    const double hp = std::max(h, 0.0);
    const ValueSlope mu = model.viscosity(t_face);
    ValueSlope phi{1.0, 0.0};
    if (factors) {
      const ValueSlope f = pressure_flow_factor(h / sigma);
      phi = {f.value, f.slope / sigma};
    }
    const double g = phi.value * hp * hp * hp / (12.0 * mu.value);
    const double dg_dh = (phi.slope * hp * hp * hp + phi.value * 3.0 * hp * hp) / (12.0 * mu.value);
    return Conductance{g, dg_dh, -g * mu.slope / mu.value};
  };

  // The gap the moving surface drags across a circumferential face: h̄T + σ φs with flow
  // factors, h without (docs/physics.md section 3); its slope in h.
  auto carried_gap = [&](double h) {
    if (!factors) return ValueSlope{h, 1.0};
    const ValueSlope gap = average_gap(h, sigma);
    const ValueSlope phis = shear_flow_factor_Phi_s(h / sigma);
    return ValueSlope{gap.value + sigma * film.shear_weight * phis.value,
                      gap.slope + film.shear_weight * phis.slope};
  };

  // Each face flux Q (m³/s) from node A to node B with its gradient, by the chain rule:
  // the rigid unknowns through h at the face midpoint, the two pressures, and the two
  // node temperatures through μ at the mean of theirs. The operator owns the stencil,
  // the face geometry and which control volumes a flux leaves and enters.
  op.for_each_face([&](const ReynoldsFace& f) {
    const bool circumferential = f.kind == ReynoldsFace::Kind::circumferential;
    const double x = f.r * std::cos(f.theta), y = f.r * std::sin(f.theta);
    const Index na = m.node(f.ia, f.ja), nb = m.node(f.ib, f.jb);
    // A face lies midway between its two nodes: the shape is their mean there. A
    // circumferential face lies within one column of the relief; a radial face on a
    // relief's edge has half its length on either side, each with its own gap
    // (docs/physics.md section 14), so its conductance is the mean of the two.
    FaceRelief::Halves relief{0.0, 0.0};
    if (!film.relief.flat())
      relief = circumferential ? FaceRelief::Halves{film.relief.in_column(f.ja, 0.5), film.relief.in_column(f.ja, 0.5)}
                               : film.relief.node_halves(f.ja);
    const double smooth = plane.at(x, y) + (deformed ? 0.5 * (delta[na] + delta[nb]) : 0.0);
    const double h = smooth + relief.before;
    const std::array<double, 3> dh = film.gap_gradient(x, y);
    const double t_face = 0.5 * (node_t[na] + node_t[nb]);
    Conductance g = conductance(h, t_face);
    if (relief.after != relief.before) {
      const Conductance other = conductance(smooth + relief.after, t_face);
      g = {0.5 * (g.g + other.g), 0.5 * (g.dg_dh + other.dg_dh), 0.5 * (g.dg_dt + other.dg_dt)};
    }
    const ValueSlope carried = circumferential ? carried_gap(h) : ValueSlope{0.0, 0.0};
    const int upwind = ReynoldsOperator::upwind_node(f, omega);
    const double theta = circumferential ? content(upwind) : 1.0;
    const ReynoldsFaceFlux flow =
        ReynoldsOperator::flux(f, omega, g.g, theta * carried.value, p_val(f.a, f.ia), p_val(f.b, f.ib));
    const double dq_dh = flow.dq_dg * g.dg_dh + flow.dq_dcarried * theta * carried.slope;
    const double dq_dt = flow.dq_dg * g.dg_dt * 0.5;
    const double dq_dtheta = flow.dq_dcarried * carried.value;
    const Index ra = p_col(f.a), rb = p_col(f.b);
    if (report) {
      if (!circumferential && f.ia == 0) totals.inner_flow -= flow.q;
      if (!circumferential && f.ib == outer) totals.outer_flow += flow.q;
      for (const auto [node, sign] : f.ends())
        if (node >= 0 && fed[std::size_t(node)]) totals.groove_flow += sign * flow.q;
    }
    for (const auto [node, sign] : f.ends()) {
      const Index row = balance_row(node);
      if (row < 0) continue;
      a.add_residual(row, sign * flow.q);
      if (!jac) continue;
      for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], sign * dq_dh * dh[d]);
      a.add_derivative(row, ra, sign * flow.dq_dpa * p_ref);
      a.add_derivative(row, rb, sign * flow.dq_dpb * p_ref);
      a.add_form(row, sign * dq_dt, model.viscosity_temperature_form(film, na));
      a.add_form(row, sign * dq_dt, model.viscosity_temperature_form(film, nb));
      a.add_form(row, sign * dq_dh * 0.5, model.shape_form(film, na));
      a.add_form(row, sign * dq_dh * 0.5, model.shape_form(film, nb));
      if (jfo && circumferential) a.add_derivative(row, content_col(upwind), sign * dq_dtheta);
    }
  });

  // A fed node's rows: p̂ = p_s / p_ref, and θ = 1.
  for (int k = 0; k < op.interior_count(); ++k) {
    if (free(k)) continue;
    const Index row = film.pressure_offset + k;
    a.set_residual(row, u[row] - *film.groove_pressure / p_ref);
    a.add_derivative(row, row, 1.0);
    if (!jfo) continue;
    const Index theta_col = film.content_offset + k;
    a.set_residual(theta_col, u[theta_col] - 1.0);
    a.add_derivative(theta_col, theta_col, 1.0);
  }

  if (jfo) {
    // Content rows: the flow balance ŵ = w / its scale, which rises with the node's own
    // content (its Couette outflow) and pressure. Pressure rows: φ(p̂, 1 − θ).
    for (int k = 0; k < op.interior_count(); ++k) {
      if (!free(k)) continue;
      const Index row = p_col(k), theta_col = content_col(k);
      if (a.mode() == Assembler::Mode::values) {
        const double scale = flow_scale_[k];
        a.set_residual(theta_col, a.residual_value(theta_col) / scale);
        if (jac) a.scale_row(theta_col, 1.0 / scale);
      }
      const Complementarity phi =
          complementarity(model.cavitation_row(), u[row] - scene.effects.cavity_pressure / p_ref, 1.0 - u[theta_col]);
      a.add_residual(row, phi.value);
      if (!jac) continue;
      a.add_derivative(row, row, phi.da);
      a.add_derivative(row, theta_col, -phi.db);
    }
    return;
  }

  // Wrap each node's flow balance in the complementarity function (for a segregated
  // scheme, which projects p ≥ 0 itself, scale it alone).
  if (a.mode() != Assembler::Mode::values) return;
  for (int k = 0; k < op.interior_count(); ++k) {
    if (!free(k)) continue;
    const Index row = p_col(k);
    const double scale = flow_scale_[k];
    const double w_hat = a.residual_value(row) / scale;
    if (model.flow_balance_rows()) {
      a.set_residual(row, w_hat);
      if (!jac) continue;
      a.scale_row(row, 1.0 / scale);
      a.add_derivative(row, row, 0.0);  // the same entries in the same order: the slot tape holds
      continue;
    }
    const Complementarity phi = complementarity(model.cavitation_row(), u[row], w_hat);
    a.set_residual(row, phi.value);
    if (!jac) continue;
    a.scale_row(row, phi.db / scale);
    a.add_derivative(row, row, phi.da);
  }
}

}  // namespace twb
