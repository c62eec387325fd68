// The twb command: `twb check SCENE`, `twb run SCENE` (also under mpirun, or one slice of a
// job array) and `twb merge` (a job array's slices into one results directory).
// Exit status: 0 success (a distress found is a result), 2 invalid input,
// 3 solver failure, 4 internal error, 5 input/output error (twb/error_family.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "interruption.h"
#include "mpi_searches.h"
#include "study/parallel/progress_heartbeat.h"
#include "study/parallel/search_journal.h"
#include "study/parallel/search_scheduler.h"
#include "study/study_support.h"
#include "twb/bearing.h"
#include "twb/error_family.h"
#include "twb/input_error.h"
#include "twb/results/limit_notes.h"
#include "twb/results/results_directory.h"
#include "twb/results/state_quantities.h"
#include "twb/results/states_table.h"
#include "twb/scene/material_library.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/result_columns.h"
#include "twb/version.h"

namespace {

constexpr int exit_invalid_input = int(twb::ErrorKind::input);
constexpr int exit_solver_failure = int(twb::ErrorKind::solver);

std::string unknowns_table(const twb::Bearing& bearing) {
  std::string out = "unknowns:\n";
  for (const twb::UnknownBlock& b : bearing.unknowns())
    out += fmt::format("  {:<44} {:>6}   ({})\n", b.name, b.size, twb::effect_name(b.effect));
  out += fmt::format("  {:<44} {:>6}\n", "total", bearing.unknown_count());
  return out;
}

// docs/physics.md section 13: the moments depend on the sampling interval and the filter, so
// they are shown with the estimate.
std::string profile_table(const twb::AsperityParameters& a) {
  if (!a.profile) return "";
  const twb::ProfileEstimate& p = *a.profile;
  std::string out = "summit statistics from measured profiles (McCool 1986, docs/physics.md section 13):\n";
  for (std::size_t k = 0; k < p.files.size(); ++k)
    out += fmt::format("  {}: {} heights at {:.6g} m, {:.6g} m long, used as given (mean removed, no filter)\n",
                       p.files[k], p.samples[k], p.spacings[k], p.spacings[k] * double(p.samples[k] - 1));
  out += fmt::format("  m0 = {:.6g} m^2 (Rq {:.4g} m), m2 = {:.6g}, m4 = {:.6g} 1/m^2, bandwidth alpha = {:.4g}\n",
                     p.m0, std::sqrt(p.m0), p.m2, p.m4, p.bandwidth);
  out += fmt::format("  summit density {:.6g} 1/m^2, summit radius {:.6g} m, summit sigma {:.6g} m, "
                     "eta R sigma_s = {:.4g}\n",
                     a.summit_density, a.summit_radius, a.summit_sigma, a.eta_r_sigma);
  return out;
}

// The oil's Roelands constants fitted to its data sheet or table, and the fit's error at
// every given point (docs/physics.md section 5).
std::string viscosity_fit_table(const twb::Lubricant& l) {
  if (!l.viscosity_source) return {};
  const twb::ViscositySource& src = *l.viscosity_source;
  std::string out = fmt::format("viscosity fitted to the scene's {}: mu_infinity = {:.6g} Pa s, G0 = {:.6g}, S0 = "
                                "{:.6g}; largest error over the fit {:.3g} %\n",
                                src.kind == "data_sheet" ? "data sheet" : "table", l.mu_infinity, l.g0, l.s0,
                                100.0 * src.largest_error);
  for (std::size_t k = 0; k < src.temperatures.size(); ++k)
    out += fmt::format("  {:7.2f} degC: given {:.6g} Pa s, fitted {:.6g} Pa s ({:+.3f} %)\n",
                       src.temperatures[k] - 273.15, src.viscosities[k],
                       src.viscosities[k] * (1.0 + src.relative_errors[k]), 100.0 * src.relative_errors[k]);
  return out;
}

// Every input the scene file writes, by the path a sensitivity study or a map's axis names
// it with (docs/physics.md section 16).
std::string inputs_table(const twb::Scene& scene) {
  std::string out = "inputs (scene paths for a sensitivity study's parameters or a map's axis; SI):\n";
  for (const twb::SceneInput& in : scene.inputs)
    out += fmt::format("  {:<44} {:.10g}{}\n", in.path, in.value, in.unit == "1" ? "" : " " + in.unit);
  return out;
}

void print_warnings(const twb::Scene& scene, std::ostream& out) {
  for (const std::string& w : scene.warnings) out << "twb: warning: " << w << "\n";
}

int check(const std::string& path, const std::vector<std::string>& overrides) {
  const twb::Scene scene = twb::load_scene(path, overrides);
  const twb::Bearing bearing(scene);
  std::cout << twb::describe_scene(scene) << "\n" << profile_table(scene.asperities)
            << viscosity_fit_table(scene.lubricant) << inputs_table(scene) << unknowns_table(bearing)
            << fmt::format("jacobian nonzeros: {}\n", bearing.jacobian_nonzeros());
  // A scene that extends others: where each value was written.
  const std::vector<twb::ValueSource> sources = twb::scene_value_sources(path, overrides);
  if (std::any_of(sources.begin(), sources.end(), [&](const twb::ValueSource& v) { return v.file != path; })) {
    std::cout << "where each value was written:\n";
    for (const twb::ValueSource& v : sources)
      std::cout << fmt::format("  {:<44} {}{}\n", v.path, v.file, v.line > 0 ? fmt::format(":{}", v.line) : "");
  }
  print_warnings(scene, std::cout);
  return 0;
}

struct RunRequest {
  std::string path;
  std::vector<std::string> overrides;
  std::string out_dir;
  bool quiet = false, verbose = false, resume = false, full_precision = false;
  int threads = 0;
  std::string slice;  // "K/N", or empty
  std::string continue_from;  // a duty cycle's results directory, or empty
};

// "K/N" of --slice.
std::pair<int, int> parse_slice(const std::string& text) {
  int k = 0, n = 0;
  char slash = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &rest) != 3 || slash != '/' || n < 1 || k < 1 || k > n)
    throw std::invalid_argument(fmt::format("--slice '{}': write K/N with 1 <= K <= N, e.g. --slice 3/8", text));
  return {k, n};
}

