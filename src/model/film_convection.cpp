// The oil's heat carried by its flow (docs/physics.md section 15). Every Reynolds face
// flux Q carries oil from the node it leaves to the node it enters; the oil entering a
// node's control volume is warmed from its upstream temperature to the node's:
//
//     ρ c Σ_in |Q| (T_node − T_upstream)       (W, taken from the node's heat balance)
//
// the first-order upwind scheme in its advective form, which equals the divergence of
// ρ c Q T wherever the film conserves mass. The edge nodes' half volumes are volumes too:
// the Couette flow crosses them along the rim (ReynoldsOperator::edge_face), and the oil
// they take in across the rim (their net outflow) arrives at the supply's temperature (a
// fed bore) or the ambient; oil leaving across a rim takes its edge node's temperature
// away. The nodes of a fed groove hold the groove's mixed temperature
// at their radius, k T_carried + (1 − k) T_s, T_carried the flow-weighted temperature of
// the oil the lands deliver into them; the heat their own balance would have kept (the
// groove's share of the heating, less what its faces conduct) is the groove oil's.
//
// The upstream node of a face changes with the sign of Q: both ends' entries are assembled
// in every state (zero on the side the oil leaves), so that the Jacobian's pattern does not
// depend on the flow's direction.
#include <algorithm>
#include <string>

#include "model/convection_effect.h"

#include "model/assembly_totals.h"
#include "model/film_face_flows.h"
#include "twb/model/bearing_state.h"

namespace twb {

struct ConvectionEffect::Delivery {
  FaceFlow flow;
  double direction = 0;  // the oil entering the groove node is max(direction · Q, 0)
  Index upstream = -1;   // the land node's temperature column
};

ConvectionEffect::ConvectionEffect(ModelSetup& setup) : model_(setup.model) {
  const Scene& scene = model_.scene();
  const Lubricant& oil = scene.lubricant;
  // The Reynolds equation is incompressible: one density, the sump's, makes the mass flux.
  heat_capacity_ = oil.density_at(scene.operating.ambient) * oil.specific_heat;
  if (oil.supply && oil.supply->temperature) supply_rise_ = *oil.supply->temperature - scene.operating.ambient;
}

void ConvectionEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const {
  for (std::size_t f = 0; f < model_.films().size(); ++f) {
    const Film& film = model_.films()[f];
    if (film.pressure_offset >= 0 && film.temperature_offset >= 0) add_film(u, film, a, totals.film[f]);
  }
}

void ConvectionEffect::report(std::span<const double>, const AssemblyTotals& totals,
                              std::vector<ReportedValue>& out) const {
  for (std::size_t f = 0; f < model_.films().size(); ++f)
    if (model_.films()[f].sliding) out.push_back({std::string(kHeatCarried), totals.film[f].convected_heat});
}

void ConvectionEffect::add_film(std::span<const double> u, const Film& film, Assembler& a, FilmTotals& totals) const {
  const FilmMesh& m = film.mesh;
  const UnknownLayout& layout = model_.layout();
  const FilmFaceFlows flows(model_, film, u);
  const bool jac = a.wants_jacobian(), values = a.mode() == Assembler::Mode::values;
  const std::optional<OilSupply>& supply = model_.scene().lubricant.supply;
  // Oil entering across a rim: the supply's at a fed bore, else the sump's (the ambient).
  const double bore_rise = supply && supply->feeds_bore() ? supply_rise_ : 0.0;
  const int outer = m.radial_nodes() - 1;

  // A fed groove mixes per radius: group (groove, interior row).
  const int rows = m.radial_nodes() - 2;
  const bool fed = film.groove_pressure.has_value();
  const int count = fed ? model_.scene().washer.grooves->count : 0;
  const int pitch = fed ? m.circumferential_nodes() / count : 1;
  auto group = [&](int i, int j) { return std::size_t((j / pitch) * rows + (i - 1)); };
  std::vector<std::vector<Delivery>> delivered(std::size_t(count * rows));
  // An edge node's faces, for the oil its half volume takes in across the rim.
  struct RimFace {
    FaceFlow flow;
    double sign;
  };
  std::vector<std::vector<RimFace>> rim(std::size_t(2 * m.circumferential_nodes()));
  auto rim_index = [&](int i, int j) { return std::size_t((i == 0 ? 0 : m.circumferential_nodes()) + j); };

  // The oil entering a node's volume through a face is warmed from the other end's
  // temperature to the node's.
  auto carry = [&](const FaceFlow& flow) {
    const ReynoldsFace& f = flow.face;
    const double q = flow.flux.q;
    for (const auto [node, sign] : f.ends()) {
      const bool at_a = sign > 0;
      const int i = at_a ? f.ia : f.ib, j = at_a ? f.ja : f.jb;
      const int other = at_a ? f.b : f.a, oi = at_a ? f.ib : f.ia, oj = at_a ? f.jb : f.ja;
      const Index other_col = film.temperature_row(m.node(oi, oj));
      // The face's flux enters this node's volume where −sign·Q > 0.
      const double direction = -sign;
      if (flows.fed(node)) {
        if (flows.free(other)) delivered[group(i, j)].push_back({flow, direction, other_col});
        continue;
      }
      if (node < 0) rim[rim_index(i, j)].push_back({flow, sign});
      const Index row = film.temperature_row(m.node(i, j));
      const double s = layout.row_scale(row);
      const double inflow = std::max(direction * q, 0.0);
      const double lift = u[std::size_t(row)] - u[std::size_t(other_col)];
      a.add_residual(row, -s * heat_capacity_ * inflow * lift);
      if (values) totals.convected_heat += heat_capacity_ * inflow * lift;
      if (!jac) continue;
      const double dinflow_dq = direction * q > 0.0 ? direction : 0.0;
      flows.add_gradient(a, row, -s * heat_capacity_ * dinflow_dq * lift, flow);
      a.add_derivative(row, row, -s * heat_capacity_ * inflow);
      a.add_derivative(row, other_col, s * heat_capacity_ * inflow);
    }
  };
  flows.for_each(carry);
  flows.for_each_edge_face(carry);

  // An edge node's half volume takes in across the rim what its faces send out beyond what
  // they bring (its net outflow, where positive), at the rim's inlet temperature.
  for (const int i : {0, outer})
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const std::vector<RimFace>& faces = rim[rim_index(i, j)];
      double net = 0.0;
      for (const RimFace& f : faces) net += f.sign * f.flow.flux.q;
      const Index row = film.temperature_row(m.node(i, j));
      const double s = layout.row_scale(row);
      const double inflow = std::max(net, 0.0);
      const double lift = u[std::size_t(row)] - (i == 0 ? bore_rise : 0.0);
      a.add_residual(row, -s * heat_capacity_ * inflow * lift);
      if (values) totals.convected_heat += heat_capacity_ * inflow * lift;
      if (!jac) continue;
      for (const RimFace& f : faces) flows.add_gradient(a, row, net > 0.0 ? -s * heat_capacity_ * lift * f.sign : 0.0, f.flow);
      a.add_derivative(row, row, -s * heat_capacity_ * inflow);
    }
  if (!fed) return;

