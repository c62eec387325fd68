// The coupled quasi-steady bearing model (docs/physics.md sections 1-7 and 9): one residual
// F(u) = 0 over the unknowns of the effects a scene enables, with its exact sparse
// Jacobian. Unknowns and residual rows are scaled so that tolerances read physically:
//   rigid body   ĉ = c/σ_ref (clearances), γ̂ = γ/γ_ref;  rows: forces / F_ext, moments / (F_ext r_o)
//   pressure     p̂ = p/p_ref;   rows: complementarity of (p̂, ŵ), ŵ = flow balance / its scale
//   temperature  T̂ = T − T_ambient in kelvin;  rows: heat balance / a node conductance (kelvin)
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <tuple>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "model/effect_assembler.h"
#include "model/film.h"
#include "twb/model/bearing_state.h"
#include "twb/model/film_fields.h"
#include "twb/model/film_mesh.h"
#include "model/gauss_rule.h"
#include "twb/model/operating_limits.h"
#include "model/sparse_assembly.h"
#include "model/unknown_layout.h"
#include "physics/roelands_viscosity.h"
#include "physics/scaled_contact.h"
#include "physics/statistical_contact.h"
#include "twb/scene/scene.h"
#include "system/segregated_system.h"

namespace twb {

struct FilmTotals;
struct AssemblyTotals;

enum class CavitationRow { fischer_burmeister, minimum };

// A component's temperature field: T(r, θ) on a polar grid, or T(r) when it rotates
// relative to the load frame (docs/physics.md section 7).
struct ComponentHeat {
  ComponentId id;
  FilmMesh grid;
  bool axisymmetric = false;
  double thickness = 0.0, conductivity = 0.0, capacity_per_area = 0.0;  // ρ c t
  bool loses_to_ambient = false;
  Index offset = -1;
  int node_count() const { return axisymmetric ? grid.radial_nodes() : grid.node_count(); }
  // Area a temperature node stands for.
  double node_area(int i) const {
    return grid.node_area(i) * (axisymmetric ? grid.circumferential_nodes() : 1);
  }
};

// As a SteadySystem the continuation parameter is the load (N) and the transient is
// the paper's thermal one: component temperatures carry their heat capacity ρ c t,
// everything else (pressures, film nodes, rigid body) is algebraic.
// The time a transient of the model runs in (SteadySystem::capacities): the heat's
// (docs/physics.md sections 7, 19: the bodies' temperatures have their capacities, the
// worn depths are held) or the wear's slow time (section 20, [W4]: the worn depths are
// the only differential unknowns, in hours, and everything else is quasi-steady).
enum class TimeScale { heat, wear };

class BearingModel final : public SegregatedSystem {
 public:
  // An effect beyond the scene's switches (a test's, a plugin's): made while the model is
  // built, after the scene's own (effect_registry.cpp), and again on every other mesh.
  using EffectMaker = std::function<std::unique_ptr<EffectAssembler>(ModelSetup&)>;
  explicit BearingModel(const Scene& scene, std::vector<EffectMaker> more_effects = {});
  // The effects hold the model they read: a model is not copied (on_mesh builds another).
  BearingModel(const BearingModel&) = delete;
  BearingModel& operator=(const BearingModel&) = delete;

  const Scene& scene() const { return scene_; }
  const UnknownLayout& layout() const { return layout_; }
  Index size() const override { return layout_.size(); }
  const SparsePattern& pattern() const override { return pattern_; }
  const std::vector<Film>& films() const { return films_; }
  const std::vector<ComponentHeat>& components() const { return components_; }

  // Residual and (if jacobian is non-empty) Jacobian values in pattern().
  void evaluate(std::span<const double> u, std::span<double> residual, std::span<double> jacobian) const override;