// What a run ends with on stdout, once its results are written.
int print_outcome(const std::filesystem::path& dir, const twb::StudyOutcome& outcome, bool verbose) {
  std::cout << twb::states_summary(outcome.states);
  for (const std::string& line : twb::summary_lines(outcome)) std::cout << line << "\n";
  for (const std::string& line : twb::limit_notes(outcome.states, outcome.distress, outcome.parameter_columns,
                                                        outcome.speeds_in_rpm)) std::cout << line << "\n";
  std::cout << fmt::format("results: {}  ({} states, {:.1f} ms)\n", dir.string(), outcome.states.size(),
                           outcome.timings.total_ms);
  if (verbose)
    for (const std::string& line : outcome.diagnostics) std::cerr << "twb: (solver) " << line << "\n";
  if (!outcome.message.empty()) std::cerr << "twb: " << outcome.message << "\n";
  return outcome.solver_failed ? exit_solver_failure : 0;
}

twb::ProgressReport progress_lines(bool quiet, const std::string& prefix = {}) {
  if (quiet) return {};
  // One write a line: the ranks of an MPI job share the terminal.
  return [prefix](const std::string& s) { std::cerr << (prefix + s + "\n") << std::flush; };
}

// Another rank of an MPI job: the same scene and model, its share of the searches, no files.
int run_as_worker(const RunRequest& r, const twb::cli::MpiJob& job) {
  twb::Scene scene = twb::load_scene(r.path, r.overrides);
  if (!twb::spreads_over_ranks(scene.study)) return 0;  // rank 0 runs such a study alone
  // The same worn washer as rank 0's (a duty cycle, which would take an end state, runs
  // on rank 0 alone).
  if (!r.continue_from.empty()) twb::continue_from(scene, r.continue_from, {}, "--continue-from");
  twb::Bearing bearing(scene);
  twb::cli::MpiScheduler scheduler(job);
  bearing.run_study(progress_lines(r.quiet || !r.verbose, fmt::format("twb[rank {}]: ", job.rank())),
                    twb::RunOptions{.threads = 1, .scheduler = &scheduler});
  return 0;
}

