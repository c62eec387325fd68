#include "study/searches/failure_load.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>


#include "model/failure_margins.h"
#include "solver/kinsol_newton.h"
#include "solver/natural_continuation.h"
#include "study/uncertainty/input_neighbours.h"
#include "study/study_support.h"

namespace twb {

namespace {

// Thrown by a trial state the branch could not be continued to (next to a fold): the
// crossing then stays at the bracket it had.
struct LostBranch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The branch near one of its states, continued to any load nearby.
class BranchSegment {
 public:
  BranchSegment(BearingModel& model, std::pair<double, std::vector<double>> state, long& solves)
      : model_(model), solves_(solves) {
    known_.push_back(std::move(state));
    natural_.newton = newton_settings(model.scene());
    natural_.newton.max_iterations = 12;
    natural_.newton.line_search = false;
  }

  // The state at `load`, continued from the nearest known state (below it where there
  // is one: the branch is followed up in load as the search followed it).
  const std::vector<double>& at(double load) {
    auto distance = [&](const auto& k) { return (k.first <= load ? 0.0 : 1e300) + std::abs(load - k.first); };
    const auto from = std::min_element(known_.begin(), known_.end(),
                                       [&](const auto& a, const auto& b) { return distance(a) < distance(b); });
    if (from->first == load) {
      model_.set_load(load);
      return from->second;
    }
    std::vector<double> u = from->second;
    const double span = std::abs(load - from->first);
    natural_.initial_step = natural_.max_step = span;
    natural_.min_step = 1e-3 * span;
    ++solves_;
    const NaturalReport rep = continue_in_parameter(model_, u, from->first, load, natural_);
    if (!rep.reached_target)
      throw LostBranch(fmt::format("the branch was not continued to {:.6g} N: {}", load, rep.message));
    model_.set_load(load);
    known_.emplace_back(load, std::move(u));
    return known_.back().second;
  }

  // A state of the branch solved elsewhere: a nearer start for the continuation.
  void add(double load, std::span<const double> u) { known_.emplace_back(load, std::vector<double>(u.begin(), u.end())); }

