// The modified Reynolds equation [1] on the sliding film (docs/physics.md section 3), finite
// volumes on the polar grid (second order), with the Reynolds cavitation condition as
// the complementarity p ≥ 0, w ≥ 0, p·w = 0 solved inside Newton through a
// semismooth function of the scaled pair (p̂, ŵ): Fischer–Burmeister or the minimum
// (CavitationRow, bearing_model.h). ReynoldsEffect (reynolds_effect.h) declares the
// unknowns and assembles the rows.
//
// w is the net volumetric outflow of a node's control volume: Couette outflow minus
// Poiseuille inflow. Where the film ruptures (p = 0, diverging gap) more oil leaves
// than enters, so w ≥ 0 there, and w = 0 wherever p > 0. In real time (a duty cycle)
// the balance is w plus the oil the control volume gains as its gap opens (add_squeeze).
//
// The discretization itself (control volumes, faces, the face flux and which balances
// it enters) is ReynoldsOperator's, the face fluxes of the bearing's film with their
// slopes in the unknowns FilmFaceFlows'; this file assembles them into the balances.
#include <array>
#include <cmath>

#include "model/reynolds_effect.h"

#include "model/assembly_totals.h"
#include "model/complementarity.h"
#include "model/film_face_flows.h"
#include "physics/average_gap.h"
#include "twb/error_family.h"

namespace twb {

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
    if (model_.films()[f].pressure_offset >= 0) add_film(u, nullptr, model_.films()[f], a, totals.film[f]);
}

void ReynoldsEffect::add_terms_in_time(std::span<const double> u, const StateRates& rates, Assembler& a,
                                       AssemblyTotals& totals) const {
  for (std::size_t f = 0; f < model_.films().size(); ++f)
    if (model_.films()[f].pressure_offset >= 0) add_film(u, &rates, model_.films()[f], a, totals.film[f]);
}

// The oil a control volume gains as its gap opens, ∫ ∂h̄T/∂t dA over it, joins its
// outflow: w + squeeze = 0 where the film is full (docs/physics.md section 19). The
// content is the average gap h̄T with flow factors and the nominal gap without (what the
// Couette term carries but its shear flow factor's part, a flux, not oil held in the
// gap); ∂h/∂t is the gap plane's rate in the rigid unknowns' rates, and on film 2 the
// imposed tilt's (the shape's rate, thermal deformation's, is not in it: physics §19;
// nor the elastic washer's deflection's, quasi-static in real time: physics §21).
// Each part of a control volume on a relief's edge has its own gap. Its entries are the
// node's rigid columns and shape form, which every face flux of the node already brings
// into the pattern (FilmFaceFlows::add_gradient): the structure pass needs none of its
// own, and the steady passes keep the structure pass's slot tape.
void ReynoldsEffect::add_squeeze(const StateRates& rates, const Film& film,
                                 const FilmFaceFlows& flows, Assembler& a) const {
  const BearingModel& model = model_;
  const FilmMesh& m = film.mesh;
  const ReynoldsOperator& op = flows.grid();
  const bool factors = model.scene().effects.flow_factors;
  const bool jac = a.wants_jacobian();
  const FilmGap& gap = flows.gap();
  const FilmRoughness& roughness = flows.roughness();
  const std::array<Index, 3> cols = film.rigid_columns();
  const double tilt_rate = film.upper == ComponentId::gear ? rates.imposed_tilt_rate : 0.0;
  for (int i = 1; i < m.radial_nodes() - 1; ++i) {
    const double r = m.radius(i);
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const int k = op.interior_index(i, j);
      const Index row = flows.pressure_column(k);
      if (row < 0) continue;
      const double x = r * std::cos(m.angle(j)), y = r * std::sin(m.angle(j));
      const std::array<double, 3> dh = film.gap_gradient(x, y);
      double h_rate = -tilt_rate * x;
      for (std::size_t d = 0; d < 3; ++d) h_rate += dh[d] * rates.rate[std::size_t(cols[d])];
      const int node = m.node(i, j);
      const double h = gap.smooth_on_plane(node, x, y);
      const FaceRelief::NodeParts parts = gap.parts(i, j);
      // σ the node's where the faces run in (film_roughness.h), with the content's slope's
      // own slope in it.
      const PointRoughness rough = roughness.at_node(node);
      double slope = 0.0, curvature = 0.0, slope_by_sigma = 0.0;
      for (int p = 0; p < parts.count; ++p) {
        const double part_h = h + parts.relief[std::size_t(p)], share = parts.share[std::size_t(p)];
        slope += share * (factors ? average_gap(part_h, rough.sigma).slope : 1.0);
        if (!factors) continue;
        curvature += share * average_gap_curvature(part_h, rough.sigma);
        if (roughness.varies()) slope_by_sigma += share * average_gap_slope_by_sigma(part_h, rough.sigma);
      }
      const double area = m.node_area(i);  // the control volume's, r_i·Δr·Δθ
      a.add_residual(row, area * slope * h_rate);
      if (!jac) continue;
      for (std::size_t d = 0; d < 3; ++d)
        a.add_derivative(row, cols[d], area * dh[d] * (curvature * h_rate + slope * rates.cj));
      a.add_form(row, area * curvature * h_rate, model.shape_form(film, node));
      roughness.add_rest(a, row, area * h_rate * slope_by_sigma * rough.sigma_by_rest, node);
      roughness.add_turn(a, row, area * h_rate * slope_by_sigma * rough.sigma_by_turn, node);
    }
  }
}

