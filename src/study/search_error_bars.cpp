#include "study/search_error_bars.h"

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
}  // namespace

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
    if (row.criterion == FailureCriterion::crossing(kFailureCriteria[c])) {
      row.failure_extrapolated = e->extrapolated;
      row.failure_error = e->error;
    }
    if (progress)
      progress(fmt::format("  error bar: {} crossed at {:.2f} N on {}; extrapolated {:.2f} ± {:.2f} N [{:.1f} s]",
                           limit_name(kFailureCriteria[c]), e->fine_fold, e->fine_mesh, e->extrapolated, e->error,
                           elapsed_ms(t0) / 1000.0));
  }
  if (row.criterion && row.criterion->distress) {
    row.failure_extrapolated = row.extrapolated_load;
    row.failure_error = row.discretization_error;
  }
  if (row.failure_load && row.failure_error)
    row.failure += fmt::format("; mesh-converged {:.1f} ± {:.1f} N", *row.failure_extrapolated, *row.failure_error);
}

}  // namespace twb
