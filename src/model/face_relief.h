// The face relief g(r, θ) of a film (docs/physics.md section 14): the extra gap of the
// washer's grooves and of its lands' shaped inlets, at rest in the load frame. It lives
// on the cells of the film's grid (cell (i, j): between radial lines i, i+1 and node
// lines j, j+1), linear in θ across each, so that every edge of a groove, step, taper or
// dam lies on a node line and each bilinear cell lies wholly in one part of the face.
// The lands' shapes run from rim to rim; a groove closed short of a rim is cut in the
// rows from its open rim to its dam only. A flat face has no relief and costs nothing.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "twb/model/film_mesh.h"
#include "twb/scene/scene.h"

namespace twb {

class FaceRelief {
 public:
  FaceRelief() = default;
  // The grooves on a grid (its circumferential node count a multiple of their count, the
  // widths whole cells, a dam on one of its radial lines: the scene resolved them so).
  // The moving face travels towards +θ, so a land's inlet is its edge at the groove
  // before it.
  FaceRelief(const Grooves& grooves, const FilmMesh& mesh);

  bool flat() const { return start_.empty(); }
  // g at the fraction t ∈ [0, 1] across cell (i, j), and on its two node lines.
  double in_cell(int i, int j, double t) const {
    const double s = cell_start(i, j);
    return s + t * (cell_end(i, j) - s);
  }
  double cell_start(int i, int j) const { return cut(i, j) ? start_[std::size_t(j)] : 0.0; }
  double cell_end(int i, int j) const { return cut(i, j) ? end_[std::size_t(j)] : 0.0; }

  // The two halves of a Reynolds face, each with its own mean relief (equal off every
  // edge): a radial face in row i straddles node line j (the upper half of column j − 1,
  // the lower half of column j); a circumferential face at the middle of column j, on
  // node row i, straddles radial line i (the upper half of row i − 1, the lower of row i).
  struct Halves {
    double before, after;
  };
  Halves across_line(int i, int j) const;
  Halves across_row(int i, int j) const;
  // Of node row i's control volume, the share beyond its line: (r + Δr/4)/(2r), ½ with
  // Δr/r → 0 (1 on the inner rim, 0 on the outer).
  double outer_share(int i) const { return outer_share_[std::size_t(i)]; }

  // The parts of the control volume of node (i, j), each with its mean relief and its
  // share of the node's area: one off every edge, two halves beside a groove's or a
  // step's edge line, four quarters on a dam's line beside a groove (the inner rows'
  // halves first).
  struct NodeParts {
    std::array<double, 4> relief{}, share{1.0, 0.0, 0.0, 0.0};
    int count = 1;
  };
  NodeParts node_parts(int i, int j) const;
  // The least relief at node (i, j) itself: the lowest of the cells meeting there.
  double least_at_node(int i, int j) const;

  // Whether node (i, j) bounds a groove: inside one or on any of its edges, a dam's
  // included, where a groove fed with oil holds the supply's pressure (physics §14).
  bool on_groove(int i, int j) const {
    const int n = int(groove_.size());
    return !groove_.empty() && i >= first_row_ && i <= end_row_ &&
           (groove_[std::size_t((j - 1 + n) % n)] || groove_[std::size_t(j % n)]);
  }

 private:
  // Whether cell (i, j) carries the column's relief: a land's always, a groove's in the
  // rows it is cut in.
  bool cut(int i, int j) const { return !groove_[std::size_t(j)] || (i >= first_row_ && i < end_row_); }

  std::vector<double> start_, end_;  // g on each column's two node lines where it is cut
  std::vector<char> groove_;         // whether each column lies in a groove
  int first_row_ = 0, end_row_ = 0;  // the rows of cells the grooves are cut in: [first, end)
  std::vector<double> outer_share_;  // of each node row's control volume, the part beyond its line
};

// The grooves on a grid of `to` nodes (radial, circumferential) instead of `from`, their
// angles and dam's radius kept (a coarser grid of a mesh sequence, a finer one of an
// error bar): none where that grid cannot hold every edge of theirs on a node line.
std::optional<Grooves> grooves_on_grid(const Grooves& grooves, std::array<int, 2> from, std::array<int, 2> to);

}  // namespace twb
