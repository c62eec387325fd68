// The validated scene: everything a run needs, in SI units (temperatures in kelvin).
// Produced only by the scene loader (scene_loader.h); every layer after it reads this.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "twb/scene/study_settings.h"

namespace twb {
struct WornWasher;  // twb/scene/worn_washer.h
}

namespace twb {

// Which film carries the relative speed (docs/physics.md section 2). Film 1 lies between
// carrier and washer (washer stuck to the gear), film 2 between washer and gear
// (washer stuck to the carrier).
enum class SlidingFilm { carrier_washer, washer_gear };

// reynolds: the Reynolds (Swift–Stieber) condition p ≥ 0, w ≥ 0, p·w = 0 (docs/physics.md
// section 3, the paper's); jfo: mass-conserving, p ≥ 0, θ ≤ 1, p·(1 − θ) = 0 with the
// film content θ carried by the Couette flow (section 12).
enum class CavitationModel { reynolds, jfo };

// Which temperature sets the oil viscosity at a film node (docs/physics.md section 7).
enum class ViscosityTemperature { surface_mean, film_node };

// How the carrier's temperature field sees the heat of film 1 (docs/physics.md section 7): fixed
// in the load frame, T(r, θ) (the model's default: the carrier does not rotate relative
// to the load), or circumferentially averaged, T(r), as for a body rotating under the
// load (a modelling alternative the validation study compares).
enum class CarrierTemperature { load_frame, axisymmetric };

enum class ViscosityModel { roelands, constant };

// How a thick plate's face expands under a hot spot (docs/physics.md section 11): laterally
// free columns (c_ν = 1) or held by the cool plate around it (c_ν = (1+ν)/(1−ν)).
enum class FaceExpansion { free, constrained };

enum class FrictionLaw { constant, empirical };

struct Effects {
  bool hydrodynamics = false;
  CavitationModel cavitation = CavitationModel::reynolds;
  // jfo only: the gauge pressure of the cavity (Pa, ≤ 0). Below ambient, the cavity draws
  // oil from the flooded edges; at ambient (0, docs/physics.md section 12) nothing supplies a
  // full washer annulus, and its film drains (docs/validation.md).
  double cavity_pressure = 0.0;
  bool flow_factors = false;
  bool asperity_contact = false;
  bool thermal = false;
  ViscosityTemperature viscosity_temperature = ViscosityTemperature::surface_mean;
  CarrierTemperature carrier_temperature = CarrierTemperature::load_frame;
  // docs/physics.md section 11 (needs thermal): the films' shapes follow the bodies' temperatures.
  bool thermal_deformation = false;
  FaceExpansion face_expansion = FaceExpansion::free;
  // docs/physics.md section 15 (needs thermal and hydrodynamics): the oil carries its
  // heat with the film's flow.
  bool convection = false;
  // docs/physics.md section 20 (needs asperity_contact): the faces of the sliding film wear
  // by Archard's law, their depths parts of its gap.
  bool wear = false;
  // docs/physics.md section 21: the washer bends as a Kirchhoff plate under the difference
  // of its films' pressures (and, with thermal_deformation, its through-thickness heat
  // flux), its deflection a part of both films' gaps.
  bool elastic_washer = false;
};

// One point of a data sheet's modulus against temperature.
struct ModulusAt {
  double temperature;  // K
  double modulus;      // Pa
};

struct Material {
  // Pa. With a curve below: the curve's value at 23 degC, the room-temperature modulus
  // data sheets lead with (the model takes the curve where it has one).
  double youngs_modulus = 201e9;
  double poisson_ratio = 0.296;
  double yield_strength = 0.993e9;  // Pa
  double conductivity = 60.5;       // W/(m K)
  double density = 7850.0;          // kg/m^3
  double specific_heat = 470.0;     // J/(kg K)
  double thermal_expansion = 1.2e-5;  // 1/K (Table 1), used by thermal_deformation
  // The hottest the material may run (bronze, polymer, a coating): a failure criterion
  // of the body's hottest face (docs/physics.md section 8). None by default (steel).
  std::optional<double> max_temperature;  // K
  // The washer's PV limit (a bronze's or a polymer's data sheet): the most mean contact
  // pressure times sliding speed its face may run at, a failure criterion (docs/physics.md
  // section 8). The washer's material only; none by default.
  std::optional<double> pv_limit;  // Pa m/s
  // The modulus over temperature (docs/physics.md section 23, [M1]), ascending in
  // temperature, at least two points; empty: the constant youngs_modulus.
  std::vector<ModulusAt> modulus_by_temperature;
  // The library material these values start from (twb/scene/material_library.h,
  // docs/materials.md), the scene's fields over it; empty: fields over the paper's steel.
  std::string library;
};

// Roughness of one component's face(s) touching a film.
struct Roughness {
  double ra = 0.45e-6;     // m, arithmetic mean roughness (delta in the paper)
  double rq = 0.515e-6;    // m, RMS roughness (sigma in the paper)
  // m³/(N·m), the face's specific wear rate k of Archard's law (docs/physics.md section 20),
  // with `wear` on. None: not given (a face of the sliding film then needs it).
  std::optional<double> wear_rate;
  // m, the face's Rq once run in (docs/physics.md section 20, running-in): with `wear` on,
  // a face of the sliding film that wears runs in from Rq to it by truncation. None: it
  // keeps its Rq as it wears.
  std::optional<double> run_in_rq;
};

// A land's shaped inlet (docs/physics.md section 14), from the edge the moving face drags
// oil in from: a taper falling linearly to the flat land, or a Rayleigh step.
enum class LandShape { flat, taper, step };
struct Land {
  LandShape shape = LandShape::flat;
  double depth = 0.0;     // m, the extra gap at the inlet edge
  double fraction = 0.0;  // of the land's angle, resolved to whole cells of the grid
};

// Where a groove ends short of a rim (docs/physics.md section 14): open at one rim, it
// runs to the dam's radius, and the land continues across the rest of its column.
enum class GrooveOpening { inner_radius, outer_radius };
struct GrooveDam {
  GrooveOpening open_at = GrooveOpening::inner_radius;
  double written_radius = 0.0;  // m, as the scene gave it
  double radius = 0.0;          // m, on the grooved film's node line `line` (resolved)
  int line = 0;                 // the radial node line of the grooved film's grid the groove ends on
};

// Radial grooves in the washer's face on one film (docs/physics.md section 14), equally
// spaced, from the inner to the outer radius or from one rim to a dam, the first
// starting at θ = 0. Resolved so that every edge lies on a node line: the circumferential
// node count is a multiple of the count, the width and the land's inlet are whole cells,
// and a dam lies on a radial node line.
struct Grooves {
  int count = 0;
  int film = 2;        // the film whose washer face is grooved
  double width = 0.0;  // rad, whole cells of the grid (resolved)
  double written_width = 0.0;  // rad, as the scene gave it: a groove parameter places the grooves anew from it
  double depth = 0.0;  // m
  Land land;
  int cells = 0;       // of the grid, per groove (resolved)
  std::optional<GrooveDam> closed_at{};  // rim to rim without
};

struct Component {
  double inner_radius = 0.0;  // m
  double outer_radius = 0.0;  // m
  double thickness = 0.0;     // m
  double tilt = 0.0;          // rad, imposed tilt about y (gear only)
  // m, the gear's free axial travel to its stop (gear only; docs/physics.md section 19):
  // the most the two films' mean gaps may add up to at the axis. None: no stop.
  std::optional<double> axial_play{};
  Material material;
  Roughness roughness;
  std::optional<Grooves> grooves{};  // the washer's face only
};

// Summit statistics estimated from measured profiles (docs/physics.md section 13): what they
// came from, for the record (the estimate itself is in AsperityParameters).
struct ProfileEstimate {
  std::vector<std::string> files;    // one profile of the combined surface, or one per face
  std::vector<double> spacings;      // m, each file's sampling interval
  std::vector<std::size_t> samples;  // heights in each file
  double m0 = 0, m2 = 0, m4 = 0;     // spectral moments of the combined surface (m², 1, 1/m²)
  double bandwidth = 0;              // α_b = m0·m4/m2²
};

// Statistical summit parameters of the combined surface (docs/physics.md section 4).
struct AsperityParameters {
  double summit_radius = 20e-6;        // m
  double summit_sigma = 0.0;           // m, summit-height standard deviation
  double summit_density = 0.0;         // 1/m^2
  double eta_r_sigma = 0.05;           // the dimensionless product eta*R*sigma_s used for defaults
  std::optional<ProfileEstimate> profile;  // when measured profiles gave the three above
};

// Where the oil's Roelands constants came from when the scene gave its data sheet or a
// table (docs/physics.md section 5): the given points and the fit's error there.
struct ViscositySource {
  std::string kind;                 // "data_sheet" or "table"
  std::vector<double> temperatures;  // K
  std::vector<double> viscosities;   // Pa s, dynamic (a data sheet's: ρ(T)·ν)
  std::vector<double> relative_errors;  // (μ_fit − μ)/μ at each
  double largest_error = 0.0;           // over every fitted temperature
};

// Where the supplied oil enters the sliding film: its inner edge (fed from the bore), its
// grooves (every node inside a groove, edges excluded), or both.
enum class SupplyInlet { inner_radius, grooves, both };

// Oil fed to the film under pressure (docs/physics.md section 14): the fed boundaries and
// nodes hold the supply pressure instead of ambient.
struct OilSupply {
  double pressure = 0.0;  // Pa, gauge
  SupplyInlet at = SupplyInlet::inner_radius;
  // With convection (docs/physics.md section 15): the temperature the supplied oil enters
  // at (none: the ambient, the sump's), and the share of the hot oil a land delivers into
  // a groove that the groove passes on unmixed with supply oil.
  std::optional<double> temperature{};  // K
  double carry_over = 0.7;
  bool feeds_bore() const { return at != SupplyInlet::grooves; }
  bool feeds_grooves() const { return at != SupplyInlet::inner_radius; }
};

struct Lubricant {
  double conductivity = 0.145;  // W/(m K)
  ViscosityModel viscosity_model = ViscosityModel::roelands;
  double mu_infinity = 6.31e-5;  // Pa s, Roelands
  double g0 = 3.545;             // Roelands
  double s0 = 1.053;             // Roelands
  double constant_viscosity = 0.06081;  // Pa s, when viscosity_model == constant
  std::optional<ViscositySource> viscosity_source;  // roelands fitted to a data sheet or table
  // Where the oil stops being trusted (twb/model/operating_limits.h): an automatic
  // transmission fluid's maximum working temperature, which its oxidation life halves
  // about every 10 K beyond, and its flash point (ASTM D92, about 180 degC).
  double max_temperature = 423.15;    // K, 150 degC
  double flash_temperature = 453.15;  // K, 180 degC
  std::optional<OilSupply> supply{};  // none: both edges at ambient
  // The heat the oil carries (convection, docs/physics.md section 15): its density at
  // 15 degC with its volumetric expansion (the data sheet's where it gives one), and its
  // specific heat, typical of transmission fluids.
  double density = 850.0;            // kg/m^3 at 15 degC
  double density_expansion = 6.5e-4;  // 1/K
  double specific_heat = 2000.0;     // J/(kg K)
  double density_at(double t) const { return density * (1.0 - density_expansion * (t - 288.15)); }
};

// Failure criteria a scene may add besides the oil's and the materials' temperatures
// (docs/physics.md section 8).
struct Limits {
  std::optional<double> min_film_ratio;  // the least h_min/σ the bearing may run at
  // The pair's critical scuffing temperature (K): the asperities' contact temperature, the
  // faces' plus Blok's flash temperature, it may reach (docs/physics.md section 8). By
  // default ISO/TR 13989-1's θ_S = 80 + (0.85 + 1.4 X_W)·X_L·S_FZG² degC for a mineral
  // oil (X_L = 1) on through-hardened steel (X_W = 1) of FZG failure load stage 8: 224 degC.
  double scuffing_temperature = 497.15;
  // With `wear`: the deepest a face may wear (m), the wear allowance that ends a life
  // (docs/physics.md section 20). None: no allowance.
  std::optional<double> wear_depth;
};

struct Operating {
  double load = 0.0;       // N, external axial load on the gear
  double speed = 0.0;      // rad/s, relative angular speed of the sliding film
  SlidingFilm sliding = SlidingFilm::carrier_washer;
  double ambient = 297.15;  // K
};

struct Friction {
  FrictionLaw law = FrictionLaw::empirical;
  double coefficient = 0.1;  // used when law == constant
};

struct MeshSettings {
  int radial_nodes = 9;            // including both edges
  int circumferential_nodes = 66;  // distinct nodes (periodic)
  int contact_quadrature = 8;      // Gauss points per direction per cell for contact integrals
  // The same on cells where the contact pressure varies by less than a factor e^½ (at
  // most contact_quadrature; 6 integrates them to rounding: docs/model.md, "Integrals over cells").
  int flat_contact_quadrature = 6;
  // How many times a study's tolerance may refine the scene's mesh by two (study.tolerance;
  // docs/physics.md section 8, "To a requested accuracy"): 2 gives three meshes, the fewest
  // that show the order; each refinement costs about six times the last.
  int max_refinements = 2;
};

// How a steady state is solved: twb's monolithic Newton (KINSOL, KLU), or the paper's
// segregated scheme (Fig. 5: Newton-Raphson on the rigid body around projected SOR and
// the heat field's solve; docs/model.md, "The paper's scheme"), kept as the baseline.
enum class SolverMethod { newton, paper };

struct SolverSettings {
  SolverMethod method = SolverMethod::newton;
  double residual_tolerance = 1e-10;  // max-norm of the scaled residual
  double step_tolerance = 1e-14;
  int max_iterations = 200;
  double cold_start_film = 3.0;  // h_min/sigma of the cold start (the paper's)
  double over_relaxation = 1.7;  // method paper: ω of the pressure's projected SOR
};

struct Output {
  std::string directory = "results";
  bool fields = false;  // write p, h, T, contact pressure on the polar grid
};

// A continuous input of the bearing (docs/physics.md section 16): the number the scene
// file writes at `path` ("geometry.gear.tilt", "lubricant.viscosity.kv40"), in SI; unit
// is the SI unit's udunits2 symbol, "1" for a pure number.
struct SceneInput {
  std::string path;
  double value = 0.0;
  std::string unit;
};

struct Scene {
  std::string source;  // path of the scene file, for messages
  // The scene's tree as it was read (its bases and overrides merged), YAML: read again
  // with an input changed (scene_inputs.h), it is validated exactly like the file.
  std::string written;
  // Every continuous input the reader took from the bearing's sections (geometry,
  // materials, surfaces, lubricant, limits, operating, friction), in the order read.
  std::vector<SceneInput> inputs;
  Effects effects;
  Component carrier, washer, gear;
  AsperityParameters asperities;
  Lubricant lubricant;
  Limits limits;
  Operating operating;
  Friction friction;
  MeshSettings mesh;
  SolverSettings solver;
  Study study;
  Output output;
  // The washer as a life wore it (twb run --continue-from DIR; docs/scenes.md, "A worn
  // washer"): its depths held in every study, a life going on from its time. Not part of
  // the scene's file: the scenes read again with an input changed keep it (with_inputs).
  // Null: a new washer.
  std::shared_ptr<const WornWasher> worn;
  // What is legal but doubtful in the scene (e.g. a profile's band too narrow for
  // McCool's relations): said by `twb check` and `twb run`, never an error.
  std::vector<std::string> warnings;
};

// Every surface's roughness set to Rq = rq (Ra in the same ratio), the summits following
// a texture scaled in height by k = new/old combined σ: McCool's spectral moments m0, m2,
// m4 all scale with k², so σs ∝ k, R ∝ 1/k and η is unchanged (docs/physics.md section 4).
void set_roughness(Scene& scene, double rq);

// The washer's grooves g (count, width as an angle, depth, land, face) placed on the
// scene's grid (docs/physics.md section 14): the circumferential node count rounded to a
// whole number of cells per groove pitch, the groove's and the shaped inlet's widths to
// whole cells, a dam's radius to a radial node line. Where they cannot be: which of the
// grooves' keys is at fault (`width`: a groove at least as wide as its pitch; `depth`: at
// least as deep as the washer; `count`: more nodes than allowed; `closed_at`: a dam
// outside the grooved film or leaving no cell of groove or of dam) and why; the scene is
// then unchanged.
struct GroovesNotPlaced {
  const char* key;
  std::string why;
};
std::optional<GroovesNotPlaced> place_grooves(Scene& scene, Grooves g);
// The next combination of a grid's value indices `at` (axis k has sizes[k] values), the
// last axis turning fastest, as an odometer; false, with `at` back at the first, after
// the last combination.
bool next_combination(std::vector<std::size_t>& at, const std::vector<std::size_t>& sizes);
// The scene path of the input a map axis sets (its own, or a named parameter's, e.g.
// friction.coefficient); empty for the roughness, which sets several.
std::string parameter_path(const MapAxis& axis);
// The inner and outer radius of film 1 (the washer's annulus) or film 2 (its overlap
// with the gear's annulus; empty, inner ≥ outer, where they do not overlap)
// (docs/physics.md section 1).
std::array<double, 2> film_radii(const Scene& scene, int film);
// The scene's grooves with one property (a map's groove_count, groove_width or
// groove_depth) set to `value`, placed anew from the width the scene gave.
std::optional<GroovesNotPlaced> place_groove_parameter(Scene& scene, MapParameter p, double value);

}  // namespace twb