  // SteadySystem: λ = load; C from docs/physics.md section 7 (bearing_dynamics.cpp).
  double parameter() const override { return load_; }
  void set_parameter(double value) override { set_load(value); }
  void parameter_derivative(std::span<const double> u, std::span<double> derivative) const override;
  void parameter_derivative_given(std::span<const double> u, std::span<const double> residual,
                                  std::span<double> derivative) const override;
  std::vector<double> capacities() const override;
  // The time scale the capacities and the worn depths' rows are of (TimeScale above).
  void set_time_scale(TimeScale scale) { time_scale_ = scale; }
  TimeScale time_scale() const { return time_scale_; }
  // The scene's effect of type T (effect_registry.cpp), nullptr where it is off: what a
  // study sets of an effect's own (a worn washer's depths).
  template <class T>
  const T* effect() const {
    for (const auto& e : effects_)
      if (const auto* found = dynamic_cast<const T*>(e.get())) return found;
    return nullptr;
  }
  template <class T>
  T* effect() {
    return const_cast<T*>(std::as_const(*this).effect<T>());
  }
  // Each unknown's heat capacity ρ·c·t·A in J/K: a body node's; 0 for every other unknown
  // (the capacities above without the rows' scales).
  std::vector<double> heat_capacities() const;
  // Real time (docs/physics.md section 19): the film's squeeze reads the rates of the
  // sliding film's rigid unknowns (ĉ, γ̂x, γ̂y); none without hydrodynamics.
  std::vector<char> rate_unknowns() const override;
  void evaluate_in_time(std::span<const double> u, std::span<const double> rate, double cj,
                        std::span<double> residual, std::span<double> jacobian) const override;
  // The imposed gear tilt's rate (rad/s) the squeeze of film 2 reads in real time: a duty
  // cycle's schedule sets it with the tilt.
  void set_imposed_tilt_rate(double rate) { imposed_tilt_rate_ = rate; }
  double imposed_tilt_rate() const { return imposed_tilt_rate_; }
  std::vector<double> step_weights() const override;
  std::vector<char> held_in_pseudo_time() const override;
  std::string block_name(Index k) const override { return layout_.block_of(k).name; }
  std::string describe_row(Index k) const override;  // row_meaning.cpp

  // The paper's cold start: both films at h_min/σ = cold_start_film, washer tilted half
  // way, ambient temperature, no pressure.
  std::vector<double> cold_start() const;
  // Its rigid-body unknowns (ĉ1, γ̂x, γ̂y, ĉ2).
  std::array<double, 4> cold_start_rigid() const;
  // State u of `source`, a model of the same scene on another mesh, carried to this
  // mesh by bilinear interpolation of every field in (r, θ) (mesh_transfer.cpp): the
  // start of a mesh sequence. std::invalid_argument when the unknowns differ.
  std::vector<double> interpolated_from(const BearingModel& source, std::span<const double> u) const;
  // The same bearing as now (load, speed and every curve parameter) on another mesh.
  std::unique_ptr<BearingModel> on_mesh(int radial_nodes, int circumferential_nodes) const;
  // Whether a grid of that many radial and circumferential nodes holds the washer's
  // grooves (every edge, a dam's too, on a node line); on_mesh needs one that does.
  bool resolves_grooves_on(int radial_nodes, int circumferential_nodes) const;

  BearingState describe(std::span<const double> u) const;
  // What an assembly at state u gathers into `totals` (each film's forces and powers per
  // node, assembly_totals.h), for a study that needs a film's per node.
  void gather_totals(std::span<const double> u, AssemblyTotals& totals) const;
  // The fields of state u on every film's grid, film 1 first (film_fields.cpp).
  std::vector<FilmFields> fields(std::span<const double> u) const;

  // The form of the pressure rows; the pattern and the roots do not change with it.
  void set_newton_form(bool on) override {
    cavitation_row_ = on ? CavitationRow::minimum : CavitationRow::fischer_burmeister;
  }
  bool newton_form() const override { return cavitation_row_ == CavitationRow::minimum; }
  bool flow_balance_rows() const { return flow_balance_rows_; }
  // |φ_FB(a, b)| ≤ (2 + √2)|min(a, b)| (Tseng): a minimum row within tol/(2 + √2) is a
  // Fischer–Burmeister row within tol (the cavitation rows' min(λ·p̂, ŵ) too, λ ≥ 1, and
  // the gear's stop's row); the other rows are the same in both forms.
  double newton_form_tolerance_ratio() const override { return 1.0 / (2.0 + std::numbers::sqrt2); }
  CavitationRow cavitation_row() const { return cavitation_row_; }

