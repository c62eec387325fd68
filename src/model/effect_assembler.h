// An effect of the bearing (docs/physics.md) as an assembler of its own share of
// F(u) = 0, as Cantera's domains or PyBaMM's submodels hold theirs: its constructor
// declares the unknown blocks the effect owns (only when the scene turns it on) with
// their row scales, and add_terms adds its terms, and their exact derivatives, to
// whichever rows they enter. The model calls the assemblers in the order they were
// registered (BearingModel::register_effects, effect_registry.cpp), then adds the
// external load and orients the rows.
//
// Adding an effect: its section in docs/physics.md, its switch in the scene, one
// assembler file (a class deriving from EffectAssembler) and its line in
// register_effects; an effect that moves the films' gap registers a GapContribution
// from its constructor; one that reports quantities of its own declares them
// (reported_quantity.h) and names its list in effect_quantities. What every effect reads of the others (films, temperatures,
// viscosity, the gap's shape, row scales) is BearingModel's public interface.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "model/film.h"
#include "model/gap_contribution.h"
#include "model/reported_quantity.h"
#include "model/sparse_assembly.h"
#include "model/unknown_layout.h"

namespace twb {

class BearingModel;
struct AssemblyTotals;
struct ComponentHeat;
struct Scene;
struct ReportedValue;

// The washer's dishing curvature (thermal deformation, docs/physics.md section 11): its
// unknown κ̂ = κ̄/curvature_ref, -1 without the effect. The heat balance adds the flux
// crossing the washer to its row.
struct WasherDishing {
  Index unknown = -1;
  double curvature_ref = 0;
};

// The washer as an elastic plate (docs/physics.md section 21, elastic_washer_effect.h):
// where its unknowns lie and how each film's nodes sit on its grid (film 1's: the
// washer's annulus at the scene's mesh sizes). Without the effect, deflection is -1.
struct WasherPlate {
  // A film's radial node i moves by Σ weight·w over these radial nodes of the washer's
  // grid, at the same angle: film 1 by +w at its own ring, film 2 by −w interpolated
  // linearly to its radius. The same weights spread the film's force at a node onto the
  // washer's nodes (virtual work: the load's slopes are the gap's transposed).
  struct Share {
    int ring = 0;
    double weight = 0;
  };
  Index deflection = -1;  // ŵ = w/deflection_ref (m) at every node of the washer's grid
  Index moment = -1;      // m̂ = m·rigidity/load_ref (m = ∇²w − (1 + ν)κ_T) at every node
  double deflection_ref = 0, load_ref = 0;
  int circumferential_nodes = 0;
  std::array<std::vector<std::vector<Share>>, 2> shares;  // per film, per radial node
  bool elastic() const { return deflection >= 0; }
  const std::vector<Share>& of(const Film& film, int ring) const {
    return shares[std::size_t(film.number - 1)][std::size_t(ring)];
  }
};

// What an effect's constructor may extend while the model is being built: the
// unknowns (blocks and their row scales), the films' columns, the heat-conducting
// bodies, the parts of the films' gap it moves (gap_contribution.h), the washer's
// dishing or its plate. The model reads only what is already declared.
struct ModelSetup {
  const BearingModel& model;
  UnknownLayout& layout;
  std::vector<Film>& films;
  std::vector<ComponentHeat>& components;
  std::vector<std::unique_ptr<GapContribution>>& gap_parts;
  WasherDishing& dishing;
  WasherPlate& plate;
};

// A film's block name, e.g. "film 1 pressure".
std::string fmt_film_block(int number, const char* what);

// The state's rates in real time (docs/physics.md section 19), IDA's c_j and the imposed
// gear tilt's rate: a term in the rates enters the iteration matrix as ∂/∂u + c_j·∂/∂u'.
struct StateRates {
  std::span<const double> rate;
  double cj = 0.0;
  double imposed_tilt_rate = 0.0;  // rad/s
};

class EffectAssembler {
 public:
  virtual ~EffectAssembler() = default;
  // Adds this effect's terms at state u: residuals always, derivatives when the
  // assembler wants them (the same entries in the same order on every call: the
  // Jacobian's slot tape, sparse_assembly.h). totals gathers what reports need.
  virtual void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const = 0;
  // The same in real time, with the terms in the state's rates an effect has (the film's
  // squeeze); most have none.
  virtual void add_terms_in_time(std::span<const double> u, const StateRates& /*rates*/, Assembler& a,
                                 AssemblyTotals& totals) const {
    add_terms(u, a, totals);
  }
  // Writes into `out` (a state of this effect's model) the unknowns this effect declared,
  // carried from state u of `source`, the same scene's model on another mesh, whose own
  // assembler of this effect is `mine_there` (mesh_transfer.cpp carries the films' and
  // bodies' fields): an effect with unknowns of its own says how they move between meshes.
  virtual void carry_from(const BearingModel& /*source*/, const EffectAssembler& /*mine_there*/,
                          std::span<const double> /*u*/, std::span<double> /*out*/) const {}
  // Appends to `out` the quantities this effect reports of solved state u (its kReported,
  // reported_quantity.h), one value each in their declared order; `totals` are what the
  // state's assembly gathered. Most effects report nothing of their own.
  virtual void report(std::span<const double> /*u*/, const AssemblyTotals& /*totals*/,
                      std::vector<ReportedValue>& /*out*/) const {}
};

}  // namespace twb
