// Statistical asperity contact pressure of Gaussian summits (Greenwood-Williamson
// summation of Jackson-Green asperities), docs/physics.md section 4, paper eqs [13]-[15]:
//
//   p_cont(h) = eta * integral_0^inf P(w) phi(w + d) dw,   d = h - y_s,
//   y_s = 0.045944/(eta R),  phi = N(0, sigma_s^2) density,
//   dp/dh     = eta * integral_0^inf P(w) phi'(w + d) dw,   phi'(z) = -z/sigma_s^2 phi(z)
//
// (w = z - d is the interference of a summit of height z; the slope formula is exact
// because P(0) = 0, so the moving lower limit of the paper's form contributes nothing).
//
// pressure() is the production path: a cubic-Hermite table of L = ln p and L' = p'/p on
// a uniform grid in h, built once at construction by adaptive Gauss-Kronrod quadrature.
// Outside the table ln p is continued: above, with its Gaussian tail (value and slope
// matched, curvature -1/sigma_s^2), so p -> 0 smoothly; below, linearly (value and slope
// matched). The continuation is C1 everywhere.
#pragma once

#include <cmath>
#include <span>

#include "physics/asperity_contact.h"
#include "physics/uniform_hermite_table.h"
#include "physics/value_slope.h"

namespace twb {

struct StatisticalContactTableOptions {
  // Table range in units of sigma_s, as d = h - y_s. p(d_min) is ~9 p(0) for the
  // defaults; p(d_max) ~ 3e-40 p(0).
  double lowest_separation_sigmas = -10.0;
  double highest_separation_sigmas = 13.0;
  // Nodes per sigma_s. For the defaults 32 gives a relative cubic-Hermite error of
  // 1.8e-10 in p and 4.4e-8 in dp/dh (the slope error is one order lower in spacing).
  int nodes_per_sigma = 32;
  // Measure the table error on every k-th interval (1 = all of them). Checking all
  // doubles-to-triples construction (two quadratures per interval: 40-60 ms against
  // ~20 ms on a loaded 2-core machine), so by default every 7th; the bound found with 1
  // differs from it by 0.1 % for the defaults (tests check both).
  int error_check_stride = 7;
};

class StatisticalContact {
 public:
  // summit_density eta (1/m^2), summit_sigma sigma_s (m).
  StatisticalContact(const JacksonGreenAsperity& asperity, double summit_density,
                     double summit_sigma, StatisticalContactTableOptions options = {});

  // docs/physics.md section 4 default summit density from the product eta*R*sigma_s.
  static double summit_density_from_product(double eta_r_sigma, double summit_radius,
                                            double summit_sigma);

  // Contact pressure p (Pa) and dp/dh (Pa/m) at mean-plane separation h (m), from the
  // table: O(1), one exp. C1 in h; p > 0 until it underflows far above the table.
  // Inline on the table: it runs at every Gauss point of every near-contact cell.
  ValueSlope pressure(double h) const {
    if (!(h >= table_.x_first() && h <= table_.x_last())) return pressure_off_table(h);
    const ValueSlope log_p = table_.evaluate(h);
    const double p = std::exp(log_p.value);
    return {p, p * log_p.slope};
  }

  // The same at every separation of a batch, into out (same size), with the exp
  // vectorized (physics/batch_math.h): equal to the scalar values to a few ulp.
  void pressure(std::span<const double> h, std::span<ValueSlope> out) const;

  // The same by direct adaptive quadrature (relative tolerance ~1e-13), split at the
  // JG transition w = 1.9 omega_c and at the Gaussian peak. For tests and table building.
  ValueSlope pressure_by_quadrature(double h) const;

  // The summits in contact at gap h, per unit of nominal area (docs/physics.md section 8,
  // scuffing): their number n = η·Q(d/σs) (Q the normal tail) and their real area
  // A_r = η ∫ A(z − d) φ(z) dz, a fraction of the nominal area, A the JG contact area
  // (asperity_contact.h). A_r from a table of ln A_r as ln p's (8 nodes per σs: relative
  // error below 1e-7), continued outside it as ln p is.
  struct SummitContacts {
    double count = 0.0;          // 1/m²
    double area_fraction = 0.0;  // A_r/A
  };
  SummitContacts contacts(double h) const;
  // A_r and dA_r/dh by direct adaptive quadrature: for tests and the table.
  ValueSlope real_area_by_quadrature(double h) const;

  // Max relative error |p_table - p_quad|/p_quad over the checked intervals (every 7th
  // by default, see StatisticalContactTableOptions), measured at construction at each
  // interval's midpoint, where the cubic-Hermite value error peaks. The slope bound is
  // measured likewise for dp/dh at t = 1/2 - 1/(2 sqrt 3) of each checked interval,
  // where the Hermite slope error peaks.
  double table_error_bound() const { return table_error_bound_; }
  double table_slope_error_bound() const { return table_slope_error_bound_; }

  // The gap above which p < 1e-30 p(0): callers may skip contact integration there.
  double contact_pressure_cutoff_gap() const { return cutoff_gap_; }
  // The gap above which p < relative_level · p(0).
  double cutoff_gap(double relative_level) const { return find_cutoff_gap(relative_level); }

  double mean_summit_offset() const { return mean_summit_offset_; }  // y_s, m
  double summit_density() const { return summit_density_; }
  double summit_sigma() const { return summit_sigma_; }
  const JacksonGreenAsperity& asperity() const { return asperity_; }
  const UniformHermiteTable& log_pressure_table() const { return table_; }  // L(h)

 private:
  JacksonGreenAsperity asperity_;
  double summit_density_;
  double summit_sigma_;
  double mean_summit_offset_;
  UniformHermiteTable table_;
  UniformHermiteTable area_table_;  // ln A_r(h)
  double table_error_bound_ = 0.0;
  double table_slope_error_bound_ = 0.0;
  double cutoff_gap_ = 0.0;

  ValueSlope pressure_off_table(double h) const;  // the continuations of ln p
  void build_table(const StatisticalContactTableOptions& options);
  void build_area_table(const StatisticalContactTableOptions& options);
  // η ∫ law(w) φ(w + d) dw and its slope in h, for a summit law (force or area) that is 0
  // at w = 0, grows as w^1.5 or w there, and changes its form at the JG transition.
  template <class Law>
  ValueSlope summit_integral(Law law, double h) const;
  double find_cutoff_gap(double relative_level) const;
};

}  // namespace twb
