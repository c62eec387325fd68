// What every study needs from the scene and the clock: the scene's Newton settings and
// elapsed wall time.
#pragma once

#include <chrono>

#include "twb/scene/scene.h"
#include "twb/solver/kinsol_newton.h"

namespace twb {

inline NewtonSettings newton_settings(const Scene& s) {
  NewtonSettings n;
  n.residual_tolerance = s.solver.residual_tolerance;
  n.step_tolerance = s.solver.step_tolerance;
  n.max_iterations = s.solver.max_iterations;
  return n;
}

inline double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace twb
