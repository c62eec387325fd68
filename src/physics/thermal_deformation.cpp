#include "physics/thermal_deformation.h"

namespace twb {

double face_expansion_per_kelvin(double expansion, double thickness, double poisson_ratio, bool constrained) {
  const double c_nu = constrained ? (1.0 + poisson_ratio) / (1.0 - poisson_ratio) : 1.0;
  return c_nu * expansion * thickness / 2.0;
}

double dishing_curvature_per_flux(double expansion, double conductivity) { return expansion / conductivity; }

double dishing_shape(double r, double inner_radius, double outer_radius) {
  const double mean_r2 = (inner_radius * inner_radius + outer_radius * outer_radius) / 2.0;
  return (r * r - mean_r2) / 2.0;
}

}  // namespace twb
