#include "model/film_gap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/bearing_model.h"

namespace twb {

NodeGaps::NodeGaps(const BearingModel& model, std::span<const double> u, const Film& film)
    : model_(&model), film_(&film), q_(model.position(u)), delta_(model.node_shapes(u, film)) {}

double NodeGaps::smooth(int i, int j) const {
  const FilmMesh& m = film_->mesh;
  return film_->node_gap_polar(q_, m.radius(i), m.angle(j)) + shape(m.node(i, j));
}

FaceRelief::NodeParts NodeGaps::parts(int i, int j) const {
  return film_->relief.flat() ? FaceRelief::NodeParts{} : film_->relief.node_parts(i, j);
}

double NodeGaps::mean(int i, int j) const {
  double h = smooth(i, j);
  if (!film_->relief.flat()) {
    const FaceRelief::NodeParts p = film_->relief.node_parts(i, j);
    double relief = 0.0;
    for (int k = 0; k < p.count; ++k) relief += p.share[std::size_t(k)] * p.relief[std::size_t(k)];
    h += relief;
  }
  return h;
}

// A plane h = c + a·x + b·y is least along −(a, b), on the outer rim. A deformed film:
// the least of the nodes' gaps and of the gap at that point (the shape interpolated
// along the rim); without expansion that is the plane's exact minimum again. A relief
// (≥ 0, docs/physics.md section 14) moves the least gap off a groove onto the land
// beside it, whose edge is a node line: the nodes with their least side's relief.
double NodeGaps::least() const {
  const FilmMesh& m = film_->mesh;
  const GapPlane plane = film_->plane(q_);
  const bool relief = !film_->relief.flat();
  if (delta_.empty() && !relief) return plane.least_within(m.outer_radius());
  auto lower_side = [&](int i, int j) { return relief ? film_->relief.least_at_node(i, j) : 0.0; };
  double least = INFINITY;
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j)
      least = std::min(least, film_->node_gap_polar(q_, m.radius(i), m.angle(j)) + shape(m.node(i, j)) +
                                  lower_side(i, j));
  if (plane.a == 0.0 && plane.b == 0.0) return least;
  const double two_pi = 2 * std::numbers::pi;
  double theta = std::atan2(-plane.b, -plane.a);
  if (theta < 0) theta += two_pi;
  const double cell = theta / m.dtheta();
  const int j = std::min(int(cell), m.circumferential_nodes() - 1);
  const double t = cell - j;
  const int rim = m.radial_nodes() - 1;
  const double rim_delta = (1 - t) * shape(m.node(rim, j)) + t * shape(m.node(rim, m.wrap(j + 1)));
  return std::min(least, film_->node_gap_polar(q_, m.outer_radius(), theta) + rim_delta +
                             (relief ? film_->relief.in_cell(rim - 1, j, t) : 0.0));
}

const LinearForm& NodeGaps::shape_form(int n) const { return model_->shape_form(*film_, n); }

}  // namespace twb
