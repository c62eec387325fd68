// A scalar kernel's value together with its exact derivative with respect to the
// kernel's single argument. The model assembles an exact Newton Jacobian by the
// chain rule, so every constitutive kernel returns both.
#pragma once

namespace twb {

struct ValueSlope {
  double value;
  double slope;
};

}  // namespace twb
