#include "model/film_face_flows.h"

#include <algorithm>
#include <cmath>

#include "physics/average_gap.h"
#include "physics/flow_factors.h"

namespace twb {

namespace {

// Poiseuille conductance φ·max(h, 0)³/(12 μ) at a face, and its slopes in h, T and σ.
struct Conductance {
  double g, dg_dh, dg_dt, dg_dsigma = 0.0;
};

// The gap the moving face carries across a circumferential face and its slopes in h, σ
// and the shear term ψ.
struct CarriedGap {
  double value, slope, by_sigma = 0.0, by_shear = 0.0;
};

}  // namespace

FilmFaceFlows::FilmFaceFlows(const BearingModel& model, const Film& film, std::span<const double> u)
    : model_(model),
      film_(film),
      u_(u),
      op_(film.mesh),
      gap_(model, u, film),
      roughness_(model, u, film),
      jfo_(film.content_offset >= 0) {
  const FilmMesh& m = film.mesh;
  // A node on a fed groove holds the supply's pressure, full of oil: like an edge node,
  // a boundary of the lands' flow (docs/physics.md section 14).
  if (film.groove_pressure) {
    fed_.assign(std::size_t(op_.interior_count()), 0);
    for (int i = 1; i < m.radial_nodes() - 1; ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) fed_[std::size_t(op_.interior_index(i, j))] = film.fed_node(i, j);
  }
  node_t_.resize(std::size_t(m.node_count()));
  for (int n = 0; n < m.node_count(); ++n) node_t_[std::size_t(n)] = model.apply(model.viscosity_temperature_form(film, n), u);
}

// An edge node holds its edge's pressure (ambient, or the supply's at a fed bore), a fed
// node the groove's.
double FilmFaceFlows::pressure(int k, int i) const {
  if (free(k)) return model_.pressure_scale() * u_[std::size_t(pressure_column(k))];
  return k >= 0 ? *film_.groove_pressure : film_.edge_pressure(i);
}

FaceFlow FilmFaceFlows::evaluate(const ReynoldsFace& f) const {
  const Scene& scene = model_.scene();
  const FilmMesh& m = film_.mesh;
  const double omega = scene.operating.speed;
  const bool factors = scene.effects.flow_factors;
  const int a_node = m.node(f.ia, f.ja), b_node = m.node(f.ib, f.jb);
  // Where the faces run in, σ and ψ at the midpoint from the two nodes' Rqs.
  const bool varies = factors && roughness_.varies();
  const PointRoughness rough = varies ? roughness_.between(a_node, b_node) : roughness_.uniform();
  const double sigma = varies ? rough.sigma : film_.sigma;

  auto conductance = [&](double h, double t_face) {
    const double hp = std::max(h, 0.0);
    const ValueSlope mu = model_.viscosity(t_face);
    ValueSlope phi{1.0, 0.0};
    double phi_by_sigma = 0.0;
    if (factors) {
      const ValueSlope fp = pressure_flow_factor(h / sigma);
      phi = {fp.value, fp.slope / sigma};
      phi_by_sigma = -fp.slope * h / (sigma * sigma);
    }
    const double g = phi.value * hp * hp * hp / (12.0 * mu.value);
    const double dg_dh = (phi.slope * hp * hp * hp + phi.value * 3.0 * hp * hp) / (12.0 * mu.value);
    return Conductance{g, dg_dh, -g * mu.slope / mu.value, phi_by_sigma * hp * hp * hp / (12.0 * mu.value)};
  };
  // The gap the moving surface drags across a circumferential face: h̄T + σ φs with flow
  // factors, h without (docs/physics.md section 3); its slope in h (and, where the faces
  // run in, in σ and in ψ = σ·w).
  auto carried_gap = [&](double h) {
    if (!factors) return CarriedGap{h, 1.0};
    const ValueSlope gap = average_gap(h, sigma);
    const ValueSlope phis = shear_flow_factor_Phi_s(h / sigma);
    if (!varies)
      return CarriedGap{gap.value + sigma * film_.shear_weight * phis.value,
                        gap.slope + film_.shear_weight * phis.slope};
    const double x = h / sigma;
    return CarriedGap{gap.value + rough.shear * phis.value, gap.slope + rough.shear / sigma * phis.slope,
                      average_gap_by_sigma(h, sigma) - rough.shear * phis.slope * x / sigma,
                      phis.value};
  };

  FaceFlow out;
  out.face = f;
  out.circumferential = f.kind == ReynoldsFace::Kind::circumferential;
  const double x = f.r * std::cos(f.theta), y = f.r * std::sin(f.theta);
  out.na = m.node(f.ia, f.ja);
  out.nb = m.node(f.ib, f.jb);
  // On a relief's edge each half of the face has its own gap (FilmGap::across): a radial
  // face's conductance is the halves' mean, a circumferential face's halves are weighed
  // by their integrals over r (∫dr/r for the conductance, ∫r dr for the gap the moving
  // face carries, i.e. the node's area shares).
  const FaceGap gap = gap_.across(f, out.na, out.nb, x, y);
  const FaceRelief::Halves relief = gap.relief;
  const double smooth = gap.smooth;
  const double h = smooth + relief.before;
  out.dh = film_.gap_gradient(x, y);
  const double t_face = 0.5 * (node_t_[std::size_t(out.na)] + node_t_[std::size_t(out.nb)]);
  Conductance g = conductance(h, t_face);
  CarriedGap carried = out.circumferential ? carried_gap(h) : CarriedGap{0.0, 0.0};
  if (relief.after != relief.before) {
    const double outer = gap.outer_share, inner = 1.0 - outer;
    const Conductance other = conductance(smooth + relief.after, t_face);
    g = {outer * g.g + inner * other.g, outer * g.dg_dh + inner * other.dg_dh, outer * g.dg_dt + inner * other.dg_dt,
         outer * g.dg_dsigma + inner * other.dg_dsigma};
    if (out.circumferential) {
      const CarriedGap moved = carried_gap(smooth + relief.after);
      carried = {inner * carried.value + outer * moved.value, inner * carried.slope + outer * moved.slope,
                 inner * carried.by_sigma + outer * moved.by_sigma, inner * carried.by_shear + outer * moved.by_shear};
    }
  }
  // Mass-conserving cavitation (docs/physics.md section 12): the Couette flux carries the
  // film content θ of its upwind node (θ = 1 on the flooded edges and grooves).
  out.upwind = ReynoldsOperator::upwind_node(f, omega);
  const double theta = out.circumferential ? content(out.upwind) : 1.0;
  out.flux = ReynoldsOperator::flux(f, omega, g.g, theta * carried.value, pressure(f.a, f.ia), pressure(f.b, f.ib));
  out.dq_dh = out.flux.dq_dg * g.dg_dh + out.flux.dq_dcarried * theta * carried.slope;
  out.dq_dt = out.flux.dq_dg * g.dg_dt * 0.5;
  out.dq_dtheta = out.flux.dq_dcarried * carried.value;
  if (varies) {
    const double by_sigma = out.flux.dq_dg * g.dg_dsigma + out.flux.dq_dcarried * theta * carried.by_sigma;
    const double by_shear = out.flux.dq_dcarried * theta * carried.by_shear;
    out.dq_drest = by_sigma * rough.sigma_by_rest + by_shear * rough.shear_by_rest;
    out.dq_dturn = by_sigma * rough.sigma_by_turn + by_shear * rough.shear_by_turn;
  }
  return out;
}

void FilmFaceFlows::add_gradient(Assembler& a, Index row, double c, const FaceFlow& flow) const {
  const std::array<Index, 3> rigid_cols = film_.rigid_columns();
  const double p_ref = model_.pressure_scale();
  for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[std::size_t(d)], c * flow.dq_dh * flow.dh[std::size_t(d)]);
  a.add_derivative(row, pressure_column(flow.face.a), c * flow.flux.dq_dpa * p_ref);
  a.add_derivative(row, pressure_column(flow.face.b), c * flow.flux.dq_dpb * p_ref);
  a.add_form(row, c * flow.dq_dt, model_.viscosity_temperature_form(film_, flow.na));
  a.add_form(row, c * flow.dq_dt, model_.viscosity_temperature_form(film_, flow.nb));
  a.add_form(row, c * flow.dq_dh * 0.5, model_.shape_form(film_, flow.na));
  a.add_form(row, c * flow.dq_dh * 0.5, model_.shape_form(film_, flow.nb));
  if (jfo_ && flow.circumferential) a.add_derivative(row, content_column(flow.upwind), c * flow.dq_dtheta);
  // The midpoint's Rqs are the mean of the two nodes'. Added whatever their values (a
  // radial face's are zero where its two pressures are equal, as in the structure pass),
  // so that every pass adds the same entries (nothing where the faces do not run in).
  for (const int n : {flow.na, flow.nb}) {
    roughness_.add_rest(a, row, 0.5 * c * flow.dq_drest, n);
    roughness_.add_turn(a, row, 0.5 * c * flow.dq_dturn, n);
  }
}

}  // namespace twb
