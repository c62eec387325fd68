// Heat balance of carrier, washer and gear with zero-capacity film nodes (docs/physics.md
// section 7). Every row says: heat in − heat out = 0 (W), scaled by a reference
// conductance so that its value reads in kelvin.
//
// Heat leaves a film node towards each bounding component through
// R = h̄T/(2 K_oil) + r_body (eqs [26], [27]; the average gap keeps R positive where the
// nominal film closes). A face temperature on a component's grid is a linear
// interpolation in r; the heat it receives is spread with the same weights, so the
// exchange between grids is conservative.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "assembly_totals.h"
#include "physics/average_gap.h"

namespace twb {

void BearingModel::build_heat_nodes() {
  const std::vector<double> zero(std::size_t(layout_.size()), 0.0);
  heat_nodes_.assign(films_.size(), {});
  for (const Film& film : films_) {
    const FilmMesh& m = film.mesh;
    auto& nodes = heat_nodes_[std::size_t(film.number - 1)];
    nodes.resize(std::size_t(m.node_count()));
    for (int i = 0; i < m.radial_nodes(); ++i) {
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        HeatNode& node = nodes[std::size_t(m.node(i, j))];
        const double r = m.radius(i), th = m.angle(j);
        node.x = r * std::cos(th);
        node.y = r * std::sin(th);
        const std::array<ComponentId, 2> sides{film.lower, film.upper};
        for (std::size_t side = 0; side < 2; ++side) {
          LinearForm face;
          face_temperature(zero, sides[side], r, j, &face);
          FaceLink& link = node.face[side];
          for (const auto& [k, w] : face.terms) {
            for (std::size_t c = 0; c < components_.size(); ++c) {
              const ComponentHeat& comp = components_[c];
              if (k < comp.offset || k >= comp.offset + comp.node_count()) continue;
              link.column[std::size_t(link.terms)] = k;
              link.weight[std::size_t(link.terms)] = w;
              link.row_scale[std::size_t(link.terms)] = component_row_scale_[c][std::size_t(k - comp.offset)];
              ++link.terms;
            }
          }
        }
      }
    }
  }
}

