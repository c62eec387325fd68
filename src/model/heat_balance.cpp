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

#include "model/heat_effect.h"

#include "model/assembly_totals.h"
#include "model/film_gap.h"
#include "model/film_roughness.h"
#include "physics/average_gap.h"

namespace twb {

HeatEffect::HeatEffect(ModelSetup& setup) : model_(setup.model) {
  const Scene& scene = model_.scene();
  const int nr = scene.mesh.radial_nodes, nt = scene.mesh.circumferential_nodes;
  for (Film& f : setup.films)
    f.temperature_offset =
        setup.layout.add(fmt_film_block(f.number, "film-node temperature"), BlockEffect::thermal, f.mesh.node_count());
  auto add_component = [&](ComponentId id, const Component& c, const FilmMesh& grid, bool axisymmetric, bool ambient,
                           const char* name) {
    ComponentHeat h{id, grid, axisymmetric, c.thickness, c.material.conductivity,
                    c.material.density * c.material.specific_heat * c.thickness, ambient};
    h.offset = setup.layout.add(std::string(name) + (axisymmetric ? " temperature T(r)" : " temperature T(r, theta)"),
                                BlockEffect::thermal, h.node_count(), true);
    setup.components.push_back(h);
  };
  // The carrier is fixed in the load frame (unless the scene averages it, a modelling
  // alternative); the gear always rotates; the washer rotates with the gear when film 1
  // slides (docs/physics.md section 7).
  const bool film1_slides = setup.films[0].sliding;
  add_component(ComponentId::carrier, scene.carrier, setup.films[0].mesh,
                scene.effects.carrier_temperature == CarrierTemperature::axisymmetric, true, "carrier");
  add_component(ComponentId::washer, scene.washer, setup.films[0].mesh, film1_slides, false, "washer");
  add_component(ComponentId::gear, scene.gear, FilmMesh(scene.gear.inner_radius, scene.gear.outer_radius, nr, nt),
                true, true, "gear");
  set_row_scales(setup);

  // Each film node's links to the faces of its two bodies.
  const std::vector<double> zero(std::size_t(setup.layout.size()), 0.0);
  heat_nodes_.assign(setup.films.size(), {});
  for (const Film& film : setup.films) {
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
          model_.face_temperature(zero, sides[side], r, j, &face);
          FaceLink& link = node.face[side];
          for (const auto& [k, w] : face.terms) {
            for (const ComponentHeat& comp : setup.components) {
              if (k < comp.offset || k >= comp.offset + comp.node_count()) continue;
              link.column[std::size_t(link.terms)] = k;
              link.weight[std::size_t(link.terms)] = w;
              link.row_scale[std::size_t(link.terms)] = setup.layout.row_scale(k);
              ++link.terms;
            }
          }
        }
      }
    }
  }
}

// Every heat row is divided by a reference conductance of its node (W/K), so that its
// value reads in kelvin: a film node's two paths through a reference film (the cold
// start's least film, h_min/σ = cold_start_film), a body node's in-plane conduction
// plus the films attached to it and its loss to ambient.
void HeatEffect::set_row_scales(ModelSetup& setup) const {
  const Scene& scene = model_.scene();
  const double h_ref = scene.solver.cold_start_film * model_.sliding_film().sigma;
  const std::vector<ComponentHeat>& components = setup.components;
  std::vector<double> attached_conductance(components.size(), 0.0);  // W/K/m² from films, reference
  for (const Film& film : setup.films) {
    const double g_lo = 1.0 / model_.heat_path(h_ref, film.lower);
    const double g_up = 1.0 / model_.heat_path(h_ref, film.upper);
    for (int i = 0; i < film.mesh.radial_nodes(); ++i)
      for (int j = 0; j < film.mesh.circumferential_nodes(); ++j)
        setup.layout.set_row_scale(film.temperature_row(film.mesh.node(i, j)),
                                   1.0 / (film.mesh.node_area(i) * (g_lo + g_up)));
    for (std::size_t c = 0; c < components.size(); ++c) {
      if (components[c].id == film.lower) attached_conductance[c] += g_lo;
      if (components[c].id == film.upper) attached_conductance[c] += g_up;
    }
  }
  for (std::size_t c = 0; c < components.size(); ++c) {
    const ComponentHeat& h = components[c];
    const FilmMesh& g = h.grid;
    const double kt = h.conductivity * h.thickness;
    for (int i = 0; i < g.radial_nodes(); ++i) {
      double diag = 0.0;  // in-plane conduction to radial neighbours (full ring if axisymmetric)
      const double ring = h.axisymmetric ? 2 * std::numbers::pi : g.dtheta();
      if (i > 0) diag += kt * (g.radius(i) - 0.5 * g.dr()) * ring / g.dr();
      if (i < g.radial_nodes() - 1) diag += kt * (g.radius(i) + 0.5 * g.dr()) * ring / g.dr();
      const double area = h.node_area(i);
      diag += area * (attached_conductance[c] + (h.loses_to_ambient ? h.conductivity / h.thickness : 0.0));
      for (int j = 0; j < (h.axisymmetric ? 1 : g.circumferential_nodes()); ++j)
        setup.layout.set_row_scale(h.offset + (h.axisymmetric ? i : g.node(i, j)), 1.0 / diag);
    }
  }
}

void HeatEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals&) const {
  const BearingModel& model = model_;
  const bool jac = a.wants_jacobian();
  const double k_oil = model.scene().lubricant.conductivity;
  const double ambient = model.scene().operating.ambient;
  const UnknownLayout& layout = model.layout();
  const bool deforms = model.deforms();
  const Index dishing_row = model.washer_dishing().unknown;
  // The plate's w row of node a reads A_a·(1 + ν)·κ_T = (1 + ν)·α/K·Q_a, Q_a the heat crossing
  // the mid-plane there, half of what enters through film 1 less half of what enters
  // through film 2 (the shares' signs), in σ_ref ([E1] as ElasticAnnulus writes it).
  const WasherPlate& plate = model.washer_plate();
  const Material& washer = model.scene().washer.material;
  const double plate_per_flow = plate.elastic() ? -(1.0 + washer.poisson_ratio) * washer.thermal_expansion /
                                                      (2.0 * washer.conductivity * plate.deflection_ref)
                                                : 0.0;

  // Film nodes and their exchange with the bounding components.
  for (const Film& film : model.films()) {
    const FilmMesh& m = film.mesh;
    const std::array<Index, 3> rigid_cols = film.rigid_columns();
    const std::array<ComponentId, 2> sides{film.lower, film.upper};
    const FilmGap gaps(model, u, film);
    const FilmRoughness roughness(model, u, film);
    for (int i = 0; i < m.radial_nodes(); ++i) {
      const double area = m.node_area(i);
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const int n = m.node(i, j);
        const HeatNode& node = heat_nodes_[std::size_t(film.number - 1)][std::size_t(n)];
        const Index row = film.temperature_row(n);
        const double scale = layout.row_scale(row);
        const double x = node.x, y = node.y;
        // A node on a relief's edge (docs/physics.md section 14): the parts of its control
        // volume conduct side by side, each through its own gap.
        const FaceRelief::NodeParts relief = gaps.parts(i, j);
        const double smooth = gaps.smooth(n, x, y);
        const std::array<double, 3> dh = gaps.rigid_slope(x, y);
        const LinearForm& shape = gaps.shape_form(n);
        std::array<ValueSlope, 4> part_gap{};
        // Where the faces run in, σ is the node's (film_roughness.h).
        const PointRoughness rough = roughness.at_node(n);
        const double sigma = roughness.varies() ? rough.sigma : film.sigma;
        std::array<double, 4> part_by_sigma{};
        for (int p = 0; p < relief.count; ++p) {
          const double hp = smooth + relief.relief[std::size_t(p)];
          part_gap[std::size_t(p)] = average_gap(hp, sigma);
          if (roughness.varies()) part_by_sigma[std::size_t(p)] = average_gap_by_sigma(hp, sigma);
        }
        const ValueSlope gap = part_gap[0];
        const bool straddles = relief.count > 1;
        const double tf = model.temperature_of(u, row);

        for (std::size_t side = 0; side < 2; ++side) {
          const FaceLink& face = node.face[side];
          double ts = ambient;
          for (int t = 0; t < face.terms; ++t) ts += face.weight[std::size_t(t)] * u[face.column[std::size_t(t)]];
          const double res = model.heat_path(gap.value, sides[side]);
          double flow = area * (tf - ts) / res;  // W from the film node into the component
          double dflow_dh = -flow / res * gap.slope / (2.0 * k_oil);
          double dflow_dsigma = -flow / res * part_by_sigma[0] / (2.0 * k_oil);
          double conductance = area / res;
          if (straddles) {
            double per_area = 0.0, slope = 0.0, by_sigma = 0.0;  // Σ share/R and Σ share·(dh̄T/dh)/R²
            for (int p = 0; p < relief.count; ++p) {
              const ValueSlope& part = part_gap[std::size_t(p)];
              const double r = model.heat_path(part.value, sides[side]), share = relief.share[std::size_t(p)];
              per_area += share / r;
              slope += share * (part.slope / (r * r));
              by_sigma += share * (part_by_sigma[std::size_t(p)] / (r * r));
            }
            conductance = area * per_area;
            flow = conductance * (tf - ts);
            dflow_dh = -area * (tf - ts) * slope / (2.0 * k_oil);
            dflow_dsigma = -area * (tf - ts) * by_sigma / (2.0 * k_oil);
          }
          // c·∂flow/∂(each face's Rq at the node) into a row, where the faces run in.
          const auto add_roughness = [&](Index to, double c) {
            roughness.add_rest(a, to, c * dflow_dsigma * rough.sigma_by_rest, n);
            roughness.add_turn(a, to, c * dflow_dsigma * rough.sigma_by_turn, n);
          };
          a.add_residual(row, -scale * flow);
          if (jac) {
            a.add_derivative(row, row, -scale * conductance);
            for (int t = 0; t < face.terms; ++t)
              a.add_derivative(row, face.column[std::size_t(t)], scale * conductance * face.weight[std::size_t(t)]);
            for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], -scale * dflow_dh * dh[d]);
            a.add_form(row, -scale * dflow_dh, shape);
            add_roughness(row, -scale);
          }
          // cw·flow into a row that the heat entering the component reads, with its slopes.
          const auto add_flow = [&](Index to, double cw) {
            a.add_residual(to, cw * flow);
            if (!jac) return;
            a.add_derivative(to, row, cw * conductance);
            for (int t = 0; t < face.terms; ++t)
              a.add_derivative(to, face.column[std::size_t(t)], -cw * conductance * face.weight[std::size_t(t)]);
            for (int d = 0; d < 3; ++d) a.add_derivative(to, rigid_cols[d], cw * dflow_dh * dh[d]);
            a.add_form(to, cw * dflow_dh, shape);
            add_roughness(to, cw);
          };
          // The heat crossing the washer dishes it (docs/physics.md section 11, film_shape.cpp)
          // and, where it bends as a plate, curves it where it crosses (section 21, [E1]).
          if (deforms && sides[side] == ComponentId::washer) {
            add_flow(dishing_row, model.dishing_row_weight(film));
            if (plate.elastic())
              for (const WasherPlate::Share& share : plate.of(film, i))
                add_flow(plate.deflection + share.ring * plate.circumferential_nodes + j,
                         plate_per_flow * share.weight);
          }
          // The face nodes of the component receive the same flow.
          for (int t = 0; t < face.terms; ++t)
            add_flow(face.column[std::size_t(t)], face.row_scale[std::size_t(t)] * face.weight[std::size_t(t)]);
        }
      }
    }
  }

  add_body_conduction(u, a);
}

