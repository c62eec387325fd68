// The face relief g(θ) of a film (docs/physics.md section 14): the extra gap of the
// washer's grooves and of its lands' shaped inlets, at rest in the load frame. It lives
// on the columns of the film's grid (column j: the cells between node lines j and j+1),
// linear across each column, so that every edge of a groove, step or taper lies on a
// node line and each bilinear cell lies wholly in one part of the face. A flat face has
// no relief and costs nothing.
#pragma once

#include <optional>
#include <vector>

#include "twb/scene/scene.h"

namespace twb {

class FaceRelief {
 public:
  FaceRelief() = default;
  // The grooves on a grid of `circumferential_nodes` columns (a multiple of their count,
  // the widths whole cells: the scene resolved them so). The moving face travels towards
  // +θ, so a land's inlet is its edge at the groove before it.
  FaceRelief(const Grooves& grooves, int circumferential_nodes);

  bool flat() const { return start_.empty(); }
  // g at the fraction t ∈ [0, 1] across column j.
  double in_column(int j, double t) const { return start_[j] + t * (end_[j] - start_[j]); }
  double column_start(int j) const { return start_[j]; }
  double column_end(int j) const { return end_[j]; }
  // The mean of g over the two halves of the control volume of a node on line j: the
  // upper half of column j − 1 and the lower half of column j. Equal off every edge.
  struct Halves {
    double before, after;
  };
  Halves node_halves(int j) const;
  // Whether node line j bounds a groove: inside one or on either of its edges, where a
  // groove fed with oil holds the supply's pressure (docs/physics.md section 14).
  bool on_groove(int j) const {
    const int n = int(groove_.size());
    return !groove_.empty() && (groove_[std::size_t((j - 1 + n) % n)] || groove_[std::size_t(j % n)]);
  }

 private:
  std::vector<double> start_, end_;  // g on each column's two node lines
  std::vector<char> groove_;         // whether each column lies in a groove
};

// The grooves on a grid of `to` circumferential nodes instead of `from`, their angles
// kept (a coarser grid of a mesh sequence, a finer one of an error bar): none where that
// grid cannot hold every edge of theirs on a node line.
std::optional<Grooves> grooves_on_grid(const Grooves& grooves, int from, int to);

}  // namespace twb
