#include "twb/bearing.h"

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "twb/results/results_directory.h"
#include "study/results_files.h"
#include "study/parallel/search_journal.h"
#include "study/parallel/search_scheduler.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"
#include "study/searches/operating_point.h"
#include "study/uncertainty/sensitivity.h"
#include "solver/sparse_lu.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace twb {

Bearing::Bearing(const Scene& scene)
    : scene_(scene), scene_load_(scene.operating.load), scene_speed_(scene.operating.speed) {
  const auto t0 = std::chrono::steady_clock::now();
  model_ = std::make_unique<BearingModel>(scene);
  setup_ms_ = elapsed_ms(t0);
}
Bearing::~Bearing() = default;
Bearing::Bearing(Bearing&&) noexcept = default;
Bearing& Bearing::operator=(Bearing&&) noexcept = default;

const Scene& Bearing::scene() const { return scene_; }

std::vector<UnknownBlock> Bearing::unknowns() const { return model_->layout().blocks(); }

long Bearing::unknown_count() const { return long(model_->size()); }
long Bearing::jacobian_nonzeros() const { return long(model_->pattern().nnz()); }

namespace {

// The model at another operating point for one solve, back at the scene's afterwards
// (on every way out), so that scene() and run_study() stay the scene's.
class OperatingPoint {
 public:
  OperatingPoint(BearingModel& model, double load, double speed, double scene_load, double scene_speed)
      : model_(model), scene_load_(scene_load), scene_speed_(scene_speed) {
    model_.set_load(load);
    model_.set_speed(speed);
  }
  ~OperatingPoint() {
    model_.set_load(scene_load_);
    model_.set_speed(scene_speed_);
  }
  OperatingPoint(const OperatingPoint&) = delete;
  OperatingPoint& operator=(const OperatingPoint&) = delete;

 private:
  BearingModel& model_;
  double scene_load_, scene_speed_;
};

}  // namespace

SolvedState Bearing::solve(double load, double speed) {
  const OperatingPoint at(*model_, load, speed, scene_load_, scene_speed_);
  SteadySolver solver(*model_, newton_settings(model_->scene()));
  std::vector<double> u = state_;
  const SteadyReport rep = u.empty() ? solver.solve_cold(u) : solver.solve(u);
  if (!rep.converged)
    throw SolverFailure(fmt::format("no steady state at {:.6g} N, {:.6g} rad/s: {}", load, speed, rep.message), -1);
  state_ = u;
  state_load_ = load;
  state_speed_ = speed;
  return recorded_state(*model_, u, rep);
}

void Bearing::forget_state() { state_.clear(); }

std::vector<std::pair<std::string, double>> Bearing::sensitivity(const std::string& path) {
  // The path first: a misspelt one is the caller's first mistake whatever the state.
  const SceneInput input = scene_input(scene_, path);
  if (state_.empty())
    throw std::logic_error("Bearing::sensitivity: no state solved yet (call solve first; a solve that fails leaves "
                           "none)");
  const OperatingPoint at(*model_, state_load_, state_speed_, scene_load_, scene_speed_);
  const std::unique_ptr<SparseLu> factors = jacobian_factors(*model_, state_);
  if (!factors)
    throw SolverFailure(fmt::format("the state at {:.6g} N has a singular Jacobian (a fold): it does not move "
                                    "smoothly with {}",
                                    state_load_, path),
                        -1);
  InputNeighbours neighbours = input_neighbours(*model_, input);
  std::mutex solve_lock;
  const std::vector<double> d = state_derivatives(neighbours, state_, state_load_, *factors, solve_lock);
  std::vector<std::pair<std::string, double>> out;
  const std::vector<StateQuantity> names = state_quantities(BearingState{});
  for (std::size_t k = 0; k < names.size(); ++k) out.emplace_back(names[k].name, d[k]);
  return out;
}

StudyOutcome Bearing::run_study(const ProgressReport& progress, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  StudyOutcome outcome = twb::run_study(*model_, progress, options);
  outcome.timings.setup_ms = setup_ms_;
  outcome.timings.total_ms = setup_ms_ + elapsed_ms(t0);
  return outcome;
}

namespace {

void take_in_slices(const std::vector<std::string>& slices, const SearchJournal& journal) {
  for (const std::string& dir : slices) {
    const SearchJournal slice(dir, *SearchJournal::scene_of(dir), true);
    for (std::size_t i : slice.entries()) journal.write_entry(i, slice.entry_bytes(i));
  }
}

}  // namespace

void check_job_slices(const std::vector<std::string>& slices, const Scene& scene) {
  const std::string scene_text = describe_scene(scene);
  for (const std::string& dir : slices) {
    const std::optional<std::string> text = SearchJournal::scene_of(dir);
    if (!text)
      throw std::invalid_argument(fmt::format("'{}' holds no journaled searches (the results directory of a twb "
                                              "run --slice K/N is meant)",
                                              dir));
    if (!SearchJournal::same_scene(*text, scene_text))
      throw std::invalid_argument(
          fmt::format("'{}' belongs to another scene (or other --set values) than this run's", dir));
  }
}

StudyOutcome Bearing::run_into(const ResultsDirectory& directory, const ResultsRun& run, const ProgressReport& progress,
                               const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string scene_text = describe_scene(scene_);
  check_job_slices(run.slices, scene_);
  const SearchJournal journal(directory.path(), scene_text, run.resume && run.slices.empty(),
                              scene_.worn ? SearchJournal::worn_identity(*scene_.worn) : std::string());
  RunOptions how = options;
  JournalOnlyScheduler only_journaled;
  if (!run.slices.empty()) {
    take_in_slices(run.slices, journal);
    how.scheduler = &only_journaled;
  }
  StudyOutcome outcome = twb::run_study(*model_, progress, how, &journal);
  outcome.timings.setup_ms = setup_ms_;
  outcome.timings.total_ms = setup_ms_ + elapsed_ms(t0);
  const bool stopped = options.stop && options.stop->load();
  if (stopped || (how.scheduler && !how.scheduler->takes_results())) return outcome;
  write_study_results(directory.path(), scene_.source, scene_, model_->layout(), outcome, run.digits);
  journal.finish();
  return outcome;
}

void Bearing::write_results(const std::string& directory, const StudyOutcome& outcome, int digits) const {
  const ResultsDirectory ready(directory);
  write_study_results(directory, scene_.source, scene_, model_->layout(), outcome, digits);
}

}  // namespace twb
