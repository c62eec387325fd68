#include "model/face_relief.h"

#include "twb/error_family.h"

namespace twb {

namespace {

// The whole cells of a land of `land` cells that its shaped inlet covers (none for a flat
// land): the scene resolved the fraction to whole cells, so this only undoes the ratio.
int inlet_cells(const Land& shape, int land) {
  return shape.shape == LandShape::flat ? 0 : int(shape.fraction * land + 0.5);
}

}  // namespace

FaceRelief::FaceRelief(const Grooves& grooves, int circumferential_nodes) {
  const int pitch = circumferential_nodes / grooves.count;
  const int land = pitch - grooves.cells;
  if (pitch * grooves.count != circumferential_nodes || grooves.cells < 1 || land < 1)
    throw InternalError("FaceRelief: the grooves are not resolved to whole cells of the grid");
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

std::optional<Grooves> grooves_on_grid(const Grooves& grooves, int from, int to) {
  // Every edge lies on a line k·(from/count) + whole cells: it stays on one if each
  // whole number of cells scales to a whole number.
  const int pitch_from = from / grooves.count;
  if (to % grooves.count != 0) return std::nullopt;
  const int pitch_to = to / grooves.count;
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
  return out;
}

FaceRelief::Halves FaceRelief::node_halves(int j) const {
  const int n = int(start_.size());
  const int before = (j - 1 + n) % n, after = j % n;
  return {start_[before] + 0.75 * (end_[before] - start_[before]),
          start_[after] + 0.25 * (end_[after] - start_[after])};
}

}  // namespace twb
