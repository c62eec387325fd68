// A worn washer (docs/physics.md section 20): the sliding film's two faces' worn depths on
// the grid they were worn on. A life study ends with one and reports one at every reported
// time (twb/results/worn_washer.h: worn_washer.json, worn_profile.csv); a scene goes on
// from one (twb run --continue-from DIR, Scene::worn): a life continued from where it
// stopped, or any other study of the washer so worn, its depths held. On another mesh of
// the same annulus the depths are interpolated bilinearly (θ periodic), to second order.
#pragma once

#include <string>
#include <vector>

namespace twb {

struct WornWasher {
  double time = 0.0;  // s of the life at which the faces were this worn
  int film = 1;       // the sliding film: 1 carrier–washer, 2 washer–gear
  double inner_radius = 0.0, outer_radius = 0.0;  // its annulus (m)
  int radial_nodes = 0, circumferential_nodes = 0;
  // m: the face at rest in the load frame, per node (radius outer loop, angle inner);
  // the turning face, per radial node (each radius's circumferential mean).
  std::vector<double> rest, turn;
  // m: each face's Rq there as it runs in (the same layout; its Rq new where it does not),
  // reported in worn_profile.csv; not in worn_washer.json (a scene's run_in_rq gives it
  // from the depths), so empty in a washer read back.
  std::vector<double> rest_rq, turn_rq;
  std::string source;  // where it was read from, for messages (not written)
};

}  // namespace twb
