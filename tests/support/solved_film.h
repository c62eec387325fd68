// A scene solved from its cold start, and its sliding film's fields: what the closed-form
// checks of a film alone compare with.
#pragma once

#include <gtest/gtest.h>

#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb::testing {

// The sliding film's fields and the state's reported quantities (its flows among them).
struct SolvedFilm {
  FilmFields film;
  BearingState state;
};

inline SolvedFilm solved_film_and_state(const Scene& scene) {
  BearingModel model(scene);
  std::vector<double> u;
  const SteadyReport rep = SteadySolver(model, {}).solve_cold(u);
  EXPECT_TRUE(rep.converged) << rep.message;
  const BearingState state = model.describe(u);
  for (const FilmFields& f : model.fields(u))
    if (f.sliding) return {f, state};
  ADD_FAILURE() << "no sliding film";
  return {model.fields(u).front(), state};
}

inline FilmFields solved_sliding_film(const Scene& scene) { return solved_film_and_state(scene).film; }

}  // namespace twb::testing