void ReynoldsEffect::add_film(std::span<const double> u, const StateRates* rates, const Film& film, Assembler& a,
                              FilmTotals& totals) const {
  const BearingModel& model = model_;
  const Scene& scene = model.scene();
  const bool jac = a.wants_jacobian();
  const FilmMesh& m = film.mesh;
  const double p_ref = model.pressure_scale();
  const FilmFaceFlows flows(model, film, u);
  const ReynoldsOperator& op = flows.grid();
  auto free = [&](int k) { return flows.free(k); };
  auto p_col = [&](int k) -> Index { return flows.pressure_column(k); };
  // Mass-conserving cavitation (docs/physics.md section 12): the flow balances are rows of
  // their own, the content's; the pressure rows state p̂ ≥ 0, 1 − θ ≥ 0.
  const bool jfo = film.content_offset >= 0;
  auto content_col = [&](int k) -> Index { return flows.content_column(k); };
  auto balance_row = [&](int k) -> Index { return jfo ? content_col(k) : p_col(k); };
  // The flows the state reports (m³/s): out of the film at each radius, and out of the fed
  // grooves into it, from the very face fluxes of the balances.
  const bool report = a.mode() == Assembler::Mode::values;
  const int outer = m.radial_nodes() - 1;

  // Each free node's outflow slope in its own pressure (w per p̂), for Newton's form below.
  const bool newton_form = model.cavitation_row() == CavitationRow::minimum && !jfo && !model.flow_balance_rows();
  std::vector<double> own_slope(newton_form ? std::size_t(op.interior_count()) : 0, 0.0);
  // Each face flux Q (m³/s) from node A to node B leaves A's balance and enters B's;
  // the operator owns the stencil and which control volumes a flux joins.
  flows.for_each([&](const FaceFlow& flow) {
    const ReynoldsFace& f = flow.face;
    if (newton_form)
      for (const auto [node, sign] : f.ends())
        if (node >= 0 && free(node))
          own_slope[std::size_t(node)] += sign * (node == f.a ? flow.flux.dq_dpa : flow.flux.dq_dpb) * p_ref;
    if (report) {
      if (!flow.circumferential && f.ia == 0) totals.inner_flow -= flow.flux.q;
      if (!flow.circumferential && f.ib == outer) totals.outer_flow += flow.flux.q;
      for (const auto [node, sign] : f.ends())
        if (flows.fed(node)) totals.groove_flow += sign * flow.flux.q;
    }
    for (const auto [node, sign] : f.ends()) {
      const Index row = balance_row(node);
      if (row < 0) continue;
      a.add_residual(row, sign * flow.flux.q);
      if (jac) flows.add_gradient(a, row, sign, flow);
    }
  });

  if (rates) {
    // The content's own rate, θ̇·h̄T, would make θ a differential unknown pinned at 1
    // wherever the film is full: a DAE of index two, which the duty cycle refuses.
    if (jfo) throw InternalError("the film's squeeze with mass-conserving cavitation is not solved");
    add_squeeze(*rates, film, flows, a);
  }

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
  for (int k = 0; k < op.interior_count(); ++k) {
    if (!free(k)) continue;
    const Index row = p_col(k);
    if (a.mode() != Assembler::Mode::values) {
      a.add_derivative(row, row, 0.0);  // where the values' passes add it: the structure's slot tape holds
      continue;
    }
    const double scale = flow_scale_[k];
    const double w_hat = a.residual_value(row) / scale;
    if (model.flow_balance_rows()) {
      a.set_residual(row, w_hat);
      if (!jac) continue;
      a.scale_row(row, 1.0 / scale);
      a.add_derivative(row, row, 0.0);  // the same entries in the same order: the slot tape holds
      continue;
    }
    // Newton's form min(λ·p̂, ŵ), λ the node's own slope of ŵ where above 1 (docs/physics.md
    // section 3): ŵ's scale, from the cold-start gap and the ambient's viscosity, makes that
    // slope (h/h_ref)³·μ_ref/μ, some 500 where a lightly loaded washer has lifted, and
    // min(p̂, ŵ) then has its kink within 1/500 of a full node's pressure from the root;
    // IDA's Newton, its Jacobian from an earlier step, jumped across it step after step.
    // Same roots; |min(p̂, ŵ)| ≤ |min(λ·p̂, ŵ)| for λ ≥ 1, so the form's tolerance ratio
    // holds. λ's own slope is left out of the Jacobian: exact at the roots, where the rows
    // reading λ·p̂ have p̂ = 0.
    const double slope = newton_form ? own_slope[std::size_t(k)] / scale : 1.0;
    const double lambda = slope > 1.0 || std::isnan(slope) ? slope : 1.0;  // a NaN shows in the row, not as 1
    const Complementarity phi = complementarity(model.cavitation_row(), lambda * u[row], w_hat);
    a.set_residual(row, phi.value);
    if (!jac) continue;
    a.scale_row(row, phi.db / scale);
    a.add_derivative(row, row, phi.da * lambda);
  }
}

}  // namespace twb
