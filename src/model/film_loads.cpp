// Loads a film puts on its bounding bodies, integrated over each cell of its polar
// grid: fluid and contact force with their moments (eqs [31]-[33]), friction and
// viscous torque (eq [39]), and the heat generated (eqs [19], [20]) spread onto the
// film nodes with the bilinear hats (docs/physics.md sections 3, 4, 6). This file holds
// the loop over cells, the scatter of each cell's sums into the rows and the boundary
// friction; the kernels that integrate over a cell are contact_cell.cpp and
// fluid_cell.cpp (film_load_pass.h).
//
// Contact, friction and shear vary steeply near the tight rim, within a fraction of a
// cell, so cells near contact use a high-order Gauss rule on the exact plane h(x, y)
// rather than nodal values times node areas.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "model/film_load_pass.h"
#include "physics/friction_law.h"

namespace twb {

CellRule::CellRule(const GaussRule& rule, const FilmMesh& mesh, const std::vector<double>& cos_node,
                   const std::vector<double>& sin_node)
    : rule_(rule), mesh_(mesh), cos_node_(cos_node), sin_node_(sin_node) {
  for (double t : rule.points) {
    cos_.push_back(std::cos(t * mesh.dtheta()));
    sin_.push_back(std::sin(t * mesh.dtheta()));
  }
}

namespace {

std::vector<double> at_node_angles(const FilmMesh& m, double (*f)(double)) {
  std::vector<double> v(std::size_t(m.circumferential_nodes() + 1));
  for (int j = 0; j <= m.circumferential_nodes(); ++j) v[std::size_t(j)] = f(m.angle(j));
  return v;
}

}  // namespace

FilmLoadPass::FilmLoadPass(const BearingModel& model, const FilmLoadRules& rules, std::span<const double> u,
                           const Film& film, const Assembler& a)
    : model(model),
      u(u),
      film(film),
      mesh(film.mesh),
      structural(a.mode() == Assembler::Mode::structure),
      jac(a.wants_jacobian()),
      hydro(film.pressure_offset >= 0),
      heat(film.sliding && model.scene().effects.thermal),
      contact(model.contact() != nullptr),
      plate(model.washer_plate().elastic()),
      omega(film.sliding ? model.scene().operating.speed : 0.0),
      cutoff(model.contact_cutoff()),
      gap(model, u, film),
      roughness(model, u, film),
      shaped(gap.shaped()),
      plane(gap.plane()),
      rigid_cols(film.rigid_columns()),
      g{film.gap_gradient(0.0, 1.0)[0], film.gap_gradient(0.0, 1.0)[1], film.gap_gradient(-1.0, 0.0)[2]},
      cos_node(at_node_angles(film.mesh, [](double t) { return std::cos(t); })),
      sin_node(at_node_angles(film.mesh, [](double t) { return std::sin(t); })),
      contact_rule(rules.contact, film.mesh, cos_node, sin_node),
      smooth_rule(rules.smooth, film.mesh, cos_node, sin_node),
      flat_rule(rules.flat_contact, film.mesh, cos_node, sin_node),
      flat_rule_is_cheaper(rules.flat_contact.points.size() < rules.contact.points.size()),
      force_row(film.sliding ? model.contact_force_unknown() : -1) {
  // The washer sees film 1 from below (+) and film 2 from above (−); the gear sees film 2 (+).
  const Index r0 = film.rigid_offset;
  const double f_ref = model.force_scale(), m_ref = f_ref * model.scene().washer.outer_radius;
  if (film.number == 1)
    rows = {{r0 + 0, 1.0 / f_ref, 0, 0}, {r0 + 1, 0, 1.0 / m_ref, 0}, {r0 + 2, 0, 0, 1.0 / m_ref}};
  else
    rows = {{r0 + 0, -1.0 / f_ref, 0, 0},
            {r0 + 1, 0, -1.0 / m_ref, 0},
            {r0 + 2, 0, 0, -1.0 / m_ref},
            {r0 + 3, 1.0 / f_ref, 0, 0}};
  const std::size_t smooth_points = smooth_rule.size() * smooth_rule.size();
  point_t.resize(smooth_points);
  point_h.resize(smooth_points);
  point_mu.resize(smooth_points);
  point_gap.resize(smooth_points);
  // Node viscosity temperatures, once per node.
  node_t.resize(std::size_t(mesh.node_count()));
  for (int n = 0; n < mesh.node_count(); ++n) node_t[std::size_t(n)] = model.apply(model.viscosity_temperature_form(film, n), u);
}

FilmCell FilmLoadPass::cell(int i, int j) const {
  FilmCell c;
  c.i = i;
  c.j = j;
  const std::array<int, 4> ci{i, i + 1, i, i + 1};
  const std::array<int, 4> cj{j, j, j + 1, j + 1};
  for (int k = 0; k < 4; ++k) {
    c.node[k] = mesh.node(ci[k], cj[k]);
    c.t_node[k] = node_t[std::size_t(c.node[k])];
    c.p_col[k] = film.pressure_column(ci[k], cj[k]);
    c.p_node[k] = c.p_col[k] >= 0 ? model.pressure_scale() * u[std::size_t(c.p_col[k])] : film.edge_pressure(ci[k]);
  }
  const double r0 = mesh.radius(i), r1 = mesh.radius(i + 1);
  const double t0 = mesh.angle(j), t1 = t0 + mesh.dtheta();
  const GapRange plane_range =
      contact ? plane.range(r0, r1, t0, t1, cos_node[j], sin_node[j], cos_node[j + 1], sin_node[j + 1]) : GapRange{};
  c.gap = gap.cell(i, j, c.node, plane_range);
  return c;
}

bool FilmLoadPass::near_contact(const FilmCell& cell) const {
  return contact && (structural || cell.gap.range.least < cutoff);
}

void FilmLoadPass::scatter(const FilmCell& cell, const CellLoads& l, Assembler& a) const {
  // The rigid-body rows.
  for (const RowSign& rs : rows) {
    const std::array<double, 3> coef{rs.force, rs.mx, rs.my};
    for (int qd = 0; qd < 3; ++qd) {
      if (coef[qd] == 0.0) continue;
      a.add_residual(rs.row, coef[qd] * l.load_val[qd]);
      if (!jac) continue;
      for (int d = 0; d < 3; ++d) a.add_derivative(rs.row, rigid_cols[d], coef[qd] * g[d] * l.load_rigid[qd][d]);
      for (int k = 0; k < 4; ++k) a.add_derivative(rs.row, cell.p_col[k], coef[qd] * l.load_p[qd][k]);
      if (shaped)
        for (int k = 0; k < 4; ++k)
          a.add_form(rs.row, coef[qd] * l.load_shape[qd][k], model.shape_form(film, cell.node[k]));
      add_roughness_slopes(cell, rs.row, coef[qd], l.load_rest[qd], l.load_turn[qd], a);
    }
  }
  // The sliding film's contact force into its own row (F_c/F_ref, add_terms).
  if (force_row >= 0) {
    const double ref = model.contact_force_scale();
    a.add_residual(force_row, l.contact_force / ref);
    if (jac) {
      for (int d = 0; d < 3; ++d) a.add_derivative(force_row, rigid_cols[d], g[d] * l.contact_rigid[d] / ref);
      for (int k = 0; k < 4; ++k) a.add_form(force_row, l.load_shape[0][k] / ref, model.shape_form(film, cell.node[k]));
      add_roughness_slopes(cell, force_row, 1.0 / ref, l.load_rest[0], l.load_turn[0], a);
    }
  }
  if (plate) load_plate(cell, l, a);
  // Viscous heat into the film-node rows (friction heat is added once f is known).
  if (!heat) return;
  for (int k = 0; k < 4; ++k) {
    const Index row = film.temperature_row(cell.node[k]);
    const double sc = model.layout().row_scale(film.temperature_row(cell.node[k]));
    a.add_residual(row, sc * l.vheat[k]);
    if (!jac) continue;
    for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], sc * g[d] * l.vheat_rigid[k][d]);
    for (int m = 0; m < 4; ++m)
      a.add_form(row, sc * l.vheat_t[k][m], model.viscosity_temperature_form(film, cell.node[m]));
    if (shaped)
      for (int m = 0; m < 4; ++m) a.add_form(row, sc * l.vheat_shape[k][m], model.shape_form(film, cell.node[m]));
    add_roughness_slopes(cell, row, sc, l.vheat_rest[k], l.vheat_turn[k], a);
  }
}