// In-plane conduction of each component (eq [21]) and, for carrier and gear, 1-D
// conduction across the thickness to the ambient (eqs [25], [28]).
void HeatEffect::add_body_conduction(std::span<const double> u, Assembler& a) const {
  const bool jac = a.wants_jacobian();
  const UnknownLayout& layout = model_.layout();
  for (const ComponentHeat& comp : model_.components()) {
    const FilmMesh& g = comp.grid;
    const double kt = comp.conductivity * comp.thickness;
    const int nr = g.radial_nodes(), nt = comp.axisymmetric ? 1 : g.circumferential_nodes();
    auto index = [&](int i, int j) -> Index { return comp.axisymmetric ? i : Index(i) * g.circumferential_nodes() + g.wrap(j); };
    auto conduct = [&](Index la, Index lb, double conductance) {
      const Index ka = comp.offset + la, kb = comp.offset + lb;
      const double flow = conductance * (u[ka] - u[kb]);  // W from a to b
      const double sa = layout.row_scale(ka), sb = layout.row_scale(kb);
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
          const double s = layout.row_scale(k);
          a.add_residual(k, -s * gamb * u[k]);
          if (jac) a.add_derivative(k, k, -s * gamb);
        }
      }
    }
  }
}

// A body's hottest node (K): the floor of its hottest face (docs/physics.md section 8,
// material temperature), whose faces beside the films describe() locates between the
// film nodes.
double BearingModel::hottest_node_temperature(std::span<const double> u, ComponentId id) const {
  const ComponentHeat* comp = component(id);
  double hottest = scene_.operating.ambient;
  if (!comp || !scene_.effects.thermal) return hottest;
  for (Index k = comp->offset; k < comp->offset + comp->node_count(); ++k)
    hottest = std::max(hottest, scene_.operating.ambient + u[k]);
  return hottest;
}

}  // namespace twb
