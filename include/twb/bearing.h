// A thrust washer bearing as a program that embeds twb sees it: built from a scene
// (twb/scene/scene_loader.h), it solves steady states at the loads and speeds asked for
// and runs the study its scene names. The model, its solvers and their settings stay
// behind this class (docs/api.md). One thread at a time per Bearing: its model keeps
// what it learned between solves (the last state, where its Jacobian's entries land);
// separate Bearings may solve on separate threads.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "twb/model/unknown_block.h"
#include "twb/results/results_directory.h"
#include "twb/results/states_table.h"
#include "twb/scene/scene.h"
#include "twb/study/study_outcome.h"

namespace twb {

class BearingModel;

// The results directories of a job array's slices (twb run --slice K/N) as
// ResultsRun::slices takes them in: each must hold the journal of a run of `scene`;
// std::invalid_argument naming the first that does not. Bearing::run_into checks them
// too; a caller checks first to refuse them before it claims its own directory.
void check_job_slices(const std::vector<std::string>& slices, const Scene& scene);

// How a study runs into a results directory (Bearing::run_into).
struct ResultsRun {
  // Keep the searches a killed run of the same scene journaled in the directory and run
  // only the others (twb run --resume); without, its journal is started afresh.
  bool resume = false;
  // Significant digits of every number in the general columns (17: each reads back as
  // the very double twb computed).
  int digits = 10;
  // The results directories of a job array's slices (twb run --slice K/N) of this
  // scene's study: their journaled searches are taken in and none runs here (twb merge).
  std::vector<std::string> slices = {};
};

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
  // (a few iterations), and from the paper's cold start the first time (or after
  // forget_state), with the same fall-backs as a study's point (pseudo-time, ramps).
  // Throws twb::SolverFailure when no steady state is found; the last good state is
  // kept. Between the cool branch's fold (W_d) and the hot branch's return, two steady
  // states exist at one load: a warm start stays on the branch it comes from, a cold
  // start finds the cool one if it can. The state says neither (its `branch` is empty);
  // a load sweep study follows and names the branches.
  SolvedState solve(double load, double speed);
  // How the last state solve() found moves with one input (docs/physics.md section 16):
  // (name, d quantity / d input) for torque_Nm, f_eff, T_mean_C, T_max_C, hmin_over_sigma
  // and fluid_share, per SI unit of the input at `path` ("geometry.gear.tilt",
  // "operating.speed"; a temperature per kelvin). Throws std::logic_error before any
  // solve, std::invalid_argument for a path that names no input, InputError where the
  // input's neighbourhood (±2·10⁻⁴ of it) leaves its range.
  std::vector<std::pair<std::string, double>> sensitivity(const std::string& path);
  // Forgets the last state: the next solve starts cold, as `twb run` on a point does.
  void forget_state();

  // The study the scene names, as `twb run` runs it (the same numbers to the last bit),
  // without writing anything, at the scene's load and speed whatever solve() was asked.
  // Its timings count the model's set-up (when this Bearing was built) and the study.
  StudyOutcome run_study(const ProgressReport& progress = {}, const RunOptions& options = {});
  // The study run into a results directory claimed beforehand (so that a directory
  // another run holds or that cannot be written is refused before the model is built), as
  // twb run and twb.run(out=DIR) do: each finished search of a sweep, map or sliding
  // choice journaled there at once (a killed run resumes from them), then every table,
  // the states' fields, a duty cycle's end and run.json last, each file atomically. Not
  // written: a study told to stop (RunOptions::stop), whose journal keeps the searches it
  // finished, and one whose scheduler does not take the results (a slice: its journal is
  // its result). std::invalid_argument for a journal or a slice of another scene's run.
  StudyOutcome run_into(const ResultsDirectory& directory, const ResultsRun& run, const ProgressReport& progress = {},
                        const RunOptions& options = {});
  // A study's results written into `directory` as `twb run` writes them there: the
  // directory made and locked against another run writing into it, an earlier run's files
  // removed, every table as CSV with `digits` significant digits, the states' fields,
  // a duty cycle's end, and run.json last (each file atomically). std::runtime_error,
  // saying which directory and why, where it cannot be used.
  void write_results(const std::string& directory, const StudyOutcome& outcome, int digits = 10) const;

  // A moved-from Bearing may only be assigned to or destroyed.

 private:
  std::unique_ptr<BearingModel> model_;
  // The scene as given: a study moves the model's own (a curve's parameter, a duty
  // cycle's speed, ambient and tilt), and the results record the scene that ran.
  Scene scene_;
  std::vector<double> state_;
  double scene_load_ = 0.0, scene_speed_ = 0.0;  // where the scene puts the bearing
  double state_load_ = 0.0, state_speed_ = 0.0;  // where state_ was solved
  double setup_ms_ = 0.0;                         // building the model
};

}  // namespace twb
