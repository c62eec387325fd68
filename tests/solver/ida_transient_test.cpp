// The IDA transient C·u' = −F(u; λ) on systems whose trajectories are known: a linear
// relaxation (closed form), and the model problems' steady states (which it must keep,
// or reach after a small step).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/lower_branch.h"
#include "../support/model_problems.h"
#include "solver/ida_transient.h"

namespace twb {
namespace {

// Newton cooling written as a DAE whose differential row has no diagonal entry:
//     C·T' = −q,   0 = q − k·(T − T∞)      (u = (T, q))
// so T(t) = T∞ + (T(0) − T∞)·e^(−k t / C). IDA's Jacobian needs (0, 0) for c_j·C,
// which the system's pattern lacks: the transient must add it.
class LinearCooling final : public SteadySystem {
 public:
  LinearCooling() {
    pattern_.rows = pattern_.cols = 2;
    pattern_.row_start = {0, 1, 3};
    pattern_.column = {1, 0, 1};
  }
  Index size() const override { return 2; }
  const SparsePattern& pattern() const override { return pattern_; }
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    r[0] = u[1];
    r[1] = u[1] - k * (u[0] - ambient_);
    if (!jac.empty()) {
      jac[0] = 1.0;
      jac[1] = -k;
      jac[2] = 1.0;
    }
  }
  double parameter() const override { return ambient_; }
  void set_parameter(double v) override { ambient_ = v; }
  void parameter_derivative(std::span<const double>, std::span<double> d) const override {
    d[0] = 0.0;
    d[1] = k;
  }
  std::vector<double> capacities() const override { return {capacity, 0.0}; }

  static constexpr double k = 2.0, capacity = 3.0;

