// The washer as an elastic plate (docs/physics.md section 21): its unknowns, its rows,
// its part of the films' gaps and what it reports.
#include "model/elastic_washer_effect.h"

#include <algorithm>
#include <memory>

#include "model/bearing_model.h"
#include "model/grid_map.h"
#include "scene/material_modulus.h"
#include "twb/error_family.h"
#include "twb/model/bearing_state.h"

namespace twb {
namespace {

// The deflection's part of a film's gap: at node (i, j), scale·σ_ref·Σ weight·ŵ over the
// washer's nodes the film's ring i sits on (WasherPlate::shares), bilinear inside a cell
// as every part is.
class PlateDeflection final : public GapContribution {
 public:
  std::string name() const override { return "washer deflection"; }
  void add_node_forms(const BearingModel& model, const Film& film, double scale,
                      std::vector<LinearForm>& forms) const override {
    const WasherPlate& plate = model.washer_plate();
    const FilmMesh& m = film.mesh;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (const WasherPlate::Share& share : plate.of(film, i))
        for (int j = 0; j < m.circumferential_nodes(); ++j)
          forms[std::size_t(m.node(i, j))].add(plate.deflection + share.ring * plate.circumferential_nodes + j,
                                               scale * plate.deflection_ref * share.weight);
  }
};

double rigidity_of(const Component& washer) {
  const Material& mat = washer.material;
  const double t = washer.thickness;
  return mat.youngs_modulus * t * t * t / (12.0 * (1.0 - mat.poisson_ratio * mat.poisson_ratio));
}

}  // namespace

ElasticWasherEffect::ElasticWasherEffect(ModelSetup& setup)
    : model_(setup.model),
      annulus_(setup.films[0].mesh.inner_radius(), setup.films[0].mesh.outer_radius(),
               setup.films[0].mesh.radial_nodes(), setup.films[0].mesh.circumferential_nodes(),
               rigidity_of(setup.model.scene().washer), setup.model.scene().washer.material.poisson_ratio) {
  const Scene& scene = setup.model.scene();
  const FilmMesh& grid = setup.films[0].mesh;  // the washer's annulus
  const int n = annulus_.nodes();
  deflection_ref_ = setup.model.clearance_scale();
  load_ref_ = std::max(scene.operating.load, 1.0);
  moment_ref_ = load_ref_ / rigidity_of(scene.washer);
  area_ = grid.area();
  outer_ = grid.outer_radius();
  modulus_ = modulus_curve(scene.washer.material);
  reference_modulus_ = scene.washer.material.youngs_modulus;
  if (modulus_) twisting_ = annulus_.twisting_terms();

  WasherPlate& plate = setup.plate;
  plate.deflection = setup.layout.add("washer deflection", BlockEffect::elastic_washer, n);
  plate.moment = setup.layout.add("washer curvature sum", BlockEffect::elastic_washer, n);
  multipliers_ = setup.layout.add("washer rigid-plane multipliers", BlockEffect::elastic_washer, 3);
  plate.deflection_ref = deflection_ref_;
  plate.load_ref = load_ref_;
  plate.circumferential_nodes = grid.circumferential_nodes();
  // Film 1 spans the washer's annulus node for node; film 2 (the overlap with the gear)
  // sits on it by linear interpolation in radius, at the same angles.
  for (const Film& film : setup.films) {
    if (film.mesh.circumferential_nodes() != grid.circumferential_nodes())
      throw InternalError("ElasticWasherEffect: the films' grids differ in angle");
    auto& rings = plate.shares[std::size_t(film.number - 1)];
    rings.assign(std::size_t(film.mesh.radial_nodes()), {});
    const double towards = film.upper == ComponentId::washer ? 1.0 : -1.0;
    for (int i = 0; i < film.mesh.radial_nodes(); ++i) {
      if (film.number == 1) {
        rings[std::size_t(i)].push_back({i, towards});
        continue;
      }
      const FilmMesh::RadialWeights rw = grid.radial_weights(film.mesh.radius(i));
      if (rw.w0 != 0.0) rings[std::size_t(i)].push_back({rw.i0, towards * rw.w0});
      if (rw.w1 != 0.0 && rw.i1 != rw.i0) rings[std::size_t(i)].push_back({rw.i1, towards * rw.w1});
    }
  }
  plate_ = plate;
  for (int k = 0; k < annulus_.size(); ++k) setup.layout.set_row_scale(global(k), row_scale(k));
  setup.gap_parts.push_back(std::make_unique<PlateDeflection>());
}

Index ElasticWasherEffect::global(int k) const {
  const int n = annulus_.nodes();
  if (k < n) return plate_.deflection + k;
  if (k < 2 * n) return plate_.moment + (k - n);
  return multipliers_ + (k - 2 * n);
}

// w in σ_ref, m in F_ref/D, λ0 in F_ref/A and λ1, λ2 in F_ref/(A·r_o): the loads' scale
// through each.
double ElasticWasherEffect::column_ref(int k) const {
  const int n = annulus_.nodes();
  if (k < n) return deflection_ref_;
  if (k < 2 * n) return moment_ref_;
  return k == 2 * n ? load_ref_ / area_ : load_ref_ / (area_ * outer_);
}

// w rows in σ_ref, m rows in F_ref, the conditions ∫w dA in σ_ref·A and ∫w·x dA in σ_ref·A·r_o.
double ElasticWasherEffect::row_scale(int k) const {
  const int n = annulus_.nodes();
  if (k < n) return 1.0 / deflection_ref_;
  if (k < 2 * n) return 1.0 / load_ref_;
  return k == 2 * n ? 1.0 / (deflection_ref_ * area_) : 1.0 / (deflection_ref_ * area_ * outer_);
}

// The operator's rows as (its entries)·u; the loads are added by the films' scatter
// (−F_a: [E1]'s right side) and κ_T by the heat balance. The conditions' rows have no
// diagonal of their own: an explicit zero keeps one in the pattern (the pseudo-time
// steps shift every diagonal). orient_rows negates them with the others.
void ElasticWasherEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals&) const {
  for (int k = 0; k < 3; ++k) a.add_derivative(multipliers_ + k, multipliers_ + k, 0.0);
  if (modulus_) {
    add_terms_with_modulus_curve(u, a);
    return;
  }
  for (const ElasticAnnulus::Entry& e : annulus_.entries()) {
    const double v = e.value * column_ref(e.column) * row_scale(e.row);
    const Index row = global(e.row), column = global(e.column);
    a.add_residual(row, v * u[std::size_t(column)]);
    a.add_derivative(row, column, v);
  }
}

