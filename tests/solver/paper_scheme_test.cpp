// The paper's scheme (solver.method: paper) solves twb's equations: from the paper's cold
// start it reaches the state twb's monolithic Newton reaches, to the tolerance both
// converge to, with every row (the complementarity rows included) within it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/paper_scheme.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

// The largest difference of two states in each block, relative to the block's scale
// (its largest entry): the rigid body in σ and γ_ref, the pressures, the temperatures.
double block_difference(const std::vector<double>& a, const std::vector<double>& b, const std::vector<Index>& block) {
  double scale = 0.0, diff = 0.0;
  for (Index k : block) {
    scale = std::max(scale, std::abs(b[std::size_t(k)]));
    diff = std::max(diff, std::abs(a[std::size_t(k)] - b[std::size_t(k)]));
  }
  return scale > 0.0 ? diff / scale : diff;
}

struct Case {
  bool thermal;
  double speed, load;
};

class PaperScheme : public ::testing::TestWithParam<Case> {};

TEST_P(PaperScheme, ReachesTheMonolithicNewtonsState) {
  const Case c = GetParam();
  Scene scene = testing::table1_scene(true, true, true, c.thermal, c.speed, c.load);
  testing::use_coarse_mesh(scene);
  BearingModel model(scene);

  std::vector<double> newton;
  const SteadyReport mono = SteadySolver(model, NewtonSettings{}).solve_cold(newton);
  ASSERT_TRUE(mono.converged) << mono.message;

  std::vector<double> paper = model.cold_start();
  const PaperSchemeReport rep = solve_by_paper_scheme(model, paper);
  std::cout << "paper scheme: " << rep.newton_iterations << " Newton-Raphson iterations, " << rep.inner_solves
            << " coupled loops, " << rep.coupled_iterations << " passes, " << rep.pressure_sweeps
            << " pressure sweeps, " << rep.heat_sweeps << " heat sweeps, " << rep.evaluations
            << " evaluations; residual " << rep.residual_norm << "\n";
  ASSERT_TRUE(rep.converged) << rep.message;

  // Every row of the model's own form (complementarity rows) within the tolerance.
  std::vector<double> r(paper.size());
  model.evaluate(paper, r, {});
  double worst = 0.0;
  for (double x : r) worst = std::max(worst, std::abs(x));
  // Fischer–Burmeister rows are within (2 + √2) of the min rows the scheme converges.
  EXPECT_LE(worst, (2.0 + std::sqrt(2.0)) * 1e-10);

  // The same state: both are roots to 1e-10 of the same rows, so they differ by the
  // tolerance over the Jacobian's smallest singular value (a well-posed state, far from
  // the fold): 1e-7 of each block's scale leaves three orders for that factor.
  const SegregatedSystem::Blocks blocks = model.segregated_blocks();
  EXPECT_LE(block_difference(paper, newton, blocks.rigid), 1e-7);
  EXPECT_LE(block_difference(paper, newton, blocks.pressure), 1e-7);
  if (c.thermal) {
    EXPECT_LE(block_difference(paper, newton, blocks.temperature), 1e-7);
  }
}

// Isothermal and thermal; mostly fluid-carried (545 rad/s, 100 N) and mixed (136 rad/s,
// 300 N, a third of the load on the asperities).
INSTANTIATE_TEST_SUITE_P(Table1CoarseMesh, PaperScheme,
                         ::testing::Values(Case{false, 545.0, 100.0}, Case{true, 545.0, 100.0},
                                           Case{true, 136.0, 300.0}));

}  // namespace
}  // namespace twb