  // SegregatedSystem: the rigid body, the pressures and the temperatures by effect
  // (mechanics, hydrodynamics, thermal), and the pressure rows as ŵ alone.
  Blocks segregated_blocks() const override;
  void set_flow_balance_rows(bool on) override { flow_balance_rows_ = on; }

  // Changes the external load; the pattern and every scale except F_ext-based ones are kept.
  // A load of zero needs the gear's stop.
  void set_load(double load);
  double load() const { return load_; }
  // Changes the sliding speed (rad/s); the pattern and all scales are kept.
  void set_speed(double speed);
  double speed() const { return scene_.operating.speed; }

  // A parameter a fold curve is continued in (SI: rad/s, 1, rad, K). The pattern and
  // every scale are kept, so states stay comparable along the curve; the dry friction
  // coefficient needs the constant friction law (std::invalid_argument otherwise).
  double curve_parameter(CurveParameter p) const;
  void set_curve_parameter(CurveParameter p, double value);

  // The gear's stop at its axial play (gear_stop.cpp, docs/physics.md section 19).
  bool gear_stop() const { return scene_.gear.axial_play.has_value(); }
  // The force the rigid rows are divided by: the load, or with the gear's stop the
  // scene's load, held as the load moves (it may reach zero).
  double force_scale() const;

  // The washer unloaded at rest (unloaded_rest.cpp, docs/physics.md section 19): while the
  // load and the speed are both zero nothing holds the massless washer and gear, and the
  // rigid rows hold them where they came to rest, the rigid unknowns of `u` (in real time
  // a differential one by a rate of zero). hold_at_rest({}) gives the balances back.
  void hold_at_rest(std::span<const double> u);
  bool held_at_rest() const { return !rest_.empty(); }

  // Scales (physical value = scale · unknown).
  double clearance_scale() const { return sigma_ref_; }
  double tilt_scale() const { return gamma_ref_; }
  double pressure_scale() const { return p_ref_; }

  RigidPosition position(std::span<const double> u) const;

  // The force (N) the oil supply holds on the sliding film's fed grooves alone: p_s times
  // their nodes' areas, a floor of the film's hydrostatic force (docs/physics.md section
  // 14). Below it no load keeps the gear down. 0 without supply into grooves.
  double groove_supply_force() const;
  // The most the oil supply alone can hold on any film: its pressure (bore or grooves,
  // the higher) over the film's whole face, which no film at a vanishing wedge exceeds.
  // Above it the supply cannot lift the gear off; below it, it may, and no steady state
  // need exist (a cold start there can search for minutes). 0 without a supply.
  double supply_lift_bound() const;

