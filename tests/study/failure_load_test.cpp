// Where the bearing fails (docs/physics.md section 8, "Failure load"): every failure
// criterion's crossing located on the branch, the failure load the least of them and of
// W_d. On the bronze washer (configs/washers/bronze_cusn8.yaml) at 3000 rpm on a coarse
// mesh, where the flash point, the bronze's temperature limit, the oil's maximum, the
// least film ratio and a PV limit of 2.5 MPa m/s (near 560 N there) are all crossed below
// any thermo-viscous distress.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "model/failure_margins.h"
#include "solver/natural_continuation.h"
#include "study/searches/steady_solver.h"
#include "study/searches/distress_search.h"
#include "study/searches/failure_load.h"
#include "study/study_support.h"
#include "twb/scene/scene_loader.h"
#include "../support/table1_scene.h"

namespace twb {
namespace {

Scene bronze(std::vector<std::string> more = {}) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml", overrides);
}

DistressSearchSettings range(double end) {
  DistressSearchSettings s;
  s.load_start = 100.0;
  s.load_end = end;
  s.march_past_distress = false;
  return s;
}

struct Shared {
  BearingModel model{bronze({"materials.washer.pv_limit=2.5 MPa m/s"})};
  DistressSearch found;
  Shared() {
    model.set_speed(model.scene().study.speeds().front());
    found = search_distress(model, range(2000.0), {});
  }
};
Shared& shared() {
  static Shared s;
  return s;
}

// The branch from the search's first state (a cold start at its load, on the cool branch
// there) continued up to `load` by natural continuation, as the search follows it; u and
// `at` carry the branch's last state and its load from call to call.
double margin_at(BearingModel& model, const DistressSearch& found, LimitKind kind, double load,
                 std::vector<double>& u, double& at) {
  NaturalSettings natural;
  natural.newton = newton_settings(model.scene());
  if (u.empty()) {
    at = found.states.front().state.load;
    model.set_load(at);
    EXPECT_TRUE(SteadySolver(model, natural.newton).solve_cold(u).converged);
  }
  natural.initial_step = natural.max_step = std::min(0.05 * load, load - at);
  natural.min_step = 1e-6 * load;
  if (load > at) {
    const NaturalReport rep = continue_in_parameter(model, u, at, load, natural);
    EXPECT_TRUE(rep.reached_target) << rep.message;
  }
  at = load;
  model.set_load(load);
  return *failure_margin(kind, LimitValues::of(model.describe(u), true), OperatingLimits::of(model.scene()));
}

TEST(FailureLoad, EveryCriterionIsCrossedWhereTheFineSweepCrossesIt) {
  Shared& s = shared();
  const DistressRow& row = s.found.row;
  ASSERT_FALSE(s.found.failed) << s.found.message;
  int located = 0;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const LimitKind kind = kFailureCriteria[c];
    if (!row.criterion_loads[c]) continue;
    ++located;
    const double w = *row.criterion_loads[c];
    // A fine sweep across the crossing in steps of a tenth of the bracket width, from the
    // branch below it: the crossing interpolated linearly between the two sweep states
    // that bracket it lies within the bracket width of the reported load (the linear
    // interpolation's own error over 0.02 % of the load is far smaller).
    std::vector<double> u;
    double at = 0.0;
    const double step = 0.1 * 0.002 * w;
    double previous_load = w - 12 * step;
    double previous = margin_at(s.model, s.found, kind, previous_load, u, at);
    ASSERT_GT(previous, 0.0) << limit_name(kind) << ": the sweep must start inside the criterion";
    std::optional<double> crossing;
    for (int k = -11; k <= 12 && !crossing; ++k) {
      const double load = w + k * step;
      const double m = margin_at(s.model, s.found, kind, load, u, at);
      if (m <= 0.0) crossing = previous_load + previous * (load - previous_load) / (previous - m);
      previous_load = load;
      previous = m;
    }
    ASSERT_TRUE(crossing) << limit_name(kind) << " is not crossed within 0.24 % above the reported " << w << " N";
    EXPECT_NEAR(*crossing, w, 0.002 * w) << limit_name(kind);
  }
  // The scene's flash point, bronze limit, oil maximum, film ratio, PV and scuffing
  // temperature are all reached.
  EXPECT_EQ(located, 6) << row.failure;
}