 private:
  double ambient_ = 1.0;
  SparsePattern pattern_;
};

TEST(IdaTransient, LinearCoolingFollowsTheExponential) {
  LinearCooling system;
  TransientSettings settings;
  IdaTransient ida(system, settings);
  const double t_end = 10.0 * LinearCooling::capacity / LinearCooling::k, start = 5.0, ambient = 1.0;
  // q(0) is wrong on purpose: CalcIC must make it consistent, k·(T(0) − T∞) = 8.
  const std::vector<double> u0 = {start, 0.0};
  const TransientStatus begun = ida.start(0.0, u0);
  ASSERT_TRUE(begun.ok) << begun.message;
  EXPECT_NEAR(ida.state()[1], LinearCooling::k * (start - ambient), 1e-10);
  EXPECT_NEAR(ida.rate()[0], -LinearCooling::k * (start - ambient) / LinearCooling::capacity, 1e-10);

  double worst = 0.0;  // largest error in units of IDA's local tolerance
  long samples = 0;
  const TransientStatus done = ida.advance(t_end, [&](double t, std::span<const double> u) {
    const double exact = ambient + (start - ambient) * std::exp(-LinearCooling::k * t / LinearCooling::capacity);
    worst = std::max(worst, std::abs(u[0] - exact) / (settings.relative_tolerance * exact + settings.absolute_tolerance));
    ++samples;
  });
  ASSERT_TRUE(done.ok) << done.message;
  EXPECT_DOUBLE_EQ(ida.time(), t_end);
  EXPECT_EQ(samples, ida.statistics().steps);
  std::cout << "linear cooling: " << samples << " steps, worst error " << worst << " local tolerances\n";
  // IDA controls the local error per step to ≤ 1 tolerance unit; on a decaying mode
  // the global error is the sum of local errors damped by e^(−k t/C), at most the
  // local error times the steps per relaxation time (≈ samples / 10 here). Assert
  // that bound: a wrong c_j·C (e.g. the missing diagonal) breaks it by orders.
  EXPECT_LE(worst, double(samples) / 10.0);
  EXPECT_GT(samples, 10);  // and the exponential was actually resolved
}

// A steady state has F = 0, so u' = 0: IDA must stay within what it resolves, one
// tolerance unit (the start's own residual, 1e-16 for Semenov and ≤ 1e-10 from KINSOL
// for Bratu, moves it by ‖J⁻¹‖·1e-10 ≈ 1e-11, five orders below).
void expect_stays(const SteadySystem& system, const std::vector<double>& steady, double t_end) {
  IdaTransient ida(system, TransientSettings{});
  ASSERT_TRUE(ida.start(0.0, steady).ok);
  double worst = 0.0;
  const TransientStatus done = ida.advance(t_end, [&](double, std::span<const double> u) {
    worst = std::max(worst, ida.differential_distance(u, steady));
  });
  ASSERT_TRUE(done.ok) << done.message;
  EXPECT_LE(worst, 1.0);
}

TEST(IdaTransient, SteadyStateStaysSteady) {
  testing::SemenovProblem semenov(0.3);
  expect_stays(semenov, testing::SemenovProblem::lower_steady_state(0.3), 100.0);
  testing::BratuProblem bratu(100, 3.0);
  expect_stays(bratu, testing::lower_branch_state(bratu, 3.0), 10.0);
}

// After a small step of λ the trajectory reaches the new steady state. Integrated over
// t = 64, 30 relaxation times (Semenov's at ψ = 0.31 is 1/(1 − θ*) ≈ 2.1), the initial
// gap has decayed by e^−30 ≈ 1e-13; what is left is IDA's global error, a few
// tolerance units (as on the linear case above).
TEST(IdaTransient, SmallStepReachesTheNewSteadyState) {
  testing::SemenovProblem semenov(0.3);
  IdaTransient ida(semenov, TransientSettings{});
  const std::vector<double> before = testing::SemenovProblem::lower_steady_state(0.3);
  const std::vector<double> after = testing::SemenovProblem::lower_steady_state(0.31);
  semenov.set_parameter(0.31);
  ASSERT_TRUE(ida.start(0.0, before).ok);
  // The algebraic unknown a = e^θ is consistent already; the step shows in θ' only,
  // as Δψ·a. CalcIC's Newton stops a fraction (IDA's 0.0033) of a tolerance unit from
  // the exact value, so θ' agrees to the relative tolerance.
  const TransientSettings tolerances;
  EXPECT_NEAR(ida.rate()[0], 0.01 * before[1], tolerances.relative_tolerance * 0.01 * before[1]);
  ASSERT_TRUE(ida.advance(64.0).ok);
  EXPECT_LE(ida.differential_distance(ida.state(), after), 10.0);
  EXPECT_NEAR(ida.state()[1], std::exp(ida.state()[0]), 1e-6 * ida.state()[1]);  // on the manifold
}

// An algebraic constraint tanh(a − ψ) = 0 whose residual is undefined (NaN, as an
// overflow would make it) beyond |a − ψ| > 5. From a = ψ − 2 the full Newton step
// (sinh(2)·cosh(2) ≈ 13.6) leaves that domain: CalcIC cannot recover, KINSOL's line
// search shortens the step. θ' = a − θ (C = 1).
class SaturatingConstraint final : public SteadySystem {
 public:
  Index size() const override { return 2; }
  const SparsePattern& pattern() const override { return pattern_; }
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    const double d = u[1] - psi_;
    r[0] = u[0] - u[1];
    r[1] = std::abs(d) > 5.0 ? NAN : std::tanh(d);
    if (!jac.empty()) {
      jac[0] = 1.0;
      jac[1] = -1.0;
      jac[2] = 0.0;
      jac[3] = 1.0 / (std::cosh(d) * std::cosh(d));
    }
  }
  double parameter() const override { return psi_; }
  void set_parameter(double v) override { psi_ = v; }
  void parameter_derivative(std::span<const double> u, std::span<double> d) const override {
    d[0] = 0.0;
    d[1] = -1.0 / (std::cosh(u[1] - psi_) * std::cosh(u[1] - psi_));
  }
  std::vector<double> capacities() const override { return {1.0, 0.0}; }

 private:
  double psi_ = 1.0;
  SparsePattern pattern_ = testing::dense_pattern(2);
};

// The fallback start is one implicit Euler step of Δτ = 1e-3 × the fastest relaxation
// time (C/J_θθ = 1): θ(Δτ) = Δτ·a/(1 + Δτ) from θ = 0 with a = ψ = 1. KINSOL's residual
// tolerance 1e-10 bounds the error of θ by 1e-10·Δτ and of a by 1e-10 (tanh' = 1).
TEST(IdaTransient, ConsistentStartBeyondCalcIcsReach) {
  SaturatingConstraint system;
  IdaTransient ida(system, TransientSettings{});
  const TransientStatus s = ida.start(0.0, std::vector<double>{0.0, -1.0});
  ASSERT_TRUE(s.ok) << s.message;
  const double dtau = 1e-3;
  EXPECT_DOUBLE_EQ(ida.time(), dtau);
  EXPECT_NEAR(ida.state()[1], 1.0, 1e-10);
  EXPECT_NEAR(ida.state()[0], dtau / (1.0 + dtau), 1e-12);
  EXPECT_NEAR(ida.rate()[0], ida.state()[1] - ida.state()[0], 1e-6);  // CalcIC's own tolerance
  ASSERT_TRUE(ida.advance(1.0).ok);
  EXPECT_NEAR(ida.state()[0], 1.0 - std::exp(-1.0), 1e-5);  // θ = 1 − e^−t, to a few tolerances
}

