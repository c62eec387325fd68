// How continuation measures a step along a branch of F(u; λ) = 0 (docs/physics.md section 8:
// distress is a fold of the steady branch continued in load).
//
// The branch lives in (u, λ), where u and λ have unrelated units (the bearing: O(1)
// scaled film and rigid-body unknowns, temperature rises in K, a load in N). Continuation
// works with the scaled parameter μ = λ/λ_scale and the inner product
//
//     ⟨a, b⟩ = Σ_k ω_k a_k b_k + a_μ b_μ,     ω_k = w_k² / Σ_j w_j²,
//
// where w are the system's step weights (what KINSOL measures a Newton step in: the
// unknowns' natural units) unless the caller gives others. Normalizing ω to sum 1 makes
// the state part a weighted RMS: a change of the whole state by one weighted unit counts
// as much as a change of λ by λ_scale, whatever the number of unknowns. λ_scale defaults
// to |λ| at the start, so a unit arclength step is a change of the order of the state
// itself or of the parameter itself.
#pragma once

#include <span>
#include <vector>

#include "system/steady_system.h"

namespace twb {

class ContinuationMetric {
 public:
  // weights: one per unknown, positive; parameter_scale > 0.
  ContinuationMetric(std::vector<double> weights, double parameter_scale);
  // The defaults above: the system's step weights (or `weights` if non-empty), and
  // |λ| (or `parameter_scale` if positive; 1 if λ = 0).
  static ContinuationMetric of(const SteadySystem& system, double parameter_scale = 0.0,
                               std::vector<double> weights = {});

  Index state_size() const { return Index(omega_.size()); }
  double parameter_scale() const { return parameter_scale_; }
  std::span<const double> state_weights() const { return omega_; }  // ω

  // Over the state part only (n entries), and over (u, μ) (n + 1 entries).
  double state_dot(std::span<const double> a, std::span<const double> b) const;
  double dot(std::span<const double> a, std::span<const double> b) const;
  double state_norm(std::span<const double> a) const;
  double norm(std::span<const double> a) const;

 private:
  std::vector<double> omega_;
  double parameter_scale_;
};

}  // namespace twb
