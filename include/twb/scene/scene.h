// The validated scene: everything a run needs, in SI units (temperatures in kelvin).
// Produced only by the scene loader (scene_loader.h); every layer after it reads this.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

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

// sliding_choice: both sliding configurations over a load grid, the one of lower
// friction torque kept (docs/physics.md section 2, the paper's "Component Rotational Speed").
enum class StudyType {
  point, load_sweep, distress_map, transient, sliding_choice, distress_curve, sensitivity, reliability, calibration,
  duty_cycle
};

// The optional second axis of a distress map or load sweep (besides speed).
// roughness: the Rq of every surface (see docs/scenes.md for how the texture scales).
// scene_input: any input of the scene by its path (Study::parameter_path; scene_inputs.h).
enum class MapParameter {
  none, friction_coefficient, gear_tilt, roughness, groove_count, groove_width, groove_depth, scene_input
};

// A parameter of the bearing a fold curve is continued in (study type distress_curve),
// set on a built model without rebuilding it.
// viscosity_scale multiplies the oil's viscosity at every temperature (1: the scene's oil).
// roughness: the Rq of every surface (set_roughness).
enum class CurveParameter { speed, friction_coefficient, gear_tilt, ambient_temperature, viscosity_scale, roughness };

// An uncertain input's distribution (study type reliability, docs/physics.md section 17).
// normal: mean, sd; lognormal: the input's own mean and sd (its logarithm normal);
// uniform: lower, upper; truncated_normal: the normal (mean, sd) cut to [lower, upper].
enum class InputDistribution { normal, lognormal, uniform, truncated_normal };

struct UncertainInput {
  std::string path;  // the input's scene path, e.g. "geometry.gear.tilt"
  std::string unit;  // its SI unit
  InputDistribution distribution = InputDistribution::normal;
  double mean = 0.0, sd = 0.0;        // SI (normal, lognormal, truncated_normal)
  double lower = 0.0, upper = 0.0;    // SI (uniform, truncated_normal)
};

// What a rig measures that a calibration study fits (docs/physics.md section 18): the
// friction torque, the effective friction coefficient, the washer's mean and the film's
// hottest temperature.
enum class MeasuredQuantity { torque, f_eff, T_mean, T_max };
inline constexpr std::size_t kMeasuredQuantities = 4;

// One measured operating point (a row of the calibration's data file).
struct MeasuredPoint {
  double load = 0.0;   // N
  double speed = 0.0;  // rad/s
  double ambient = 0.0;  // K, the oil's (the sump's) at the point; 0: the scene's operating.ambient
  // SI (N m, 1, K), by MeasuredQuantity; NaN where the point does not measure it
  std::array<double, kMeasuredQuantities> values{};
  // Each reading's own standard deviation (SI; a temperature's in K), where the data give
  // one (a `<quantity>_sd` column); NaN elsewhere
  std::array<double, kMeasuredQuantities> sd{std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN()};
  int line = 0;  // its line in the data file
};

// An input fitted by a calibration study: its scene path and SI unit, where the fit
// starts and the bounds it keeps to (SI).
struct FittedInput {
  std::string path, unit;
  double start = 0.0, lower = 0.0, upper = 0.0;
};

// How a distress search estimates the discretization error of W_d.
enum class ErrorEstimate {
  none,
  richardson,   // the fold again on the mesh refined by two in each direction, extrapolated
  every_state,  // that, and every state of a sweep too (load_sweep, distress_map)
};

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
};

struct Material {
  double youngs_modulus = 201e9;  // Pa
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
};

