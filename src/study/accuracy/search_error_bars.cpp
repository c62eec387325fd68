#include "study/accuracy/search_error_bars.h"

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

#include "study/searches/distress_curve.h"
#include "study/searches/load_step_march.h"
#include "study/parallel/parallel.h"
#include "study/parallel/search_journal.h"
#include "study/parallel/search_scheduler.h"
#include "study/parallel/spare_threads.h"
#include "study/accuracy/richardson.h"
#include "study/accuracy/mesh_convergence.h"
#include "study/searches/failure_load.h"
#include "study/accuracy/state_error.h"
#include "study/study_support.h"
#include "twb/scene/scene_loader.h"
#include "solver/sparse_lu.h"
#include "study/searches/steady_solver.h"
#include "study/searches/distress_search.h"
#include "twb/error_family.h"

namespace twb {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

// Every state of a search again on the refined mesh (study.error_estimate: every_state),
// on the search's thread; a state without one says why in the search's row.
void estimate_state_errors(const BearingModel& model, DistressSearch& found, const ProgressReport& progress) {
  const ErrorBarSettings* bars = model.scene().study.error_bars();
  if (!bars || bars->estimate != ErrorEstimate::every_state || found.states.empty() ||
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

namespace {

// What one piece of a search's bars found: a refined load extrapolated, or why not.
struct RefinedBar {
  std::optional<MeshErrorEstimate> estimate;
  std::string why;
  double seconds = 0.0;
  long klu_factorizations = 0;  // on the thread that ran it
};

// What the meshes of a sequence hold of the washer's grooves: each refinement doubles the
// cells, so every mesh holds the grooves the scene's mesh resolved (whole cells), which
// is the geometry the mesh-converged load belongs to, beside the width asked.
std::string grooves_held(const Scene& scene) {
  const Grooves& g = *scene.washer.grooves;
  const double mean_radius = 0.5 * (scene.washer.inner_radius + scene.washer.outer_radius);
  return fmt::format("every mesh holds the grooves as the scene's does: {} cells of {} ({:.4g} mm at the mean "
                     "radius; {:.4g} mm asked)",
                     g.cells, scene.mesh.circumferential_nodes, 1e3 * g.width * mean_radius,
                     1e3 * g.written_width * mean_radius);
}

// How closely a finer mesh's load is needed: a thousandth of the step the order two
// predicts from the last one (at least a thousandth of a percent of the load), which
// moves the estimate and its bar by about 0.1 % of that step.
double load_accuracy(const MeshSequence& sequence) {
  const std::vector<double>& w = sequence.loads();
  return 1e-3 * std::max(std::abs(w.back() - w[w.size() - 2]) / 4.0, 1e-3 * std::abs(w.back()));
}

// W_d again on the refined mesh: from the coarse fold by Newton on the fold system, else
// by a search there from where the coarse one began (a light load past distress); then,
// with a tolerance, on each finer mesh from the last one's fold until its bar meets it.
RefinedBar refined_fold(const BearingModel& model, const DistressSearchSettings& settings, const DistressSearch& found,
                        const ProgressReport& progress) {
  RefinedBar bar;
  DistressSearchSettings from = settings;
  from.load_start = found.states.front().state.load;
  const double tolerance = settings.error_tolerance;
  try {
    const CoarseFold coarse{*found.row.fold_load, &model, found.fold ? &*found.fold : nullptr};
    std::optional<RefinedFold> fine = refined_fold(model.scene(), model.speed(), coarse, from, bar.why, progress);
    if (!fine) return bar;
    MeshSequence sequence(model.scene(), coarse.load);
    sequence.add(fine->load);
    std::unique_ptr<BearingModel> at = std::move(fine->model);
    std::optional<FoldPoint> point = std::move(fine->point);
    std::string finest = mesh_name(at->scene());
    while (tolerance > 0.0 && sequence.wants_more(tolerance)) {
      const Scene* next = sequence.next_mesh();
      if (!next) break;
      if (!point) {
        sequence.stop(fmt::format("the fold on {} was found by a search without a located fold to go on from",
                                  finest));
        break;
      }
      const auto t0 = Clock::now();
      std::unique_ptr<BearingModel> finer = at->on_mesh(next->mesh.radial_nodes, next->mesh.circumferential_nodes);
      std::string why;
      std::optional<FoldPoint> located = fold_on_finer_mesh(*at, *point, *finer, load_accuracy(sequence), why);
      if (!located) {
        sequence.stop(fmt::format("the fold on {} from the one on {} failed: {}", mesh_name(*next), finest, why));
        break;
      }
      sequence.add(located->lambda);
      at = std::move(finer);
      point = std::move(located);
      finest = mesh_name(*next);
      if (progress) {
        const MeshConvergence c = sequence.estimate();
        progress(fmt::format("  error bar: the fold on {}: {:.2f} N; mesh-converged {:.2f} ± {:.2f} N{} [{:.1f} s]",
                             finest, point->lambda, c.value, c.error,
                             c.order ? fmt::format(" (observed order {:.2f})", *c.order) : std::string(),
                             elapsed_ms(t0) / 1000.0));
      }
    }
    bar.estimate = sequence_estimate(sequence, tolerance, finest);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& failure) {
    bar.why = std::string("the refined mesh's search failed: ") + failure.what();
  }
  return bar;
}

// Criterion c's crossing again on the refined mesh, on a refined model of its own, and
// with a tolerance on each finer mesh from the last one's crossing until its bar meets it.
// The crossing is located to a fifth of the tolerance where that is finer than the
// search's bracket width, so that its location moves the bar by little.
RefinedBar refined_crossing(const BearingModel& model, const DistressSearchSettings& settings,
                            const DistressSearch& found, std::size_t c) {
  RefinedBar bar;
  try {
    // Each finer mesh's bearing from the search's, held while the next starts from it.
    std::vector<std::unique_ptr<BearingModel>> held;
    bar.estimate = crossing_sequence(model, kFailureCriteria[c], found.crossing_states[c], settings.bracket_width,
                                     settings.load_end, settings.error_tolerance,
                                     [&](const Scene& next) -> BearingModel& {
                                       held.push_back(model.on_mesh(next.mesh.radial_nodes,
                                                                    next.mesh.circumferential_nodes));
                                       return *held.back();
                                     },
                                     bar.why);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& failure) {
    bar.why = failure.what();
  }
  return bar;
}

}  // namespace

long estimate_failure_errors(const BearingModel& model, const DistressSearchSettings& settings,
                             DistressSearch& found, const ProgressReport& progress, SpareThreads* spare) {
  if (!settings.failure_error_bars) return 0;
  DistressRow& row = found.row;
  // The pieces: W_d's fold where the search found one, and each criterion's crossing
  // above the searched range's start (one at the start lies below it: nothing to refine).
  const bool fold = row.distress_load && row.fold_load && !found.states.empty();
  // A W_d bracketed by transients alone has no fold to locate again on the refined mesh;
  // a bisection there would cost the search's transients again on four times the nodes.
  if (row.distress_load && !row.fold_load)
    row.method += "; no error bar for W_d: bracketed by bisection alone (no fold located to refine)";
  std::vector<std::size_t> crossings;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
    if (row.criterion_loads[c] && found.crossing_states.size() > c && !found.crossing_states[c].second.empty() &&
        *row.criterion_loads[c] > settings.load_start)
      crossings.push_back(c);
  const std::size_t pieces = (fold ? 1 : 0) + crossings.size();
  if (fold && progress) {
    const Scene fine = refined_mesh(model.scene());
    progress(fmt::format("  error bar: the fold on the {} x {} mesh", fine.mesh.radial_nodes,
                         fine.mesh.circumferential_nodes));
  }
  std::vector<RefinedBar> bars(pieces);
  const std::thread::id caller = std::this_thread::get_id();
  {
    const BorrowedThreads helpers(spare, int(pieces) - 1);
    run_in_parallel(pieces, 1 + helpers.count(), [&](std::size_t k) {
      const auto t0 = Clock::now();
      const SparseLu::Counts before = SparseLu::thread_counts();
      bars[k] = fold && k == 0 ? refined_fold(model, settings, found, progress)
                               : refined_crossing(model, settings, found, crossings[k - (fold ? 1 : 0)]);
      bars[k].seconds = elapsed_ms(t0) / 1000.0;
      if (std::this_thread::get_id() != caller)
        bars[k].klu_factorizations = SparseLu::thread_counts().factored_since(before);
    });
  }
  // The pieces' results in their fixed order, whichever thread ran them.
  long factorizations = 0;
  for (const RefinedBar& b : bars) factorizations += b.klu_factorizations;
  const auto unmet = [](const MeshErrorEstimate& e) {
    return e.convergence.tolerance_met && !*e.convergence.tolerance_met;
  };
  if (fold) {
    const RefinedBar& b = bars.front();
    if (!b.estimate) {
      row.method += "; no error estimate: " + b.why;
    } else {
      row.fine_fold_load = b.estimate->fine_fold;
      row.extrapolated_load = b.estimate->extrapolated;
      row.discretization_error = b.estimate->error;
      row.fold_convergence = b.estimate->convergence;
      if (unmet(*b.estimate)) row.method += "; W_d not to the tolerance: " + b.estimate->convergence.why_unmet;
      if (progress)
        progress(fmt::format("  error bar: fold {:.2f} N on {}; extrapolated W_d = {:.2f} ± {:.2f} N [{:.1f} s]",
                             b.estimate->fine_fold, b.estimate->fine_mesh, b.estimate->extrapolated,
                             b.estimate->error, b.seconds));
    }
  }
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const std::size_t c = crossings[k];
    const RefinedBar& b = bars[k + (fold ? 1 : 0)];
    if (!b.estimate) {
      row.method += fmt::format("; no error bar for {}: {}", limit_name(kFailureCriteria[c]), b.why);
      continue;
    }
    row.criterion_errors[c] = b.estimate->error;
    row.criterion_extrapolated[c] = b.estimate->extrapolated;
    if (unmet(*b.estimate))
      row.method += fmt::format("; {} not to the tolerance: {}", limit_name(kFailureCriteria[c]),
                                b.estimate->convergence.why_unmet);
    if (row.criterion == FailureCriterion::crossing(kFailureCriteria[c])) {
      row.failure_extrapolated = b.estimate->extrapolated;
      row.failure_error = b.estimate->error;
      row.failure_convergence = b.estimate->convergence;
    }
    if (progress)
      progress(fmt::format("  error bar: {} crossed at {:.2f} N on {}; extrapolated {:.2f} ± {:.2f} N [{:.1f} s]",
                           limit_name(kFailureCriteria[c]), b.estimate->fine_fold, b.estimate->fine_mesh,
                           b.estimate->extrapolated, b.estimate->error, b.seconds));
  }
  if (row.criterion && row.criterion->distress) {
    row.failure_extrapolated = row.extrapolated_load;
    row.failure_error = row.discretization_error;
    row.failure_convergence = row.fold_convergence;
  }
  if (row.failure_load && row.failure_error) {
    // The already-past note of locate_failure stays; the rest is said again converged first.
    const std::size_t past = row.failure.find(" (already past it at the start");
    row.failure = converged_failure_sentence(row, found.searched_to > 0.0 ? found.searched_to : settings.load_end) +
                  (past == std::string::npos ? std::string() : row.failure.substr(past));
    if (model.scene().washer.grooves && !row.failure_convergence.meshes.empty())
      row.failure += "; " + grooves_held(model.scene());
  }
  return factorizations;
}

}  // namespace twb