// A finite-time blow-up (Semenov far above ψ = 1/e: θ' ≥ ψ·e^θ − θ explodes before
// t ≈ 2) ends in an IDA failure reported by name, not in a crash.
TEST(IdaTransient, BlowUpIsReportedByFlagName) {
  testing::SemenovProblem semenov(2.0);
  IdaTransient ida(semenov, TransientSettings{});
  ASSERT_TRUE(ida.start(0.0, std::vector<double>{0.0, 1.0}).ok);
  const TransientStatus s = ida.advance(10.0);
  EXPECT_FALSE(s.ok);
  EXPECT_LT(ida.time(), 2.0);
  EXPECT_EQ(s.flag_name.rfind("IDA_", 0), 0u) << s.flag_name;
  EXPECT_FALSE(s.message.empty());
  std::cout << "blow-up at t = " << ida.time() << ": " << s.message << "\n";
}

// A lumped body in real time (docs/physics.md section 19): a plate of thickness t_b,
// heated over its face by a flux q and losing heat through its thickness to an ambient
// T_a(t), uniform in its plane. With ϑ = T − T_a its balance, in the bearing's form
// (a row scaled by t_b/(K·A), in kelvin), is
//     τ·(ϑ' + T_a') + ϑ − q·t_b/K = 0,     τ = ρ·c·t_b²/K,
// so that with q and T_a' held over a segment ϑ relaxes to ϑ_∞ = q·t_b/K − τ·T_a' as
// exp(−t/τ). The schedule's inputs move through TransientSettings::inputs_at, which
// returns T_a', as a duty cycle's do.
class LumpedBody final : public SteadySystem {
 public:
  LumpedBody() {
    pattern_.rows = pattern_.cols = 1;
    pattern_.row_start = {0, 1};
    pattern_.column = {0};
  }
  Index size() const override { return 1; }
  const SparsePattern& pattern() const override { return pattern_; }
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    r[0] = u[0] - flux * thickness / conductivity;
    if (!jac.empty()) jac[0] = 1.0;
  }
  double parameter() const override { return flux; }
  void set_parameter(double v) override { flux = v; }
  void parameter_derivative(std::span<const double>, std::span<double> d) const override {
    d[0] = -thickness / conductivity;
  }
  std::vector<double> capacities() const override { return {time_constant()}; }
  static double time_constant() { return density * specific_heat * thickness * thickness / conductivity; }

  // Steel, the paper's carrier: τ = 6.1 s.
  static constexpr double density = 7850.0, specific_heat = 470.0, thickness = 10e-3, conductivity = 60.5;
  double flux = 0.0;  // W/m²

 private:
  SparsePattern pattern_;
};

// Heated for 20 s at 50 kW/m² while the ambient rises at 0.5 K/s, then cooled for 40 s with
// the flux off and the ambient held: the march restarts at the kink, as a duty cycle does
// at a point of its schedule. The body's rise ϑ against the closed form of each segment,
// in units of IDA's local tolerance, bounded as on the linear cooling above (a global
// error of at most the local one times the steps per relaxation time).
TEST(IdaTransient, ALumpedBodyHeatsAndCoolsInRealTimeAsTheClosedFormSays) {
  LumpedBody body;
  const double tau = LumpedBody::time_constant(), q = 5e4, ramp = 0.5, heated = 20.0, end = 60.0;
  std::size_t segment = 0;
  TransientSettings settings;
  settings.real_time = true;
  settings.inputs_at = [&](double) {
    body.flux = segment == 0 ? q : 0.0;
    return segment == 0 ? ramp : 0.0;
  };
  IdaTransient ida(body, settings);
  const double rise = q * LumpedBody::thickness / LumpedBody::conductivity;  // 8.26 K
  auto expect_follows = [&](double t0, double t1, double start, double settles) {
    const TransientStatus begun = ida.start(t0, std::vector<double>{start});
    ASSERT_TRUE(begun.ok) << begun.message;
    EXPECT_NEAR(ida.rate()[0], (settles - start) / tau, 1e-12);  // the consistent rate
    double worst = 0.0;
    long samples = 0;
    const TransientStatus done = ida.advance(t1, [&](double t, std::span<const double> u) {
      const double exact = settles + (start - settles) * std::exp(-(t - t0) / tau);
      worst = std::max(worst, std::abs(u[0] - exact) /
                                  (settings.relative_tolerance * std::abs(exact) + settings.absolute_tolerance));
      ++samples;
    });
    ASSERT_TRUE(done.ok) << done.message;
    EXPECT_LE(worst, std::max(1.0, double(samples) * tau / (t1 - t0)));
    EXPECT_GT(samples, 10);
  };
  expect_follows(0.0, heated, 0.0, rise - tau * ramp);
  // Cooled from where the heating left it (its last step, at the kink, checked above).
  segment = 1;
  expect_follows(heated, end, ida.state()[0], 0.0);
}

}  // namespace
}  // namespace twb
