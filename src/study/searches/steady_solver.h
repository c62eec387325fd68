// A steady state of the bearing at the model's current load, from a given start or
// from the paper's cold start, with globalization beyond KINSOL's line search
// (Cantera's pattern: from a given start damped Newton first, pseudo-time steps when it
// fails, then Newton again; from the cold start, where Newton never converges,
// pseudo-time at once; solver/pseudo_transient.h). When even that fails, the speed is ramped up from rest, then
// the load from a fraction the cold start reaches, each step warm-started from the last
// and halved on failure. Failure is reported, not hidden.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/kinsol_newton.h"
#include "solver/pseudo_transient.h"

namespace twb {


class SteadySolver {
 public:
  SteadySolver(BearingModel& model, NewtonSettings settings,
               SparseLu::Ordering ordering = SparseLu::Ordering::by_size);

  // From u (a warm start), falling back to a speed ramp, then a load ramp, from the cold start.
  SteadyReport solve(std::vector<double>& u);
  // From u alone: Newton, then pseudo-time steps from u when it fails, and no ramps: for
  // a caller that asks where u itself leads (the ramps start from the cold start and
  // would reach a state that owes nothing to u).
  SteadyReport solve_near(std::vector<double>& u);
  // From the paper's cold start, by the scene's solver.method. On meshes finer than
  // kSequenceAbove nodes per film, by a mesh sequence first (solve_by_mesh_sequence);
  // where the gap has parts (thermal deformation), by their homotopy
  // (solve_by_deformation_homotopy); the cold start itself when those fail.
  SteadyReport solve_cold(std::vector<double>& u);
  // Off: every cold start by pseudo-time on the mesh itself (the growth benchmark's
  // comparison).
  void set_mesh_sequence(bool on) { mesh_sequence_ = on; }
  // Off: thermal deformation's cold start without its homotopy (the tests' comparison).
  void set_deformation_homotopy(bool on) { deformation_homotopy_ = on; }
  // Above the paper's 9×66 (594 nodes) and its 17×66 or 9×132 refinements.
  static constexpr int kSequenceAbove = 1500;

 private:
  // The scene's solver.method: paper (solver/paper_scheme.h), from the cold start in u.
  SteadyReport solve_by_paper(std::vector<double>& u);
  // The state on the mesh with every other node line, interpolated here, then Newton
  // (pseudo-time if Newton fails).
  SteadyReport solve_by_mesh_sequence(std::vector<double>& u);
  // Thermal deformation's cold start: the rigid film's (the shapes scaled by 0), then the
  // shapes brought in by walking their scale to 1, each step Newton from the last.
  SteadyReport solve_by_deformation_homotopy(std::vector<double>& u);
  bool newton(std::vector<double>& u, const NewtonSettings& s, SteadyReport& rep) {
    return pseudo_transient_.newton(u, s, rep);
  }
  SteadyReport ramp(std::vector<double>& u, SteadyReport rep);
  bool speed_ramp(std::vector<double>& u, SteadyReport& rep);
  bool reach(std::vector<double>& u, SteadyReport& rep, bool newton_first = true) {
    return pseudo_transient_.reach(u, rep, newton_first);
  }
  // reach(), then the ramps when it fails (where `ramps`).
  SteadyReport settle(std::vector<double>& u, bool newton_first, bool ramps = true);
  // Walks a parameter (speed, load) from `from` up to `target`, each step warm-started
  // from the last state; the step grows 1.5× after a success and halves after a failure,
  // giving up below 1e-4 of the target. Returns the value reached; leaves the
  // parameter at the target.
  double walk(const std::function<void(double)>& set, double from, double target, double step,
              std::vector<double>& state, const std::function<bool(std::vector<double>&)>& solve_step);

  BearingModel& model_;
  NewtonSettings settings_;
  KinsolNewton newton_;
  PseudoTransient pseudo_transient_;
  // For the states on the way (a ramp's, a homotopy's, a coarser mesh's): the settings
  // without a caller's early stop (NewtonSettings::watched, quantities), which judge the
  // state asked for, not one at another speed, load or mesh.
  NewtonSettings on_the_way_;
  PseudoTransient ramp_transient_;
  bool mesh_sequence_ = true;
  bool deformation_homotopy_ = true;
};

}  // namespace twb
