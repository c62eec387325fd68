// The maximum over a state's films of a quantity defined at every point (a FilmPoint's
// film temperature, the asperities' contact temperature), located between the nodes
// (docs/physics.md section 8): the hottest node of each film, then Brent's search along
// θ and r within the cells beside it, alternately, until neither moves. A quantity
// continuous in (r, θ) then has a maximum that moves continuously with the state and
// converges with the mesh as the fields it is read from do, where the hottest node's
// value jumps as the hot spot passes from node to node.
#pragma once

#include <functional>

#include "model/film.h"

namespace twb {

struct LocatedMaximum {
  double value = 0.0;
  int film = 0;  // its number, 1 or 2; 0 where no film holds the quantity
  double r = 0.0, theta = 0.0;
};

// value(film, r, θ); films for which `applies` is false are skipped.
LocatedMaximum locate_maximum(const std::vector<Film>& films,
                              const std::function<double(const Film&, double, double)>& value,
                              const std::function<bool(const Film&)>& applies);

}  // namespace twb
