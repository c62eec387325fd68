// A material's modulus over temperature as the model takes it (docs/physics.md section 23):
// the data's [M1] curve where the material has one.
#pragma once

#include <optional>

#include "physics/modulus_curve.h"
#include "twb/scene/scene.h"

namespace twb {

// The material's curve, or none where its modulus is the constant youngs_modulus.
std::optional<ModulusCurve> modulus_curve(const Material& material);

}  // namespace twb
