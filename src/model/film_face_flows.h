// The oil's volumetric flux through every face of a sliding film's Reynolds control
// volumes (docs/physics.md sections 3, 12 and 14), with its slopes in the unknowns: the
// flux the Reynolds balances sum (reynolds_film.cpp), the flows a state reports, and the
// flux that carries the oil's heat (convection, docs/physics.md section 15). One
// evaluation, so that the mass the balances conserve is the mass that carries heat.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "model/bearing_model.h"
#include "model/film_gap.h"
#include "model/film_roughness.h"
#include "model/reynolds_operator.h"

namespace twb {

// One face's flux Q (m³/s, from node A to node B) and what it depends on.
struct FaceFlow {
  ReynoldsFace face;
  int na = 0, nb = 0;  // the two mesh nodes
  ReynoldsFaceFlux flux{};
  double dq_dh = 0;      // in the gap at the face midpoint
  double dq_dt = 0;      // in each node's viscosity temperature (μ at the mean of theirs)
  double dq_dtheta = 0;  // in the upwind node's film content (circumferential faces, JFO)
  // In each face's Rq at the midpoint (the mean of the two nodes'), where the faces run in.
  double dq_drest = 0, dq_dturn = 0;
  std::array<double, 3> dh{};  // the gap's slopes in the rigid unknowns at the midpoint
  int upwind = -1;             // interior ordinal whose content the Couette flow carries
  bool circumferential = false;
};

class FilmFaceFlows {
 public:
  // The film must slide (it has the pressure unknowns); u is the state.
  FilmFaceFlows(const BearingModel& model, const Film& film, std::span<const double> u);

  const ReynoldsOperator& grid() const { return op_; }
  // Whether interior node k holds a fed groove's pressure (Film::fed_node): a boundary of
  // the lands' flow with no balance of its own.
  bool fed(int k) const { return k >= 0 && !fed_.empty() && fed_[std::size_t(k)]; }
  bool free(int k) const { return k >= 0 && !fed(k); }
  // The pressure and content columns of interior node k, −1 where the value is held.
  Index pressure_column(int k) const { return free(k) ? film_.pressure_offset + k : -1; }
  Index content_column(int k) const { return jfo_ && free(k) ? film_.content_offset + k : -1; }

  // Visits every face in the operator's order with its FaceFlow.
  template <class Visit>
  void for_each(Visit&& visit) const {
    op_.for_each_face([&](const ReynoldsFace& f) { visit(evaluate(f)); });
  }
  // Visits the edge rows' circumferential half faces (ReynoldsOperator::edge_face).
  template <class Visit>
  void for_each_edge_face(Visit&& visit) const {
    for (const int i : {0, film_.mesh.radial_nodes() - 1})
      for (int j = 0; j < film_.mesh.circumferential_nodes(); ++j) visit(evaluate(op_.edge_face(i, j)));
  }
  // The film's gap as the fluxes read it.
  const FilmGap& gap() const { return gap_; }
  // Its roughness as they read it (film_roughness.h).
  const FilmRoughness& roughness() const { return roughness_; }
  // d(row) += c · ∇Q of a face, in the order the Reynolds rows have always summed it.
  void add_gradient(Assembler& a, Index row, double c, const FaceFlow& flow) const;

 private:
  FaceFlow evaluate(const ReynoldsFace& f) const;
  double pressure(int k, int i) const;
  double content(int k) const { return content_column(k) >= 0 ? u_[std::size_t(content_column(k))] : 1.0; }

  const BearingModel& model_;
  const Film& film_;
  std::span<const double> u_;
  ReynoldsOperator op_;
  FilmGap gap_;
  FilmRoughness roughness_;
  bool jfo_;
  std::vector<char> fed_;  // per interior node; empty where no groove is fed
  std::vector<double> node_t_;
};

}  // namespace twb
