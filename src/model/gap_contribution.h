// A part of a film's gap that moves with the state (docs/physics.md section 1): the
// thermal deformation's shape today, a worn depth or an elastic deflection next. Each
// is registered by its effect (ModelSetup::gap_parts) and gives, at every node of a
// film, its change δ of the gap as a linear form in the unknowns. The model sums the
// parts' forms once per node (BearingModel::shape_form), and every kernel reads the gap
// as the plane plus that sum plus the face's relief (film_gap.h), so that a new part
// changes nothing else in the model.
//
// Linear in the unknowns, so that the gap's derivatives are exact and its forms are built
// once per model: a part that depends on the state in another way gives that dependence
// an unknown and a row of its own (as the washer's dishing curvature is), and its form
// reads that unknown. Its effect owns those unknowns: their rows (written as "what the
// state implies − the unknown", which BearingModel::orient_rows negates), their block's
// BlockEffect (segregated_blocks groups by it) and their move to another mesh
// (EffectAssembler::carry_from).
//
// In real time the squeeze (reynolds_film.cpp) reads the rate of the plane alone: thermal
// deformation's shape moves on the thermal time scale and is left out of it (physics
// §19). A part whose unknowns move on the squeeze's own time scale (a worn depth is
// slow; an elastic deflection is not) needs its rate there, which is not built yet.
#pragma once

#include <string>
#include <vector>

#include "model/film.h"
#include "model/sparse_assembly.h"

namespace twb {

class BearingModel;

class GapContribution {
 public:
  virtual ~GapContribution() = default;
  // What the part is, for messages ("thermal deformation").
  virtual std::string name() const = 0;
  // Whether it moves this film's gap at all: a film no part moves keeps its plane (and
  // the kernels' rigid paths).
  virtual bool moves(const Film& /*film*/) const { return true; }
  // Adds scale × (this part's δ form) at every node of the film to forms[node]; the
  // model's unknowns are all declared. scale is the cold start's homotopy
  // (BearingModel::set_deformation_scale): 0 is the rigid film, 1 the model.
  virtual void add_node_forms(const BearingModel& model, const Film& film, double scale,
                              std::vector<LinearForm>& forms) const = 0;
};

}  // namespace twb