// A corner's force F_k = ∫ p·N_k dA enters the m row of each washer node its ring sits on,
// weighted as the deflection enters its gap (WasherPlate::shares): [E1]'s right side −F_a,
// in the row's scale F_ref.
void FilmLoadPass::load_plate(const FilmCell& cell, const CellLoads& l, Assembler& a) const {
  const WasherPlate& washer = model.washer_plate();
  const int nt = mesh.circumferential_nodes();
  for (int k = 0; k < 4; ++k) {
    const int ring = cell.node[k] / nt, j = cell.node[k] % nt;
    for (const WasherPlate::Share& share : washer.of(film, ring)) {
      const Index row = washer.moment + share.ring * washer.circumferential_nodes + j;
      const double c = -share.weight / washer.load_ref;
      a.add_residual(row, c * l.corner_force[k]);
      if (!jac) continue;
      for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], c * g[d] * l.corner_force_rigid[k][d]);
      for (int m = 0; m < 4; ++m) a.add_derivative(row, cell.p_col[m], c * l.corner_force_p[k][m]);
      for (int m = 0; m < 4; ++m) a.add_form(row, c * l.corner_force_shape[k][m], model.shape_form(film, cell.node[m]));
      add_roughness_slopes(cell, row, c, l.corner_force_rest[k], l.corner_force_turn[k], a);
    }
  }
}

