#include "study/study_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "distress_curve.h"
#include "load_step_march.h"
#include "parallel.h"
#include "study/search_journal.h"
#include "study/search_scheduler.h"
#include "richardson.h"
#include "state_error.h"
#include "study_support.h"
#include "twb/scene/scene_loader.h"
#include "solver/sparse_lu.h"
#include "study/steady_solver.h"
#include "study/distress_search.h"
#include "twb/error_family.h"
#include "study/search_error_bars.h"
#include "study/followed_map.h"
#include "study/study_searches.h"
#include "study/operating_point.h"
#include "study/calibration.h"
#include "study/reliability.h"
#include "study/duty_cycle.h"
#include "study/sensitivity.h"

namespace twb {

namespace {

using Clock = std::chrono::steady_clock;

void run_point(BearingModel& model, StudyOutcome& out) {
  std::vector<double> u;
  if (!solve_operating_point(model, out, u)) return;
  if (model.scene().study.error_estimate == ErrorEstimate::none) return;
  // Its error bars (state_error.h), with the warning where the mesh is more than 5 % off.
  std::string why;
  try {
    const double tolerance = model.scene().study.tolerance;
    if (tolerance > 0.0) {
      // To the tolerance asked for: the meshes' estimates and their lines.
      if (refine_state_to_tolerance(model, u, out.states.back(), tolerance, out.summary, why,
                                    &out.timings.newton_iterations, &out.timings.jacobian_evaluations))
        return;
    } else if (const std::unique_ptr<BearingModel> fine = refined_model(model, why);
               fine && refine_state(model, *fine, u, out.states.back(), why, SparseLu::Ordering::minimum_degree,
                                    &out.timings.newton_iterations, &out.timings.jacobian_evaluations)) {
      const std::vector<std::string> lines = state_error_lines(model.scene(), out.states);
      out.summary.insert(out.summary.end(), lines.begin(), lines.end());
      return;
    }
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    why = e.what();
  }
  out.summary.push_back("no error bar: " + why);
}

// distress_curve: one fold curve for the scene's bearing, or one per member of its family
// (study.family: the map parameters).
// The members of a family are independent: on `threads` threads, each with its own
// model, their outcomes joined in the family's order (the same files for any count).
void run_distress_curve(BearingModel& base, StudyOutcome& out, const ProgressReport& progress, int threads) {
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_columns);
  out.fold_curve_column = fold_curve_column(base.scene().study.curve_parameter);
  std::vector<StudyOutcome> parts(variants.size());
  std::mutex lock;
  const ProgressReport say = one_line_at_a_time(progress, lock);
  run_in_parallel(variants.size(), threads, [&](std::size_t i) {
    const SparseLu::Counts before = SparseLu::thread_counts();
    StudyOutcome& part = parts[i];
    try {
      BearingModel model(variants[i].scene ? *variants[i].scene : base.scene());
      // Threads the family's members leave over serve each curve's own pieces.
      // A family has one axis (the scene reader's): its member is that value.
      const std::optional<double> member =
          variants[i].parameters.empty() ? std::nullopt : std::optional<double>(variants[i].parameters.front());
      run_fold_curve(model, member, variants[i].label, part, say,
                     std::max(1, threads / int(variants.size())));
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      part.summary.push_back(fmt::format("fold curve{}: failed: {}", variants[i].label, e.what()));
    }
    part.timings.klu_factorizations +=
        SparseLu::thread_counts().factored_since(before) + part.timings.ida_factorizations;
  });
  for (StudyOutcome& part : parts) {
    out.states.insert(out.states.end(), part.states.begin(), part.states.end());
    out.distress.insert(out.distress.end(), part.distress.begin(), part.distress.end());
    out.fold_curve.insert(out.fold_curve.end(), part.fold_curve.begin(), part.fold_curve.end());
    out.summary.insert(out.summary.end(), part.summary.begin(), part.summary.end());
    out.diagnostics.insert(out.diagnostics.end(), part.diagnostics.begin(), part.diagnostics.end());
    out.timings.transients += part.timings.transients;
    out.timings.ida_steps += part.timings.ida_steps;
    out.timings.ida_factorizations += part.timings.ida_factorizations;
    out.timings.klu_factorizations += part.timings.klu_factorizations;
  }
}

std::vector<double> load_grid(const Study& st) {
  std::vector<double> grid;
  for (int k = 0; k < st.load_steps; ++k)
    grid.push_back(st.load_start + (st.load_end - st.load_start) * k / (st.load_steps - 1));
  return grid;
}

// The study's load range and bracket width: a distress map's search.
DistressSearchSettings range_settings(const Study& st) {
  DistressSearchSettings s;
  s.load_start = st.load_start;
  s.load_end = st.load_end;
  s.bracket_width = st.bracket_width;
  s.keep_state_vectors = st.error_estimate == ErrorEstimate::every_state;
  return s;
}

// A sweep's search: the range, the requested grid, and on past distress.
DistressSearchSettings grid_settings(const Study& st) {
  DistressSearchSettings s = range_settings(st);
  s.grid = load_grid(st);
  s.continue_past_distress = true;
  return s;
}

void keep_failure(StudyOutcome& out, const DistressSearch& found) {
  if (!found.failed && found.message.empty()) return;
  out.solver_failed = out.solver_failed || found.failed;
  out.message += (out.message.empty() ? "" : "; ") + found.message;
}

void run_load_sweep(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, const Running& how) {
  const std::vector<Variant> variants = parameter_variants(model.scene(), out.parameter_columns);
  run_searches(model, variants, grid_settings(model.scene().study), progress, how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t, const BearingModel&, DistressSearch& found) {
                 out.states.insert(out.states.end(), found.states.begin(), found.states.end());
                 out.trajectory.insert(out.trajectory.end(), found.runaway.begin(), found.runaway.end());
                 out.distress.push_back(found.row);
                 keep_failure(out, found);
               });
}