void BearingModel::assemble_heat(std::span<const double> u, Assembler& a, const Totals&) const {
  const bool jac = a.wants_jacobian();
  const double k_oil = scene_.lubricant.conductivity;
  const double ambient = scene_.operating.ambient;
  const RigidPosition q = position(u);

  // Film nodes and their exchange with the bounding components.
  for (const Film& film : films_) {
    const FilmMesh& m = film.mesh;
    const std::array<Index, 3> rigid_cols = film.rigid_columns();
    const std::array<ComponentId, 2> sides{film.lower, film.upper};
    for (int i = 0; i < m.radial_nodes(); ++i) {
      const double area = m.node_area(i);
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const int n = m.node(i, j);
        const HeatNode& node = heat_nodes_[std::size_t(film.number - 1)][std::size_t(n)];
        const Index row = film.temperature_row(n);
        const double scale = film_row_scale_[film.number - 1][n];
        const double x = node.x, y = node.y;
        const double h = film.node_gap(q, x, y) + (deforms() ? shape_at(u, film, n) : 0.0);
        const std::array<double, 3> dh = film.gap_gradient(x, y);
        const LinearForm& shape = shape_form(film, n);
        const ValueSlope gap = average_gap(h, film.sigma);
        const double tf = temperature_of(u, row);

        for (std::size_t side = 0; side < 2; ++side) {
          const FaceLink& face = node.face[side];
          double ts = ambient;
          for (int t = 0; t < face.terms; ++t) ts += face.weight[std::size_t(t)] * u[face.column[std::size_t(t)]];
          const double res = gap.value / (2.0 * k_oil) + body_resistance(sides[side]);
          const double flow = area * (tf - ts) / res;  // W from the film node into the component
          const double dflow_dh = -flow / res * gap.slope / (2.0 * k_oil);
          const double conductance = area / res;
          a.add_residual(row, -scale * flow);
          if (jac) {
            a.add_derivative(row, row, -scale * conductance);
            for (int t = 0; t < face.terms; ++t)
              a.add_derivative(row, face.column[std::size_t(t)], scale * conductance * face.weight[std::size_t(t)]);
            for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], -scale * dflow_dh * dh[d]);
            a.add_form(row, -scale * dflow_dh, shape);
          }
          // The heat crossing the washer dishes it (docs/physics.md section 11, film_shape.cpp).
          if (deforms() && sides[side] == ComponentId::washer) {
            const double cw = dishing_row_weight(film);
            a.add_residual(dishing_offset_, cw * flow);
            if (jac) {
              a.add_derivative(dishing_offset_, row, cw * conductance);
              for (int t = 0; t < face.terms; ++t)
                a.add_derivative(dishing_offset_, face.column[std::size_t(t)],
                                 -cw * conductance * face.weight[std::size_t(t)]);
              for (int d = 0; d < 3; ++d) a.add_derivative(dishing_offset_, rigid_cols[d], cw * dflow_dh * dh[d]);
              a.add_form(dishing_offset_, cw * dflow_dh, shape);
            }
          }
          for (int t = 0; t < face.terms; ++t) {
            const Index k = face.column[std::size_t(t)];
            const double cw = face.row_scale[std::size_t(t)] * face.weight[std::size_t(t)];
            a.add_residual(k, cw * flow);
            if (!jac) continue;
            a.add_derivative(k, row, cw * conductance);
            for (int t2 = 0; t2 < face.terms; ++t2)
              a.add_derivative(k, face.column[std::size_t(t2)], -cw * conductance * face.weight[std::size_t(t2)]);
            for (int d = 0; d < 3; ++d) a.add_derivative(k, rigid_cols[d], cw * dflow_dh * dh[d]);
            a.add_form(k, cw * dflow_dh, shape);
          }
        }
      }
    }
  }

  // In-plane conduction of each component (eq [21]) and, for carrier and gear, 1-D
  // conduction across the thickness to the ambient (eqs [25], [28]).
  for (std::size_t c = 0; c < components_.size(); ++c) {
    const ComponentHeat& comp = components_[c];
    const FilmMesh& g = comp.grid;
    const double kt = comp.conductivity * comp.thickness;
    const int nr = g.radial_nodes(), nt = comp.axisymmetric ? 1 : g.circumferential_nodes();
    auto index = [&](int i, int j) -> Index { return comp.axisymmetric ? i : Index(i) * g.circumferential_nodes() + g.wrap(j); };
    auto conduct = [&](Index la, Index lb, double conductance) {
      const Index ka = comp.offset + la, kb = comp.offset + lb;
      const double flow = conductance * (u[ka] - u[kb]);  // W from a to b
      const double sa = component_row_scale_[c][la], sb = component_row_scale_[c][lb];
      a.add_residual(ka, -sa * flow);
      a.add_residual(kb, sb * flow);
      if (!jac) return;
      a.add_derivative(ka, ka, -sa * conductance);
      a.add_derivative(ka, kb, sa * conductance);
      a.add_derivative(kb, ka, sb * conductance);
      a.add_derivative(kb, kb, -sb * conductance);
    };
    const double ring = comp.axisymmetric ? 2.0 * std::numbers::pi : g.dtheta();
    for (int i = 0; i < nr; ++i) {
      for (int j = 0; j < nt; ++j) {
        if (i + 1 < nr) conduct(index(i, j), index(i + 1, j), kt * (g.radius(i) + 0.5 * g.dr()) * ring / g.dr());
        if (!comp.axisymmetric) {
          const double width = (i == 0 || i == nr - 1) ? 0.5 * g.dr() : g.dr();
          conduct(index(i, j), index(i, j + 1), kt * width / (g.radius(i) * g.dtheta()));
        }
        if (comp.loses_to_ambient) {
          const Index k = comp.offset + index(i, j);
          const double gamb = comp.node_area(i) * comp.conductivity / comp.thickness;
          const double s = component_row_scale_[c][index(i, j)];
          a.add_residual(k, -s * gamb * u[k]);
          if (jac) a.add_derivative(k, k, -s * gamb);
        }
      }
    }
  }
}

// A body's hottest face (docs/physics.md section 8, material temperature): the face
// temperature at a film node lies on the heat path between the film node and the body's
// own node, body_resistance/R of the way from the body's; the carrier's and gear's faces
// are their nodes (no resistance on their side), the washer's lie half its thickness
// nearer the film than its mid-plane.
double BearingModel::hottest_face_temperature(std::span<const double> u, ComponentId id) const {
  const ComponentHeat* comp = component(id);
  double hottest = scene_.operating.ambient;
  if (!comp || !scene_.effects.thermal) return hottest;
  for (Index k = comp->offset; k < comp->offset + comp->node_count(); ++k)
    hottest = std::max(hottest, scene_.operating.ambient + u[k]);
  const double own = body_resistance(id);
  if (own <= 0.0) return hottest;
  const RigidPosition q = position(u);
  const double k_oil = scene_.lubricant.conductivity;
  for (const Film& film : films_) {
    if (film.lower != id && film.upper != id) continue;
    const FilmMesh& m = film.mesh;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const int n = m.node(i, j);
        const HeatNode& node = heat_nodes_[std::size_t(film.number - 1)][std::size_t(n)];
        const double h = film.node_gap(q, node.x, node.y) + (deforms() ? shape_at(u, film, n) : 0.0);
        const double path = average_gap(h, film.sigma).value / (2.0 * k_oil) + own;
        const double body = face_temperature(u, id, m.radius(i), j, nullptr);
        const double tf = temperature_of(u, film.temperature_row(n));
        hottest = std::max(hottest, body + (tf - body) * own / path);
      }
  }
  return hottest;
}

}  // namespace twb