int run(RunRequest r, const twb::cli::MpiJob& job) {
  if (job.rank() != 0) return run_as_worker(r, job);
  twb::Scene scene = twb::load_scene(r.path, r.overrides);
  print_warnings(scene, std::cerr);
  std::optional<twb::SliceScheduler> slice;
  if (!r.slice.empty()) {
    if (twb::spreads_over_ranks(scene.study) && !twb::has_independent_searches(scene.study))
      throw std::invalid_argument("--slice cannot share out a reliability study: each batch of its Monte Carlo "
                                  "samples starts from the states the batches before it found, which the slices of "
                                  "a job array cannot pass each other; spread it over the ranks of one MPI job "
                                  "(mpirun -np N twb run SCENE) or over threads (--threads)");
    if (!twb::has_independent_searches(scene.study))
      throw std::invalid_argument("--slice needs a study of independent searches (load_sweep, distress_map, "
                                  "sliding_choice; a distress_map with method: follow chains its combinations): "
                                  "this scene's study is one piece of work");
    const auto [k, n] = parse_slice(r.slice);
    slice.emplace(k, n);
  }
  if (r.out_dir.empty()) r.out_dir = scene.output.directory;
  std::optional<twb::CycleState> cycle_start;
  if (!r.continue_from.empty()) cycle_start = twb::continue_from(scene, r.continue_from, r.out_dir, "--continue-from");
  // (`twb merge` reads the scene back from the slices' journal, which holds the scene's
  // file, not the washer it was worn to)
  if (slice && scene.worn)
    throw std::invalid_argument("--slice with --continue-from a worn washer: its slices cannot be merged yet; run "
                                "the study whole (threads or MPI ranks share its searches)");
  // Before any work: a directory this run cannot write into, or one another run is
  // writing into, is the user's to fix now, not after the study.
  const twb::ResultsDirectory results(r.out_dir);
  twb::cli::end_cleanly_on_interruption(r.out_dir.c_str());
  twb::Bearing bearing(scene);
  if (!r.quiet)
    std::cerr << fmt::format("twb: {} unknowns, {} Jacobian nonzeros\n", bearing.unknown_count(),
                             bearing.jacobian_nonzeros());

  std::optional<twb::cli::MpiScheduler> ranks;
  twb::SearchScheduler* scheduler = nullptr;
  int threads = r.threads;
  if (slice) {
    scheduler = &*slice;
  } else if (job.active()) {
    if (twb::spreads_over_ranks(scene.study)) {
      ranks.emplace(job);
      scheduler = &*ranks;
      if (threads == 0) threads = 1;  // one search per rank, as on every other rank
    } else if (!r.quiet) {
      std::cerr << "twb: this study is one piece of work: rank 0 runs it, the other ranks wait\n";
    }
  }
  // Under a terminal a quiet stretch of the study says it is still at work.
  std::optional<twb::ProgressHeartbeat> heartbeat;
  if (!r.quiet && isatty(STDERR_FILENO)) heartbeat.emplace(progress_lines(false), std::chrono::seconds(5));
  // Each finished search of the study is kept at once: a killed run resumes from them.
  const twb::StudyOutcome outcome = bearing.run_into(
      results, twb::ResultsRun{.resume = r.resume, .digits = r.full_precision ? 17 : 10},
      heartbeat ? heartbeat->report() : progress_lines(r.quiet),
      twb::RunOptions{.threads = threads, .cycle_start = cycle_start ? &*cycle_start : nullptr, .scheduler = scheduler});
  heartbeat.reset();  // the study is done: its summary follows, not a beat
  twb::cli::run_is_complete();
  if (slice) {
    const std::size_t total = twb::SearchJournal::entries_in(r.out_dir).size();
    std::cout << fmt::format("slice {}: {} searches journaled in {} ({:.1f} s); when every slice is done:\n"
                             "  twb merge --out RESULTS SLICE_DIR...\n",
                             r.slice, total, r.out_dir, outcome.timings.total_ms / 1000.0);
    return outcome.solver_failed ? exit_solver_failure : 0;
  }
  return print_outcome(r.out_dir, outcome, r.verbose);
}

// twb merge: the slices' journals into one results directory, exactly as one run writes it.
int merge(const std::vector<std::string>& slices, const std::string& out_dir, bool quiet, bool verbose,
          bool full_precision) {
  const std::optional<std::string> scene_text = twb::SearchJournal::scene_of(slices.front());
  if (!scene_text)
    throw std::invalid_argument(fmt::format("'{}' holds no journaled searches (the results directory of a twb "
                                            "run --slice K/N is meant)",
                                            slices.front()));
  const std::string scene_name = (std::filesystem::path(slices.front()) / ".twb-journal" / "scene.yaml").string();
  const twb::Scene scene = twb::load_scene_text(*scene_text, scene_name);
  twb::check_job_slices(slices, scene);  // every slice, before --out is touched
  const twb::ResultsDirectory results(out_dir);
  twb::cli::end_cleanly_on_interruption(out_dir.c_str());
  twb::Bearing bearing(scene);
  const twb::StudyOutcome outcome =
      bearing.run_into(results, twb::ResultsRun{.digits = full_precision ? 17 : 10, .slices = slices},
                       progress_lines(quiet), twb::RunOptions{.threads = 1});
  twb::cli::run_is_complete();
  return print_outcome(out_dir, outcome, verbose);
}

}  // namespace