 private:
  BearingModel& model_;
  long& solves_;
  NaturalSettings natural_;
  BranchStates known_;
};

// Where the margin crosses zero between loads a (within, margin fa > 0) and b (past,
// fb <= 0), the branch continued from `segment`'s states.
double locate_crossing(BearingModel& model, BranchSegment& segment, LimitKind kind, const OperatingLimits& limits,
                       double width, double a, double fa, double b, double fb) {
  // Each load's margin kept: the bracket's ends are read back without another solve.
  std::map<double, double> known{{a, fa}, {b, fb}};
  auto margin = [&](double load) {
    const auto [it, fresh] = known.try_emplace(load, 0.0);
    if (fresh) it->second = *state_margin(model, segment.at(load), kind, limits);
    return it->second;
  };
  // The bracket [a, b] is narrowed until its relative width is the search's; TOMS 748
  // converges superlinearly on the smooth pieces of a margin (a maximum over nodes is
  // piecewise smooth), so that takes a few solves.
  auto narrow_enough = [&](double lo, double hi) { return hi - lo <= width * hi; };
  try {
    std::uintmax_t iterations = 40;
    const auto [lo, hi] = boost::math::tools::toms748_solve(margin, a, b, fa, fb, narrow_enough, iterations);
    if (lo != a) fa = margin(lo);
    if (hi != b) fb = margin(hi);
    a = lo;
    b = hi;
  } catch (const LostBranch&) {
    // Next to a fold the trial state may not be reached: the crossing lies in the bracket
    // the states give, located by its secant.
  }
  if (fa == fb) return b;
  return std::clamp(a - fa * (b - a) / (fb - fa), a, b);
}

}  // namespace

std::optional<double> state_margin(const BearingModel& model, std::span<const double> u, LimitKind kind,
                                   const OperatingLimits& limits) {
  return failure_margin(kind, LimitValues::of(model.describe(u), model.scene().effects.thermal), limits);
}

std::optional<double> crossing_near(BearingModel& model, LimitKind kind, std::pair<double, std::vector<double>>& state,
                                    double& slope, double width, double load_end, long& solves, std::string& why,
                                    KinsolNewton* corrector, BearingState* described, bool load_only) {
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  const bool thermal = model.scene().effects.thermal;
  NewtonSettings newton = newton_settings(model.scene());
  newton.max_iterations = 12;
  newton.line_search = false;
  std::optional<KinsolNewton> own;
  if (!corrector) corrector = &own.emplace(model);
  BranchSegment segment(model, state, solves);
  // The state at `load` from the last one: Newton from the branch's tangent there (a
  // constant predictor until a solve here has left its factors), a few iterations for
  // the secant's short steps.
  std::vector<double> u = state.second;
  double u_load = state.first;
  std::vector<double> tangent;  // J⁻¹F_W at u: u(W + Δ) ≈ u − Δ·tangent; empty where none
  auto take_tangent = [&] {
    tangent.clear();
    if (!corrector->factorization().factored()) return;
    tangent.resize(u.size());
    model.parameter_derivative(u, tangent);
    corrector->factorization().solve(tangent);
  };
  // A refined mesh's crossing starts from the caller's polish with this corrector: its
  // factors are the start's.
  if (load_only) take_tangent();
  // The load alone needed: a solve may stop where its margin is settled to a fiftieth of
  // the width in load at the secant's slope s (a fifth of the secant's last step, the
  // root's uncertainty at its stop).
  double s = 0.0;
  NewtonSettings settling = newton;
  if (load_only) {
    settling.quantities.at = [&](std::span<const double> w) {
      return std::vector<double>{*state_margin(model, w, kind, limits)};
    };
    settling.quantities.settled = [&](const NewtonSettings::QuantityReads& reads) {
      return settled_by_contraction(
          reads, [&](std::size_t, double) { return std::abs(s) * 0.02 * width * model.load(); });
    };
  }
  // A step Newton cannot take is halved towards the last state, twice at most, and the
  // branch continued to the last halving only where Newton still fails there: on a
  // steep stretch of the branch (a fold nearly reached) the secant overshoots the
  // crossing, and continuing the branch that far, through the steep stretch in small
  // steps, is the dearest solve of the search. `load` becomes the load the state is at.
  auto state_at = [&](double& load) -> const std::vector<double>& {
    for (int halving = 0; halving <= 2; ++halving) {
      model.set_load(load);
      std::vector<double> trial = tangent.empty() ? u : moved_state(u, tangent, load - u_load);
      ++solves;
      const NewtonReport rep = corrector->solve(trial, settling);
      if (rep.converged) {
        u = std::move(trial);
        u_load = load;
        // (A load-only solve stops once its margin is settled: not a state to continue from.)
        if (!load_only) segment.add(load, u);
        // A start KINSOL accepted as it was factors nothing: the factors are another solve's.
        if (rep.jacobian_evaluations > 0)
          take_tangent();
        else
          tangent.clear();
        return u;
      }
      if (halving < 2) load = u_load + 0.5 * (load - u_load);
    }
    u = segment.at(load);
    u_load = load;
    tangent.clear();
    return u;
  };
  BearingState here;
  auto margin_at = [&](std::span<const double> v) {
    here = model.describe(v);
    return *failure_margin(kind, LimitValues::of(here, thermal), limits);
  };
  try {
    double w0 = state.first;
    model.set_load(w0);
    double m0 = margin_at(u);
    // The secant on the margin along the branch, its first step with the caller's slope
    // (the crossing's at a nearby parameter), each step at most 30 % of the load.
    const bool local_slope = slope < 0.0;
    s = local_slope ? slope : -std::max(std::abs(m0), 1e-3) / (0.1 * w0);
    for (int step = 0; step < 16; ++step) {
      double w1 = std::clamp(w0 - m0 / s, 0.7 * w0, 1.3 * w0);
      if (w1 > load_end && w0 >= load_end) {
        why = fmt::format("not crossed up to {:.6g} N", load_end);
        return std::nullopt;
      }
      // The next step a tenth of the width: the root lies within it of w0 (superlinear
      // convergence). Only on a secant through w0, or on the branch's own slope at the
      // start (a refined mesh's, load_only: a Newton step): a nearby crossing's slope
      // may be far off where the margin bends sharply (contact setting in).
      if ((step > 0 || (load_only && local_slope)) && w1 <= load_end && std::abs(w1 - w0) <= 0.1 * width * w0) {
        slope = s;
        state = {w0, u};
        if (described) *described = std::move(here);
        // The load alone: the secant's root, closer than the last state solved.
        return load_only ? w1 : w0;
      }
      w1 = std::min(w1, load_end);
      const double m1 = margin_at(state_at(w1));
      if (m1 != m0) s = (m1 - m0) / (w1 - w0);
      if (!(s < 0.0)) s = -std::max(std::abs(m1), 1e-3) / (0.1 * w1);  // keep walking towards the crossing
      w0 = w1;
      m0 = m1;
    }
    why = "the secant on the margin did not converge in 16 steps";
  } catch (const LostBranch& e) {
    why = e.what();
  }
  return std::nullopt;
}

void locate_failure(BearingModel& model, const BranchStates& branch, const FailureSettings& settings,
                    DistressRow& row, long& solves, BranchStates* crossings) {
  const ParameterScope load_as_given(model);
  row.criterion_loads.fill(std::nullopt);
  if (crossings) crossings->assign(std::size(kFailureCriteria), {});
  if (branch.empty()) return;
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  const bool thermal = model.scene().effects.thermal;
  // Each branch state described once (an assembly each), for every criterion; only the
  // criteria the scene applies.
  std::vector<FailureMargins> margins;
  auto margins_at = [&](std::size_t k) -> const FailureMargins& {
    while (margins.size() <= k) {
      model.set_load(branch[margins.size()].first);
      margins.emplace_back(LimitValues::of(model.describe(branch[margins.size()].second), thermal), limits);
    }
    return margins[k];
  };
  const PerCriterion<bool> in_force = criteria_in_force(limits, thermal);
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const LimitKind kind = kFailureCriteria[c];
    if (!in_force[c]) continue;
    std::optional<double> previous;
    for (std::size_t k = 0; k < branch.size(); ++k) {
      const std::optional<double> m = margins_at(k)[c];
      if (!m) break;  // the scene does not apply this criterion
      if (*m <= 0.0) {
        // Past it already at the start: the crossing lies at or below the searched range.
        if (k == 0) {
          row.criterion_loads[c] = branch[0].first;
          if (crossings) (*crossings)[c] = branch[0];
          break;
        }
        BranchSegment segment(model, branch[k - 1], solves);
        const double w = locate_crossing(model, segment, kind, limits, settings.bracket_width, branch[k - 1].first,
                                         *previous, branch[k].first, *m);
        row.criterion_loads[c] = w;
        if (crossings) {
          try {
            (*crossings)[c] = {w, segment.at(w)};
          } catch (const LostBranch&) {
            (*crossings)[c] = branch[k - 1];  // next to the fold: the state below it
          }
        }
        break;
      }
      previous = m;
    }
  }
  row.failure_load.reset();
  row.criterion.reset();
  if (row.distress_load) {
    row.failure_load = row.distress_load;
    row.criterion = FailureCriterion::thermo_viscous_distress();
  }
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const std::optional<double>& w = row.criterion_loads[c];
    if (w && (!row.failure_load || *w < *row.failure_load)) {
      row.failure_load = w;
      row.criterion = FailureCriterion::crossing(kFailureCriteria[c]);
    }
  }
  row.failure = failure_sentence(row, settings.load_end);
  if (row.failure_load && !row.criterion->distress && *row.failure_load <= settings.load_start)
    row.failure += fmt::format(" (already past it at the start, {:.6g} N: the crossing lies below the searched "
                               "range)",
                               settings.load_start);
}

