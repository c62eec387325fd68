// A thrust washer bearing as a program that embeds twb sees it: built from a scene
// (twb/scene/scene_loader.h), it solves steady states at the loads and speeds asked for
// and runs the study its scene names. The model, its solvers and their settings stay
// behind this class (docs/api.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "twb/model/unknown_block.h"
#include "twb/results/states_table.h"
#include "twb/scene/scene.h"
#include "twb/study/study_outcome.h"

namespace twb {

class BearingModel;

class Bearing {
 public:
  // The scene as loaded (load_scene); throws std::invalid_argument for a combination of
  // settings the model cannot build.
  explicit Bearing(const Scene& scene);
  ~Bearing();
  Bearing(Bearing&&) noexcept;
  Bearing& operator=(Bearing&&) noexcept;

  const Scene& scene() const;
  std::vector<UnknownBlock> unknowns() const;
  long unknown_count() const;
  long jacobian_nonzeros() const;

  // The steady state at `load` (N) and `speed` (rad/s): Newton from the last state this
  // object solved, which is what a caller stepping through nearby operating points wants
  // (one or two iterations), and from the paper's cold start the first time or after a
  // failure, with the same fall-backs as a study's point (pseudo-time, ramps). Throws
  // twb::SolverFailure when no steady state is found; the last good state is kept.
  SolvedState solve(double load, double speed);
  // Forgets the last state: the next solve starts cold, as `twb run` on a point does.
  void forget_state();

  // The study the scene names, as `twb run` runs it (the same numbers to the last bit),
  // without writing anything. The load and speed are the scene's.
  StudyOutcome run_study(const ProgressReport& progress = {}, const RunOptions& options = {});

  // The model itself, for twb's own layers (its header is not installed).
  BearingModel& model() { return *model_; }

 private:
  std::unique_ptr<BearingModel> model_;
  std::vector<double> state_;
};

}  // namespace twb
