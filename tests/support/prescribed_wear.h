// A part of the films' gap added from outside the model, as a new effect adds one
// (docs/architecture.md, "Adding an effect that moves the gap"): a worn depth on film 1,
// one unknown per node, held by its own row at a depth the test prescribes. It is the
// worked example of model/gap_contribution.h, and what the tests check a new part
// against: its slopes in every kernel (jacobian_test), a uniform depth absorbed by the
// clearance (gap_contribution_test), its unknowns carried to another mesh. It reports its
// deepest wear as a quantity of its own (model/reported_quantity.h), which states.csv
// and the journal carry without a change of theirs (reported_quantity_test).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>

#include "model/bearing_model.h"

namespace twb::testing {

class PrescribedWear final : public EffectAssembler {
 public:
  // The worn depth (m) at (r, θ) of film 1.
  using Depth = std::function<double(double r, double theta)>;

  PrescribedWear(ModelSetup& setup, Depth depth) : model_(setup.model), depth_(std::move(depth)) {
    const Film& film = setup.films[0];
    offset_ = setup.layout.add("film 1 worn depth", BlockEffect::thermal_deformation, film.mesh.node_count());
    setup.gap_parts.push_back(std::make_unique<Part>(offset_));
  }

  static constexpr ReportedQuantity kReported[] = {
      {"worn_depth_max_um", "µm", "the deepest prescribed wear of film 1"}};

  // The model's effect list entry for it.
  static BearingModel::EffectMaker maker(Depth depth) {
    return [depth](ModelSetup& setup) { return std::make_unique<PrescribedWear>(setup, depth); };
  }

  // The depth in σ_ref (the gap's scale): depth − d̂ = 0 at every node, oriented by the model.
  double prescribed(int node) const {
    const FilmMesh& m = model_.films()[0].mesh;
    const int i = node / m.circumferential_nodes(), j = node % m.circumferential_nodes();
    return depth_(m.radius(i), m.angle(j)) / model_.clearance_scale();
  }
  Index offset() const { return offset_; }

  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals&) const override {
    for (int n = 0; n < model_.films()[0].mesh.node_count(); ++n) {
      a.add_residual(offset_ + n, prescribed(n) - u[std::size_t(offset_ + n)]);
      a.add_derivative(offset_ + n, offset_ + n, -1.0);
    }
  }
  void report(std::span<const double> u, const AssemblyTotals&, std::vector<ReportedValue>& out) const override {
    double deepest = 0.0;
    for (int n = 0; n < model_.films()[0].mesh.node_count(); ++n)
      deepest = std::max(deepest, u[std::size_t(offset_ + n)] * model_.clearance_scale());
    out.push_back({std::string(kReported[0].column), deepest * 1e6});
  }
  // Prescribed, so the depth of this mesh's own nodes.
  void carry_from(const BearingModel&, const EffectAssembler&, std::span<const double>,
                  std::span<double> out) const override {
    for (int n = 0; n < model_.films()[0].mesh.node_count(); ++n) out[std::size_t(offset_ + n)] = prescribed(n);
  }

 private:
  // Film 1's gap opens by the depth, σ_ref · d̂ at each node.
  class Part final : public GapContribution {
   public:
    explicit Part(Index offset) : offset_(offset) {}
    std::string name() const override { return "prescribed wear"; }
    bool moves(const Film& film) const override { return film.number == 1; }
    void add_node_forms(const BearingModel& model, const Film& film, double scale,
                        std::vector<LinearForm>& forms) const override {
      for (int n = 0; n < film.mesh.node_count(); ++n)
        forms[std::size_t(n)].add(offset_ + n, scale * model.clearance_scale());
    }

   private:
    Index offset_;
  };

  const BearingModel& model_;
  Depth depth_;
  Index offset_ = -1;
};

}  // namespace twb::testing
