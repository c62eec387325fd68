// One accepted state of a branch as continuation hands it to its caller (the bearing
// study writes each to states.csv and checks it with a transient).
#pragma once

#include <functional>
#include <span>

namespace twb {

class SparseLu;

struct BranchPoint {
  int index = 0;  // 0: the start state
  std::span<const double> u;
  double lambda = 0.0;
  double arclength = 0.0;           // from the start, in the continuation metric; 0 in natural continuation
  std::span<const double> tangent;  // (t_u, t_μ), unit in the metric; empty in natural continuation
  long corrector_iterations = 0;    // of the correction that produced this state
  // Natural continuation: the corrector's factors of ∂F/∂u at u or one Newton step from
  // it, in Newton's form (a linear stability test needs no other); null otherwise.
  const SparseLu* factors = nullptr;
};

// Called for every accepted state, the start included, with the system's parameter at
// the state's λ (the continuation gives the caller's back when it ends); returning false
// stops the continuation there.
using BranchCallback = std::function<bool(const BranchPoint&)>;

}  // namespace twb
