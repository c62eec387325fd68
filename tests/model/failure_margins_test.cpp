// A state's margins to the failure criteria (model/failure_margins.h) on limits and
// values made by hand: which criteria a scene applies, the first one past, a crossing
// between two states, and the least margin as a share of each criterion's allowance.
#include <gtest/gtest.h>

#include <iterator>

#include "model/failure_margins.h"

namespace twb {
namespace {

// The oil's limits at 420 and 450 K, a washer limited to 470 K and a least film ratio of
// 3 (whole kelvins: the margins below are exact); no PV limit, no scuffing temperature.
OperatingLimits some_limits() {
  OperatingLimits l;
  l.max_oil_temperature = 420.0;
  l.flash_point = 450.0;
  l.material_temperature = {std::nullopt, 470.0, std::nullopt};
  l.min_film_ratio = 3.0;
  return l;
}

// A thermal state comfortably within every limit of some_limits().
LimitValues within() {
  LimitValues v;
  v.thermal = true;
  v.washer_mean_temperature = 370.0;
  v.oil_peak_temperature = 390.0;
  v.body_temperature = {380.0, 380.0, 380.0};
  v.hmin_over_sigma = 6.0;
  return v;
}

std::size_t at(LimitKind kind) { return *criterion_index(kind); }

TEST(FailureMargins, EveryCriterionHasItsPlaceAndNoOtherLimitHasOne) {
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) EXPECT_EQ(criterion_index(kFailureCriteria[c]), c);
  EXPECT_FALSE(criterion_index(LimitKind::contact_pressure));
  EXPECT_FALSE(criterion_index(LimitKind::film_below_statistics));
}

TEST(FailureMargins, TemperaturesApplyOnlyWithTheThermalEffect) {
  const OperatingLimits l = some_limits();
  const PerCriterion<bool> thermal = criteria_in_force(l, true), isothermal = criteria_in_force(l, false);
  EXPECT_TRUE(thermal[at(LimitKind::oil_temperature)]);
  EXPECT_TRUE(thermal[at(LimitKind::oil_peak_temperature)]);
  EXPECT_TRUE(thermal[at(LimitKind::washer_temperature)]);
  EXPECT_FALSE(thermal[at(LimitKind::carrier_temperature)]) << "no material limit given";
  EXPECT_FALSE(thermal[at(LimitKind::pv)]);
  EXPECT_FALSE(thermal[at(LimitKind::scuffing)]);
  for (LimitKind kind : {LimitKind::oil_temperature, LimitKind::oil_peak_temperature, LimitKind::washer_temperature})
    EXPECT_FALSE(isothermal[at(kind)]) << limit_name(kind);
  EXPECT_TRUE(isothermal[at(LimitKind::film_ratio)]) << "a film ratio needs no temperature";

  LimitValues v = within();
  v.thermal = false;
  const FailureMargins m(v, l);
  EXPECT_FALSE(m[at(LimitKind::oil_temperature)]);
  EXPECT_DOUBLE_EQ(*m[at(LimitKind::film_ratio)], 3.0);
}

TEST(FailureMargins, TheFirstCriterionPastInTheTablesOrder) {
  const OperatingLimits l = some_limits();
  LimitValues v = within();
  EXPECT_FALSE(FailureMargins(v, l).first_past());
  // On a limit is within it.
  v.hmin_over_sigma = 3.0;
  EXPECT_FALSE(FailureMargins(v, l).first_past());
  v.hmin_over_sigma = 2.5;
  EXPECT_EQ(FailureMargins(v, l).first_past(), LimitKind::film_ratio);
  // The washer's material past too: it comes first in kFailureCriteria.
  v.body_temperature[1] = 480.0;
  const FailureMargins m(v, l);
  EXPECT_EQ(m.first_past(), LimitKind::washer_temperature);
  EXPECT_TRUE(m.past(at(LimitKind::film_ratio)));
  EXPECT_FALSE(m.past(at(LimitKind::oil_temperature)));
  EXPECT_EQ(*m[at(LimitKind::washer_temperature)], -10.0);
}

TEST(FailureMargins, ACrossingIsAChangeOfSignEitherWay) {
  const OperatingLimits l = some_limits();
  LimitValues v = within();
  const FailureMargins before(v, l);
  v.oil_peak_temperature = 460.0;
  const FailureMargins after(v, l);
  const std::size_t peak = at(LimitKind::oil_peak_temperature);
  EXPECT_TRUE(after.crossed_since(before, peak));
  EXPECT_TRUE(before.crossed_since(after, peak)) << "a recovery";
  EXPECT_FALSE(after.crossed_since(before, at(LimitKind::oil_temperature)));
  // A criterion the scene does not apply is never crossed.
  v.thermal = false;
  EXPECT_FALSE(FailureMargins(v, l).crossed_since(after, peak));
}

TEST(FailureMargins, TheLeastMarginIsTheLeastShareOfItsAllowance) {
  const OperatingLimits l = some_limits();
  LimitValues v = within();
  // Margins: oil 50 K, peak 60 K, washer 90 K, film ratio 3.
  PerCriterion<std::optional<double>> allowance;
  allowance[at(LimitKind::oil_temperature)] = 100.0;       // 0.5
  allowance[at(LimitKind::oil_peak_temperature)] = 200.0;  // 0.3
  allowance[at(LimitKind::washer_temperature)] = 0.0;      // no allowance: no share
  allowance[at(LimitKind::film_ratio)] = 6.0;              // 0.5
  std::optional<FailureMargins::Least> least = FailureMargins(v, l).least_share(allowance);
  ASSERT_TRUE(least);
  EXPECT_EQ(least->kind, LimitKind::oil_peak_temperature);
  EXPECT_EQ(least->share, 0.3);
  // Past a limit the share is negative, and the least.
  v.hmin_over_sigma = 1.5;
  least = FailureMargins(v, l).least_share(allowance);
  ASSERT_TRUE(least);
  EXPECT_EQ(least->kind, LimitKind::film_ratio);
  EXPECT_EQ(least->share, -0.25);
  // Equal shares: the first criterion's.
  allowance[at(LimitKind::oil_peak_temperature)] = 120.0;  // 0.5, as the oil's
  v.hmin_over_sigma = 6.0;
  least = FailureMargins(v, l).least_share(allowance);
  ASSERT_TRUE(least);
  EXPECT_EQ(least->kind, LimitKind::oil_temperature);
  // Without any allowance there is no least share.
  EXPECT_FALSE(FailureMargins(v, l).least_share({}));
}

}  // namespace
}  // namespace twb