  // The gap's shape (docs/physics.md section 1; gap_contribution.h): the change δ of a
  // film's gap at a node from its plane, δ = form · u (m), the sum of the parts the
  // effects register (thermal deformation's: the carrier's and gear's face expansion
  // and the washer's dishing, film_shape.cpp). Empty forms without any.
  bool gap_shaped() const { return !gap_parts_.empty(); }
  // Whether some part moves this film's gap (GapContribution::moves).
  bool gap_shaped(const Film& film) const;
  const std::vector<std::unique_ptr<GapContribution>>& gap_parts() const { return gap_parts_; }
  // Thermal deformation is on: the washer's dishing curvature is an unknown.
  bool deforms() const { return dishing_.unknown >= 0; }
  // The shapes δ scaled by s in [0, 1] (the cold start's homotopy, study/steady_solver.cpp): 0
  // is the rigid film with the shape's own unknowns riding along, 1 the model.
  // The Jacobian's pattern is the same for every s.
  void set_deformation_scale(double s);
  double deformation_scale() const { return deformation_scale_; }
  const LinearForm& shape_form(const Film& film, int node) const {
    return shape_forms_[std::size_t(film.number - 1)][std::size_t(node)];
  }
  double shape_at(std::span<const double> u, const Film& film, int node) const;
  // δ at every node of a film, once per evaluation; empty without a shape.
  std::vector<double> node_shapes(std::span<const double> u, const Film& film) const;
  // The least gap (m) of a film: its plane's exact minimum over the annulus, c − |∇h|·r_o,
  // or for a shaped film the least of its nodes' gaps and of the gap at that point
  // (film_gap.cpp).
  double least_gap(std::span<const double> u, const Film& film) const;
  // The sliding film's total contact force F̂c = F_c/contact_force_scale as an unknown
  // of its own, −1 without: with the empirical friction law and a shaped gap, every δ
  // moves F_c, which sets f in every heat row; one column couples them instead of a
  // dense block. Its scale is the scene's load (fixed, unlike the rigid rows' F_ext, so
  // that the load enters no other row).
  Index contact_force_unknown() const { return contact_force_unknown_; }
  double contact_force_scale() const { return contact_force_scale_; }
  const WasherDishing& washer_dishing() const { return dishing_; }
  // The washer's plate (docs/physics.md section 21): elastic() with the effect elastic_washer.
  const WasherPlate& washer_plate() const { return plate_; }
  // The washer's deflection (m, towards film 2) at every node of a film, at state u.
  std::vector<double> washer_deflection_at(std::span<const double> u, const Film& film) const;
  // The washer's area-mean dishing curvature κ̄ (1/m) of state u; 0 without the effect.
  double dishing_curvature(std::span<const double> u) const;
  // The dishing row's weight of a heat flow (W) from a film node into the washer: the
  // washer's mean through-thickness flux (film 1 in, film 2 out) in curvature units.
  double dishing_row_weight(const Film& film) const;

  // Film content θ at node (i, j): 1 on the (flooded) edges, where the film is full,
  // and without the mass-conserving cavitation model.
  double content_at(std::span<const double> u, const Film& film, int i, int j) const;

  // Pressure (Pa) at node (i, j) of the sliding film; 0 on edges and without hydrodynamics.
  double pressure_at(std::span<const double> u, const Film& film, int i, int j) const;
  double temperature_of(std::span<const double> u, Index k) const;
  // The hottest node temperature (K) of a body in state u, the least its hottest face can
  // be (describe locates the faces beside the films); the ambient without the thermal
  // effect.
  double hottest_node_temperature(std::span<const double> u, ComponentId id) const;

  // What the effects share (effect_assembler.h).
  // The viscosity temperature's gradient at film node (i, j), which depends only on the
  // grids: built once, shared by every evaluation (the value is T_ambient + form · u).
  const LinearForm& viscosity_temperature_form(const Film& film, int node) const {
    return viscosity_forms_[film.number - 1][node];
  }
  // T_ambient + form · u (K).
  double apply(const LinearForm& form, std::span<const double> u) const;
  ValueSlope viscosity(double temperature) const;
  // The same at every temperature of a batch (Gauss points), vectorized.
  void viscosity(std::span<const double> temperature, std::span<ValueSlope> out) const;
  // Temperature (K) of a component's face at radius r, circumferential node j, with gradient.
  double face_temperature(std::span<const double> u, ComponentId id, double r, int j, LinearForm* form) const;
  // Half the washer's thickness lies on the path from a film node to its mid-plane
  // (eqs [26], [27]); carrier and gear faces are their surfaces.
  double body_resistance(ComponentId id) const;
  // The heat path (m² K/W) from a film node to a body across the film of average gap
  // h̄T: half the oil's, then the body's own part (eqs [26], [27]).
  double heat_path(double mean_gap, ComponentId id) const {
    return mean_gap / (2.0 * scene_.lubricant.conductivity) + body_resistance(id);
  }
  const ComponentHeat* component(ComponentId id) const;
  const Film& sliding_film() const;
  // The summit population of both films (docs/physics.md section 4), null without
  // contact, and the gap above which its pressure is negligible (p < 1e-20 p(0)).
  const StatisticalContact* contact() const { return contact_.get(); }
  double contact_cutoff() const { return contact_cutoff_; }
  // Where the sliding film's faces run in (docs/physics.md section 20): the same population
  // scaled by k = σ/σ0 of the film, for k from the run-in faces' to 1 ([W8]); null else.
  const ScaledContact* scaled_contact() const { return scaled_contact_.get(); }

