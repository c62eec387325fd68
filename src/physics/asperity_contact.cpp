#include "physics/asperity_contact.h"

#include <cmath>
#include <numbers>

namespace twb {

JacksonGreenAsperity::JacksonGreenAsperity(double effective_modulus, double yield_strength,
                                           double poisson_ratio, double summit_radius)
    : effective_modulus_(effective_modulus),
      yield_strength_(yield_strength),
      poisson_ratio_(poisson_ratio),
      summit_radius_(summit_radius) {
  using std::numbers::pi;
  c_factor_ = 1.295 * std::exp(0.736 * poisson_ratio_);  // eq [12]
  // Critical (yield onset) interference and force of the sphere, eq [11] and JG 2005.
  const double yield_pressure = pi * c_factor_ * yield_strength_ / 2.0;
  const double ratio = yield_pressure / effective_modulus_;
  critical_interference_ = ratio * ratio * summit_radius_;
  const double r_over_e = summit_radius_ / effective_modulus_;
  critical_force_ = (4.0 / 3.0) * r_over_e * r_over_e * yield_pressure * yield_pressure *
                    yield_pressure;
  yield_strain_ = yield_strength_ / effective_modulus_;
  hardness_exponent_ = 0.14 * std::exp(23.0 * yield_strain_);
  log_radius_ratio_factor_ = std::log(pi * c_factor_ * yield_strain_ / 2.0);
  log_transition_ratio_ = std::log(transition_interference_ratio);
}

double JacksonGreenAsperity::effective_modulus(double E1, double nu1, double E2,
                                               double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

double JacksonGreenAsperity::force(double interference) const {
  if (interference <= 0.0) return 0.0;
  const double w = interference / critical_interference_;  // omega*
  const double elastic = w * std::sqrt(w);                 // omega*^1.5
  if (w <= transition_interference_ratio) return critical_force_ * elastic;  // eq [8]
  // The powers below are taken as exp(k ln omega*) from one logarithm: this is called
  // ~1e6 times while the statistical contact table is built, and it halves the cost of
  // the four pow() calls of the literal formulas (rounding differences ~1e-15).
  const double log_w = std::log(w);
  // Eq [10] corrected: a/R = (pi C e_y / 2) sqrt(omega*) (omega*/1.9)^(B/2),
  // H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)].
  const double log_contact_radius_ratio =
      log_radius_ratio_factor_ + 0.5 * log_w +
      0.5 * hardness_exponent_ * (log_w - log_transition_ratio_);
  const double hardness_over_yield =
      2.84 * (1.0 - std::exp(-0.82 * std::exp(-0.7 * log_contact_radius_ratio)));
  // Eq [9]: fading elastic part plus the plastic (hardness-limited) part.
  const double elastic_part = std::exp(-0.25 * std::exp(5.0 / 12.0 * log_w)) * elastic;
  const double plastic_part = 4.0 * hardness_over_yield / c_factor_ *
                              (1.0 - std::exp(-std::exp(5.0 / 9.0 * log_w) / 25.0)) * w;
  const double ratio = elastic_part + plastic_part;
  return critical_force_ * ratio;
}

double JacksonGreenAsperity::contact_area(double interference) const {
  if (interference <= 0.0) return 0.0;
  const double w = interference / critical_interference_;
  const double hertz = std::numbers::pi * summit_radius_ * interference;
  if (w <= transition_interference_ratio) return hertz;
  return hertz * std::exp(hardness_exponent_ * (std::log(w) - log_transition_ratio_));
}

}  // namespace twb
