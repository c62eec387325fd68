// The twb command: `twb check SCENE` and `twb run SCENE`.
// Exit status: 0 success (a distress found is a result), 2 invalid input,
// 3 solver failure, 4 internal error.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "interruption.h"
#include "results_directory.h"
#include "model/bearing_model.h"
#include "results/atomic_file.h"
#include "twb/results/fields_table.h"
#include "results/run_record.h"
#include "twb/results/limit_notes.h"
#include "twb/results/states_table.h"
#include "study/search_journal.h"
#include "twb/scene/input_error.h"
#include "twb/scene/scene_loader.h"
#include "solver/sundials_context.h"
#include "study/study_runner.h"
#include "twb/version.h"

namespace {

constexpr int exit_invalid_input = 2;
constexpr int exit_solver_failure = 3;
constexpr int exit_internal_error = 4;

std::string unknowns_table(const twb::UnknownLayout& layout) {
  std::string out = "unknowns:\n";
  for (const auto& b : layout.blocks())
    out += fmt::format("  {:<44} {:>6}   ({})\n", b.name, b.size, b.effect);
  out += fmt::format("  {:<44} {:>6}\n", "total", layout.size());
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

void print_warnings(const twb::Scene& scene, std::ostream& out) {
  for (const std::string& w : scene.warnings) out << "twb: warning: " << w << "\n";
}

int check(const std::string& path, const std::vector<std::string>& overrides) {
  const twb::Scene scene = twb::load_scene(path, overrides);
  const twb::BearingModel model(scene);
  std::cout << twb::describe_scene(scene) << "\n" << profile_table(scene.asperities) << unknowns_table(model.layout())
            << fmt::format("jacobian nonzeros: {}\n", model.pattern().nnz());
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

int run(const std::string& path, const std::vector<std::string>& overrides, std::string out_dir, bool quiet,
        bool verbose, int threads, bool resume) {
  const auto t0 = std::chrono::steady_clock::now();
  const twb::Scene scene = twb::load_scene(path, overrides);
  print_warnings(scene, std::cerr);
  if (out_dir.empty()) out_dir = scene.output.directory;
  // Before any work: a directory this run cannot write into, or one another run is
  // writing into, is the user's to fix now, not after the study.
  const twb::cli::ResultsDirectory results(out_dir);
  twb::cli::end_cleanly_on_interruption(out_dir.c_str());
  // Each finished search of the study is kept at once: a killed run resumes from them.
  const twb::SearchJournal journal(out_dir, twb::describe_scene(scene), resume);
  twb::BearingModel model(scene);
  const double setup_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!quiet) std::cerr << fmt::format("twb: {} unknowns, {} Jacobian nonzeros\n", model.size(), model.pattern().nnz());

  twb::StudyOutcome outcome =
      twb::run_study(model, quiet ? twb::ProgressReport{} : [](const std::string& s) { std::cerr << s << "\n"; },
                     twb::RunOptions{.threads = threads, .journal = &journal});
  outcome.timings.setup_ms = setup_ms;
  outcome.timings.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const std::filesystem::path dir(out_dir);
  for (const twb::NamedTable& table : twb::study_tables(outcome, scene.study.type))
    twb::write_file_atomically(dir / (table.name + ".csv"), table.table.csv());
  twb::write_state_fields(dir, outcome.states);
  const std::string verdict = outcome.solver_failed ? "solver failure: " + outcome.message
                                                    : (outcome.message.empty() ? "ok" : outcome.message);
  twb::write_file_atomically(dir / "run.json", twb::run_json(path, twb::describe_scene(scene), model.layout(),
                                                             outcome.timings, verdict));
  journal.finish();
  twb::cli::run_is_complete();
  std::cout << twb::states_summary(outcome.states);
  for (const twb::DistressRow& d : outcome.distress)
    std::cout << fmt::format(
        "distress at {:.6g} rad/s{}{}: {}{} ({})\n", d.speed,
        d.parameter ? fmt::format(", {} = {:.6g}", outcome.parameter_column, *d.parameter) : "",
        d.sliding.empty() ? "" : ", sliding " + d.sliding,
        d.distress_load ? fmt::format("W_d = {:.2f} N", *d.distress_load) : "none",
        d.extrapolated_load && d.discretization_error
            ? fmt::format(" on the scene's mesh; mesh-converged {:.1f} ± {:.1f} N (Richardson, {:.2f} N on the "
                          "mesh refined by two)",
                          *d.extrapolated_load, *d.discretization_error, *d.fine_fold_load)
            : "",
        d.method);
  for (const std::string& line : twb::limit_notes(outcome.states, outcome.distress)) std::cout << line << "\n";
  for (const std::string& line : outcome.summary) std::cout << line << "\n";
  std::cout << fmt::format("results: {}  ({} states, {:.1f} ms)\n", dir.string(), outcome.states.size(),
                           outcome.timings.total_ms);
  if (verbose)
    for (const std::string& line : outcome.diagnostics) std::cerr << "twb: (solver) " << line << "\n";
  if (!outcome.message.empty()) std::cerr << "twb: " << outcome.message << "\n";
  return outcome.solver_failed ? exit_solver_failure : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"twb: thrust washer bearings in mixed lubrication (Jackson & Green 2006)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(twb::version()));

  std::string scene_path, out_dir;
  std::vector<std::string> overrides;
  bool quiet = false;

  auto* check_cmd = app.add_subcommand("check", "validate a scene, print it resolved (SI) and its unknowns");
  check_cmd->add_option("scene", scene_path, "scene file (YAML)")->required();
  check_cmd->add_option("--set", overrides, "override a key: path=value, e.g. operating.load=\"800 N\"");

  auto* run_cmd = app.add_subcommand("run", "run the scene's study and write the results directory");
  run_cmd->add_option("scene", scene_path, "scene file (YAML)")->required();
  run_cmd->add_option("--out", out_dir, "results directory (default: the scene's output.directory)");
  run_cmd->add_option("--set", overrides, "override a key: path=value, e.g. operating.load=\"800 N\"");
  run_cmd->add_flag("-q,--quiet", quiet, "no progress on stderr");
  bool verbose = false;
  int threads = 0;
  run_cmd->add_option("--threads", threads,
                      "threads for a study's independent searches (speeds, parameter values); default: one per core. "
                      "The results are the same for any number")
      ->check(CLI::NonNegativeNumber);
  bool resume = false;
  run_cmd->add_flag("--resume", resume,
                    "finish a run that was killed: the searches it finished are read from the results directory's "
                    "journal, the others run (the same scene and --set values)");
  run_cmd->add_flag("-v,--verbose", verbose,
                    "also the solvers' own words where a search went on regardless (e.g. why natural "
                    "continuation stopped at a fold)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : exit_invalid_input;
  }

  try {
    if (*check_cmd) return check(scene_path, overrides);
    return run(scene_path, overrides, out_dir, quiet, verbose, threads, resume);
  } catch (const twb::InputError& e) {
    std::cerr << e.what() << "\n";
    return exit_invalid_input;
  } catch (const twb::cli::ResultsDirectoryError& e) {
    std::cerr << "twb: error: " << e.what() << "\n";
    return exit_invalid_input;
  } catch (const std::invalid_argument& e) {
    std::cerr << "twb: error: " << e.what() << "\n";
    return exit_invalid_input;
  } catch (const twb::SolverFailure& e) {
    std::cerr << "twb: solver failure: " << e.what() << "\n";
    return exit_solver_failure;
  } catch (const std::exception& e) {
    std::cerr << "twb: internal error: " << e.what() << "\n";
    return exit_internal_error;
  }
}