 private:
  // The effects of the scene, in the order they add their terms (effect_registry.cpp).
  void register_effects();
  void assemble(std::span<const double> u, Assembler& a, AssemblyTotals* totals,
                const StateRates* rates = nullptr) const;
  void orient_rows(Assembler& a) const;
  void add_gear_stop(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const;
  void add_rest_rows(std::span<const double> u, Assembler& a, const StateRates* rates) const;

  // Viscosity temperature (K) at film node (i, j) and its gradient in the unknowns.
  double viscosity_temperature(std::span<const double> u, const Film& film, int i, int j, LinearForm* form) const;
  void build_contact();  // the summit population of the scene (docs/physics.md section 4), if contact is on

  Scene scene_;
  double load_ = 0;
  CavitationRow cavitation_row_ = CavitationRow::fischer_burmeister;
  bool flow_balance_rows_ = false;
  std::vector<Film> films_;
  std::vector<ComponentHeat> components_;
  UnknownLayout layout_;
  Index rigid_offset_ = 0;
  std::vector<std::unique_ptr<EffectAssembler>> effects_;
  std::vector<EffectMaker> more_effects_;
  TimeScale time_scale_ = TimeScale::heat;
  // One summit population for both films (scene.asperities; docs/physics.md section 4).
  std::shared_ptr<const StatisticalContact> contact_;  // shared with models of the same surfaces
  double contact_cutoff_ = 0.0;  // gap above which contact is negligible (p < 1e-20 p(0))
  ContactTableKey contact_key_{};
  std::shared_ptr<const ScaledContact> scaled_contact_;
  RoelandsViscosity roelands_{};
  double viscosity_scale_ = 1.0;  // CurveParameter::viscosity_scale
  double deformation_scale_ = 1.0;  // set_deformation_scale
  std::optional<double> uniform_roughness_;  // CurveParameter::roughness, once set
  std::tuple<Component, Component, Component, AsperityParameters> roughness_origin_;  // the scene's surfaces
  double sigma_ref_ = 0, gamma_ref_ = 0, p_ref_ = 0;
  SparsePattern pattern_;
  // Where each Jacobian entry of a pass lands (sparse_assembly.h): the structure pass's,
  // then the last Jacobian pass's that left it (evaluate()): a model is used by one thread
  // at a time (study/parallel.h).
  mutable SlotTape slot_tape_;
  // The same for passes in real time, whose squeeze terms add entries of their own.
  mutable SlotTape rate_slot_tape_;
  double imposed_tilt_rate_ = 0.0;
  std::vector<double> rest_;  // the rigid unknowns held at rest (hold_at_rest); empty: none
  std::array<char, 4> rest_by_rate_{};  // which of them is held by its rate in real time
  std::vector<std::vector<LinearForm>> viscosity_forms_;  // per film, per node

  // The gap's shape: its parts in the order their effects registered them, and their
  // summed forms δ = form · u per film, per node (film_gap.cpp).
  std::vector<std::unique_ptr<GapContribution>> gap_parts_;
  std::vector<std::vector<LinearForm>> shape_forms_;
  void build_shape_forms();
  WasherDishing dishing_;
  WasherPlate plate_;
  Index contact_force_unknown_ = -1;
  double contact_force_scale_ = 0.0;
};

}  // namespace twb
