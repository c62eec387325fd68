#include <cmath>

#include "twb/scene/scene.h"

namespace twb {

void set_roughness(Scene& scene, double rq) {
  const double before = std::hypot(scene.carrier.roughness.rq, scene.washer.roughness.rq);
  for (Component* c : {&scene.carrier, &scene.washer, &scene.gear}) {
    c->roughness.ra *= rq / c->roughness.rq;
    c->roughness.rq = rq;
  }
  const double k = std::hypot(rq, rq) / before;
  scene.asperities.summit_sigma *= k;
  scene.asperities.summit_radius /= k;
}

}  // namespace twb
