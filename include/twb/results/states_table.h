// states.csv: one row per solved state, units in the column names (issue contract).
#pragma once

#include <string>
#include <vector>

#include "twb/model/bearing_model.h"

namespace twb {

struct SolvedState {
  BearingState state;
  bool converged = false;
  long iterations = 0;
  double residual = 0.0;
  double wall_ms = 0.0;
  // Film 1 and film 2 on their polar grids when the scene asks for them
  // (output.fields); empty otherwise. Written by fields_table.h.
  std::vector<FilmFields> fields;
};

std::string states_csv(const std::vector<SolvedState>& rows);

// The short table printed after a run.
std::string states_summary(const std::vector<SolvedState>& rows);

}  // namespace twb