// Roughness of one component's face(s) touching a film.
struct Roughness {
  double ra = 0.45e-6;     // m, arithmetic mean roughness (delta in the paper)
  double rq = 0.515e-6;    // m, RMS roughness (sigma in the paper)
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

// One axis of a map, sweep or curve family: a named parameter or an input by its scene
// path, and its values.
struct MapAxis {
  MapParameter parameter = MapParameter::none;
  std::string path;            // scene_input: the input's path, e.g. "geometry.gear.tilt"
  std::string unit;            // scene_input: its SI unit ("rad"; "1" for a pure number)
  std::vector<double> values;  // SI (dimensionless, rad, m; scene_input: the input's SI unit)
  bool operator==(const MapAxis&) const = default;
};

// How a distress map finds each combination's failure load: a failure search at each,
// or followed by Newton from a neighbour's settled criteria (docs/physics.md section 16).
enum class MapMethod { search, follow };

// A point of a duty cycle's schedule (study type duty_cycle, docs/physics.md section 19):
// the operating point at `time`, piecewise linear between points, held after the last.
struct SchedulePoint {
  double time = 0.0;     // s, strictly increasing along the schedule
  double load = 0.0;     // N
  double speed = 0.0;    // rad/s; negative: the washer turns back
  double ambient = 0.0;  // K
  double tilt = 0.0;     // rad, the gear's imposed tilt (geometry.gear.tilt)
  // Where it was written, for messages: the scene file's or the schedule CSV's path and
  // 1-based line.
  std::string file;
  int line = 0;
};

struct Study {
  StudyType type = StudyType::point;
  // load_sweep, distress_map, sliding_choice: the load range continued over; transient:
  // the load before (load_start) and after (load_end) the step.
  double load_start = 0.0;  // N
  double load_end = 0.0;    // N
  int load_steps = 0;       // load_sweep, sliding_choice: states on the requested grid, ends included
  // load_sweep, distress_map, sliding_choice: the speeds, one search per speed (a load
  // sweep without `speeds` in the file gets operating.speed)
  std::vector<double> speeds;  // rad/s
  // load_sweep, distress_map: the axes besides the speed, each search one combination of
  // their values (a grid: the first axis outermost); distress_curve: its family's axis.
  std::vector<MapAxis> axes;
  // Distress bracket refined by bisection to (high − low)/high <= bracket_width.
  double bracket_width = 0.002;
  // distress_curve: the fold continued in this parameter from `from` to `to` (SI).
  CurveParameter curve_parameter = CurveParameter::speed;
  double from = 0.0, to = 0.0;
  // load_sweep, distress_map: W_d's discretization error (docs/model.md, "Distress on the bearing").
  ErrorEstimate error_estimate = ErrorEstimate::richardson;
  // load_sweep, distress_map: the relative accuracy every failure load is wanted to; the
  // mesh is refined by two until each estimated error is within it (docs/physics.md
  // section 8, "To a requested accuracy"). 0: none (one refinement, a bar of the formal
  // order, as error_estimate alone gives).
  double tolerance = 0.01;
  // distress_map: the cool branch is searched on past the first failure criterion it
  // crosses only up to this factor times that load (W_d and the other criteria beyond
  // it are not searched: far past the first failure they cost minutes and lie past the
  // oil's and the model's validity). 0: none, on to load_end.
  double search_past_failure = 2.0;
  // The scene gave its speeds (study.speeds, or operating.speed where the study names
  // none) in rpm: the figures (run.json's speed_unit), the summaries and the progress
  // lines say rpm too.
  bool speeds_in_rpm = false;
  // distress_map: a search at every combination, or each followed from its neighbour's.
  MapMethod map_method = MapMethod::search;
  // transient: pseudo-time span in s; 0 marches until the state settles or runs away.
  double duration = 0.0;
  // sensitivity: the inputs differentiated against, by their scene paths (empty: every
  // input the scene file writes, Scene::inputs).
  std::vector<std::string> parameters;
  // reliability: the uncertain inputs (independent), the failure probabilities whose loads
  // are wanted (inverse FORM), and the Monte Carlo check: importance sampling round the
  // design point until the estimate's coefficient of variation is `sampling_cov` (none
  // with max_samples 0), its samples drawn from `seed`.
  std::vector<UncertainInput> uncertain_inputs;
  std::vector<double> probabilities;
  double sampling_cov = 0.1;
  int max_samples = 4000;
  long seed = 1;
  // calibration: the measurements (from the file `data`, as resolved), the inputs fitted
  // to them, and each measured quantity's standard deviation (by MeasuredQuantity; 0
  // where not given: then every residual is relative to its reading and the covariance
  // is scaled by the residuals' own variance).
  std::string data;
  std::vector<MeasuredPoint> measurements;
  std::vector<FittedInput> fitted;
  std::array<double, kMeasuredQuantities> measurement_sd{};
  int fit_iterations = 50;  // calibration: Levenberg-Marquardt iterations at most (study.max_iterations)
  // duty_cycle: the operating point in time, every field given (a field a point leaves
  // out is the point before's, the first point's the scene's operating point and gear
  // tilt); `schedule_file`: the CSV it was read from (as resolved), empty where the scene
  // lists it.
  std::vector<SchedulePoint> schedule;
  std::string schedule_file;
  // duty_cycle: the failure load at the cycle's worst moment (a failure search there).
  bool failure_load_at_worst = true;
  // duty_cycle: IDA's relative tolerance a step (study.relative_tolerance).
  double march_tolerance = 1e-6;
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
