#include "solver/fold_curve.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/kinsol_newton.h"
#include "solver/natural_continuation.h"

namespace twb {

FoldCurveSystem::FoldCurveSystem(SteadySystem& base, SecondParameter& parameter, ContinuationMetric metric,
                                 std::span<const double> fold_state, double fold_load,
                                 std::span<const double> null_vector)
    : parameter_(parameter), p_(parameter.value()) {
  p_scale_ = std::abs(p_) > 0.0 ? std::abs(p_) : 1.0;
  base.set_parameter(fold_load);
  std::vector<double> f_lambda(std::size_t(base.size()));
  base.parameter_derivative(fold_state, f_lambda);
  fold_ = std::make_unique<FoldSystem>(base, std::move(metric), f_lambda, null_vector);
}

void FoldCurveSystem::set_parameter(double value) {
  p_ = value;
  parameter_.set(value);
}

void FoldCurveSystem::evaluate(std::span<const double> x, std::span<double> residual,
                               std::span<double> jacobian) const {
  parameter_.set(p_);
  fold_->evaluate(x, residual, jacobian);
}

void FoldCurveSystem::parameter_derivative(std::span<const double> x, std::span<double> derivative) const {
  const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(p_), p_scale_);
  std::vector<double> plus(x.size()), minus(x.size());
  parameter_.set(p_ + h);
  fold_->evaluate(x, plus, {});
  parameter_.set(p_ - h);
  fold_->evaluate(x, minus, {});
  parameter_.set(p_);
  for (std::size_t k = 0; k < x.size(); ++k) derivative[k] = (plus[k] - minus[k]) / (2.0 * h);
}

namespace {

// The fold system through a located fold, as a system in p: its load scaled by the fold's.
FoldCurveSystem curve_through(SteadySystem& base, SecondParameter& parameter, const FoldPoint& fold) {
  const double load_scale = std::abs(fold.lambda) > 0.0 ? std::abs(fold.lambda) : 1.0;
  return FoldCurveSystem(base, parameter, ContinuationMetric::of(base, load_scale), fold.u, fold.lambda,
                         fold.null_vector);
}

}  // namespace

std::optional<FoldCurvePoint> fold_at(SteadySystem& base, SecondParameter& parameter, const FoldPoint& fold,
                                      const FoldCurvePoint& near, double p, const NewtonSettings& newton) {
  const auto n = std::size_t(base.size());
  FoldCurveSystem curve = curve_through(base, parameter, fold);
  std::vector<double> x = curve.fold().extend(near.u, near.lambda);
  NaturalSettings natural;
  natural.newton = newton;
  const NaturalReport rep = continue_in_parameter(curve, x, near.p, p, natural);
  if (!rep.reached_target) return std::nullopt;
  // The curvature is the base system's at p (the fold system does not set p itself).
  curve.set_parameter(p);
  FoldCurvePoint out;
  out.p = p;
  out.lambda = curve.fold().lambda_of(x);
  out.u.assign(x.begin(), x.begin() + std::ptrdiff_t(n));
  out.curvature = curve.fold().fold_curvature(x);
  return out;
}

FoldCurve trace_fold_curve(SteadySystem& base, SecondParameter& parameter, const FoldPoint& fold,
                           const FoldCurveSettings& settings, const FoldCurveCallback& on_point) {
  FoldCurve out;
  const auto n = std::size_t(base.size());
  FoldCurveSystem curve = curve_through(base, parameter, fold);
  curve.set_parameter(parameter.value());
  std::vector<double> x = curve.fold().extend(fold.u, fold.lambda);

  // The fold with the curve system's own borders: the located fold meets F and g within
  // the tolerance with the borders it was located with (or was bracketed without g at
  // all); a Newton polish at fixed p makes it a point of this system.
  {
    KinsolNewton polish(curve);
    const NewtonReport rep = polish.solve(x, settings.arclength.newton);
    if (!rep.converged) {
      out.message = "the fold is not a solution of the fold system at the start: " + rep.message;
      return out;
    }
  }
  ArclengthSettings arc = settings.arclength;
  arc.parameter_scale = settings.p_scale > 0.0 ? settings.p_scale : std::abs(parameter.value());
  if (!(arc.parameter_scale > 0.0)) arc.parameter_scale = 1.0;
  arc.lambda_min = settings.p_min;
  arc.lambda_max = settings.p_max;
  arc.direction = settings.direction;
  arc.locate_folds = true;
  // A turning point of the fold curve is located along the arclength (t_p = 0): the
  // minimally augmented system of the fold system would need its second derivatives.
  arc.fold.minimally_augmented = false;
  const ArclengthReport rep =
      continue_by_arclength(curve, x, parameter.value(), arc, [&](const BranchPoint& b) {
        FoldCurvePoint& pt = out.points.emplace_back();
        pt.index = b.index;
        pt.p = b.lambda;
        pt.lambda = curve.fold().lambda_of(b.u);
        pt.u.assign(b.u.begin(), b.u.begin() + std::ptrdiff_t(n));
        pt.tangent_p = b.tangent.empty() ? 0.0 : b.tangent.back();
        curve.set_parameter(pt.p);  // the corrector sets it again before its next evaluation
        pt.curvature = curve.fold().fold_curvature(b.u);
        return on_point ? on_point(pt) : true;
      });
  out.message = rep.message;
  // A turn lies between two consecutive points whose tangents' p components have
  // opposite signs (the continuation's own test); it reports them in that order.
  std::size_t next_turn = 0;
  for (std::size_t k = 0; k + 1 < out.points.size() && next_turn < rep.folds.size(); ++k) {
    if (out.points[k].tangent_p * out.points[k + 1].tangent_p >= 0.0) continue;
    const FoldPoint& f = rep.folds[next_turn++];
    CurveTurn turn;
    turn.point = f;
    turn.p = f.lambda;
    turn.lambda = curve.fold().lambda_of(f.u);
    turn.cusp = out.points[k].curvature * out.points[k + 1].curvature < 0.0;
    out.turns.push_back(std::move(turn));
  }
  return out;
}

}  // namespace twb
