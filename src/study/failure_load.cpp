#include "study/failure_load.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "model/limit_thresholds.h"
#include "solver/natural_continuation.h"
#include "study_support.h"

namespace twb {

namespace {

// Thrown by a trial state the branch could not be continued to (next to a fold): the
// crossing then stays at the bracket it had.
struct LostBranch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The branch between two of its states, continued to any load between them.
class BranchSegment {
 public:
  BranchSegment(BearingModel& model, const BranchStates& branch, std::size_t below, long& solves)
      : model_(model), solves_(solves) {
    known_.push_back(branch[below]);
    natural_.newton = newton_settings(model.scene());
    natural_.newton.max_iterations = 12;
    natural_.newton.line_search = false;
  }

  // The state at `load`, continued from the nearest known state below it.
  std::vector<double> at(double load) {
    const auto from = std::max_element(known_.begin(), known_.end(), [&](const auto& a, const auto& b) {
      return (a.first <= load ? a.first : -1e300) < (b.first <= load ? b.first : -1e300);
    });
    std::vector<double> u = from->second;
    const double span = load - from->first;
    if (span > 0.0) {
      model_.set_load(from->first);
      natural_.initial_step = natural_.max_step = span;
      natural_.min_step = 1e-3 * span;
      ++solves_;
      const NaturalReport rep = continue_in_parameter(model_, u, load, natural_);
      if (!rep.reached_target)
        throw LostBranch(fmt::format("the branch was not continued to {:.6g} N: {}", load, rep.message));
      known_.emplace_back(load, u);
    }
    model_.set_load(load);
    return u;
  }

 private:
  BearingModel& model_;
  long& solves_;
  NaturalSettings natural_;
  BranchStates known_;
};

std::optional<double> margin_of(const BearingModel& model, std::span<const double> u, LimitKind kind,
                                const OperatingLimits& limits) {
  return failure_margin(kind, LimitValues::of(model.describe(u), model.scene().effects.thermal), limits);
}

// Where the margin crosses zero between branch[k - 1] (within) and branch[k] (past).
double locate_crossing(BearingModel& model, const BranchStates& branch, std::size_t k, LimitKind kind,
                       const OperatingLimits& limits, double width, double within, double past, long& solves) {
  BranchSegment segment(model, branch, k - 1, solves);
  double a = branch[k - 1].first, b = branch[k].first, fa = within, fb = past;
  auto margin = [&](double load) {
    const std::vector<double> u = segment.at(load);
    return *margin_of(model, u, kind, limits);
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

void locate_failure(BearingModel& model, const BranchStates& branch, const FailureSettings& settings,
                    DistressRow& row, long& solves) {
  row.criterion_loads.fill(std::nullopt);
  if (branch.empty()) return;
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const LimitKind kind = kFailureCriteria[c];
    std::optional<double> previous;
    for (std::size_t k = 0; k < branch.size(); ++k) {
      model.set_load(branch[k].first);
      const std::optional<double> m = margin_of(model, branch[k].second, kind, limits);
      if (!m) break;  // the scene does not apply this criterion
      if (*m <= 0.0) {
        // Past it already at the start: the crossing lies at or below the searched range.
        row.criterion_loads[c] = k == 0 ? branch[0].first
                                        : locate_crossing(model, branch, k, kind, limits, settings.bracket_width,
                                                          *previous, *m, solves);
        break;
      }
      previous = m;
    }
  }
  row.failure_load.reset();
  row.criterion.clear();
  if (row.distress_load) {
    row.failure_load = row.distress_load;
    row.criterion = "distress";
  }
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const std::optional<double>& w = row.criterion_loads[c];
    if (w && (!row.failure_load || *w < *row.failure_load)) {
      row.failure_load = w;
      row.criterion = std::string(limit_name(kFailureCriteria[c]));
    }
  }
  row.failure = failure_sentence(row, settings.load_end);
  if (row.failure_load && row.criterion != "distress" && *row.failure_load <= settings.load_start)
    row.failure += fmt::format(" (already past it at the start, {:.6g} N: the crossing lies below the searched "
                               "range)",
                               settings.load_start);
}

std::string failure_sentence(const DistressRow& row, double load_end) {
  if (!row.failure_load)
    return fmt::format("no failure up to {:.6g} N (no thermo-viscous distress, no limit crossed)", load_end);
  if (row.criterion == "distress")
    return fmt::format("fails at {:.2f} N by thermo-viscous distress", *row.failure_load);
  std::string kind_phrase;
  for (LimitKind kind : kFailureCriteria)
    if (limit_name(kind) == row.criterion) kind_phrase = std::string(criterion_phrase(kind));
  return fmt::format("fails at {:.2f} N by {} ({})", *row.failure_load, kind_phrase,
                     row.distress_load ? fmt::format("thermo-viscous distress at {:.2f} N", *row.distress_load)
                                       : fmt::format("no thermo-viscous distress up to {:.6g} N", load_end));
}

}  // namespace twb
