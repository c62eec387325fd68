// Statistical contact tables shared by the models of a process. A table costs ~15 ms of
// adaptive quadrature (statistical_contact.h) and studies build a model per point: a
// map's speeds, a fold curve's family, the p ± h of a fold curve's derivative in
// roughness. Models with the same asperities and materials share one; it is read-only
// once built, so threads share it too.
#pragma once

#include <compare>
#include <memory>

#include "physics/statistical_contact.h"

namespace twb {

// What a table depends on: the asperity law's material and summit radius, and the summit
// population (docs/physics.md section 4).
struct ContactTableKey {
  double effective_modulus, yield_strength, poisson_ratio, summit_radius;  // Pa, Pa, -, m
  double summit_density, summit_sigma;                                     // 1/m², m
  auto operator<=>(const ContactTableKey&) const = default;
};

// The table for key, built on first use. The most recent few are kept.
std::shared_ptr<const StatisticalContact> shared_contact_table(const ContactTableKey& key);

}  // namespace twb
