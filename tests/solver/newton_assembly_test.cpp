// KinsolNewton assembles the residual with its Jacobian at every Newton point, except
// at the point it expects to meet the tolerance (kinsol_newton.cpp): where Newton
// converges quadratically no Jacobian is assembled and thrown away at the last point.
#include <gtest/gtest.h>

#include "../support/model_problems.h"
#include "solver/kinsol_newton.h"

namespace twb {
namespace {

// Forwards to a system and counts its assemblies, with and without the Jacobian.
class CountingSystem final : public SteadySystem {
 public:
  explicit CountingSystem(SteadySystem& base) : base_(base) {}
  Index size() const override { return base_.size(); }
  const SparsePattern& pattern() const override { return base_.pattern(); }
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    ++(jac.empty() ? residual_only : with_jacobian);
    base_.evaluate(u, r, jac);
  }
  double parameter() const override { return base_.parameter(); }
  void set_parameter(double v) override { base_.set_parameter(v); }
  void parameter_derivative(std::span<const double> u, std::span<double> d) const override {
    base_.parameter_derivative(u, d);
  }
  std::vector<double> capacities() const override { return base_.capacities(); }
  mutable int residual_only = 0, with_jacobian = 0;

 private:
  SteadySystem& base_;
};

TEST(NewtonAssembly, NoJacobianIsAssembledAtTheConvergedPoint) {
  // Bratu at λ = 1 from u = 0: Newton converges quadratically (residual 1, then
  // ~1e-1, 1e-3, 1e-7, 1e-14), so after three points the guess C‖F‖² falls 100× below
  // the tolerance and the last point is assembled without its Jacobian.
  testing::BratuProblem bratu(100, 1.0);
  CountingSystem counted(bratu);
  KinsolNewton newton(counted);
  std::vector<double> u(100, 0.0);
  const NewtonReport rep = newton.solve(u, {.residual_tolerance = 1e-10, .max_step = 0.0});
  ASSERT_TRUE(rep.converged) << rep.message;
  ASSERT_GE(rep.iterations, 3);
  // One assembly with the Jacobian per Jacobian KINSOL used, and one without: the last.
  EXPECT_EQ(counted.with_jacobian, rep.jacobian_evaluations);
  EXPECT_EQ(counted.residual_only, 1);
  EXPECT_EQ(counted.with_jacobian + counted.residual_only, rep.residual_evaluations);
}

}  // namespace
}  // namespace twb