  std::vector<std::vector<int>> nodes(delivered.size());
  for (int i = 1; i < m.radial_nodes() - 1; ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j)
      if (film.fed_node(i, j)) nodes[group(i, j)].push_back(m.node(i, j));
  for (std::size_t g = 0; g < nodes.size(); ++g) {
    if (nodes[g].empty()) continue;
    const double r = m.radius(int(g) % rows + 1);
    const double fresh = kGrooveFreshShare * std::abs(model_.scene().operating.speed) * r / 2 * film.sigma * m.dr();
    add_groove_mixing(u, film, flows, nodes[g], delivered[g], fresh, a, totals);
  }
}

void ConvectionEffect::add_groove_mixing(std::span<const double> u, const Film& film, const FilmFaceFlows& flows,
                                         const std::vector<int>& nodes, const std::vector<Delivery>& delivered,
                                         double fresh, Assembler& a, FilmTotals& totals) const {
  const double k = model_.scene().lubricant.supply->carry_over;
  double carried = fresh, heat = fresh * supply_rise_;  // Σ inflow (m³/s), Σ inflow · T (m³/s · K)
  for (const Delivery& d : delivered) {
    const double inflow = std::max(d.direction * d.flow.flux.q, 0.0);
    carried += inflow;
    heat += inflow * u[std::size_t(d.upstream)];
  }
  const double mean = carried > 0.0 ? heat / carried : supply_rise_;
  const double mixed = k * mean + (1.0 - k) * supply_rise_;
  const UnknownLayout& layout = model_.layout();
  for (const int n : nodes) {
    const Index row = film.temperature_row(n);
    // What the node's balance held so far (heating less conduction) the groove's oil takes.
    if (a.mode() == Assembler::Mode::values) totals.convected_heat += a.residual_value(row) / layout.row_scale(row);
    a.set_residual(row, mixed - u[std::size_t(row)]);
    if (!a.wants_jacobian()) continue;
    a.scale_row(row, 0.0);
    a.add_derivative(row, row, -1.0);
    for (const Delivery& d : delivered) {
      const double inflow = std::max(d.direction * d.flow.flux.q, 0.0);
      const double dinflow_dq = d.direction * d.flow.flux.q > 0.0 ? d.direction : 0.0;
      const double dmixed_dinflow = carried > 0.0 ? k * (u[std::size_t(d.upstream)] - mean) / carried : 0.0;
      flows.add_gradient(a, row, dmixed_dinflow * dinflow_dq, d.flow);
      a.add_derivative(row, d.upstream, carried > 0.0 ? k * inflow / carried : 0.0);
    }
  }
}

}  // namespace twb
