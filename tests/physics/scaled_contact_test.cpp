// The contact pressure of a summit population scaled by k = σ/σ0 (docs/physics.md
// sections 4 and 20): exact at its tables, within its measured error between them, with
// exact slopes, and Greenwood–Williamson's scale invariance where the summits stay elastic.
#include "physics/scaled_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

// The paper's summit population (Table 1; the model's, physics §4).
ContactTableKey paper_population() {
  const BearingModel model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml"));
  const StatisticalContact& c = *model.contact();
  const JacksonGreenAsperity& a = c.asperity();
  return {a.effective_modulus(), a.yield_strength(), a.poisson_ratio(), a.summit_radius(), c.summit_density(),
          c.summit_sigma()};
}

StatisticalContact table_at(const ContactTableKey& key, double k) {
  const ContactTableKey s = ScaledContact::scaled(key, k);
  return StatisticalContact(JacksonGreenAsperity(s.effective_modulus, s.yield_strength, s.poisson_ratio, s.summit_radius),
                            s.summit_density, s.summit_sigma);
}

// Separations across the contact: from five summit deviations below the summits' mean
// plane (heavy contact) to where p falls to 1e-30 of its value at contact.
template <class Visit>
void across_contact(const StatisticalContact& t, Visit visit) {
  const double low = t.mean_summit_offset() - 5.0 * t.summit_sigma(), high = t.contact_pressure_cutoff_gap();
  for (int s = 0; s <= 40; ++s) visit(low + (high - low) * s / 40.0);
}

// A face run in to a third of its Rq. The interpolation in ln k (cubic, nodes 0.1 apart)
// errs by O(Δ⁴·G'''') between its tables: the bound it measured at construction is small
// (7e-6 of p on the paper's population; 2e-5 asked, far below the model's discretization
// error of 1e-3), and holds at scales it did not measure within twice itself; at its
// tables the error is each table's own (1e-10).
TEST(ScaledContact, BetweenItsTablesItErrsByTheBoundItMeasured) {
  const ContactTableKey key = paper_population();
  const ScaledContact scaled(key, 1.0 / 3.0);
  EXPECT_LT(scaled.error_bound(), 2e-5);
  for (const double k : {1.0 / 3.0, 0.41, 0.5, 0.77, 0.93, 1.0}) {
    SCOPED_TRACE(k);
    const StatisticalContact direct = table_at(key, k);
    across_contact(direct, [&](double h) {
      const double exact = direct.pressure(h).value;
      EXPECT_NEAR(scaled.pressure(h, k).value, exact, 2.0 * scaled.error_bound() * exact + 1e-300);
    });
  }
}

// ∂p/∂h and ∂p/∂k of the interpolant against its central differences (steps 1e-6 of σs
// and of k: truncation O(step²) about 1e-12 relative; rounding ε·p/step, 1e-10 of p/σs).
TEST(ScaledContact, ItsSlopesAreExact) {
  const ContactTableKey key = paper_population();
  const ScaledContact scaled(key, 0.3);
  const StatisticalContact unscaled = table_at(key, 1.0);
  for (const double k : {0.35, 0.6, 0.85}) {
    across_contact(unscaled, [&](double h1) {
      const double h = k * h1;
      SCOPED_TRACE(::testing::Message() << "k " << k << " h " << h);
      const ScaledContact::Pressure p = scaled.pressure(h, k);
      if (!(p.value > 1e-20 * scaled.pressure(0.0, k).value)) return;
      const double dh = 1e-6 * key.summit_sigma, dk = 1e-6;
      const double by_h = (scaled.pressure(h + dh, k).value - scaled.pressure(h - dh, k).value) / (2.0 * dh);
      const double by_k = (scaled.pressure(h, k + dk).value - scaled.pressure(h, k - dk).value) / (2.0 * dk);
      EXPECT_NEAR(p.dh, by_h, 1e-6 * std::abs(by_h) + 1e-9 * p.value / key.summit_sigma);
      EXPECT_NEAR(p.dk, by_k, 1e-6 * std::abs(by_k) + 1e-9 * p.value);
    });
  }
}

// Summits that do not yield are Hertz's, and Greenwood–Williamson's sum of them is
// scale-invariant: p(h; k) = k·p(h/k; 1), to the tables' own error (1e-10). A yield
// strength thirty times the paper's puts the critical interference at 12.8 σs, Jackson–
// Green's elastic law holding to 24 σs: summits past it, 19 σs above the mean at the
// heaviest contact probed, weigh below 1e-40.
TEST(ScaledContact, ElasticSummitsAreScaleInvariant) {
  ContactTableKey key = paper_population();
  key.yield_strength *= 30.0;
  // (tables half a unit of ln k apart: G does not change with k here, and each of these
  // tables takes a third of a second to build)
  const ScaledContact scaled(key, 0.25, 0.5);
  const StatisticalContact unscaled = table_at(key, 1.0);
  for (const double k : {0.25, 0.4, 0.66}) {
    across_contact(unscaled, [&](double h1) {
      const double expected = k * unscaled.pressure(h1).value;
      EXPECT_NEAR(scaled.pressure(k * h1, k).value, expected, 1e-8 * expected);
    });
  }
}

// The summits in contact at (h, k), the flash temperature's junctions: their count depends
// on the heights alone (the new population's at h/k, to its table's error), the real area
// is interpolated in ln k as p is, and both change with k only through the summits'
// plastic share: within twice p's measured bound, as p is (measured: 1.9e-6 against p's 6.7e-6).
TEST(ScaledContact, ItsSummitsInContactAreTheScaledPopulations) {
  const ContactTableKey key = paper_population();
  const ScaledContact scaled(key, 1.0 / 3.0);
  for (const double k : {0.41, 0.5, 0.77, 0.93}) {
    SCOPED_TRACE(k);
    const StatisticalContact direct = table_at(key, k);
    across_contact(direct, [&](double h) {
      const StatisticalContact::SummitContacts exact = direct.contacts(h);
      if (!(exact.area_fraction > 0.0)) return;
      const StatisticalContact::SummitContacts c = scaled.contacts(h, k);
      EXPECT_NEAR(c.count, exact.count, 1e-8 * exact.count);
      EXPECT_NEAR(c.area_fraction, exact.area_fraction, 2.0 * scaled.error_bound() * exact.area_fraction);
    });
  }
}

// Beyond its range a scale is held at the nearest end, without a slope in k.
TEST(ScaledContact, AScaleBeyondItsRangeIsHeldAtTheEnd) {
  const ContactTableKey key = paper_population();
  const ScaledContact scaled(key, 0.5);
  const double h = 0.5 * key.summit_sigma;
  EXPECT_EQ(scaled.pressure(h, 0.2).value, scaled.pressure(h, 0.5).value);
  EXPECT_EQ(scaled.pressure(h, 0.2).dk, 0.0);
  EXPECT_EQ(scaled.pressure(h, 1.5).value, scaled.pressure(h, 1.0).value);
  EXPECT_THROW(ScaledContact(key, 0.0), std::invalid_argument);
  const ScaledContact none(key, 1.0);  // no running-in: the one table
  EXPECT_DOUBLE_EQ(none.pressure(h, 1.0).value, table_at(key, 1.0).pressure(h).value);
}

}  // namespace
}  // namespace twb
