// A state's margin to each failure criterion (failure_margin, each in its criterion's own
// unit), and what the studies ask of them: which criteria a scene applies, the first one
// a state is past, whether one was crossed between two states, and the least margin as a
// share of each criterion's allowance. A criterion added to kFailureCriteria reaches every
// study through it.
#pragma once

#include <cstddef>
#include <optional>

#include "model/limit_thresholds.h"
#include "twb/model/operating_limits.h"

namespace twb {

// Which failure criteria the scene applies at all (criterion_applies of each).
PerCriterion<bool> criteria_in_force(const OperatingLimits& limits, bool thermal);

class FailureMargins {
 public:
  FailureMargins(const LimitValues& values, const OperatingLimits& limits);

  // Criterion c's margin (kFailureCriteria order); none where the scene does not apply it.
  const std::optional<double>& operator[](std::size_t c) const { return margins_[c]; }
  // Whether the state is past criterion c's limit (a margin of zero is on it, not past).
  bool past(std::size_t c) const { return margins_[c] && *margins_[c] < 0.0; }
  // The first criterion (kFailureCriteria order) the state is past, if any.
  std::optional<LimitKind> first_past() const;
  // Whether criterion c's margin changed sign since `before`: crossed or recovered in
  // between. A margin of zero counts as within.
  bool crossed_since(const FailureMargins& before, std::size_t c) const;

  // The least margin as a share of its criterion's allowance (a margin in the allowance's
  // unit; 1 where the state keeps all of it, 0 on the limit), which makes criteria of
  // different units comparable; criteria without a positive allowance take no part.
  struct Least {
    double share;
    LimitKind kind;
  };
  std::optional<Least> least_share(const PerCriterion<std::optional<double>>& allowance) const;

 private:
  PerCriterion<std::optional<double>> margins_;
};

}  // namespace twb
