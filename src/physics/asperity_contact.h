// Single elasto-plastic hemispherical asperity against a rigid flat, Jackson & Green
// (2005), as used in the paper's eqs [8]-[12]; docs/physics.md section 4 (with the corrected
// eq [10]: e_y = S_y/E' and exponent B/2).
#pragma once

namespace twb {

class JacksonGreenAsperity {
 public:
  // Transition from the elastic (Hertz) law [8] to the elasto-plastic fit [9], in
  // units of omega_c.
  static constexpr double transition_interference_ratio = 1.9;

  // effective_modulus E' (Pa, see effective_modulus()); yield_strength S_y (Pa) and
  // poisson_ratio nu of the softer material; summit_radius R (m).
  JacksonGreenAsperity(double effective_modulus, double yield_strength,
                       double poisson_ratio, double summit_radius);

  // 1/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
  static double effective_modulus(double E1, double nu1, double E2, double nu2);

  // Contact force (N) at interference omega (m); 0 for omega <= 0.
  // Elastic branch (omega* <= 1.9): P_c omega*^1.5 = (4/3) E' sqrt(R) omega^1.5 (Hertz).
  // The fit [9] does not meet [8] exactly at omega* = 1.9: the force jumps up by 0.55 %
  // for steel. Statistical integrals split there.
  double force(double interference) const;

  // Contact area (m²) at interference omega (m), Jackson and Green (2005): Hertz's π R ω
  // while elastic (omega* <= 1.9), π R ω (omega*/1.9)^B beyond, the B of eq [10] (the
  // contact radius of eq [10] is its root over π); 0 for omega <= 0.
  double contact_area(double interference) const;

  double critical_interference() const { return critical_interference_; }  // omega_c, m
  double critical_force() const { return critical_force_; }                // P_c, N
  double c_factor() const { return c_factor_; }            // C = 1.295 exp(0.736 nu)
  double transition_interference() const {                 // 1.9 omega_c, m
    return transition_interference_ratio * critical_interference_;
  }
  double effective_modulus() const { return effective_modulus_; }
  double yield_strength() const { return yield_strength_; }
  double poisson_ratio() const { return poisson_ratio_; }
  double summit_radius() const { return summit_radius_; }

 private:
  double effective_modulus_;
  double yield_strength_;
  double poisson_ratio_;
  double summit_radius_;
  double c_factor_;
  double critical_interference_;
  double critical_force_;
  double yield_strain_;        // e_y = S_y / E'
  double hardness_exponent_;   // B = 0.14 exp(23 e_y)
  double log_radius_ratio_factor_;  // ln(pi C e_y / 2), eq [10]
  double log_transition_ratio_;     // ln 1.9
};

}  // namespace twb
