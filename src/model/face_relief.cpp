#include "model/face_relief.h"

#include <algorithm>
#include <cmath>

#include "twb/error_family.h"

namespace twb {

namespace {

// The whole cells of a land of `land` cells that its shaped inlet covers (none for a flat
// land): the scene resolved the fraction to whole cells, so this only undoes the ratio.
int inlet_cells(const Land& shape, int land) {
  return shape.shape == LandShape::flat ? 0 : int(shape.fraction * land + 0.5);
}

}  // namespace

FaceRelief::FaceRelief(const Grooves& grooves, const FilmMesh& mesh) {
  const int circumferential_nodes = mesh.circumferential_nodes();
  const int pitch = circumferential_nodes / grooves.count;
  const int land = pitch - grooves.cells;
  if (pitch * grooves.count != circumferential_nodes || grooves.cells < 1 || land < 1)
    throw InternalError("FaceRelief: the grooves are not resolved to whole cells of the grid");
  const int rows = mesh.radial_nodes() - 1;
  first_row_ = 0;
  end_row_ = rows;
  if (const std::optional<GrooveDam>& dam = grooves.closed_at) {
    if (dam->line < 1 || dam->line >= rows)
      throw InternalError("FaceRelief: the grooves' dam is not on an interior radial line of the grid");
    (dam->open_at == GrooveOpening::inner_radius ? end_row_ : first_row_) = dam->line;
  }
  // A node's control volume reaches half a cell either side of its radius: the part
  // beyond its line holds (r + Δr/4)/(2r) of its area.
  outer_share_.assign(std::size_t(mesh.radial_nodes()), 0.0);
  outer_share_.front() = 1.0;
  for (int i = 1; i < rows; ++i) outer_share_[std::size_t(i)] = (mesh.radius(i) + 0.25 * mesh.dr()) / (2.0 * mesh.radius(i));
  start_.assign(std::size_t(circumferential_nodes), 0.0);
  end_.assign(std::size_t(circumferential_nodes), 0.0);
  groove_.assign(std::size_t(circumferential_nodes), 0);
  const Land& shape = grooves.land;
  const int inlet = inlet_cells(shape, land);
  for (int first = 0; first < circumferential_nodes; first += pitch) {
    for (int c = 0; c < grooves.cells; ++c) {
      start_[first + c] = end_[first + c] = grooves.depth;
      groove_[first + c] = 1;
    }
    for (int c = 0; c < inlet; ++c) {
      const int j = first + grooves.cells + c;
      if (shape.shape == LandShape::step) {
        start_[j] = end_[j] = shape.depth;
      } else {
        // The taper falls linearly from its depth at the inlet edge to the flat land.
        start_[j] = shape.depth * (1.0 - double(c) / inlet);
        end_[j] = shape.depth * (1.0 - double(c + 1) / inlet);
      }
    }
  }
}

std::optional<Grooves> grooves_on_grid(const Grooves& grooves, std::array<int, 2> from, std::array<int, 2> to) {
  // Every edge lies on a line k·(from/count) + whole cells: it stays on one if each
  // whole number of cells scales to a whole number; a dam's radial line likewise.
  const int pitch_from = from[1] / grooves.count;
  if (to[1] % grooves.count != 0) return std::nullopt;
  const int pitch_to = to[1] / grooves.count;
  auto scaled = [&](int cells) -> std::optional<int> {
    if ((cells * pitch_to) % pitch_from != 0) return std::nullopt;
    return cells * pitch_to / pitch_from;
  };
  const std::optional<int> cells = scaled(grooves.cells);
  if (!cells || *cells < 1 || *cells >= pitch_to) return std::nullopt;
  Grooves out = grooves;
  out.cells = *cells;
  if (grooves.land.shape != LandShape::flat) {
    const int land = pitch_from - grooves.cells;
    const std::optional<int> inlet = scaled(inlet_cells(grooves.land, land));
    const int land_to = pitch_to - *cells;
    if (!inlet || *inlet < 1 || *inlet > land_to || (grooves.land.shape == LandShape::step && *inlet == land_to))
      return std::nullopt;
    out.land.fraction = double(*inlet) / land_to;
  }
  if (out.closed_at) {
    const int rows_from = from[0] - 1, rows_to = to[0] - 1;
    const int line = out.closed_at->line;
    if ((line * rows_to) % rows_from != 0) return std::nullopt;
    out.closed_at->line = line * rows_to / rows_from;
    if (out.closed_at->line < 1 || out.closed_at->line >= rows_to) return std::nullopt;
  }
  return out;
}

FaceRelief::Halves FaceRelief::across_line(int i, int j) const {
  const int n = int(start_.size());
  const int before = (j - 1 + n) % n, after = j % n;
  const double b0 = cell_start(i, before), a0 = cell_start(i, after);
  return {b0 + 0.75 * (cell_end(i, before) - b0), a0 + 0.25 * (cell_end(i, after) - a0)};
}

FaceRelief::Halves FaceRelief::across_row(int i, int j) const {
  const int rows = int(outer_share_.size()) - 1;
  return {in_cell(std::max(i - 1, 0), j, 0.5), in_cell(std::min(i, rows - 1), j, 0.5)};
}

FaceRelief::NodeParts FaceRelief::node_parts(int i, int j) const {
  const int rows = int(outer_share_.size()) - 1;
  const Halves inner = across_line(std::max(i - 1, 0), j), outer = across_line(std::min(i, rows - 1), j);
  NodeParts parts;
  if (i == 0 || i == rows || (inner.before == outer.before && inner.after == outer.after)) {
    const Halves h = i == 0 ? outer : inner;
    if (h.before == h.after) {
      parts.relief[0] = h.before;
      parts.share[0] = 1.0;
      return parts;
    }
    parts.count = 2;
    parts.relief = {h.before, h.after, 0.0, 0.0};
    parts.share = {0.5, 0.5, 0.0, 0.0};
    return parts;
  }
  const double w = outer_share_[std::size_t(i)];
  parts.count = 4;
  parts.relief = {inner.before, inner.after, outer.before, outer.after};
  parts.share = {0.5 * (1.0 - w), 0.5 * (1.0 - w), 0.5 * w, 0.5 * w};
  return parts;
}

double FaceRelief::least_at_node(int i, int j) const {
  const int n = int(start_.size()), rows = int(outer_share_.size()) - 1;
  const int before = (j - 1 + n) % n, after = j % n;
  double least = INFINITY;
  for (int row : {i - 1, i})
    if (row >= 0 && row < rows) least = std::min({least, cell_end(row, before), cell_start(row, after)});
  return least;
}

}  // namespace twb
