// The distress search (distress_search.h) as its phases, with the search's state in one
// place. From a steady state at settings.load_start:
//   1. continue the cool branch     natural continuation, every state judged by its
//                                   linear stability or a transient (cool_branch_phase.cpp),
//                                   up to load_end, a runaway, or the fold's neighbourhood
//   2. no distress                  the branch reached load_end: say why (gradual
//                                   heating, no thermal effect, a constant viscosity)
//   3. locate the fold              arclength round the branch's end
//   4. prove it                     two transients beside it (fold_proof.h)
//   5. bisect where proof fails     transients from the last cool state
//   6. march past distress          the first runaway step, to the hot state it reaches
//   7. sweep the hot branch         load_sweep only, on to load_end
// Phases 3-7 are distress_phases.cpp. The model's load is set explicitly before every
// solver a phase calls; a state is recorded at the load it is the state of.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "study/searches/distress_search.h"
#include "study/searches/fold_proof.h"
#include "solver/arclength_continuation.h"
#include "solver/natural_continuation.h"
#include "solver/runaway.h"
#include "study/searches/steady_solver.h"

namespace twb {

// The corrector of a natural continuation along the cool branch, whose predictions lie
// in Newton's quadratic basin: a few full steps converge, and a failure (a step that
// outran the branch) is cut short, without a line search, and the step halved.
NewtonSettings in_basin(NewtonSettings newton);

// Pseudo-arclength continuation from `state` at `load` near the end of the cool branch
// round its first turning point only (up to load_end). cool_side, if given, receives the
// states it passes before the turn.
ArclengthReport round_the_fold(BearingModel& model, std::span<const double> state, double load, double load_end,
                               const NewtonSettings& newton, BranchStates* cool_side = nullptr);

class DistressSearchPhases {
 public:
  // cool and approach receive the branch's states (continued in load, and passed by
  // arclength before the fold), for the failure criteria.
  DistressSearchPhases(BearingModel& model, const DistressSearchSettings& settings, const SearchProgress& progress,
                       BranchStates& cool, BranchStates& approach);
  // The search from u, steady at settings.load_start and on the cool branch.
  DistressSearch run(std::vector<double> u, const SteadyReport& first);

 private:
  // How phase 1 ended.
  enum class CoolBranchEnd {
    load_end,  // continued to load_end: no fold, no runaway on the way
    runaway,   // a load step between two of its states ran away (at runaway_load_)
    ended,     // it ends near low_: a fold found round it, or continuation stopped
    bounded,   // continued to searched_to_, the bound past the first failure criterion
  };
  CoolBranchEnd continue_cool_branch();          // phase 1 (cool_branch_phase.cpp)
  // The first accepted state past a failure criterion bounds the search (a distress
  // map's search_past_failure): the targets from index t on end at the bound.
  void bound_past_failure(std::size_t t);
  void report_no_distress();                     // phase 2
  void report_steady_fold();                     // without transients: the steady branch's fold only
  // Phases 3-6; false where the search stops (its row says why).
  bool locate_and_prove_fold(CoolBranchEnd end, std::vector<double>& u);
  void sweep_hot_branch(std::vector<double> u, double load);  // phase 7: from u at load

  // Where the proof failed: bisection by transients from the last cool state. False
  // where no bracket results (the row says why).
  bool bisect(bool ran_away, FoldProof& proof, std::optional<FoldPoint>& fold, std::string& disagreement);
  // The first runaway step marched to where it goes (u: the hot state); false where it
  // does not settle or nothing marches on.
  bool march_past(FoldProof& proof, std::vector<double>& u);

  // A state of the branch at `load`, recorded as solved (and its unknowns kept where
  // every state gets an error bar).
  void keep(double load, std::span<const double> v, long iterations, double wall_ms);
  void say(const std::string& line) const;

  BearingModel& model_;
  const DistressSearchSettings& settings_;
  const SearchProgress& progress_;
  const std::chrono::steady_clock::time_point started_;
  const NewtonSettings newton_;
  // The runaway detector of every load step past phase 1 (distress_detector): a step
  // that settles must also land on the branch continued from its start.
  const RunawaySettings detector_;
  // Without the thermal effect nothing has a heat capacity: no transient checks states
  // or brackets W_d (thermo-viscous distress needs heat), only the steady branch and its
  // fold remain; nor with fold_only (a mesh refined for the error estimate).
  bool dynamics_ = false, transient_ = false;
  // Natural continuation's stops: the requested grid, never more than 15 % apart.
  std::vector<double> targets_;
  NaturalSettings natural_;

  // The search's state.
  DistressSearch out_;
  BranchStates& cool_;      // the cool branch's states (load, state), to start a proof from
  BranchStates& approach_;  // those arclength passed before the fold
  double low_ = 0.0;        // the last load accepted on the cool branch, and its state
  std::vector<double> low_state_;
  double runaway_load_ = 0.0;                 // where phase 1 saw a runaway
  double searched_to_ = 0.0;                  // load_end, or the bound past the first failure
  std::optional<double> first_failure_;       // the first accepted load past a failure criterion
  std::optional<ArclengthReport> around_fold_;  // the arclength round the fold, once run
};

}  // namespace twb
