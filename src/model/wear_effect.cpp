// Wear of the sliding film's faces (docs/physics.md section 20), its unknowns, its part of
// the gap and the rates it reports.
#include "model/wear_effect.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "model/assembly_totals.h"
#include "model/bearing_model.h"
#include "model/grid_map.h"
#include "twb/scene/worn_washer.h"
#include "twb/error_family.h"

namespace twb {
namespace {

// The two depths open the sliding film's gap [W3]: at node (i, j) by σ_ref·(d̂_rest(i, j) +
// d̂_turn(i)), bilinear inside a cell as every part is.
class WornFaces final : public GapContribution {
 public:
  WornFaces(int film, Index rest, Index turn) : film_(film), rest_(rest), turn_(turn) {}
  std::string name() const override { return "wear"; }
  bool moves(const Film& film) const override { return film.number == film_; }
  void add_node_forms(const BearingModel& model, const Film& film, double scale,
                      std::vector<LinearForm>& forms) const override {
    const int nt = film.mesh.circumferential_nodes();
    for (int n = 0; n < film.mesh.node_count(); ++n) {
      forms[std::size_t(n)].add(rest_ + n, scale * model.clearance_scale());
      forms[std::size_t(n)].add(turn_ + n / nt, scale * model.clearance_scale());
    }
  }

