#include "scene/material_modulus.h"

#include <vector>

namespace twb {

std::optional<ModulusCurve> modulus_curve(const Material& material) {
  if (material.modulus_by_temperature.empty()) return std::nullopt;
  std::vector<double> temperatures, moduli;
  for (const ModulusAt& point : material.modulus_by_temperature) {
    temperatures.push_back(point.temperature);
    moduli.push_back(point.modulus);
  }
  return ModulusCurve(temperatures, moduli);
}

}  // namespace twb