void FilmLoadPass::add_roughness_slopes(const FilmCell& cell, Index row, double c, const std::array<double, 4>& by_rest,
                                        const std::array<double, 4>& by_turn, Assembler& a) const {
  if (!roughness.varies()) return;
  for (int m = 0; m < 4; ++m) {
    roughness.add_rest(a, row, c * by_rest[m], cell.node[m]);
    roughness.add_turn(a, row, c * by_turn[m], cell.node[m]);
  }
}

void FilmLoadPass::keep_power_slopes(const FilmCell& cell, const CellLoads& l, FilmTotals& tot) const {
  // Every cell's terms, zero or not, so that every pass adds the same entries in the
  // same order (the slot tape, sparse_assembly.h).
  if (!film.sliding || !contact) return;
  if (shaped)
    for (int n = 0; n < 4; ++n)
      for (int m = 0; m < 4; ++m) tot.contact_power_shape.push_back({cell.node[n], cell.node[m], l.power_shape[n][m]});
  if (!roughness.varies()) return;
  for (int n = 0; n < 4; ++n)
    for (int m = 0; m < 4; ++m) {
      const auto [rest, rest_slope] = roughness.rest_column(cell.node[m]);
      const auto [turn, turn_slope] = roughness.turn_column(cell.node[m]);
      tot.contact_power_depth.push_back({cell.node[n], rest, l.power_rest[n][m] * rest_slope});
      tot.contact_power_depth.push_back({cell.node[n], turn, l.power_turn[n][m] * turn_slope});
    }
}

