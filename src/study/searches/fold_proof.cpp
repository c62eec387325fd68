#include "study/searches/fold_proof.h"

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
  // The step starts from the cool state nearest below the bracket: natural
  // continuation's last, or one arclength continuation passed on its way to the fold.
  // The nearer the start, the shorter the transient, and the branch test (the branch
  // continued from the start must reach the settled state) has less way to creep near
  // the fold.
  auto below_bracket = [&](const BranchStates& states) {
    return std::find_if(states.rbegin(), states.rend(), [&](const auto& c) { return c.first < b.low; });
  };
  const auto start = below_bracket(cool), nearest = below_bracket(approach);
  if (start == cool.rend()) {
    b.message = fmt::format("no cool state below the fold's bracket at {:.6g} N to step from", b.low);
    return proof;
  }
  const auto& from = (nearest != approach.rend() && nearest->first > start->first) ? *nearest : *start;
  say(fmt::format("  proving the fold at {:.2f} N: a load step {:.2f} -> {:.2f} N", fold, from.first, b.low));
  StepOutcome below = classify_step(model, from.second, from.first, b.low, runaway);
  counts.add(below);
  b.steps.push_back({b.low, below.verdict, below.evidence, below.time, below.reason});
  if (!below.settled()) {
    b.message = fmt::format("the dynamics disagree with the fold: the step to {:.6g} N, below it, runs away ({})", b.low,
                            below.reason);
    return proof;
  }
  say(fmt::format("  proving the fold at {:.2f} N: it settles; a load step {:.2f} -> {:.2f} N", fold, b.low, b.high));
  const TransientObserver record_runaway = [&](double t, std::span<const double> u) {
    TrajectorySample& sample = proof.runaway.emplace_back();
    sample.time = t;
    sample.state = model.describe(u);
  };
  StepOutcome above =
      classify_step(model, below.final_state, b.low, b.high, runaway,
                    keep_trajectory ? record_runaway : TransientObserver{});
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
