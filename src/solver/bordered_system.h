// A base system F(u; λ) extended by one unknown and one equation: x = (u, μ) with the
// scaled parameter μ = λ/λ_scale (continuation_metric.h), equations [F(u; μ·λ_scale);
// h(x) − p]. Pseudo-arclength continuation (h: the distance along the tangent, p: the
// step) and the minimally augmented fold system (h: the singularity test function,
// p: its target, 0) are of this kind; this class holds what they share. The Jacobian
// has the base pattern bordered by a dense row and column (bordered_matrix.h), and
// ∂/∂p of the equations is −e_{n+1}.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "solver/bordered_matrix.h"
#include "solver/continuation_metric.h"
#include "system/steady_system.h"

namespace twb {

class BorderedSystem : public SteadySystem {
 public:
  const ContinuationMetric& metric() const { return metric_; }
  SteadySystem& base() const { return base_; }
  // x = (u, λ/λ_scale), and back.
  std::vector<double> extend(std::span<const double> u, double lambda) const;
  double lambda_of(std::span<const double> x) const { return x[std::size_t(base_.size())] * metric_.parameter_scale(); }

  Index size() const override { return base_.size() + 1; }
  const SparsePattern& pattern() const override { return matrix_.pattern(); }
  double parameter() const override { return parameter_; }
  void set_parameter(double value) override { parameter_ = value; }
  void parameter_derivative(std::span<const double> x, std::span<double> derivative) const override;
  // The last unknown is algebraic and, being O(1), weighs 1 in KINSOL's step measure;
  // the base's weights keep its step cap in the base's units.
  std::vector<double> capacities() const override;
  std::vector<double> step_weights() const override;
  std::string block_name(Index k) const override;
  std::string describe_row(Index k) const override;

 protected:
  BorderedSystem(SteadySystem& base, ContinuationMetric metric, std::string last_equation);
  const BorderedMatrix& matrix() const { return matrix_; }

 private:
  SteadySystem& base_;
  ContinuationMetric metric_;
  BorderedMatrix matrix_;
  std::string last_equation_;
  double parameter_ = 0.0;
};

}  // namespace twb