// Physics §23: an m row's flux of node k's m is D(T_k)·(its constant-D coefficient), and
// the twisting terms [M2]-[M3] (twisting_) each take D at their node;
// T_k the washer's temperature at node k (its mid-plane's, §7), the ambient without the
// thermal effect.
void ElasticWasherEffect::add_terms_with_modulus_curve(std::span<const double> u, Assembler& a) const {
  const int n = annulus_.nodes(), nt = plate_.circumferential_nodes;
  std::vector<double> factor(static_cast<std::size_t>(n)), slope(static_cast<std::size_t>(n));
  std::vector<LinearForm> temperature(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double t = model_.face_temperature(u, ComponentId::washer, annulus_.radius(k / nt), k % nt,
                                             &temperature[std::size_t(k)]);
    const ModulusCurve::Value e = modulus_->at(t);
    factor[std::size_t(k)] = e.modulus / reference_modulus_;
    slope[std::size_t(k)] = e.slope / reference_modulus_;
  }
  for (const ElasticAnnulus::Entry& e : annulus_.entries()) {
    const double v = e.value * column_ref(e.column) * row_scale(e.row);
    const Index row = global(e.row), column = global(e.column);
    const int node = annulus_.rigidity_node(e);
    if (node == ElasticAnnulus::kReplacedByTwisting) continue;
    const double x = u[std::size_t(column)];
    if (node < 0) {
      a.add_residual(row, v * x);
      a.add_derivative(row, column, v);
      continue;
    }
    a.add_residual(row, v * factor[std::size_t(node)] * x);
    a.add_derivative(row, column, v * factor[std::size_t(node)]);
    for (const auto& [k, w] : temperature[std::size_t(node)].terms)
      a.add_derivative(row, k, v * x * slope[std::size_t(node)] * w);
  }
  for (const ElasticAnnulus::TwistingTerm& t : twisting_) {
    const double v = t.value * column_ref(t.column) * row_scale(t.row);
    const Index row = global(t.row), column = global(t.column);
    const double x = u[std::size_t(column)];
    a.add_residual(row, v * factor[std::size_t(t.node)] * x);
    a.add_derivative(row, column, v * factor[std::size_t(t.node)]);
    for (const auto& [k, w] : temperature[std::size_t(t.node)].terms)
      a.add_derivative(row, k, v * x * slope[std::size_t(t.node)] * w);
  }
}

