// The paper's case as the benchmarks use it: the shipped scene at a load and speed,
// and its converged state from the cold start.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/searches/steady_solver.h"

namespace twb::bench {

inline Scene paper_scene(double load, double speed) {
  Scene s = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml");
  s.operating.load = load;
  s.operating.speed = speed;
  return s;
}

// The converged state of the model at its load and speed, from the cold start.
inline std::vector<double> converged_state(BearingModel& model) {
  SteadySolver solver(model, {});
  std::vector<double> u;
  if (!solver.solve_cold(u).converged) throw std::runtime_error("no converged state from the cold start");
  return u;
}

}  // namespace twb::bench
