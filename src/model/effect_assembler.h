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
// register_effects. What every effect reads of the others (films, temperatures,
// viscosity, shapes, row scales) is BearingModel's public interface.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/film.h"
#include "model/sparse_assembly.h"
#include "model/unknown_layout.h"

namespace twb {

class BearingModel;
struct AssemblyTotals;
struct ComponentHeat;
struct Scene;

// Thermal deformation's scalar unknowns (docs/physics.md section 11), -1 without them,
// and their scales: the film's shape reads the dishing curvature, the film loads and
// the friction law read the contact force.
struct ShapeUnknowns {
  Index dishing = -1, contact_force = -1;
  double curvature_ref = 0, contact_force_ref = 0;
};

// What an effect's constructor may extend while the model is being built: the
// unknowns (blocks and their row scales), the films' columns, the heat-conducting
// bodies, the deformation's scalars. The model reads only what is already declared.
struct ModelSetup {
  const BearingModel& model;
  UnknownLayout& layout;
  std::vector<Film>& films;
  std::vector<ComponentHeat>& components;
  ShapeUnknowns& shape;
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
};

}  // namespace twb
