// A state's discretization error (study.error_estimate: richardson for a point,
// every_state for each state of a sweep): the state again on the mesh refined by two,
// from the scene mesh's state interpolated there, and each reported quantity
// (kMeshErrorQuantities) extrapolated with its error bar (richardson.h; two grids alone,
// F_s = 3). Where a quantity's estimated error exceeds 5 % the run says so and names the
// mesh that would meet it (the error falling as h², the formal order).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/sparse_lu.h"
#include "twb/results/states_table.h"

namespace twb {

// The refined model states are solved on, or none with the reason in `why` (beyond the
// 65 x 528 twb refines a state on: the refined system outgrows a workstation's memory
// and minutes).
std::unique_ptr<BearingModel> refined_model(const BearingModel& model, std::string& why);

// `state` (solved at u on `model`, at the model's load and speed) again on `fine` at the
// same load: its mesh_errors filled, or false with the reason in `why`: at once for a
// state past the contact model's validity (limit contact_pressure), else where Newton and
// pseudo-time from the interpolated state fail (no ramps from the cold start: their cost
// is many times the point's, for a state that owes nothing to this one). Newton iterations
// and Jacobians are added to the counters given. `ordering`: the refined solver's
// (sparse_lu.h): minimum_degree for a state refined alone (a point), by_size where a run
// refines many on one mesh (nested dissection's order is found once for them all).
bool refine_state(const BearingModel& model, BearingModel& fine, std::span<const double> u, SolvedState& state,
                  std::string& why, SparseLu::Ordering ordering, long* newton_iterations = nullptr,
                  long* jacobians = nullptr);

// The state (solved at u on `model`) on the scene's mesh refined by two, again and again
// (mesh_convergence.h: mesh.max_refinements, each mesh from the last one's state), until
// each quantity's bar is within the relative `tolerance` (temperatures: of their rise
// above the ambient); its mesh_errors filled from the meshes' estimates (the observed
// order from three meshes on). `lines` gets the meshes and, where some quantity stays
// outside the tolerance, a warning naming it. False, with the reason in `why`, where not
// even the first refined mesh solved.
bool refine_state_to_tolerance(const BearingModel& model, std::span<const double> u, SolvedState& state,
                               double tolerance, std::vector<std::string>& lines, std::string& why,
                               long* newton_iterations = nullptr, long* jacobians = nullptr);

// The run's lines on the states' error bars: which mesh gave them, and a warning where a
// quantity of a state is more than 5 % off its extrapolation, with the mesh that would
// meet 5 %. None where no state has a bar.
std::vector<std::string> state_error_lines(const Scene& scene, const std::vector<SolvedState>& states);

}  // namespace twb
