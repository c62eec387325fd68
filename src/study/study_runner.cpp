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

namespace twb {

namespace {

using Clock = std::chrono::steady_clock;

SolvedState record(const BearingModel& model, const std::vector<double>& u, const SteadyReport& rep) {
  SolvedState row = solved_state(model, u);
  row.converged = rep.converged;
  row.iterations = rep.iterations;
  row.residual = rep.residual_norm;
  row.wall_ms = rep.wall_ms;
  return row;
}

void run_point(BearingModel& model, StudyOutcome& out) {
  SteadySolver solver(model, newton_settings(model.scene()));
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  out.timings.newton_iterations += rep.iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state at {:.6g} N: {}", model.load(), rep.message);
    return;
  }
  out.states.push_back(record(model, u, rep));
  if (model.scene().study.error_estimate == ErrorEstimate::none) return;
  // Its error bars (state_error.h), with the warning where the mesh is more than 5 % off.
  std::string why;
  try {
    const std::unique_ptr<BearingModel> fine = refined_model(model, why);
    if (fine && refine_state(model, *fine, u, out.states.back(), why, SparseLu::Ordering::minimum_degree,
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

// Every state of a search again on the refined mesh (study.error_estimate: every_state),
// on the search's thread; a state without one says why in the search's row.
void estimate_state_errors(const BearingModel& model, DistressSearch& found, const ProgressReport& progress) {
  if (model.scene().study.error_estimate != ErrorEstimate::every_state || found.states.empty() ||
      found.state_vectors.size() != found.states.size())
    return;
  const auto t0 = Clock::now();
  std::string why;
  std::size_t refined = 0;
  try {
    const std::unique_ptr<BearingModel> fine = refined_model(model, why);
    BearingModel at(model.scene());  // the search's model, at each state's load in turn
    at.set_speed(model.speed());
    for (std::size_t i = 0; fine && i < found.states.size(); ++i) {
      at.set_load(found.states[i].state.load);
      fine->set_speed(model.speed());
      std::string missing;
      if (refine_state(at, *fine, found.state_vectors[i], found.states[i], missing, SparseLu::Ordering::by_size))
        ++refined;
      else
        why = missing;
    }
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (refined < found.states.size())
    found.row.method += fmt::format("; error bars at {} of {} states (the last missing: {})", refined,
                                    found.states.size(), why);
  if (progress)
    progress(fmt::format("  error bars: {} of {} states on the refined mesh [{:.1f} s]", refined, found.states.size(),
                         elapsed_ms(t0) / 1000.0));
  found.state_vectors.clear();
}

// The name of a parameter's column in the results, with its unit.
std::string parameter_column(MapParameter p) {
  switch (p) {
    case MapParameter::friction_coefficient:
      return "friction_coefficient";
    case MapParameter::gear_tilt:
      return "gear_tilt_rad";
    case MapParameter::roughness:
      return "roughness_Rq_m";
    case MapParameter::none:
      break;
  }
  return {};
}

// Applies a study's second parameter to a scene.
Scene with_parameter(Scene scene, MapParameter p, double value) {
  switch (p) {
    case MapParameter::friction_coefficient:
      scene.friction.coefficient = value;
      break;
    case MapParameter::gear_tilt:
      scene.gear.tilt = value;
      break;
    case MapParameter::roughness:
      set_roughness(scene, value);
      break;
    case MapParameter::none:
      break;
  }
  return scene;
}

// One configuration of the bearing a study searches at every speed: the scene's own
// (no scene here), a parameter value, or a sliding film.
struct Variant {
  std::optional<Scene> scene;
  std::optional<double> parameter;
  std::string sliding;
  std::string label;  // for progress lines, e.g. ", friction_coefficient = 0.1"
};

// The scene's own configuration, or one per value of its second parameter.
std::vector<Variant> parameter_variants(const Scene& scene, std::string& column) {
  const Study& st = scene.study;
  column = parameter_column(st.parameter);
  if (st.parameter == MapParameter::none) return {Variant{}};
  std::vector<Variant> out;
  for (double value : st.parameter_values)
    out.push_back({with_parameter(scene, st.parameter, value), value, {}, fmt::format(", {} = {:.6g}", column, value)});
  return out;
}

// distress_curve: one fold curve for the scene's bearing, or one per member of its family
// (study.family: the map parameters).
// The members of a family are independent: on `threads` threads, each with its own
// model, their outcomes joined in the family's order (the same files for any count).
void run_distress_curve(BearingModel& base, StudyOutcome& out, const ProgressReport& progress, int threads) {
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_column);
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
      run_fold_curve(model, variants[i].parameter, variants[i].label, part, say,
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

// The speeds a study searches at: study.speeds, or the model's speed for a scene built
// without them (the loader fills them in).
std::vector<double> study_speeds(const BearingModel& model) {
  const std::vector<double>& listed = model.scene().study.speeds;
  return listed.empty() ? std::vector<double>{model.speed()} : listed;
}

// Called after each search with the speed's index in study_speeds and a model of its
// variant, whose films (not its speed) a taker may read.
using SearchResult = std::function<void(const Variant&, std::size_t speed, const BearingModel&, DistressSearch&)>;

// W_d's error bar (study.error_estimate: richardson) for a search that found a fold.
void estimate_mesh_error(const BearingModel& model, const DistressSearchSettings& settings, DistressSearch& found,
                         const ProgressReport& progress) {
  const Study& st = model.scene().study;
  const bool searches_distress = st.type == StudyType::load_sweep || st.type == StudyType::distress_map;
  if (!searches_distress || st.error_estimate == ErrorEstimate::none || !found.row.distress_load ||
      !found.row.fold_load || found.states.empty())
    return;
  const Scene fine = refined_mesh(model.scene());
  if (progress)
    progress(fmt::format("  error bar: the fold on the {} x {} mesh", fine.mesh.radial_nodes,
                         fine.mesh.circumferential_nodes));
  DistressSearchSettings from = settings;
  from.load_start = found.states.front().state.load;  // where the search began (a light load past distress)
  std::string why;
  const auto t0 = Clock::now();
  std::optional<MeshErrorEstimate> e;
  try {
    const CoarseFold coarse{*found.row.fold_load, &model, found.fold ? &*found.fold : nullptr};
    e = richardson_estimate(model.scene(), model.speed(), coarse, from, why, progress);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& failure) {
    why = std::string("the refined mesh's search failed: ") + failure.what();
  }
  if (!e) {
    found.row.method += "; no error estimate: " + why;
    return;
  }
  found.row.fine_fold_load = e->fine_fold;
  found.row.extrapolated_load = e->extrapolated;
  found.row.discretization_error = e->error;
  if (progress)
    progress(fmt::format("  error bar: fold {:.2f} N on {}; extrapolated W_d = {:.2f} ± {:.2f} N [{:.1f} s]",
                         e->fine_fold, e->fine_mesh, e->extrapolated, e->error, elapsed_ms(t0) / 1000.0));
}

// Each failure criterion's crossing again on the refined mesh (study.error_estimate:
// richardson), and W_fail's mesh-converged value and error bar: W_d's where distress
// sets it, else its criterion's.
void estimate_crossing_errors(const BearingModel& model, const DistressSearchSettings& settings, DistressSearch& found,
                              const ProgressReport& progress) {
  const Study& st = model.scene().study;
  const bool searches = st.type == StudyType::load_sweep || st.type == StudyType::distress_map;
  DistressRow& row = found.row;
  if (!searches || st.error_estimate == ErrorEstimate::none) return;
  std::unique_ptr<BearingModel> fine;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    if (!row.criterion_loads[c] || found.crossing_states.size() <= c || found.crossing_states[c].second.empty())
      continue;
    // A crossing at the start lies below the searched range: no crossing to refine.
    if (*row.criterion_loads[c] <= settings.load_start) continue;
    const auto t0 = Clock::now();
    std::string why;
    std::optional<MeshErrorEstimate> e;
    try {
      if (!fine) {
        const Scene refined = refined_mesh(model.scene());
        fine = model.on_mesh(refined.mesh.radial_nodes, refined.mesh.circumferential_nodes);
      }
      e = crossing_estimate(model, *fine, kFailureCriteria[c], found.crossing_states[c].first,
                            found.crossing_states[c].second, settings.bracket_width, settings.load_end, why);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& failure) {
      why = failure.what();
    }
    if (!e) {
      row.method += fmt::format("; no error bar for {}: {}", limit_name(kFailureCriteria[c]), why);
      continue;
    }
    row.criterion_errors[c] = e->error;
    if (row.criterion == limit_name(kFailureCriteria[c])) {
      row.failure_extrapolated = e->extrapolated;
      row.failure_error = e->error;
    }
    if (progress)
      progress(fmt::format("  error bar: {} crossed at {:.2f} N on {}; extrapolated {:.2f} ± {:.2f} N [{:.1f} s]",
                           limit_name(kFailureCriteria[c]), e->fine_fold, e->fine_mesh, e->extrapolated, e->error,
                           elapsed_ms(t0) / 1000.0));
  }
  if (row.criterion == "distress") {
    row.failure_extrapolated = row.extrapolated_load;
    row.failure_error = row.discretization_error;
  }
  if (row.failure_load && row.failure_error)
    row.failure += fmt::format("; mesh-converged {:.1f} ± {:.1f} N", *row.failure_extrapolated, *row.failure_error);
}

// How a study's searches run: on how many threads here, journaled where, spread how.
struct Running {
  int threads = 1;
  const SearchJournal* journal = nullptr;
  SearchScheduler* scheduler = nullptr;
  const std::atomic<bool>* stop = nullptr;
};

// One search of run_searches: its own model (no state shared between threads), found
// and tagged with its run.
struct SearchTask {
  const Variant* variant = nullptr;
  std::size_t speed_index = 0;
  double speed = 0.0;
};
struct SearchDone {
  // What `take` reads the films of: the search's own model, or for a search found
  // elsewhere its variant's (the films do not depend on the speed).
  std::shared_ptr<const BearingModel> model;
  DistressSearch found;
  long klu_factorizations = 0;  // the whole task's, its error bar's search included
};

SearchDone search_one(const BearingModel& base, const SearchTask& task, const DistressSearchSettings& settings,
                      const ProgressReport& progress) {
  SearchDone done;
  DistressSearch& found = done.found;
  const Variant& variant = *task.variant;
  const SparseLu::Counts before = SparseLu::thread_counts();  // this thread's, so this task's
  try {
    auto model = std::make_shared<BearingModel>(variant.scene ? *variant.scene : base.scene());
    model->set_speed(task.speed);
    done.model = model;
    found = search_distress(*model, settings, progress);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    found = DistressSearch{};
    found.failed = true;
    found.row.speed = task.speed;
    found.row.verdict = DistressVerdict::solver_failure;
    found.row.method = std::string("solver failure: ") + e.what();
    found.message = found.row.method;
  }
  if (done.model) {
    estimate_mesh_error(*done.model, settings, found, progress);
    estimate_crossing_errors(*done.model, settings, found, progress);
    estimate_state_errors(*done.model, found, progress);
  }
  done.klu_factorizations = SparseLu::thread_counts().factored_since(before) + found.counts.ida_factorizations;
  found.row.parameter = variant.parameter;
  found.row.sliding = variant.sliding;
  for (std::size_t i = 0; i < found.states.size(); ++i) {
    SolvedState& state = found.states[i];
    state.parameter = variant.parameter;
    state.sliding = variant.sliding;
    state.branch = i < found.cool_states ? Branch::cool : Branch::hot;
  }
  for (TrajectorySample& sample : found.runaway) {
    sample.parameter = variant.parameter;
    sample.sliding = variant.sliding;
  }
  return done;
}

// One distress search per variant and speed, on `threads` threads. Every search builds
// its own model and solvers, so a search's numbers do not depend on which thread ran it
// or on what ran before; results are handed to `take` in the order of the study (variant
// outer, speed inner), each as soon as all before it are, so the study's files are the
// same, byte for byte, whatever the thread count. Progress lines "[k/n] ..." with the time
// left; a search that throws becomes a failed row, so that the study's other searches are
// kept.
void run_searches(BearingModel& base, const std::vector<Variant>& variants, const DistressSearchSettings& settings,
                  const ProgressReport& progress, const Running& how, RunTimings& timings,
                  std::vector<std::string>& diagnostics, const SearchResult& take) {
  const std::vector<double> speeds = study_speeds(base);
  std::vector<SearchTask> tasks;
  for (const Variant& variant : variants)
    for (std::size_t k = 0; k < speeds.size(); ++k) tasks.push_back({&variant, k, speeds[k]});
  const std::size_t total = tasks.size();
  std::mutex lock;  // guards everything below it and the progress stream
  const ProgressReport say = one_line_at_a_time(progress, lock);
  std::map<std::size_t, SearchDone> ready;
  std::size_t next_to_take = 0, done = 0;
  const auto t0 = Clock::now();
  const SearchJournal* journal = how.journal;

  // Hands search i to `take` once all before it are taken: the study's order.
  auto deliver = [&](std::size_t i, SearchDone result) {
    const std::lock_guard<std::mutex> hold(lock);
    ready.emplace(i, std::move(result));
    ++done;
    for (auto it = ready.find(next_to_take); it != ready.end(); it = ready.find(next_to_take)) {
      const SearchTask& t = tasks[it->first];
      DistressSearch& found = it->second.found;
      for (const std::string& d : found.diagnostics)
        diagnostics.push_back(fmt::format("{:.6g} rad/s{}: {}", t.speed, t.variant->label, d));
      add_search_work(timings, found.counts);
      timings.klu_factorizations += it->second.klu_factorizations;
      if (it->second.model) take(*t.variant, t.speed_index, *it->second.model, found);
      else take(*t.variant, t.speed_index, base, found);
      if (progress) {
        // Wall time per finished search (the threads' searches finish in parallel).
        const double per_search = elapsed_ms(t0) / double(done);
        progress(fmt::format("[{}/{}] done: W_d = {} ({}); {} stability tests, {} transients ({} IDA steps), {} "
                             "KLU factorizations; about {:.0f} s left",
                             it->first + 1, total,
                             found.row.distress_load ? fmt::format("{:.2f} N", *found.row.distress_load) : "none",
                             found.row.method, found.counts.stability_tests, found.counts.transients,
                             found.counts.ida_steps, found.counts.klu_factorizations,
                             per_search * double(total - done) / 1000.0));
      }
      ready.erase(it);
      ++next_to_take;
    }
  };
  // A search found elsewhere (the journal, another process) is not run again; the takers
  // read the films of its variant's model, built once per variant (about 10 ms each on
  // 9 x 66: not once per search, which on rank 0 of an MPI job would delay every
  // answer). None when the model cannot be built.
  std::vector<std::shared_ptr<const BearingModel>> variant_models(variants.size());
  std::mutex variant_models_lock;
  auto from_entry = [&](std::size_t i, JournaledSearch&& kept) -> std::optional<SearchDone> {
    const Variant& variant = *tasks[i].variant;
    SearchDone result;
    try {
      const std::lock_guard<std::mutex> hold(variant_models_lock);
      std::shared_ptr<const BearingModel>& model = variant_models[std::size_t(&variant - variants.data())];
      if (!model) model = std::make_shared<const BearingModel>(variant.scene ? *variant.scene : base.scene());
      result.model = model;
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception&) {
      return std::nullopt;
    }
    result.found = std::move(kept.found);
    result.klu_factorizations = kept.klu_factorizations;
    return result;
  };

  // Found before the run was stopped: read, not run. A search whose model cannot be built
  // runs again, which reports why.
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < total; ++i) {
    std::optional<JournaledSearch> kept = journal ? journal->read(i) : std::nullopt;
    std::optional<SearchDone> result = kept ? from_entry(i, std::move(*kept)) : std::nullopt;
    if (!result) {
      todo.push_back(i);
      continue;
    }
    if (say)
      say(fmt::format("[{}/{}] {:.6g} rad/s{}: from the journal", i + 1, total, tasks[i].speed, tasks[i].variant->label));
    deliver(i, std::move(*result));
  }

  SearchScheduler::Work work;
  auto run = [&](std::size_t i) {
    const SearchTask& task = tasks[i];
    if (say) say(fmt::format("[{}/{}] {:.6g} rad/s{}", i + 1, total, task.speed, task.variant->label));
    return search_one(base, task, settings, say);
  };
  work.run_here = [&](std::size_t i) {
    if (how.stop && how.stop->load()) return;  // the study ends with the searches taken so far
    SearchDone result = run(i);
    // A search that failed is not kept: a resume tries it again (perhaps with fewer
    // threads, or after the user freed memory).
    if (journal && !result.found.failed) journal->write(i, result.found, result.klu_factorizations);
    deliver(i, std::move(result));
  };
  work.run_for_another = [&](std::size_t i) {
    const SearchDone result = run(i);
    return journal_entry(result.found, result.klu_factorizations);
  };
  work.arrived = [&](std::size_t i, const std::string& entry) {
    std::optional<JournaledSearch> kept = read_journal_entry(entry);
    if (!kept) throw std::runtime_error(fmt::format("search {} came back damaged from another process", i + 1));
    if (journal && !kept->found.failed) journal->write_entry(i, entry);
    std::optional<SearchDone> result = from_entry(i, std::move(*kept));
    if (!result) throw std::runtime_error(fmt::format("search {}: its model cannot be built here", i + 1));
    deliver(i, std::move(*result));
  };
  ThreadScheduler here;
  (how.scheduler ? *how.scheduler : here).run(todo, how.threads, work);
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
  const std::vector<Variant> variants = parameter_variants(model.scene(), out.parameter_column);
  run_searches(model, variants, grid_settings(model.scene().study), progress, how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t, const BearingModel&, DistressSearch& found) {
                 out.states.insert(out.states.end(), found.states.begin(), found.states.end());
                 out.trajectory.insert(out.trajectory.end(), found.runaway.begin(), found.runaway.end());
                 out.distress.push_back(found.row);
                 keep_failure(out, found);
               });
}

void run_distress_map(BearingModel& base, StudyOutcome& out, const ProgressReport& progress, const Running& how) {
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_column);
  DistressSearchSettings settings = range_settings(base.scene().study);
  settings.march_past_distress = false;  // the map keeps neither the hot states nor the trajectories
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
    variants.push_back({std::move(scene), std::nullopt, name, ", sliding " + name});
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
  out.states.push_back(record(model, u, rep));
  if (progress) progress(fmt::format("steady at {:.6g} N; stepping to {:.6g} N", st.load_start, st.load_end));
  StepMarch march = march_load_step(model, u, st.load_end, TransientSettings{}, newton, st.duration);
  out.timings.newton_iterations += rep.iterations + march.newton_iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  out.timings.transients += 1;
  out.timings.ida_steps += march.ida_steps;
  out.timings.ida_factorizations += march.ida_factorizations;
  out.trajectory = std::move(march.trajectory);
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
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  const Running how{threads, plumbing.journal, plumbing.scheduler, options.stop};
  StudyOutcome out;
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
  }
  // Searches run on worker threads count their own (run_searches); the rest ran here.
  const StudyType type = model.scene().study.type;
  if (type != StudyType::load_sweep && type != StudyType::distress_map && type != StudyType::sliding_choice &&
      type != StudyType::distress_curve) {
    out.timings.klu_factorizations =
        SparseLu::thread_counts().factored_since(klu_before) + out.timings.ida_factorizations;
  }
  if (options.stop && options.stop->load() && has_independent_searches(type)) {
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
  if (type != StudyType::point && type != StudyType::transient)
    for (const SolvedState& s : out.states) out.timings.newton_iterations += s.iterations;
  out.timings.solve_ms = elapsed_ms(t0);
  return out;
}

}  // namespace twb
