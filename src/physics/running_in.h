// Running-in of a face's roughness by truncation (docs/physics.md section 20, [W5]-[W6];
// Jeng, Lin and Shyu 2004): a face whose heights were Gaussian with Rq σ0 loses what lies
// above a cut at c = τ·σ0, the heights above it flattened onto it. In units of σ0, with φ
// and Φ the standard normal density and distribution and Q = 1 − Φ:
//
//   d/σ0      = φ(τ) − τ·Q(τ)                                   [W5]  the mean depth removed
//   (σ/σ0)²   = Φ(τ) − τ·φ(τ) + τ²·Q(τ) − (τ·Q(τ) − φ(τ))²       [W6]  the plateau face's Rq
//
// [W5] falls from 0 (no cut, τ → ∞) to −τ (the cut far below the mean), so each depth has
// one cut. Along the wear, dd/dτ = −σ0·Q(τ) and d(σ/σ0)²/dτ = 2·Q·(τ·Φ + φ), so that
//
//   dσ/dd = −(τ·Φ(τ) + φ(τ)) / sqrt([W6])
//
// which grows without bound, as τ, while the first summits go (the slope of a new face
// is infinite, logarithmically): the cut is held at τ ≤ kHighestCut, below which depth
// (1.1e-18 σ0) a face is new to the last digit of σ. Running-in stops at the face's run-in
// Rq (Kragelskii's equilibrium roughness): from the depth where [W6] reaches it the face
// wears with that texture, σ held.
#pragma once

#include <optional>

#include "physics/value_slope.h"

namespace twb {

// [W5] and [W6] at the cut τ (in σ0).
double truncated_depth(double cut);
double truncated_variance(double cut);
// The cut at which [W5] removes the depth `depth` (in σ0): at most kHighestCut.
double cut_for_depth(double depth);

class RunningIn {
 public:
  // The highest cut held (see above): [W5] there is 1.1e-18, [W6] 1 to the last digit.
  static constexpr double kHighestCut = 8.5;

  // rq_new σ0 > 0 (m); rq_run_in in (0, σ0] (m), or none: the face keeps σ0.
  RunningIn(double rq_new, std::optional<double> rq_run_in);

  // The face's Rq (m) and dRq/dd at the worn depth d (m); a depth below zero is a new
  // face's (σ0, and the slope at the highest cut, so that the derivative is continuous).
  ValueSlope rq(double depth) const;
  // Where running-in ends (m): the depth at which [W6] reaches the run-in Rq; none
  // without one (the face keeps σ0 at every depth).
  std::optional<double> run_in_depth() const { return run_in_depth_; }
  double rq_new() const { return rq_new_; }
  // The face's Rq once run in: its run-in Rq, or σ0 without one.
  double rq_run_in() const { return rq_run_in_.value_or(rq_new_); }

 private:
  double rq_new_;
  std::optional<double> rq_run_in_, run_in_depth_;
};

}  // namespace twb
