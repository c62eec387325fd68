// The first-order reliability method (FORM, docs/physics.md section 17) in the standard
// normal space of independent inputs u: the failure load h(u) (W_fail at the inputs
// x(u)) against an operating load W, failure where g(u) = h(u) − W ≤ 0.
//   design_point: the most probable failure point u* (the point of g = 0 nearest the
//     origin), by the improved HL-RF iteration (Zhang & Der Kiureghian 1997: the HL-RF
//     step with an Armijo line search on the merit ½|u|² + c|g|); β = ±|u*|, + where
//     the mean inputs survive; P_f ≈ Φ(−β), exact where g is linear in u.
//   inverse_design_point: the load whose failure probability is P: the least h on the
//     sphere |u| = β_P = −Φ⁻¹(P) (the most probable point of that reliability), by the
//     fixed point u = −β_P ∇h/|∇h| (the advanced mean value iteration), halved where it
//     oscillates.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace twb {

// h and, when asked, ∇h (per unit of each u) at u; none, with why, where h cannot be
// evaluated there.
struct FailureLoadValue {
  double load = 0.0;
  std::vector<double> gradient;
};
using FailureLoadFunction =
    std::function<std::optional<FailureLoadValue>(std::span<const double> u, bool gradient, std::string& why)>;

struct FormSettings {
  double load_tolerance = 1e-4;       // |g| ≤ this × the operating load at the design point
  double direction_tolerance = 1e-3;  // |u − (α·u)α| ≤ this × max(1, |u|) (u along ∇h)
  int max_iterations = 40;
};

struct DesignPoint {
  bool converged = false;
  std::vector<double> u;         // the design point in standard normal space
  double beta = 0.0;             // the reliability index
  double probability = 0.0;      // Φ(−β)
  double load = 0.0;             // h(u*): the failure load there (W for the forward FORM)
  std::vector<double> gradient;  // ∇h at u*
  std::vector<double> alpha;     // −∇h/|∇h|: each input's share; importance α_i²
  int iterations = 0;            // gradients taken
  int evaluations = 0;           // h evaluated (with or without its gradient)
  std::string why;               // why it did not converge
};

DesignPoint design_point(const FailureLoadFunction& h, std::size_t inputs, double operating_load,
                         const FormSettings& settings = {});

DesignPoint inverse_design_point(const FailureLoadFunction& h, std::size_t inputs, double probability,
                                 const FormSettings& settings = {});

// Φ(−β) and β = −Φ⁻¹(P).
double failure_probability(double beta);
double reliability_index(double probability);

}  // namespace twb