TEST(FailureLoad, TheFailureLoadIsTheLeastCriterion) {
  const DistressRow& row = shared().found.row;
  ASSERT_TRUE(row.failure_load) << row.failure;
  double least = INFINITY;
  std::string which;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
    if (row.criterion_loads[c] && *row.criterion_loads[c] < least) {
      least = *row.criterion_loads[c];
      which = std::string(limit_name(kFailureCriteria[c]));
    }
  if (row.distress_load && *row.distress_load < least) {
    least = *row.distress_load;
    which = "distress";
  }
  EXPECT_EQ(*row.failure_load, least);
  ASSERT_TRUE(row.criterion);
  EXPECT_EQ(criterion_name(*row.criterion), which);
  EXPECT_NE(row.failure.find(fmt::format("fails at {:.2f} N", least)), std::string::npos) << row.failure;
}

// States past a criterion name it, whatever their branch.
TEST(FailureLoad, StatesPastACriterionNameIt) {
  const DistressSearch& found = shared().found;
  const OperatingLimits limits = OperatingLimits::of(shared().model.scene());
  int past = 0;
  for (const SolvedState& s : found.states) {
    const bool hot = s.state.oil_peak_temperature > limits.flash_point;
    const std::string names = failure_names(s.state.limits);
    EXPECT_EQ(names.find("oil_peak_temperature") != std::string::npos, hot) << s.state.load << " N: " << names;
    past += hot;
  }
  EXPECT_GT(past, 0);
}

// Raising the flash point and the scuffing temperature above every temperature reached
// leaves the other criteria: the least of them is then the failure load, whichever order
// they come in.
TEST(FailureLoad, AnotherOrderReportsTheLowerCriterion) {
  BearingModel model(bronze({"lubricant.flash_temperature=295 degC", "limits.scuffing_temperature=300 degC"}));
  model.set_speed(model.scene().study.speeds().front());
  const DistressSearch found = search_distress(model, range(2000.0), {});
  const DistressRow& row = found.row;
  ASSERT_TRUE(row.failure_load) << row.failure;
  const auto flash = criterion_load(row, LimitKind::oil_peak_temperature);
  const auto washer = criterion_load(row, LimitKind::washer_temperature);
  const auto oil = criterion_load(row, LimitKind::oil_temperature);
  ASSERT_TRUE(washer && oil) << row.failure;
  // The shared search's loads of these two criteria do not depend on the flash point.
  EXPECT_NEAR(*washer, *criterion_load(shared().found.row, LimitKind::washer_temperature), 1e-6 * *washer);
  const double expected = std::min({*washer, *oil, flash ? *flash : INFINITY});
  EXPECT_EQ(*row.failure_load, expected);
  ASSERT_TRUE(row.criterion);
  const LimitKind least = flash && *flash < std::min(*washer, *oil) ? LimitKind::oil_peak_temperature
                          : *washer < *oil                          ? LimitKind::washer_temperature
                                                                    : LimitKind::oil_temperature;
  EXPECT_EQ(*row.criterion, FailureCriterion::crossing(least));
  EXPECT_EQ(criterion_name(*row.criterion), limit_name(least));
}

