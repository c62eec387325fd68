#include "model/failure_margins.h"

namespace twb {

PerCriterion<bool> criteria_in_force(const OperatingLimits& limits, bool thermal) {
  PerCriterion<bool> in_force{};
  for (std::size_t c = 0; c < in_force.size(); ++c) in_force[c] = criterion_applies(kFailureCriteria[c], limits, thermal);
  return in_force;
}

FailureMargins::FailureMargins(const LimitValues& values, const OperatingLimits& limits) {
  for (std::size_t c = 0; c < margins_.size(); ++c) margins_[c] = failure_margin(kFailureCriteria[c], values, limits);
}

std::optional<LimitKind> FailureMargins::first_past() const {
  for (std::size_t c = 0; c < margins_.size(); ++c)
    if (past(c)) return kFailureCriteria[c];
  return std::nullopt;
}

bool FailureMargins::crossed_since(const FailureMargins& before, std::size_t c) const {
  const std::optional<double>&a = before[c], &b = margins_[c];
  return a && b && (*a >= 0.0) != (*b >= 0.0);
}

std::optional<FailureMargins::Least> FailureMargins::least_share(
    const PerCriterion<std::optional<double>>& allowance) const {
  std::optional<Least> least;
  for (std::size_t c = 0; c < margins_.size(); ++c) {
    const std::optional<double>& room = allowance[c];
    if (!margins_[c] || !room || !(*room > 0.0)) continue;
    const double share = *margins_[c] / *room;
    if (!least || share < least->share) least = Least{share, kFailureCriteria[c]};
  }
  return least;
}

}  // namespace twb
