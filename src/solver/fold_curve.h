// The fold of a steady branch continued in a second parameter (two-parameter
// continuation, as the established continuation packages do it): the minimally
// augmented system [F(u; λ, p); g(u; λ, p)] = 0 of fold_system.h, whose unknowns are
// x = (u, λ/λ_scale), is itself a SteadySystem in p, and pseudo-arclength continuation
// follows its solution curve through (u, λ, p). On the bearing λ is the load and p the
// speed (or another scene parameter): the curve is W_d(p), with the state at the fold
// all along it.
//
// Where the fold curve turns back in p (the p component of its tangent changes sign)
// the curve is located there by bracketing t_p = 0 along the arclength
// (fold_location.h's fallback: the minimally augmented system of a fold curve would need
// third derivatives). At a cusp the branch's two folds (the S-curve's upper and lower
// turning points) merge and disappear: the fold's curvature κ (FoldSystem::
// fold_curvature) changes sign there, the fold of largest λ becoming one of smallest,
// which tells a cusp from a fold curve that only turns back in p.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/arclength_continuation.h"
#include "solver/fold_system.h"

namespace twb {

// A second parameter of a SteadySystem besides its continuation parameter λ.
class SecondParameter {
 public:
  virtual ~SecondParameter() = default;
  virtual double value() const = 0;
  virtual void set(double p) = 0;
};

// The fold system as a SteadySystem in p. ∂/∂p by central differences of the fold
// system's residual (the bearing has no exact ∂F/∂p): with ε = ∛(machine ε)·max(|p|,
// p_scale) truncation and rounding balance at ~1e-11 relative, far below what the
// continuation's predictor and its tangent need.
class FoldCurveSystem final : public SteadySystem {
 public:
  // At a fold x = (u, λ/λ_scale) of `base` at p = parameter.value(): F_λ and the null
  // vector there give the fold system's borders (fold_system.h).
  FoldCurveSystem(SteadySystem& base, SecondParameter& parameter, ContinuationMetric metric,
                  std::span<const double> fold_state, double fold_load, std::span<const double> null_vector);

  const FoldSystem& fold() const { return *fold_; }
  Index size() const override { return fold_->size(); }
  const SparsePattern& pattern() const override { return fold_->pattern(); }
  void evaluate(std::span<const double> x, std::span<double> residual, std::span<double> jacobian) const override;
  double parameter() const override { return p_; }
  void set_parameter(double value) override;
  void parameter_derivative(std::span<const double> x, std::span<double> derivative) const override;
  std::vector<double> capacities() const override { return std::vector<double>(std::size_t(size()), 0.0); }
  std::vector<double> step_weights() const override { return fold_->step_weights(); }
  std::string block_name(Index k) const override { return fold_->block_name(k); }
  std::string describe_row(Index k) const override { return fold_->describe_row(k); }

 private:
  SecondParameter& parameter_;
  std::unique_ptr<FoldSystem> fold_;
  double p_ = 0.0, p_scale_ = 1.0;
};

struct FoldCurvePoint {
  double p = 0.0, lambda = 0.0;
  std::vector<double> u;
  double curvature = 0.0;  // κ of the fold: > 0 the branch's largest λ, < 0 its smallest
  double tangent_p = 0.0;  // the p component of the curve's unit tangent
  int index = 0;           // 0: the start
};

struct CurveTurn {
  FoldPoint point;  // λ holds p here; u holds (u, λ/λ_scale) of the base
  double p = 0.0, lambda = 0.0;
  bool cusp = false;  // κ changed sign across it
};

struct FoldCurveSettings {
  double p_min = 0.0, p_max = 0.0;  // the curve stops after its first point outside
  int direction = +1;               // start towards increasing (+1) or decreasing (−1) p
  ArclengthSettings arclength;      // steps in the metric over (u, λ/λ_scale, p/p_scale)
  double p_scale = 0.0;             // 0: |p| at the start
};

struct FoldCurve {
  std::vector<FoldCurvePoint> points;
  std::vector<CurveTurn> turns;  // where the curve turned back in p, in order
  std::string message;           // why it stopped
};

using FoldCurveCallback = std::function<bool(const FoldCurvePoint&)>;

// From a located fold of `base` at the current p (fold.u, fold.lambda, fold.null_vector).
// Leaves p and λ wherever the curve stopped.
FoldCurve trace_fold_curve(SteadySystem& base, SecondParameter& parameter, const FoldPoint& fold,
                           const FoldCurveSettings& settings, const FoldCurveCallback& on_point = {});

// The fold at exactly p, by natural continuation of the fold system in p from a point of
// the curve traced from `fold` (whose borders it reuses), p on the same side of any turn
// as `near`. Empty when the continuation does not reach p.
std::optional<FoldCurvePoint> fold_at(SteadySystem& base, SecondParameter& parameter, const FoldPoint& fold,
                                      const FoldCurvePoint& near, double p, const NewtonSettings& newton);

}  // namespace twb