std::vector<double> ElasticWasherEffect::deflection(std::span<const double> u) const {
  std::vector<double> w(std::size_t(annulus_.nodes()));
  for (int k = 0; k < annulus_.nodes(); ++k) w[std::size_t(k)] = deflection_ref_ * u[std::size_t(plate_.deflection + k)];
  return w;
}

std::vector<double> ElasticWasherEffect::curvature_sum(std::span<const double> u) const {
  std::vector<double> m(std::size_t(annulus_.nodes()));
  for (int k = 0; k < annulus_.nodes(); ++k) m[std::size_t(k)] = moment_ref_ * u[std::size_t(plate_.moment + k)];
  return m;
}

std::array<double, 3> ElasticWasherEffect::multipliers(std::span<const double> u) const {
  const int n = annulus_.nodes();
  std::array<double, 3> l{};
  for (int k = 0; k < 3; ++k) l[std::size_t(k)] = column_ref(2 * n + k) * u[std::size_t(multipliers_ + k)];
  return l;
}

// w and m interpolated from the other mesh's washer grid (both span the washer's
// annulus), the multipliers in their physical units.
void ElasticWasherEffect::carry_from(const BearingModel&, const EffectAssembler& mine_there,
                                     std::span<const double> u, std::span<double> out) const {
  const auto& there = dynamic_cast<const ElasticWasherEffect&>(mine_there);
  const ElasticAnnulus& src = there.annulus_;
  const int nt = plate_.circumferential_nodes, src_nt = there.plate_.circumferential_nodes;
  const int nr = annulus_.nodes() / nt, src_nr = src.nodes() / src_nt;
  const GridMap map{src_nr, src_nt, nr, nt};
  const std::vector<double> w = there.deflection(u), m = there.curvature_sum(u);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j) {
      const int k = annulus_.node(i, j);
      const auto at = [&](const std::vector<double>& f) {
        return map.at(i, j, [&](int a, int b) { return f[std::size_t(src.node(a, b))]; });
      };
      out[std::size_t(plate_.deflection + k)] = at(w) / deflection_ref_;
      out[std::size_t(plate_.moment + k)] = at(m) / moment_ref_;
    }
  const std::array<double, 3> l = there.multipliers(u);
  for (int k = 0; k < 3; ++k)
    out[std::size_t(multipliers_ + k)] = l[std::size_t(k)] / column_ref(annulus_.nodes() * 2 + k);
}

void ElasticWasherEffect::report(std::span<const double> u, const AssemblyTotals&,
                                 std::vector<ReportedValue>& out) const {
  const std::vector<double> w = deflection(u);
  const auto [least, greatest] = std::minmax_element(w.begin(), w.end());
  const double values[] = {1e6 * (*greatest - *least)};
  static_assert(std::size(values) == std::size(kReported));
  for (std::size_t q = 0; q < std::size(kReported); ++q) out.push_back({std::string(kReported[q].column), values[q]});
}

}  // namespace twb