int main(int argc, char** argv) {
  const twb::cli::MpiJob job(argc, argv);
  CLI::App app{"twb: thrust washer bearings in mixed lubrication (Jackson & Green 2006)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(twb::version()));

  std::string scene_path;
  std::vector<std::string> overrides;
  RunRequest request;

  auto* check_cmd = app.add_subcommand("check", "validate a scene, print it resolved (SI) and its unknowns");
  check_cmd->add_option("scene", scene_path, "scene file (YAML)")->required();
  check_cmd->add_option("--set", overrides, "override a key: path=value, e.g. operating.load=\"800 N\"");

  auto* run_cmd = app.add_subcommand("run", "run the scene's study and write the results directory");
  run_cmd->add_option("scene", request.path, "scene file (YAML)")->required();
  run_cmd->add_option("--out", request.out_dir, "results directory (default: the scene's output.directory)");
  run_cmd->add_option("--set", request.overrides, "override a key: path=value, e.g. operating.load=\"800 N\"");
  run_cmd->add_flag("-q,--quiet", request.quiet, "no progress on stderr");
  run_cmd->add_option("--threads", request.threads,
                      "threads for a study's independent searches (speeds, parameter values); default: one per core "
                      "(under mpirun: one per rank). The results are the same for any number")
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_option("--continue-from", request.continue_from,
                      "DIR: go on from an earlier run's results in DIR. A duty cycle goes on from where the cycle "
                      "there ended (its cycle_end_state.json: the schedule's first point must be that end's time "
                      "and inputs); any other study from the washer a life study there wore (worn_washer.json): a "
                      "life goes on from its time to study.duration, every other study holds its worn depths");
  run_cmd->add_flag("--resume", request.resume,
                    "finish a run that was killed: the searches it finished are read from the results directory's "
                    "journal, the others run (the same scene and --set values)");
  run_cmd->add_option("--slice", request.slice,
                      "K/N: run only slice K of N of the study's independent searches (a job array; docs/scaling.md) "
                      "and journal them in the results directory; `twb merge` makes the study's files of all N");
  run_cmd->add_flag("--full-precision", request.full_precision,
                    "write every number of the general columns with 17 significant digits, so that each reads "
                    "back as the very double twb computed (default: 10)");
  run_cmd->add_flag("-v,--verbose", request.verbose,
                    "also the solvers' own words where a search went on regardless (e.g. why natural "
                    "continuation stopped at a fold)");

  std::vector<std::string> slice_dirs;
  std::string merge_out;
  bool merge_quiet = false, merge_verbose = false, merge_full_precision = false;
  auto* merge_cmd = app.add_subcommand("merge", "make one study's results directory of the slices of a job array "
                                                "(twb run --slice K/N), the same files as one run writes");
  merge_cmd->add_option("slices", slice_dirs, "the slices' results directories")->required();
  merge_cmd->add_option("--out", merge_out, "results directory to write")->required();
  merge_cmd->add_flag("-q,--quiet", merge_quiet, "no progress on stderr");
  merge_cmd->add_flag("-v,--verbose", merge_verbose, "also the solvers' own words (as twb run --verbose)");
  merge_cmd->add_flag("--full-precision", merge_full_precision, "17 significant digits (as twb run --full-precision)");

  auto* columns_cmd = app.add_subcommand(
      "columns", "print the columns of the results directory's CSV files as JSON (python/twb/plot/columns.json)");
  bool columns_markdown = false;
  columns_cmd->add_flag("--markdown", columns_markdown,
                        "instead, the table of states.csv's columns with their units and meanings (docs/results.md)");

  auto* materials_cmd = app.add_subcommand(
      "materials", "print the library's materials, their values and sources, as Markdown (docs/materials.md)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : exit_invalid_input;
  }

  // Under mpirun every rank reads the same scene: only rank 0 says what is wrong, and an
  // error there ends the job (the other ranks would wait for work). An I/O error (an MPI
  // call that failed) is the rank's own: it says so, with its rank, and ends the job.
  auto fail = [&](int status, const std::string& message) {
    const bool own = status == int(twb::ErrorKind::io) && job.active();
    if (job.rank() == 0) std::cerr << message << "\n";
    else if (own) std::cerr << "(rank " << job.rank() << ") " << message << "\n";
    if (job.active() && (job.rank() == 0 || own)) job.abort(status);
    return status;
  };
  try {
    if (*check_cmd) return check(scene_path, overrides);
    if (*columns_cmd) {
      if (job.rank() == 0) std::cout << (columns_markdown ? twb::state_quantities_markdown() : twb::result_columns_json());
      return 0;
    }
    if (*materials_cmd) {
      if (job.rank() == 0) std::cout << twb::material_library_markdown();
      return 0;
    }
    if (*merge_cmd) return merge(slice_dirs, merge_out, merge_quiet, merge_verbose, merge_full_precision);
    return run(request, job);
  } catch (...) {
    // The error family (twb/error_family.h): input 2, solver 3, internal 4, I/O 5.
    const twb::ErrorReport report = twb::report_error(std::current_exception());
    return fail(report.exit_status(), report.message);
  }
}
