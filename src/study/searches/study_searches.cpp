#include "study/searches/study_searches.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "twb/results/run_axes.h"
#include "twb/scene/scene_inputs.h"

#include "study/searches/distress_curve.h"
#include "study/searches/load_step_march.h"
#include "study/parallel/parallel.h"
#include "study/parallel/search_journal.h"
#include "study/parallel/search_scheduler.h"
#include "study/accuracy/richardson.h"
#include "study/accuracy/state_error.h"
#include "study/study_support.h"
#include "twb/scene/scene_loader.h"
#include "solver/sparse_lu.h"
#include "study/searches/steady_solver.h"
#include "study/searches/distress_search.h"
#include "twb/error_family.h"
#include "study/accuracy/search_error_bars.h"
#include "study/parallel/spare_threads.h"

namespace twb {

std::string input_column(const std::string& path, const std::string& unit) {
  if (unit == "1") return path;
  std::string suffix;
  for (char c : unit)  // "W/(m K)" -> "W_m_K", "rad/s" -> "rad_s"
    if (std::isalnum(static_cast<unsigned char>(c)))
      suffix += c;
    else if (!suffix.empty() && suffix.back() != '_')
      suffix += '_';
  while (!suffix.empty() && suffix.back() == '_') suffix.pop_back();
  return path + "_" + suffix;
}

std::string parameter_column(const MapAxis& axis) {
  if (axis.parameter == MapParameter::scene_input) return input_column(axis.path, axis.unit);
  return parameter_column(axis.parameter);
}

std::string parameter_column(MapParameter p) {
  switch (p) {
    case MapParameter::friction_coefficient:
      return "friction_coefficient";
    case MapParameter::gear_tilt:
      return "gear_tilt_rad";
    case MapParameter::roughness:
      return "roughness_Rq_m";
    case MapParameter::groove_count:
      return "groove_count";
    case MapParameter::groove_width:
      return "groove_width_rad";
    case MapParameter::groove_depth:
      return "groove_depth_m";
    case MapParameter::none:
    case MapParameter::scene_input:
      break;
  }
  return {};
}

Scene with_parameter(Scene scene, const MapAxis& axis, double value) {
  const MapParameter p = axis.parameter;
  switch (p) {
    case MapParameter::scene_input: {
      // The scene reader tried every value.
      const std::pair<std::string, double> set[] = {{axis.path, value}};
      return with_inputs(scene, set);
    }
    case MapParameter::friction_coefficient:
      scene.friction.coefficient = value;
      break;
    case MapParameter::gear_tilt:
      scene.gear.tilt = value;
      break;
    case MapParameter::roughness:
      set_roughness(scene, value);
      break;
    case MapParameter::groove_count:
    case MapParameter::groove_width:
    case MapParameter::groove_depth: {
      // The scene reader checked that every value can be placed.
      if (const std::optional<GroovesNotPlaced> not_placed = place_groove_parameter(scene, p, value))
        throw InternalError("grooves the scene reader accepted cannot be placed: " + not_placed->why);
      break;
    }
    case MapParameter::none:
      break;
  }
  return scene;
}

std::vector<Variant> parameter_variants(const Scene& scene, std::vector<std::string>& columns) {
  const std::span<const MapAxis> axes = scene.study.axes();
  columns.clear();
  for (const MapAxis& axis : axes) columns.push_back(parameter_column(axis));
  if (axes.empty()) return {Variant{}};
  // The combinations as an odometer, the last axis turning fastest. The inputs by path
  // first, all at once: the scene is read again with them (with_inputs), which would undo
  // a named parameter set before; then the named ones in the axes' order (the scene
  // reader placed groove combinations so).
  std::vector<Variant> out;
  std::vector<std::size_t> at(axes.size(), 0), sizes;
  for (const MapAxis& axis : axes) sizes.push_back(axis.values.size());
  do {
    std::vector<std::pair<std::string, double>> inputs;
    for (std::size_t k = 0; k < axes.size(); ++k)
      if (axes[k].parameter == MapParameter::scene_input) inputs.emplace_back(axes[k].path, axes[k].values[at[k]]);
    Scene variant = inputs.empty() ? scene : with_inputs(scene, inputs, /*keep_study=*/true);
    std::vector<double> values;
    for (std::size_t k = 0; k < axes.size(); ++k) {
      if (axes[k].parameter != MapParameter::scene_input)
        variant = with_parameter(std::move(variant), axes[k], axes[k].values[at[k]]);
      values.push_back(axes[k].values[at[k]]);
    }
    // A groove's width as the grid holds it (whole cells, once every groove axis placed
    // them), which is what is solved.
    for (std::size_t k = 0; k < axes.size(); ++k)
      if (axes[k].parameter == MapParameter::groove_width) values[k] = variant.washer.grooves->width;
    std::string label = run_axes_text(columns, values);
    out.push_back({std::move(variant), std::move(values), {}, std::move(label)});
  } while (next_combination(at, sizes));
  return out;
}

std::vector<double> study_speeds(const BearingModel& model) {
  const std::span<const double> listed = model.scene().study.speeds();
  return listed.empty() ? std::vector<double>{model.speed()} : std::vector<double>(listed.begin(), listed.end());
}


namespace {

using Clock = std::chrono::steady_clock;

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
                      const ProgressReport& progress, SpareThreads* spare) {
  SearchDone done;
  DistressSearch& found = done.found;
  const Variant& variant = *task.variant;
  const SparseLu::Counts before = SparseLu::thread_counts();  // this thread's, so this task's
  bool searched = false;
  try {
    auto model = std::make_shared<BearingModel>(variant.scene ? *variant.scene : base.scene());
    model->set_speed(task.speed);
    done.model = model;
    DistressSearchSettings lent = settings;
    lent.spare_threads = spare;
    found = search_distress(*model, lent, progress);
    searched = true;
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
  // The task's factorizations on every thread: the search's own count (IDA's and a start
  // check's beside it included; this thread's alone where it failed), then the bars'.
  const SparseLu::Counts after_search = SparseLu::thread_counts();
  long factorizations = searched ? found.counts.klu_factorizations : after_search.factored_since(before);
  if (done.model) {
    factorizations += estimate_failure_errors(*done.model, settings, found, progress, spare);
    estimate_state_errors(*done.model, found, progress);
  }
  done.klu_factorizations = factorizations + SparseLu::thread_counts().factored_since(after_search);
  found.row.parameters = variant.parameters;
  found.row.sliding = variant.sliding;
  for (std::size_t i = 0; i < found.states.size(); ++i) {
    SolvedState& state = found.states[i];
    state.parameters = variant.parameters;
    state.sliding = variant.sliding;
    state.branch = i < found.cool_states ? Branch::cool : Branch::hot;
  }
  for (TrajectorySample& sample : found.runaway) {
    sample.parameters = variant.parameters;
    sample.sliding = variant.sliding;
  }
  return done;
}

}  // namespace

void run_searches(BearingModel& base, const std::vector<Variant>& variants, const DistressSearchSettings& settings,
                  const ProgressReport& progress, const Running& how, RunTimings& timings,
                  std::vector<std::string>& diagnostics, const SearchResult& take) {
  const std::vector<double> speeds = study_speeds(base);
  const bool in_rpm = base.scene().study.speeds_in_rpm;
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
        diagnostics.push_back(fmt::format("{}{}: {}", speed_text(t.speed, in_rpm), t.variant->label, d));
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
      say(fmt::format("[{}/{}] {}{}: from the journal", i + 1, total, speed_text(tasks[i].speed, in_rpm),
                      tasks[i].variant->label));
    deliver(i, std::move(*result));
  }

  SearchScheduler::Work work;
  // On this process's threads alone, those no search is left for serve the running
  // searches' bars (an MPI rank or a slice runs the searches another process deals).
  std::optional<SpareThreads> spare;
  if (!how.scheduler) spare.emplace(how.threads, todo.size());
  auto run = [&](std::size_t i) {
    const SearchTask& task = tasks[i];
    if (say) say(fmt::format("[{}/{}] {}{}", i + 1, total, speed_text(task.speed, in_rpm), task.variant->label));
    SearchDone result = search_one(base, task, settings, say, spare ? &*spare : nullptr);
    if (spare) spare->search_finished();
    return result;
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

}  // namespace twb
