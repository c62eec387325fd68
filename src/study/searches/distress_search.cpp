#include "study/searches/distress_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <memory>
#include <optional>
#include <system_error>

#include <fmt/format.h>

#include "study/searches/failure_load.h"
#include "study/searches/fold_proof.h"
#include "study/searches/distress_phases.h"
#include "study/study_support.h"
#include "solver/natural_continuation.h"
#include "solver/runaway.h"
#include "solver/sparse_lu.h"
#include "study/parallel/spare_threads.h"
#include "study/searches/steady_solver.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

namespace twb {

namespace {

// The light load a start is checked against: a tenth of it. On the paper's bearing the
// cool branch is the only one a tenth of the distress load (the hot branch turns back
// well above that), and the branch down there costs a handful of continuation steps.
constexpr double light_load_fraction = 0.1;

}  // namespace

DistressSearchSettings range_settings(const FailureSearch& search) {
  DistressSearchSettings s;
  s.load_start = search.loads.start;
  s.load_end = search.loads.end;
  s.bracket_width = search.bracket_width;
  return s;
}

RunawaySettings distress_detector(const Scene& scene, double bracket_width) {
  RunawaySettings r;
  // The scene's tolerances, the detector's own bound on the settle test's iterations.
  const int settle_iterations = r.newton.max_iterations;
  r.newton = newton_settings(scene);
  r.newton.max_iterations = std::min(r.newton.max_iterations, settle_iterations);
  r.relative_width = bracket_width;
  // An integration error δ acts on the slow drift near the fold like a shift of the load
  // by a relative O(δ) (ida_transient.h). The proof's steps lie half a bracket width
  // from the fold, and a bisection stops at a bracket width: a relative tolerance of a
  // two-hundredth of the width keeps that shift 100 times below the nearest step (1e-5
  // at the default 0.2 %; IDA takes ~115 steps per W_d instead of ~183 at 1e-6, for the
  // same brackets), and never below what double precision resolves over a transient.
  r.transient.relative_tolerance = std::max(1e-10, bracket_width / 200.0);
  NaturalSettings natural;
  natural.newton = r.newton;
  natural.newton.max_iterations = 12;
  // The branch continued from the start in quarters of the step (a single long step
  // could itself jump across the fold), down to a thousandth of it: past the fold it
  // stops, and reaches nothing.
  r.on_branch = [natural](SteadySystem& system, std::span<const double> start, double start_load,
                          std::span<const double> settled, double load) mutable {
    if (load <= start_load) return true;
    std::vector<double> x(start.begin(), start.end());
    natural.initial_step = natural.max_step = 0.25 * (load - start_load);
    natural.min_step = 1e-3 * (load - start_load);
    const NaturalReport rep = continue_in_parameter(system, x, start_load, load, natural);
    return rep.reached_target && same_state(x, settled);
  };
  return r;
}

namespace {

// The search from a steady state `u` at settings.load_start, on the cool branch, by its
// phases (distress_phases.h).
DistressSearch search_from(BearingModel& model, const DistressSearchSettings& settings, std::vector<double> u,
                           const SteadyReport& first, const SearchProgress& progress, BranchStates& cool,
                           BranchStates& approach) {
  return DistressSearchPhases(model, settings, progress, cool, approach).run(std::move(u), first);
}

// Whether the start's branch leads down to the light load's own state (search_from_start).
struct StartCheck {
  double light = 0.0;
  std::vector<double> down;  // the start's branch continued down to `light`
  NaturalReport descent;
  std::vector<double> light_state;
  SteadyReport light_start;  // the light load's cold start
  std::string unchecked;     // why no light load was tried, if none was
  long klu_factorizations = 0;
};

// The cool branch is the one that goes on down to light loads, where the bearing has one
// steady state: continued down to a tenth of the start, the start's branch must get
// there without a turning point and land on that light load's own cold start.
StartCheck check_start(BearingModel& model, const DistressSearchSettings& settings, std::span<const double> u) {
  const SparseLu::Counts before = SparseLu::thread_counts();
  const NewtonSettings newton = newton_settings(model.scene());
  SteadySolver steady(model, newton);
  StartCheck c;
  c.light = settings.load_start * light_load_fraction;
  if (model.scene().lubricant.supply) {
    // Oil fed under pressure lifts the gear off a load light enough, which then has no
    // steady state, and a cold start there fails only after minutes (a fed grooved washer
    // on 17 × 144: 10 min at 15 N, where 30 N solves in 4 s): the light load is the
    // lightest of a tenth, a fifth, … of the start, and no less than the most the supply
    // can hold, that has one, up to two thirds of the start.
    const double top = settings.load_start / 1.5;
    c.light = std::max(c.light, model.supply_lift_bound());
    for (; c.light <= top; c.light *= 2.0) {
      model.set_load(c.light);
      c.light_start = steady.solve_cold(c.light_state);
      if (c.light_start.converged || 2.0 * c.light > top) break;
    }
    if (c.light > top) {
      c.unchecked = fmt::format("the oil supply may hold up to {:.3g} N, too near the start for a lighter load",
                                model.supply_lift_bound());
      return c;
    }
  }
  c.down.assign(u.begin(), u.end());
  NaturalSettings natural;
  natural.newton = in_basin(newton);
  natural.initial_step = natural.max_step = 0.15 * settings.load_start;
  natural.min_step = settings.bracket_width * c.light;
  c.descent = continue_in_parameter(model, c.down, settings.load_start, c.light, natural);
  model.set_load(c.light);
  if (!model.scene().lubricant.supply) c.light_start = steady.solve_cold(c.light_state);
  c.klu_factorizations = SparseLu::thread_counts().factored_since(before);
  return c;
}

DistressSearch search_from_start(BearingModel& model, const DistressSearchSettings& settings,
                                 const SearchProgress& progress, BranchStates& cool, BranchStates& approach) {
  const NewtonSettings newton = newton_settings(model.scene());
  model.set_load(settings.load_start);
  std::vector<double> u;
  SteadySolver steady(model, newton);
  const SteadyReport first = steady.solve_cold(u);
  if (!first.converged) {
    DistressSearch out;
    out.row.speed = model.speed();
    out.failed = true;
    out.message = fmt::format("no steady state at the starting load {:.6g} N: {}", settings.load_start,
                              first.message);
    out.row.method = "no steady state at load_start";
    return out;
  }
  const std::vector<double> capacity = model.capacities();
  const bool checks_start =
      !settings.fold_only && std::any_of(capacity.begin(), capacity.end(), [](double c) { return c > 0.0; });
  // Which branch the start lies on. The cold start finds some steady state, and past
  // distress that is a hot one. A branch continued up from the start through stable
  // states to a turning point the dynamics confirm (the step below settles, the step
  // above runs away) is the cool branch of the S: the hot branch turns back only at its
  // lower end, and a start on the unstable middle branch runs away at its first step.
  // Otherwise the start's branch is checked (check_start); if it does not lead down to
  // the light load's state, the search starts from the light load. The check depends on
  // the start alone: on a thread the study lends it runs beside the search, on a model
  // of its own (the same bearing), and is dropped if the fold is proven.
  std::optional<BorrowedThreads> helper;
  std::future<StartCheck> ahead;
  if (checks_start && settings.spare_threads) {
    helper.emplace(settings.spare_threads, 1);
    if (helper->count() == 1) {
      std::shared_ptr<BearingModel> twin =
          model.on_mesh(model.scene().mesh.radial_nodes, model.scene().mesh.circumferential_nodes);
      try {
        ahead = std::async(std::launch::async, [twin, &settings, start = u]() {
          return check_start(*twin, settings, start);
        });
      } catch (const std::system_error&) {
        // No thread to be had after all: the check runs after the search, as on one thread.
      }
    }
    if (!ahead.valid()) helper.reset();
  }
  DistressSearch out = search_from(model, settings, u, first, progress, cool, approach);
  if (!checks_start) return out;
  if (out.fold_proven) {
    // Not needed. Its thread is the study's again once the check is done (a few
    // continuation steps and one cold start: the branch to a fold takes longer). A bug
    // in it is not hidden; any other failure of an unneeded check is.
    if (ahead.valid()) {
      try {
        ahead.get();
      } catch (const InternalError&) {
        throw;
      } catch (const std::exception&) {
      }
    }
    return out;
  }
  const bool beside = ahead.valid();
  if (progress && !beside)
    progress(fmt::format("  {}: is the start at {:.6g} N on the cool branch? following it down to a "
                         "lighter load",
                         speed_text(model.speed(), model.scene().study.speeds_in_rpm), settings.load_start));
  const StartCheck check = beside ? ahead.get() : check_start(model, settings, u);
  helper.reset();
  // Counted as on one thread: the search's own count holds the check's factorizations
  // there, and a check dropped with the fold proven counts nowhere.
  if (beside) out.counts.klu_factorizations += check.klu_factorizations;
  const double light = check.light;
  if (progress)
    progress(fmt::format("  is the start on the cool branch? its branch followed down to {:.3g} N", light));
  if (check.descent.reached_target && check.light_start.converged && same_state(check.down, check.light_state))
    return out;
  if (!check.light_start.converged) {
    // No reference to judge by: the search from the start as it is, and say so.
    out.row.method = fmt::format("the start's branch could not be checked ({}); {}",
                                 check.unchecked.empty() ? fmt::format("no steady state at {:.3g} N", light)
                                                         : check.unchecked,
                                 out.row.method);
    return out;
  }
  if (progress)
    progress(fmt::format("  the start at {:.6g} N is not on the cool branch ({}); searching from {:.3g} N",
                         settings.load_start,
                         check.descent.reached_target ? "it continues down to another state than the light load's"
                                                      : "its branch turns back on the way down",
                         light));
  // The first search's work counts too.
  const SearchCounts spent = out.counts;
  DistressSearchSettings from_light = settings;
  from_light.load_start = light;
  out = search_from(model, from_light, check.light_state, check.light_start, progress, cool, approach);
  out.counts.add(spent);
  if (out.row.distress_load && *out.row.distress_load < settings.load_start) {
    out.start_past_distress = true;
    out.row.method = fmt::format("the start at {:.6g} N is already past distress (W_d ≈ {:.6g} N, continued from "
                                 "{:.3g} N): {}",
                                 settings.load_start, *out.row.distress_load, light, out.row.method);
  } else {
    // The start's branch did not lead down to the light load's state, yet the branch from
    // there has no distress below the start: say what was done, claim nothing more.
    out.row.method = fmt::format("the start at {:.6g} N did not continue down to the light load's state; searched "
                                 "from {:.3g} N instead: {}",
                                 settings.load_start, light, out.row.method);
  }
  return out;
}

}  // namespace

DistressSearch search_distress(BearingModel& model, const DistressSearchSettings& settings,
                               const SearchProgress& progress) {
  const ParameterScope load_as_given(model);
  const SparseLu::Counts before = SparseLu::thread_counts();
  BranchStates cool, approach;
  DistressSearch out = search_from_start(model, settings, progress, cool, approach);
  if (!settings.fold_only && !out.failed) {
    // The branch from the start up to where it ends: the states continuation accepted,
    // those arclength passed before the turn, and the fold.
    BranchStates branch = std::move(cool);
    for (auto& state : approach)
      if (branch.empty() || state.first > branch.back().first) branch.push_back(std::move(state));
    if (out.fold && out.fold->u.size() >= std::size_t(model.size()) &&
        (branch.empty() || out.fold->lambda > branch.back().first))
      branch.emplace_back(out.fold->lambda, std::vector<double>(out.fold->u.begin(), out.fold->u.begin() +
                                                                   std::ptrdiff_t(model.size())));
    const double start = out.states.empty() ? settings.load_start : out.states.front().state.load;
    const auto t0 = std::chrono::steady_clock::now();
    long solves = 0;
    if (progress)
      progress(fmt::format("  {}: where the branch crosses each failure criterion, up to {:.6g} N",
                           speed_text(model.speed(), model.scene().study.speeds_in_rpm), out.searched_to));
    locate_failure(model, branch, {start, out.searched_to, settings.bracket_width}, out.row, solves,
                   &out.crossing_states);
    if (progress && out.row.failure_load)
      progress(fmt::format("  {}: {} [{} steady solves, {:.1f} s]",
                           speed_text(model.speed(), model.scene().study.speeds_in_rpm), out.row.failure, solves,
                           elapsed_ms(t0) / 1000.0));
  }
  // (Plus the start's check where it ran beside the search: search_from_start.)
  out.counts.klu_factorizations += SparseLu::thread_counts().factored_since(before) + out.counts.ida_factorizations;
  return out;
}

}  // namespace twb