namespace {
// Up to where the branch holds no thermo-viscous distress: load_end, or the bound past
// the first failure (DistressVerdict::bounded), which was not searched past.
std::string no_distress_up_to(const DistressRow& row, double load_end) {
  return row.verdict == DistressVerdict::bounded
             ? fmt::format("thermo-viscous distress not searched past {:.6g} N", load_end)
             : fmt::format("no thermo-viscous distress up to {:.6g} N", load_end);
}
}  // namespace

std::string failure_sentence(const DistressRow& row, double load_end) {
  if (!row.failure_load)
    return fmt::format("no failure up to {:.6g} N (no thermo-viscous distress, no limit crossed)", load_end);
  if (!row.criterion || row.criterion->distress)
    return fmt::format("fails at {:.2f} N by thermo-viscous distress", *row.failure_load);
  return fmt::format("fails at {:.2f} N by {} ({})", *row.failure_load, criterion_phrase(row.criterion->limit),
                     row.distress_load ? fmt::format("thermo-viscous distress at {:.2f} N", *row.distress_load)
                                       : no_distress_up_to(row, load_end));
}

std::string converged_failure_sentence(const DistressRow& row, double load_end) {
  if (!row.failure_load || !row.failure_extrapolated || !row.failure_error) return failure_sentence(row, load_end);
  const LoadConvergence& c = row.failure_convergence;
  const std::string how = c.meshes.empty() ? std::string("Richardson on the mesh refined by two") : convergence_phrase(c);
  std::string s = fmt::format("fails at {:.1f} ± {:.1f} N by {} (mesh-converged {}; {:.2f} N on the scene's mesh)",
                              *row.failure_extrapolated, *row.failure_error,
                              row.criterion->distress ? std::string("thermo-viscous distress")
                                                      : std::string(criterion_phrase(row.criterion->limit)),
                              how, *row.failure_load);
  if (!row.criterion->distress)
    s += row.distress_load
             ? (row.extrapolated_load && row.discretization_error
                    ? fmt::format("; thermo-viscous distress at {:.1f} ± {:.1f} N", *row.extrapolated_load,
                                  *row.discretization_error)
                    : fmt::format("; thermo-viscous distress at {:.2f} N on the scene's mesh", *row.distress_load))
             : "; " + no_distress_up_to(row, load_end);
  if (c.tolerance_met && !*c.tolerance_met) s += "; NOT to the tolerance";
  return s;
}

}  // namespace twb
