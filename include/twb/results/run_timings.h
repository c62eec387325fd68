// What a run cost: wall times and the solvers' counts, as run.json reports them.
#pragma once

namespace twb {

struct RunTimings {
  // setup: building the bearing's model; solve: the study; total: both, and writing the
  // journal of a run into a directory (not reading the scene, nor writing the files).
  double total_ms = 0.0, setup_ms = 0.0, solve_ms = 0.0;
  int states = 0;
  long newton_iterations = 0, jacobian_evaluations = 0;
  // Distress searches: their transients, IDA steps and the KLU factorizations inside IDA;
  // and every KLU factorization of the study, twb's own and IDA's.
  long transients = 0, ida_steps = 0, ida_factorizations = 0, klu_factorizations = 0;
};

}  // namespace twb
