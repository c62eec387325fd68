#include "fold_proof.h"

#include <algorithm>

#include <fmt/format.h>

namespace twb {

FoldProof prove_fold(BearingModel& model, const BranchStates& cool, const BranchStates& approach, double fold,
                     const RunawaySettings& runaway, bool keep_trajectory, SearchCounts& counts,
                     const SearchProgress& say) {
  FoldProof proof;
  Bracket& b = proof.bracket;
  const double half = 0.5 * runaway.relative_width;
  b.low = fold * (1.0 - half);
  b.high = fold * (1.0 + half);
  auto start = std::find_if(cool.rbegin(), cool.rend(), [&](const auto& c) { return c.first < b.low; });
  if (start == cool.rend()) {
    b.message = fmt::format("no cool state below the fold's bracket at {:.6g} N to step from", b.low);
    return proof;
  }
  say(fmt::format("  proving the fold at {:.2f} N: a load step {:.2f} -> {:.2f} N", fold, start->first, b.low));
  // Where the step settles must be the cool branch's state: the branch test continues
  // the branch there, from the nearest state arclength continuation passed on its way to
  // the fold when that is nearer than the step's start (near the fold, natural
  // continuation over the whole step creeps).
  RunawaySettings below_settings = runaway;
  const auto nearest = std::find_if(approach.rbegin(), approach.rend(), [&](const auto& c) { return c.first < b.low; });
  if (runaway.on_branch && nearest != approach.rend() && nearest->first > start->first)
    below_settings.on_branch = [test = runaway.on_branch, &nearest](SteadySystem& system, std::span<const double>,
                                                                     double, std::span<const double> settled,
                                                                     double load) {
      return test(system, nearest->second, nearest->first, settled, load);
    };
  model.set_load(start->first);
  StepOutcome below = classify_step(model, start->second, b.low, below_settings);
  counts.add(below);
  b.steps.push_back({b.low, below.verdict, below.evidence, below.time, below.reason});
  if (!below.settled()) {
    b.message = fmt::format("the dynamics disagree with the fold: the step to {:.6g} N, below it, runs away ({})", b.low,
                            below.reason);
    return proof;
  }
  say(fmt::format("  proving the fold at {:.2f} N: it settles; a load step {:.2f} -> {:.2f} N", fold, b.low, b.high));
  model.set_load(b.low);
  const TransientObserver record_runaway = [&](double t, std::span<const double> u) {
    TrajectorySample& sample = proof.runaway.emplace_back();
    sample.time = t;
    sample.state = model.describe(u);
  };
  StepOutcome above =
      classify_step(model, below.final_state, b.high, runaway, keep_trajectory ? record_runaway : TransientObserver{});
  counts.add(above);
  b.steps.push_back({b.high, above.verdict, above.evidence, above.time, above.reason});
  if (above.settled()) {
    b.message = fmt::format("the dynamics disagree with the fold: the step to {:.6g} N, above it, settles ({})",
                            b.high, above.reason);
    return proof;
  }
  say(fmt::format("  proving the fold at {:.2f} N: it runs away ({})", fold, above.reason));
  b.low_state = std::move(below.final_state);
  proof.runaway_state = std::move(above.final_state);
  proof.runaway_time = above.time;
  model.set_load(b.low);
  b.valid = true;
  return proof;
}

}  // namespace twb
