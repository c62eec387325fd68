// Wear of the sliding film's two faces (docs/physics.md section 20): Archard's law [W1],
// the face at rest in the load frame wearing its own field and the turning face each
// radius's circumferential mean [W2], both depths parts of the film's gap [W3].
//
// Unknowns: the face at rest's depth at every node of the sliding film, the turning
// face's at every radial node, in σ_ref (the gap's scale). On the heat's time scale
// (steady studies, transients, duty cycles) rows d − d_given = 0 hold them at the given
// depths (a new washer: zero), and every state reports the rates it would wear them at.
// On the wear's own time scale (BearingModel::TimeScale::wear, the slow time of [W4])
// the rows are the depths' rates in σ_ref per hour, with their exact derivatives: a
// depth is then a differential unknown of unit capacity and everything else is algebraic.
// The rate rows' entries are in the pattern either way, so that one model switches.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "model/effect_assembler.h"
#include "physics/running_in.h"

namespace twb {

struct FilmTotals;
struct WornWasher;
class FilmMesh;

class WearEffect final : public EffectAssembler {
 public:
  static constexpr ReportedQuantity kReported[] = {
      {"worn_depth_rest_um", "µm", "with wear: the deepest worn depth of the sliding film's face at rest"},
      {"worn_depth_turn_um", "µm", "with wear: the deepest worn depth of the sliding film's turning face"},
      {"wear_rate_rest_um_h", "µm/h",
       "with wear: how fast the face at rest wears where it wears fastest (Archard's law)"},
      {"wear_rate_turn_um_h", "µm/h",
       "with wear: how fast the turning face wears at the radius where it wears fastest"},
      {"wear_volume_rate_rest_mm3_h", "mm³/h", "with wear: the volume the face at rest loses per hour"},
      {"wear_volume_rate_turn_mm3_h", "mm³/h", "with wear: the volume the turning face loses per hour"}};

  explicit WearEffect(ModelSetup& setup);
  void add_terms(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const override;
  // Holds the depths (m) at the given values on this model's mesh (the face at rest's per
  // node, the turning face's per radial node): what a steady state of a worn washer has.
  void hold(std::span<const double> rest, std::span<const double> turn);
  void carry_from(const BearingModel& source, const EffectAssembler& mine_there, std::span<const double> u,
                  std::span<double> out) const override;
  void report(std::span<const double> u, const AssemblyTotals& totals, std::vector<ReportedValue>& out) const override;

  // The rates [W1]–[W2] (m/s) at the nodes of the face at rest and at the radial nodes of
  // the turning face, from the sliding film's friction power per node ∫ p_c·|V|·N_a dA,
  // lumped: the rate at node a is k·P_a/A_a.
  struct Rates {
    std::vector<double> rest, turn;
  };
  Rates rates(const FilmTotals& sliding) const;
  // The same at state u (an assembly of the model).
  Rates rates_at(std::span<const double> u) const;
  // The worn volume per second of each face, k·∫ p_c·|V| dA (m³/s).
  std::array<double, 2> volume_rates(const FilmTotals& sliding) const;

  // The depths of state u (m): the face at rest's per node, the turning face's per radial node.
  std::vector<double> rest_depths(std::span<const double> u) const;
  std::vector<double> turn_depths(std::span<const double> u) const;
  // Each face's wear at state u: its deepest and area-mean depth (m) and the volume worn
  // off (m³), the exact integral of the bilinear depths (Σ A_a·d_a), and its Rq (m), the
  // root of the area mean of its nodes' Rq² (lumped as the volume); the face at rest's first.
  struct Worn {
    double deepest = 0.0, mean = 0.0, volume = 0.0, rq = 0.0;
  };
  std::array<Worn, 2> worn(std::span<const double> u) const;
  // The washer worn to state u at `time` (s) of its life, on this mesh's grid.
  WornWasher worn_washer(std::span<const double> u, double time) const;
  Index rest_offset() const { return rest_offset_; }
  Index turn_offset() const { return turn_offset_; }
  // k of the face at rest and of the turning face (m³/(N·m)).
  double rest_rate() const { return k_rest_; }
  double turn_rate() const { return k_turn_; }

  // Running-in (docs/physics.md section 20, [W5]-[W6]): whether a face of the sliding film
  // has a run-in Rq (else both keep their Rq and nothing below is needed).
  bool runs_in() const { return runs_in_; }
  // Each face's Rq (m) at state u's depths and its slope in the depth: the face at rest's
  // per node, the turning face's per radial node.
  struct FaceRoughness {
    std::vector<ValueSlope> rest, turn;
  };
  FaceRoughness roughness(std::span<const double> u) const;
  // The faces' combined Rq once both have run in (m): the least the sliding film's σ reaches.
  double run_in_sigma() const;

 private:
  const Film& film() const;
  void hold_worn(const WornWasher& worn, const FilmMesh& mesh);
  // Adds weight × the rates [W1]-[W2] in σ_ref per hour to the depth rows, with their
  // derivatives through the film's friction power (its rigid and shape slopes).
  void add_rates(const FilmTotals& sliding, double weight, Assembler& a) const;

  const BearingModel& model_;
  std::size_t film_index_ = 0;  // the sliding film's
  double k_rest_ = 0, k_turn_ = 0;
  RunningIn rest_running_in_, turn_running_in_;
  bool runs_in_ = false;
  Index rest_offset_ = -1, turn_offset_ = -1;
  // The depths the steady rows hold, in σ_ref: a new washer's zeros.
  std::vector<double> held_rest_, held_turn_;
};

}  // namespace twb
