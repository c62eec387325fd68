#include "model/film_roughness.h"

#include <cmath>

#include "model/bearing_model.h"
#include "model/wear_effect.h"

namespace twb {

// σ = sqrt(σr² + σt²); ψ = (σt² − σr²)/σ, so ∂ψ/∂σt = 2σt/σ − ψ·σt/σ², ∂ψ/∂σr = −2σr/σ − ψ·σr/σ².
PointRoughness PointRoughness::of(double rest, double turn) {
  PointRoughness p;
  p.sigma = std::hypot(rest, turn);
  p.shear = (turn * turn - rest * rest) / p.sigma;
  p.sigma_by_rest = rest / p.sigma;
  p.sigma_by_turn = turn / p.sigma;
  p.shear_by_rest = -2.0 * rest / p.sigma - p.shear * rest / (p.sigma * p.sigma);
  p.shear_by_turn = 2.0 * turn / p.sigma - p.shear * turn / (p.sigma * p.sigma);
  return p;
}

FilmRoughness::FilmRoughness(const BearingModel& model, std::span<const double> u, const Film& film) : film_(&film) {
  uniform_.sigma = film.sigma;
  uniform_.shear = film.sigma * film.shear_weight;
  const WearEffect* wear = model.effect<WearEffect>();
  if (!film.sliding || !wear || !wear->runs_in()) return;
  WearEffect::FaceRoughness r = wear->roughness(u);
  // The slopes per scaled unknown (a depth unknown is in σ_ref).
  for (ValueSlope& v : r.rest) v.slope *= model.clearance_scale();
  for (ValueSlope& v : r.turn) v.slope *= model.clearance_scale();
  rest_ = std::move(r.rest);
  turn_ = std::move(r.turn);
  rest_offset_ = wear->rest_offset();
  turn_offset_ = wear->turn_offset();
}

PointRoughness FilmRoughness::at_node(int n) const {
  if (!varies()) return uniform_;
  const int i = n / film_->mesh.circumferential_nodes();
  return PointRoughness::of(rest_[std::size_t(n)].value, turn_[std::size_t(i)].value);
}

PointRoughness FilmRoughness::between(int a, int b) const {
  if (!varies()) return uniform_;
  const int nt = film_->mesh.circumferential_nodes();
  return PointRoughness::of(0.5 * (rest_[std::size_t(a)].value + rest_[std::size_t(b)].value),
                            0.5 * (turn_[std::size_t(a / nt)].value + turn_[std::size_t(b / nt)].value));
}

PointRoughness FilmRoughness::in_cell(const std::array<int, 4>& corners, double s, double t) const {
  if (!varies()) return uniform_;
  const int nt = film_->mesh.circumferential_nodes();
  const std::array<double, 4> w{(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
  double rest = 0.0;
  for (int k = 0; k < 4; ++k) rest += w[std::size_t(k)] * rest_[std::size_t(corners[std::size_t(k)])].value;
  const double turn = (1 - s) * turn_[std::size_t(corners[0] / nt)].value + s * turn_[std::size_t(corners[1] / nt)].value;
  return PointRoughness::of(rest, turn);
}

std::pair<Index, double> FilmRoughness::rest_column(int n) const {
  return {rest_offset_ + n, rest_[std::size_t(n)].slope};
}

std::pair<Index, double> FilmRoughness::turn_column(int n) const {
  const int i = n / film_->mesh.circumferential_nodes();
  return {turn_offset_ + i, turn_[std::size_t(i)].slope};
}

void FilmRoughness::add_rest(Assembler& a, Index row, double c, int n) const {
  if (!varies()) return;
  const auto [column, slope] = rest_column(n);
  a.add_derivative(row, column, c * slope);
}

void FilmRoughness::add_turn(Assembler& a, Index row, double c, int n) const {
  if (!varies()) return;
  const auto [column, slope] = turn_column(n);
  a.add_derivative(row, column, c * slope);
}

}  // namespace twb
