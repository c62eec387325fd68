// The thermal effect (docs/physics.md section 7): film-node and body temperatures, and
// the heat balances of the film nodes, the carrier, the washer and the gear
// (heat_balance.cpp). The heat sources (viscous shear, boundary friction) are the film
// loads' (film_loads_effect.h); they add to these rows with these rows' scales.
#pragma once

#include <array>
#include <vector>

#include "model/effect_assembler.h"

namespace twb {

class HeatEffect final : public EffectAssembler {
 public:
  // Declares every film's node temperatures and the bodies' temperature fields, with
  // their row scales (a reference conductance: the rows read in kelvin).
  explicit HeatEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;

 private:
  void set_row_scales(ModelSetup& setup) const;
  // The bodies' own conduction: in-plane, and across carrier and gear to the ambient.
  void add_body_conduction(std::span<const double> u, Assembler& a) const;

  const BearingModel& model_;
  // A film node's heat path to the face of one bounding component: the face
  // temperature interpolated from the component's nodes (at most two), those nodes'
  // row scales, and the node's position. Grids only: built once per model.
  struct FaceLink {
    int terms = 0;
    std::array<Index, 2> column{};
    std::array<double, 2> weight{}, row_scale{};
  };
  struct HeatNode {
    double x = 0, y = 0;
    std::array<FaceLink, 2> face;  // lower, upper
  };
  std::vector<std::vector<HeatNode>> heat_nodes_;  // per film, per node
};

}  // namespace twb