void run_distress_map(BearingModel& base, StudyOutcome& out, const ProgressReport& progress, const Running& how) {
  DistressSearchSettings settings = range_settings(base.scene().study);
  settings.march_past_distress = false;  // the map keeps neither the hot states nor the trajectories
  settings.search_past_failure = base.scene().study.search_past_failure;
  if (base.scene().study.map_method == MapMethod::follow) {
    run_followed_map(base, settings, out, progress, how);
    return;
  }
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_columns);
  run_searches(base, variants, settings, progress, how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t, const BearingModel&, DistressSearch& found) {
    out.distress.push_back(found.row);
    // The cool branch's states are results too (f_eff, temperature against load).
    out.states.insert(out.states.end(), found.states.begin(),
                      found.states.begin() + std::ptrdiff_t(found.cool_states));
    // One point that fails must not lose the map's other rows.
    if (found.failed) out.message += (out.message.empty() ? "" : "; ") + found.message;
  });
}

// Which film slides (docs/physics.md section 2): both configurations swept over the load grid
// at every speed, each continued past its own distress; at every grid load the one of
// lower friction torque is chosen, the paper's assumption that the washer settles where
// the friction loss is least.
void run_sliding_choice(BearingModel& base, StudyOutcome& out, const ProgressReport& progress, const Running& how) {
  const Study& st = base.scene().study;
  out.sliding_column = true;
  std::vector<Variant> variants;
  for (SlidingFilm film : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}) {
    Scene scene = base.scene();
    scene.operating.sliding = film;
    const std::string name(scene_name(film));
    variants.push_back({std::move(scene), {}, film, ", sliding " + name});
  }
  const std::vector<double> grid = load_grid(st);
  // Per speed and grid load, the state of each configuration that reached it.
  std::vector<std::vector<std::vector<SlidingRow>>> at(study_speeds(base).size(),
                                                        std::vector<std::vector<SlidingRow>>(grid.size()));
  run_searches(base, variants, grid_settings(st), progress, how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t speed, const BearingModel& model, DistressSearch& found) {
    const auto film = std::find_if(model.films().begin(), model.films().end(), [](const Film& f) { return f.sliding; });
    const double area = film->mesh.area();
    for (const SolvedState& state : found.states)
      for (std::size_t k = 0; k < grid.size(); ++k)
        if (std::abs(state.state.load - grid[k]) <= 1e-9 * grid[k]) at[speed][k].push_back({state, area, false});
    out.trajectory.insert(out.trajectory.end(), found.runaway.begin(), found.runaway.end());
    out.distress.push_back(found.row);
    keep_failure(out, found);
  });
  for (auto& speed : at)
    for (std::vector<SlidingRow>& rows : speed) {
      if (rows.empty()) continue;
      auto best = std::min_element(rows.begin(), rows.end(), [](const SlidingRow& a, const SlidingRow& b) {
        return a.solved.state.torque < b.solved.state.torque;
      });
      best->chosen = true;
      out.states.push_back(best->solved);
      out.sliding.insert(out.sliding.end(), rows.begin(), rows.end());
    }
}

