// Convection (docs/physics.md section 15): the oil carries the film's temperature with the
// film's flow. It adds to the sliding film's node heat balances the heat that warms the
// oil flowing in (first-order upwind, the Reynolds face fluxes of FilmFaceFlows), and
// makes the nodes of fed grooves hold the groove's mixed temperature
// (film_convection.cpp). No unknowns of its own.
#pragma once

#include <string_view>
#include <vector>

#include "model/effect_assembler.h"

namespace twb {

struct FilmTotals;
class FilmFaceFlows;

class ConvectionEffect final : public EffectAssembler {
 public:
  // The supply oil present at every radius of a fed groove, as a share of the Couette
  // flow a film of the roughness's height carries across a row, (ω r/2)·σ·Δr: it joins the
  // lands' deliveries in the groove's flow-weighted mean, which without it jumps from one
  // land's temperature to the supply's where the only delivering face's flow changes sign
  // (Newton's iterates then toggle across the jump). docs/physics.md section 15.
  static constexpr double kGrooveFreshShare = 0.01;

  // The heat the oil carries out of the sliding film (W, docs/physics.md section 15): with
  // the heat conducted to the ambient, it balances the heat the film generates.
  static constexpr std::string_view kHeatCarried = "heat_carried_W";
  static constexpr ReportedQuantity kReported[] = {
      {kHeatCarried, "W", "with convection, the heat the oil carries out of the film"}};

  explicit ConvectionEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;
  void report(std::span<const double> u, const AssemblyTotals& totals, std::vector<ReportedValue>& out) const override;

 private:
  void add_film(std::span<const double> u, const Film& film, Assembler& a, FilmTotals& totals) const;
  // The mixed temperature rows of one fed groove at one radius (docs/physics.md section 15).
  struct Delivery;
  void add_groove_mixing(std::span<const double> u, const Film& film, const FilmFaceFlows& flows,
                         const std::vector<int>& nodes, const std::vector<Delivery>& delivered, double fresh,
                         Assembler& a, FilmTotals& totals) const;

  const BearingModel& model_;
  double heat_capacity_ = 0.0;  // ρ c of the oil, J/(m³ K), at the sump's temperature
  double supply_rise_ = 0.0;    // the supply's temperature above ambient, K
};

}  // namespace twb