// Boundary friction f·p_cont (docs/physics.md section 6). The empirical law [18] depends on
// the film's total contact force, so f couples every heat row to the rigid body.
void FilmLoadPass::friction(FilmTotals& tot, Assembler& a) const {
  const Scene& scene = model.scene();
  if (scene.friction.law == FrictionLaw::constant) {
    tot.friction_coefficient = scene.friction.coefficient;
    tot.friction_slope = 0.0;
  } else {
    // Where the gap has a part the law reads the contact-force unknown (equal to the
    // integral at a solution), so that its slope is one column of every heat row.
    const double contact_force =
        force_row >= 0 ? u[std::size_t(force_row)] * model.contact_force_scale() : tot.contact_force;
    const FrictionLawResult fr = empirical_friction(contact_force);
    tot.friction_coefficient = fr.coefficient;
    tot.friction_slope = fr.slope;
    tot.friction_clamped = fr.clamped;
  }
  for (double cp : tot.contact_power) tot.friction_heat += tot.friction_coefficient * cp;
  if (!heat) return;
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Index row = film.temperature_row(n);
    const double sc = model.layout().row_scale(film.temperature_row(n));
    a.add_residual(row, sc * tot.friction_coefficient * tot.contact_power[n]);
    if (!jac) continue;
    const double slope_rigid = force_row >= 0 ? 0.0 : tot.friction_slope;
    for (int d = 0; d < 3; ++d)
      a.add_derivative(row, rigid_cols[d],
                       sc * (tot.friction_coefficient * tot.contact_power_rigid[n][d] +
                             slope_rigid * tot.contact_power[n] * tot.contact_force_rigid[d]));
    if (force_row >= 0)
      a.add_derivative(row, force_row, sc * tot.friction_slope * model.contact_force_scale() * tot.contact_power[n]);
  }
  if (!jac) return;
  for (const ShapeTerm& term : tot.contact_power_shape)
    a.add_form(film.temperature_row(term.node),
               model.layout().row_scale(film.temperature_row(term.node)) * tot.friction_coefficient * term.coefficient,
               model.shape_form(film, term.corner));
  for (const DepthTerm& term : tot.contact_power_depth)
    a.add_derivative(film.temperature_row(term.node), term.column,
                     model.layout().row_scale(film.temperature_row(term.node)) * tot.friction_coefficient *
                         term.coefficient);
}

FilmLoadsEffect::FilmLoadsEffect(ModelSetup& setup)
    : model_(setup.model),
      rules_{GaussRule::legendre(4), GaussRule::legendre(setup.model.scene().mesh.contact_quadrature),
             GaussRule::legendre(std::min(setup.model.scene().mesh.flat_contact_quadrature,
                                          setup.model.scene().mesh.contact_quadrature))} {}

// The contact force's row is assembled as (what the state implies − the unknown) and
// negated with the others by orient_rows: F̂c − F_c(u)/F_ref, with +1 on the diagonal;
// the cells add what the state implies.
void FilmLoadsEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const {
  for (std::size_t f = 0; f < model_.films().size(); ++f) add_film(u, model_.films()[f], a, totals.film[f]);
  const Index force = model_.contact_force_unknown();
  if (force < 0) return;
  a.add_residual(force, -u[std::size_t(force)]);
  a.add_derivative(force, force, -1.0);
}

void FilmLoadsEffect::add_film(std::span<const double> u, const Film& film, Assembler& a, FilmTotals& tot) const {
  FilmLoadPass pass(model_, rules_, u, film, a);
  const FilmMesh& m = film.mesh;
  if (film.sliding) {
    tot.contact_power.assign(m.node_count(), 0.0);
    tot.contact_power_rigid.assign(m.node_count(), {0.0, 0.0, 0.0});
    tot.viscous_power.assign(m.node_count(), 0.0);
  }
  for (int i = 0; i < m.radial_nodes() - 1; ++i) {
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const FilmCell cell = pass.cell(i, j);
      CellLoads loads;
      if (pass.near_contact(cell)) pass.contact_on_cell(cell, loads, tot);
      pass.keep_power_slopes(cell, loads, tot);
      pass.fluid_on_cell(cell, loads, tot);
      pass.scatter(cell, loads, a);
      if (film.sliding)
        for (int k = 0; k < 4; ++k) tot.viscous_power[std::size_t(cell.node[k])] += loads.vheat[k];
    }
  }
  if (film.sliding) pass.friction(tot, a);
}

}  // namespace twb
