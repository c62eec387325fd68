// A scene solved from its cold start, and its sliding film's fields: what the closed-form
// checks of a film alone compare with.
#pragma once

#include <gtest/gtest.h>

#include "model/bearing_model.h"
#include "study/steady_solver.h"

namespace twb::testing {

inline FilmFields solved_sliding_film(const Scene& scene) {
  BearingModel model(scene);
  std::vector<double> u;
  const SteadyReport rep = SteadySolver(model, {}).solve_cold(u);
  EXPECT_TRUE(rep.converged) << rep.message;
  for (const FilmFields& f : model.fields(u))
    if (f.sliding) return f;
  ADD_FAILURE() << "no sliding film";
  return model.fields(u).front();
}

}  // namespace twb::testing
