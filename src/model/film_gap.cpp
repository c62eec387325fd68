#include "model/film_gap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/bearing_model.h"

namespace twb {

namespace {

// Whether the direction at angle ts (in (−π, π]) lies on the arc [t0, t1].
bool on_arc(double ts, double t0, double t1) {
  const double two_pi = 2.0 * std::numbers::pi;
  while (ts < t0) ts += two_pi;
  while (ts - two_pi >= t0) ts -= two_pi;
  return ts <= t1;
}

}  // namespace

PlaneOverCells::PlaneOverCells(const GapPlane& plane)
    : c_(plane.c),
      a_(plane.a),
      b_(plane.b),
      tilted_(plane.a != 0.0 || plane.b != 0.0),
      down_(std::atan2(-plane.b, -plane.a)),
      up_(std::atan2(plane.b, plane.a)) {}

GapRange PlaneOverCells::range(double r0, double r1, double t0, double t1, double c0, double s0, double c1,
                               double s1) const {
  const double e0 = a_ * c0 + b_ * s0, e1 = a_ * c1 + b_ * s1;
  const std::array<double, 4> corners{c_ + r0 * e0, c_ + r0 * e1, c_ + r1 * e0, c_ + r1 * e1};
  GapRange range{*std::min_element(corners.begin(), corners.end()), *std::max_element(corners.begin(), corners.end())};
  if (!tilted_) return range;
  // Along the plane's steepest descent (ascent) the gap is c ∓ r·|(a, b)|.
  const double slope = std::hypot(a_, b_);
  if (on_arc(down_, t0, t1)) range.least = std::min(range.least, c_ - r1 * slope);
  if (on_arc(up_, t0, t1)) range.greatest = std::max(range.greatest, c_ + r1 * slope);
  return range;
}

FilmGap::FilmGap(const BearingModel& model, std::span<const double> u, const Film& film)
    : model_(&model),
      film_(&film),
      q_(model.position(u)),
      plane_(film.plane(q_)),
      delta_(model.node_shapes(u, film)) {}

double FilmGap::smooth(int i, int j) const {
  const FilmMesh& m = film_->mesh;
  return film_->node_gap_polar(q_, m.radius(i), m.angle(j)) + shape(m.node(i, j));
}

FaceRelief::NodeParts FilmGap::parts(int i, int j) const {
  return film_->relief.flat() ? FaceRelief::NodeParts{} : film_->relief.node_parts(i, j);
}

double FilmGap::mean(int i, int j) const {
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
double FilmGap::least() const {
  const FilmMesh& m = film_->mesh;
  const GapPlane plane = film_->plane(q_);
  const bool relief = !film_->relief.flat();
  if (delta_.empty() && !relief) return plane.least_within(m.outer_radius());
  auto lower_side = [&](int i, int j) { return relief ? film_->relief.least_at_node(i, j) : 0.0; };
  double least = INFINITY;
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j)
      least = std::min(least, smooth(i, j) + lower_side(i, j));
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

// A face lies midway between its two nodes: the shape is their mean there. A face on a
// relief's edge has half its length on either side, each with its own gap
// (docs/physics.md section 14): a radial face beside a groove's or step's edge line, a
// circumferential face on a dam's line (its halves weighed by their integrals over r:
// the outer half's share of ∫r dr is the inner's of ∫dr/r; ½ across a radial face).
FaceGap FilmGap::across(const ReynoldsFace& f, int na, int nb, double x, double y) const {
  FaceGap g;
  const bool circumferential = f.kind == ReynoldsFace::Kind::circumferential;
  if (!film_->relief.flat())
    g.relief = circumferential ? film_->relief.across_row(f.ia, f.ja) : film_->relief.across_line(std::min(f.ia, f.ib), f.ja);
  g.smooth = plane_.at(x, y) + (shaped() ? 0.5 * (delta_[std::size_t(na)] + delta_[std::size_t(nb)]) : 0.0);
  if (g.relief.after != g.relief.before) g.outer_share = circumferential ? film_->relief.outer_share(f.ia) : 0.5;
  return g;
}

// A bilinear shape stays within its corners' values, and a linear relief within its edges'.
CellGap FilmGap::cell(int i, int j, const std::array<int, 4>& corner_nodes, GapRange plane_range) const {
  CellGap c;
  c.range = plane_range;
  c.shaped = shaped();
  if (c.shaped) {
    for (int k = 0; k < 4; ++k) c.shape[std::size_t(k)] = delta_[std::size_t(corner_nodes[std::size_t(k)])];
    c.range.least += *std::min_element(c.shape.begin(), c.shape.end());
    c.range.greatest += *std::max_element(c.shape.begin(), c.shape.end());
  }
  if (!film_->relief.flat()) {
    c.relief = true;
    c.relief_start = film_->relief.cell_start(i, j);
    c.relief_end = film_->relief.cell_end(i, j);
    c.range.least += std::min(c.relief_start, c.relief_end);
    c.range.greatest += std::max(c.relief_start, c.relief_end);
  }
  return c;
}

double FilmGap::at_point(double r, double theta, int i, int j, double s, double t) const {
  double h = film_->node_gap_polar(q_, r, theta);
  if (shaped()) {
    const FilmMesh& m = film_->mesh;
    const auto v = [&](int di, int dj) { return delta_[std::size_t(m.node(i + di, j + dj))]; };
    h += (1 - s) * (1 - t) * v(0, 0) + s * (1 - t) * v(1, 0) + (1 - s) * t * v(0, 1) + s * t * v(1, 1);
  }
  if (!film_->relief.flat()) h += film_->relief.in_cell(i, j, t);
  return h;
}

const LinearForm& FilmGap::shape_form(int n) const { return model_->shape_form(*film_, n); }

// Each part's forms in the order the parts were registered: with one part, its own forms.
void BearingModel::build_shape_forms() {
  shape_forms_.assign(films_.size(), {});
  for (const Film& film : films_) {
    std::vector<LinearForm>& forms = shape_forms_[std::size_t(film.number - 1)];
    forms.resize(std::size_t(film.mesh.node_count()));
    for (const std::unique_ptr<GapContribution>& part : gap_parts_)
      if (part->moves(film)) part->add_node_forms(*this, film, deformation_scale_, forms);
  }
}

void BearingModel::set_deformation_scale(double s) {
  if (s == deformation_scale_) return;
  deformation_scale_ = s;
  // The same terms with other coefficients: the pattern and its slot tape still hold.
  build_shape_forms();
}

bool BearingModel::gap_shaped(const Film& film) const {
  for (const std::unique_ptr<GapContribution>& part : gap_parts_)
    if (part->moves(film)) return true;
  return false;
}

double BearingModel::shape_at(std::span<const double> u, const Film& film, int node) const {
  double delta = 0.0;
  for (const auto& [k, c] : shape_form(film, node).terms) delta += c * u[std::size_t(k)];
  return delta;
}

std::vector<double> BearingModel::node_shapes(std::span<const double> u, const Film& film) const {
  std::vector<double> delta(gap_shaped(film) ? std::size_t(film.mesh.node_count()) : 0);
  for (std::size_t n = 0; n < delta.size(); ++n) delta[n] = shape_at(u, film, int(n));
  return delta;
}

double BearingModel::least_gap(std::span<const double> u, const Film& film) const {
  return FilmGap(*this, u, film).least();
}

}  // namespace twb
