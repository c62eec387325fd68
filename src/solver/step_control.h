// What both continuations (natural, pseudo-arclength) do with a step: correct the
// prediction by Newton, and adapt the step: longer after an easy correction, since
// Newton's few iterations say the prediction was close; halved after a rejected one;
// below a floor the continuation gives up and reports.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "solver/kinsol_newton.h"

namespace twb {

class StepControl {
 public:
  StepControl(double initial, double min, double max, double growth, int easy_iterations)
      : step_(std::min(initial, max)), min_(min), max_(max), growth_(growth), easy_(easy_iterations) {}

  double step() const { return step_; }
  double min_step() const { return min_; }
  void accept(long corrector_iterations) {
    if (corrector_iterations <= easy_) step_ = std::min(step_ * growth_, max_);
  }
  // Halves the step; false once it falls below the minimum.
  bool reject() {
    step_ *= 0.5;
    return step_ >= min_;
  }

 private:
  double step_, min_, max_, growth_;
  int easy_;
};

// Newton from the prediction in x, which it replaces by the last iterate; counts the
// iterations into `total`. Returns why the correction failed, or nothing.
inline std::string correct(KinsolNewton& newton, std::vector<double>& x, const NewtonSettings& settings,
                           long& iterations, long& total) {
  const NewtonReport rep = newton.solve(x, settings);
  iterations = rep.iterations;
  total += rep.iterations;
  return rep.converged ? std::string() : "the corrector did not converge: " + rep.message;
}

}  // namespace twb