 private:
  int film_;
  Index rest_, turn_;
};

// Which component's face is at rest in the load frame and which turns (section 20):
// film 1 sliding, the carrier rests and the washer turns with the gear; film 2 sliding,
// the washer rests on the carrier and the gear turns.
std::array<const Component*, 2> resting_and_turning(const Scene& scene) {
  if (scene.operating.sliding == SlidingFilm::carrier_washer) return {&scene.carrier, &scene.washer};
  return {&scene.washer, &scene.gear};
}

RunningIn running_in_of(const Component& face) { return RunningIn(face.roughness.rq, face.roughness.run_in_rq); }

std::vector<double> face_rq(const RunningIn& face, const std::vector<double>& depths) {
  std::vector<double> rq;
  for (const double d : depths) rq.push_back(face.rq(d).value);
  return rq;
}

}  // namespace

WearEffect::WearEffect(ModelSetup& setup)
    : model_(setup.model),
      rest_running_in_(running_in_of(*resting_and_turning(setup.model.scene())[0])),
      turn_running_in_(running_in_of(*resting_and_turning(setup.model.scene())[1])) {
  const Scene& scene = setup.model.scene();
  if (!scene.effects.asperity_contact) throw std::invalid_argument("wear needs the asperity_contact effect");
  const auto [rest, turn] = resting_and_turning(scene);
  runs_in_ = rest->roughness.run_in_rq.has_value() || turn->roughness.run_in_rq.has_value();
  if (!rest->roughness.wear_rate || !turn->roughness.wear_rate)
    throw std::invalid_argument("wear: a face of the sliding film has no wear rate");
  k_rest_ = *rest->roughness.wear_rate;
  k_turn_ = *turn->roughness.wear_rate;
  while (!setup.films[film_index_].sliding) ++film_index_;
  const Film& f = setup.films[film_index_];
  rest_offset_ = setup.layout.add(fmt_film_block(f.number, "worn depth, face at rest"), BlockEffect::wear,
                                  f.mesh.node_count());
  turn_offset_ = setup.layout.add(fmt_film_block(f.number, "worn depth, turning face"), BlockEffect::wear,
                                  f.mesh.radial_nodes());
  held_rest_.assign(std::size_t(f.mesh.node_count()), 0.0);
  held_turn_.assign(std::size_t(f.mesh.radial_nodes()), 0.0);
  if (scene.worn) hold_worn(*scene.worn, f.mesh);
  setup.gap_parts.push_back(std::make_unique<WornFaces>(f.number, rest_offset_, turn_offset_));
}

// The worn washer's grid spans this film's annulus (set_worn_washer checked it): its
// depths interpolated onto this mesh, held.
void WearEffect::hold_worn(const WornWasher& worn, const FilmMesh& m) {
  const int nr = m.radial_nodes(), nt = m.circumferential_nodes();
  const GridMap map{worn.radial_nodes, worn.circumferential_nodes, nr, nt};
  const GridMap radial{worn.radial_nodes, 1, nr, 1};
  const double scale = model_.clearance_scale();
  for (int i = 0; i < nr; ++i) {
    for (int j = 0; j < nt; ++j)
      held_rest_[std::size_t(i * nt + j)] =
          map.at(i, j, [&](int a, int b) { return worn.rest[std::size_t(a * worn.circumferential_nodes + b)]; }) /
          scale;
    held_turn_[std::size_t(i)] = radial.at(i, 0, [&](int a, int) { return worn.turn[std::size_t(a)]; }) / scale;
  }
}

const Film& WearEffect::film() const { return model_.films()[film_index_]; }

// On the heat's time scale each row is assembled as (what is given − the unknown) and
// negated with the others by orient_rows: d̂ − d̂_given, with +1 on the diagonal. On the
// wear's, it is the rate the state implies, R̂(u), negated to −R̂: with the unit capacity
// IDA's residual is d̂' − R̂(u) = 0 ([W4]).
void WearEffect::add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const {
  const double held = model_.time_scale() == TimeScale::wear ? 0.0 : 1.0;
  auto hold_rows = [&](Index offset, const std::vector<double>& given) {
    for (std::size_t n = 0; n < given.size(); ++n) {
      const Index row = offset + Index(n);
      a.add_residual(row, held * (given[n] - u[std::size_t(row)]));
      a.add_derivative(row, row, -held);
    }
  };
  hold_rows(rest_offset_, held_rest_);
  hold_rows(turn_offset_, held_turn_);
  add_rates(totals.film[film_index_], 1.0 - held, a);
}

void WearEffect::add_rates(const FilmTotals& sliding, double weight, Assembler& a) const {
  const Film& f = film();
  const FilmMesh& m = f.mesh;
  const int nr = m.radial_nodes(), nt = m.circumferential_nodes();
  const bool jac = a.wants_jacobian();
  const std::array<Index, 3> rigid = f.rigid_columns();
  // m/s of depth per watt of friction power at a node, as σ_ref per hour.
  const double per_hour = weight * 3600.0 / model_.clearance_scale();
  std::vector<double> rest_scale(static_cast<std::size_t>(nr)), turn_scale(static_cast<std::size_t>(nr));
  for (int i = 0; i < nr; ++i) {
    rest_scale[std::size_t(i)] = per_hour * k_rest_ / m.node_area(i);
    turn_scale[std::size_t(i)] = per_hour * k_turn_ / (nt * m.node_area(i));
  }
  for (int n = 0; n < m.node_count(); ++n) {
    const std::size_t i = std::size_t(n / nt);
    const double power = sliding.contact_power[std::size_t(n)];
    a.add_residual(rest_offset_ + n, rest_scale[i] * power);
    a.add_residual(turn_offset_ + Index(i), turn_scale[i] * power);
    if (!jac) continue;
    for (int d = 0; d < 3; ++d) {
      const double slope = sliding.contact_power_rigid[std::size_t(n)][std::size_t(d)];
      a.add_derivative(rest_offset_ + n, rigid[std::size_t(d)], rest_scale[i] * slope);
      a.add_derivative(turn_offset_ + Index(i), rigid[std::size_t(d)], turn_scale[i] * slope);
    }
  }
  if (!jac) return;
  for (const ShapeTerm& term : sliding.contact_power_shape) {
    const std::size_t i = std::size_t(term.node / nt);
    const LinearForm& shape = model_.shape_form(f, term.corner);
    a.add_form(rest_offset_ + term.node, rest_scale[i] * term.coefficient, shape);
    a.add_form(turn_offset_ + Index(i), turn_scale[i] * term.coefficient, shape);
  }
  for (const DepthTerm& term : sliding.contact_power_depth) {
    const std::size_t i = std::size_t(term.node / nt);
    a.add_derivative(rest_offset_ + term.node, term.column, rest_scale[i] * term.coefficient);
    a.add_derivative(turn_offset_ + Index(i), term.column, turn_scale[i] * term.coefficient);
  }
}

void WearEffect::hold(std::span<const double> rest, std::span<const double> turn) {
  if (rest.size() != held_rest_.size() || turn.size() != held_turn_.size())
    throw InternalError("WearEffect::hold: depths of another mesh");
  for (std::size_t n = 0; n < rest.size(); ++n) held_rest_[n] = rest[n] / model_.clearance_scale();
  for (std::size_t i = 0; i < turn.size(); ++i) held_turn_[i] = turn[i] / model_.clearance_scale();
}

// Held, so the depths this mesh's own rows give.
void WearEffect::carry_from(const BearingModel&, const EffectAssembler&, std::span<const double>,
                            std::span<double> out) const {
  std::copy(held_rest_.begin(), held_rest_.end(), out.begin() + rest_offset_);
  std::copy(held_turn_.begin(), held_turn_.end(), out.begin() + turn_offset_);
}

WearEffect::Rates WearEffect::rates(const FilmTotals& sliding) const {
  const FilmMesh& m = film().mesh;
  const int nr = m.radial_nodes(), nt = m.circumferential_nodes();
  if (sliding.contact_power.size() != std::size_t(m.node_count()))
    throw InternalError("WearEffect::rates: the totals are not the sliding film's");
  Rates r{std::vector<double>(std::size_t(m.node_count())), std::vector<double>(std::size_t(nr))};
  for (int i = 0; i < nr; ++i) {
    double ring = 0.0;
    for (int j = 0; j < nt; ++j) {
      const double power = sliding.contact_power[std::size_t(i * nt + j)];
      r.rest[std::size_t(i * nt + j)] = k_rest_ * power / m.node_area(i);
      ring += power;
    }
    r.turn[std::size_t(i)] = k_turn_ * ring / (nt * m.node_area(i));
  }
  return r;
}

WearEffect::FaceRoughness WearEffect::roughness(std::span<const double> u) const {
  FaceRoughness r;
  for (const double d : rest_depths(u)) r.rest.push_back(rest_running_in_.rq(d));
  for (const double d : turn_depths(u)) r.turn.push_back(turn_running_in_.rq(d));
  return r;
}

double WearEffect::run_in_sigma() const {
  return std::hypot(rest_running_in_.rq_run_in(), turn_running_in_.rq_run_in());
}

WearEffect::Rates WearEffect::rates_at(std::span<const double> u) const {
  AssemblyTotals totals;
  model_.gather_totals(u, totals);
  return rates(totals.film[film_index_]);
}

std::array<double, 2> WearEffect::volume_rates(const FilmTotals& sliding) const {
  const double power = std::accumulate(sliding.contact_power.begin(), sliding.contact_power.end(), 0.0);
  return {k_rest_ * power, k_turn_ * power};
}

std::vector<double> WearEffect::rest_depths(std::span<const double> u) const {
  std::vector<double> d(u.begin() + rest_offset_, u.begin() + rest_offset_ + Index(held_rest_.size()));
  for (double& x : d) x *= model_.clearance_scale();
  return d;
}

std::vector<double> WearEffect::turn_depths(std::span<const double> u) const {
  std::vector<double> d(u.begin() + turn_offset_, u.begin() + turn_offset_ + Index(held_turn_.size()));
  for (double& x : d) x *= model_.clearance_scale();
  return d;
}

std::array<WearEffect::Worn, 2> WearEffect::worn(std::span<const double> u) const {
  const FilmMesh& m = film().mesh;
  const int nt = m.circumferential_nodes();
  const std::vector<double> rest = rest_depths(u), turn = turn_depths(u);
  Worn r{std::max(0.0, *std::max_element(rest.begin(), rest.end())), 0.0, 0.0, 0.0};
  Worn t{std::max(0.0, *std::max_element(turn.begin(), turn.end())), 0.0, 0.0, 0.0};
  double rest_square = 0.0, turn_square = 0.0;
  for (std::size_t n = 0; n < rest.size(); ++n) {
    const double area = m.node_area(int(n) / nt), rq = rest_running_in_.rq(rest[n]).value;
    r.volume += area * rest[n];
    rest_square += area * rq * rq;
  }
  for (std::size_t i = 0; i < turn.size(); ++i) {
    const double area = nt * m.node_area(int(i)), rq = turn_running_in_.rq(turn[i]).value;
    t.volume += area * turn[i];
    turn_square += area * rq * rq;
  }
  r.mean = r.volume / m.area();
  t.mean = t.volume / m.area();
  r.rq = std::sqrt(rest_square / m.area());
  t.rq = std::sqrt(turn_square / m.area());
  return {r, t};
}

WornWasher WearEffect::worn_washer(std::span<const double> u, double time) const {
  const Film& f = film();
  return WornWasher{.time = time,
                    .film = f.number,
                    .inner_radius = f.mesh.inner_radius(),
                    .outer_radius = f.mesh.outer_radius(),
                    .radial_nodes = f.mesh.radial_nodes(),
                    .circumferential_nodes = f.mesh.circumferential_nodes(),
                    .rest = rest_depths(u),
                    .turn = turn_depths(u),
                    .rest_rq = face_rq(rest_running_in_, rest_depths(u)),
                    .turn_rq = face_rq(turn_running_in_, turn_depths(u)),
                    .source = {}};
}

void WearEffect::report(std::span<const double> u, const AssemblyTotals& totals,
                        std::vector<ReportedValue>& out) const {
  constexpr double um = 1e6, per_hour = 3600.0, mm3 = 1e9;
  auto deepest = [](const std::vector<double>& v) { return std::max(0.0, *std::max_element(v.begin(), v.end())); };
  const FilmTotals& sliding = totals.film[film_index_];
  const Rates r = rates(sliding);
  const std::array<double, 2> volume = volume_rates(sliding);
  const std::array<Worn, 2> w = worn(u);
  const double values[] = {um * w[0].deepest,                 um * w[1].deepest,
                           um * per_hour * deepest(r.rest),   um * per_hour * deepest(r.turn),
                           mm3 * per_hour * volume[0],        mm3 * per_hour * volume[1]};
  static_assert(std::size(values) == std::size(kReported));
  for (std::size_t q = 0; q < std::size(kReported); ++q) out.push_back({std::string(kReported[q].column), values[q]});
}

}  // namespace twb