// A search bounded past its first failure (a distress map's study.search_past_failure)
// stops at the bound, reports what lies below it as the whole search does, and says the
// rest was not searched.
TEST(FailureLoad, ASearchBoundedPastTheFirstFailureStopsThere) {
  const DistressSearch& whole = shared().found;
  const OperatingLimits limits = OperatingLimits::of(shared().model.scene());
  // The first state of the whole search past a criterion: the bounded search follows the
  // same states up to there (the same continuation targets), so its bound is twice this.
  double first = 0.0;
  for (const SolvedState& s : whole.states)
    if (FailureMargins(LimitValues::of(s.state, true), limits).first_past()) {
      first = s.state.load;
      break;
    }
  ASSERT_GT(first, 0.0);
  const double bound = 2.0 * first;

  BearingModel model(bronze({"materials.washer.pv_limit=2.5 MPa m/s"}));
  model.set_speed(model.scene().study.speeds().front());
  DistressSearchSettings settings = range(2000.0);
  settings.search_past_failure = 2.0;
  const DistressSearch found = search_distress(model, settings, {});
  const DistressRow& row = found.row;
  EXPECT_EQ(row.verdict, DistressVerdict::bounded) << row.method;
  EXPECT_DOUBLE_EQ(found.searched_to, bound);
  ASSERT_FALSE(found.states.empty());
  EXPECT_DOUBLE_EQ(found.states.back().state.load, bound);
  for (const SolvedState& s : found.states) EXPECT_LE(s.state.load, bound);
  EXPECT_FALSE(row.distress_load);
  // Below the bound each crossing is the whole search's, to the bracket width it locates
  // loads to; above it none is reported. The test needs one of each.
  int below = 0, above = 0;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const std::optional<double>& all = whole.row.criterion_loads[c];
    if (!all) continue;
    if (*all < bound) {
      ++below;
      ASSERT_TRUE(row.criterion_loads[c]) << limit_name(kFailureCriteria[c]);
      EXPECT_NEAR(*row.criterion_loads[c], *all, settings.bracket_width * *all) << limit_name(kFailureCriteria[c]);
    } else {
      ++above;
      EXPECT_FALSE(row.criterion_loads[c]) << limit_name(kFailureCriteria[c]);
    }
  }
  EXPECT_GT(below, 0);
  EXPECT_GT(above, 0);
  ASSERT_TRUE(row.failure_load && whole.row.failure_load);
  EXPECT_NEAR(*row.failure_load, *whole.row.failure_load, settings.bracket_width * *whole.row.failure_load);
  EXPECT_NE(row.failure.find(fmt::format("thermo-viscous distress not searched past {:.6g} N", bound)),
            std::string::npos)
      << row.failure;
  EXPECT_NE(row.method.find("not searched further"), std::string::npos) << row.method;
}

// Below every criterion up to load_end: no failure load, and the row says so.
TEST(FailureLoad, NoneReachedSaysSo) {
  BearingModel model(bronze());
  model.set_speed(model.scene().study.speeds().front());
  const DistressSearch found = search_distress(model, range(150.0), {});
  const DistressRow& row = found.row;
  EXPECT_FALSE(row.failure_load);
  EXPECT_FALSE(row.criterion);
  for (const auto& load : row.criterion_loads) EXPECT_FALSE(load);
  EXPECT_NE(row.failure.find("no failure up to 150 N"), std::string::npos) << row.failure;
}

// A crossing just below the fold, approached by a secant whose first step overshoots the
// fold (the slope of a crossing further down, where the margin falls slowly): no state
// exists past the fold and the branch cannot be continued there; the step is halved back
// below it and the crossing found where the branch's margin is nought. The paper's
// bearing on the coarse mesh at 545 rad/s, with the flash point set to the oil's peak
// temperature at 97 % of W_d.
TEST(FailureLoad, ACrossingNextToTheFoldIsFoundFromAStepThatOvershootsIt) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  testing::use_coarse_mesh(s);
  s.lubricant.flash_temperature = 1000.0;  // K: not crossed, until set below
  BearingModel model(s);
  DistressSearchSettings settings = range(600.0);
  settings.fold_only = true;
  const DistressSearch found = search_distress(model, settings, {});
  ASSERT_TRUE(found.row.fold_load) << found.row.method;
  const double fold = *found.row.fold_load;

  // The branch at 97 % of W_d sets the flash point; the start at 85 %.
  std::vector<double> u;
  double at = 0.0;
  margin_at(model, found, LimitKind::oil_peak_temperature, 0.97 * fold, u, at);
  s.lubricant.flash_temperature = model.describe(u).oil_peak_temperature;
  BearingModel limited(s);
  std::vector<double> start;
  const double m0 = margin_at(limited, found, LimitKind::oil_peak_temperature, 0.85 * fold, start, at);
  ASSERT_GT(m0, 0.0);

  // The first step lands at 110 % of W_d.
  std::pair<double, std::vector<double>> state{0.85 * fold, start};
  double slope = -m0 / (1.10 * fold - 0.85 * fold);
  long solves = 0;
  std::string why;
  const std::optional<double> w = crossing_near(limited, LimitKind::oil_peak_temperature, state, slope,
                                                settings.bracket_width, settings.load_end, solves, why);
  ASSERT_TRUE(w) << why;
  // The secant stops where its next step is a tenth of the width: the root lies within
  // that step (superlinear convergence), and the flash point was read off a state
  // converged to the solver's tolerance, whose margin error moves the root by far less.
  EXPECT_NEAR(*w, 0.97 * fold, 0.1 * settings.bracket_width * fold);
}

}  // namespace
}  // namespace twb