void run_transient(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  const Study& st = model.scene().study;
  const NewtonSettings newton = newton_settings(model.scene());
  model.set_load(st.load_start);
  SteadySolver solver(model, newton);
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state before the step, at {:.6g} N: {}", st.load_start, rep.message);
    return;
  }
  out.states.push_back(recorded_state(model, u, rep));
  if (progress) progress(fmt::format("steady at {:.6g} N; stepping to {:.6g} N", st.load_start, st.load_end));
  StepMarch march = march_load_step(model, u, st.load_start, st.load_end, TransientSettings{}, newton, st.duration);
  out.timings.newton_iterations += rep.iterations + march.newton_iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  out.timings.transients += 1;
  out.timings.ida_steps += march.ida_steps;
  out.timings.ida_factorizations += march.ida_factorizations;
  out.trajectory = std::move(march.trajectory);
  model.set_load(st.load_end);  // the march's last state is at the load it stepped to
  SolvedState last = solved_state(model, march.state);
  last.converged = march.settled;
  last.iterations = march.newton_iterations;
  std::vector<double> r(march.state.size());
  model.evaluate(march.state, r, {});
  last.residual = max_norm(r);
  last.wall_ms = march.wall_ms;
  out.states.push_back(last);
  out.message = "transient: " + march.message;
  // A march that never started has no trajectory to report: the study failed.
  if (!march.started) out.solver_failed = true;
}

}  // namespace

StudyOutcome run_study(BearingModel& model, const ProgressReport& progress, const RunOptions& options,
                       const StudyPlumbing& plumbing) {
  // The public API's own check (the command line's option checks the same).
  if (options.threads < 0)
    throw std::invalid_argument(
        fmt::format("threads must be 0 (one per core) or a positive count, not {}", options.threads));
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  const Running how{threads, plumbing.journal, plumbing.scheduler, options.stop};
  StudyOutcome out;
  out.speeds_in_rpm = model.scene().study.speeds_in_rpm;
  const auto t0 = Clock::now();
  const SparseLu::Counts klu_before = SparseLu::thread_counts();
  switch (model.scene().study.type) {
    case StudyType::point:
      run_point(model, out);
      break;
    case StudyType::load_sweep:
      run_load_sweep(model, out, progress, how);
      break;
    case StudyType::distress_map:
      run_distress_map(model, out, progress, how);
      break;
    case StudyType::transient:
      run_transient(model, out, progress);
      break;
    case StudyType::sliding_choice:
      run_sliding_choice(model, out, progress, how);
      break;
    case StudyType::distress_curve:
      run_distress_curve(model, out, progress, threads);
      break;
    case StudyType::sensitivity:
      run_sensitivity(model, out, progress, threads);
      break;
    case StudyType::reliability:
      run_reliability(model, out, progress, threads, plumbing.scheduler);
      break;
    case StudyType::calibration:
      run_calibration(model, out, progress, threads);
      break;
    case StudyType::duty_cycle:
      run_duty_cycle(model, out, progress, options.cycle_start);
      break;
  }
  // Searches run on worker threads count their own (run_searches); the rest ran here.
  const StudyType type = model.scene().study.type;
  if (type != StudyType::load_sweep && type != StudyType::distress_map && type != StudyType::sliding_choice &&
      type != StudyType::distress_curve) {  // (a followed map counts its threads' in run_followed_map)
    out.timings.klu_factorizations =
        SparseLu::thread_counts().factored_since(klu_before) + out.timings.ida_factorizations;
  }
  if (options.stop && options.stop->load() && has_independent_searches(model.scene().study)) {
    out.stopped = true;
    out.message += (out.message.empty() ? "" : "; ") + std::string("stopped before the study's end: searches are missing");
  }
  if (model.scene().study.error_estimate == ErrorEstimate::every_state) {
    const std::vector<std::string> lines = state_error_lines(model.scene(), out.states);
    out.summary.insert(out.summary.end(), lines.begin(), lines.end());
  }
  out.timings.states = int(out.states.size());
  // Continuation and distress searches count their work in states, transients and
  // factorizations; their Newton iterations are those that solved the reported states.
  if (type != StudyType::point && type != StudyType::transient && type != StudyType::sensitivity &&
      type != StudyType::reliability && type != StudyType::calibration && type != StudyType::duty_cycle)
    for (const SolvedState& s : out.states) out.timings.newton_iterations += s.iterations;
  out.timings.solve_ms = elapsed_ms(t0);
  return out;
}

}  // namespace twb
