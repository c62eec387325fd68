// What a scene's study asks for: the study types, the settings each reads from the
// scene's `study` section (docs/scenes.md), in SI units, and the study, which holds the
// settings of its type alone; part of the validated scene (scene.h).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace twb {

// sliding_choice: both sliding configurations over a load grid, the one of lower
// friction torque kept (docs/physics.md section 2, the paper's "Component Rotational Speed").
enum class StudyType {
  point, load_sweep, distress_map, transient, sliding_choice, distress_curve, sensitivity, reliability, calibration,
  duty_cycle, life
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
  bool operator==(const UncertainInput&) const = default;
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
  bool operator==(const SchedulePoint&) const = default;
};

// The pieces several types' settings share.

// The loads a search covers or a step joins.
struct LoadRange {
  double start = 0.0;  // N
  double end = 0.0;    // N
  bool operator==(const LoadRange&) const = default;
};

// A failure search between two loads: the distress bracket refined by bisection to
// (high − low)/high <= bracket_width.
struct FailureSearch {
  LoadRange loads;
  double bracket_width = 0.002;
  bool operator==(const FailureSearch&) const = default;
};

// A load grid (load_sweep, sliding_choice): the load range continued over, and the
// states on the requested grid, ends included.
struct LoadGrid : FailureSearch {
  int load_steps = 0;
  // The speeds, one search per speed (a grid without `speeds` in the file gets
  // operating.speed).
  std::vector<double> speeds;  // rad/s
  bool operator==(const LoadGrid&) const = default;
};

// The error bars of a study's answers.
struct ErrorBarSettings {
  // W_d's discretization error (docs/model.md, "Distress on the bearing").
  ErrorEstimate estimate = ErrorEstimate::richardson;
  // The relative accuracy every failure load is wanted to; the mesh is refined by two
  // until each estimated error is within it (docs/physics.md section 8, "To a requested
  // accuracy"). 0: none (one refinement, a bar of the formal order, as the estimate
  // alone gives).
  double tolerance = 0.01;
  bool operator==(const ErrorBarSettings&) const = default;
};

// Each study type's settings.

// point: the bearing at the operating point. Its bar is the two-mesh estimate unless a
// tolerance is asked for (scene/studies/point_keys.cpp says why).
struct PointSettings {
  ErrorBarSettings error_bars{.estimate = ErrorEstimate::richardson, .tolerance = 0.0};
  bool operator==(const PointSettings&) const = default;
};

// load_sweep: a load grid at each speed and combination of the axes, past distress.
struct LoadSweepSettings {
  LoadGrid grid;
  // The axes besides the speed, each search one combination of their values (a grid:
  // the first axis outermost).
  std::vector<MapAxis> axes;
  ErrorBarSettings error_bars;
  bool operator==(const LoadSweepSettings&) const = default;
};

// distress_map: the failure loads over speeds and combinations of the axes.
struct DistressMapSettings {
  FailureSearch search;
  std::vector<double> speeds;  // rad/s, one search per speed
  // The axes besides the speed, as a load sweep's.
  std::vector<MapAxis> axes;
  ErrorBarSettings error_bars;
  // A search at every combination, or each followed from its neighbour's.
  MapMethod map_method = MapMethod::search;
  // The cool branch is searched on past the first failure criterion it crosses only up
  // to this factor times that load (W_d and the other criteria beyond it are not
  // searched: far past the first failure they cost minutes and lie past the oil's and
  // the model's validity). 0: none, on to the search's end.
  double search_past_failure = 2.0;
  bool operator==(const DistressMapSettings&) const = default;
};

// transient: the load before (loads.start) and after (loads.end) the step.
struct LoadStepSettings {
  LoadRange loads;
  // Pseudo-time span in s; 0 marches until the state settles or runs away.
  double duration = 0.0;
  bool operator==(const LoadStepSettings&) const = default;
};

// sliding_choice: both sliding films over a load grid.
struct SlidingChoiceSettings {
  LoadGrid grid;
  bool operator==(const SlidingChoiceSettings&) const = default;
};

// distress_curve: the fold continued in one parameter.
struct DistressCurveSettings {
  // The first fold's search (the reader's defaults: a fifth and four times
  // operating.load).
  FailureSearch search;
  // The fold continued in this parameter from `from` to `to` (SI).
  CurveParameter curve_parameter = CurveParameter::speed;
  double from = 0.0, to = 0.0;
  // Its family's axis: a curve for each of its values (none: the scene's bearing alone).
  std::vector<MapAxis> axes;
  ErrorBarSettings error_bars;
  bool operator==(const DistressCurveSettings&) const = default;
};

// sensitivity: the state's derivatives against the scene's inputs, and the failure
// load's where a load range is given.
struct SensitivitySettings {
  // The inputs differentiated against, by their scene paths (empty: every input the
  // scene file writes, Scene::inputs).
  std::vector<std::string> parameters;
  // The failure search at the operating point; none where loads.end is 0.
  FailureSearch search;
  bool operator==(const SensitivitySettings&) const = default;
};

// reliability: the uncertain inputs (independent), the failure probabilities whose loads
// are wanted (inverse FORM), and the Monte Carlo check: importance sampling round the
// design point until the estimate's coefficient of variation is `sampling_cov` (none
// with max_samples 0), its samples drawn from `seed`.
struct ReliabilitySettings {
  // The failure search at the inputs' medians, and at every other point of theirs.
  FailureSearch search;
  std::vector<UncertainInput> uncertain_inputs;
  std::vector<double> probabilities;
  double sampling_cov = 0.1;
  int max_samples = 4000;
  long seed = 1;
  bool operator==(const ReliabilitySettings&) const = default;
};

// calibration: the measurements (from the file `data`, as resolved), the inputs fitted
// to them, and each measured quantity's standard deviation (by MeasuredQuantity; 0
// where not given: then every residual is relative to its reading and the covariance
// is scaled by the residuals' own variance).
struct CalibrationSettings {
  std::string data;
  std::vector<MeasuredPoint> measurements;
  std::vector<FittedInput> fitted;
  std::array<double, kMeasuredQuantities> measurement_sd{};
  int fit_iterations = 50;  // Levenberg-Marquardt iterations at most (study.max_iterations)
};

// duty_cycle: the operating point in time, every field given (a field a point leaves
// out is the point before's, the first point's the scene's operating point and gear
// tilt); `schedule_file`: the CSV it was read from (as resolved), empty where the scene
// lists it.
struct DutyCycleSettings {
  std::vector<SchedulePoint> schedule;
  std::string schedule_file;
  // The failure load at the cycle's worst moment (a failure search there).
  bool failure_load_at_worst = true;
  // IDA's relative tolerance a step (study.relative_tolerance).
  double march_tolerance = 1e-6;
  bool operator==(const DutyCycleSettings&) const = default;
};

// life: the washer worn at the operating point, or through a duty cycle repeated, over
// `duration` in the wear's slow time (docs/physics.md section 20, [W4]), its depths
// integrated to `tolerance`, the bearing reported every `report_every`.
struct LifeSettings {
  double duration = 0.0;         // s
  double tolerance = 0.01e-6;    // m, the depths' error at the end of the life
  double report_every = 0.0;     // s; 0: a twentieth of the duration
  // The failure load at every reported time (every criterion, on the scene's mesh: a
  // search of the worn washer at the operating speed, or at a cycle's worst moment).
  bool failure_load = true;
  // The duty cycle repeated (study.schedule, its march's study.relative_tolerance; its
  // failure_load_at_worst unused: the life's failure_load decides), none at one
  // operating point.
  std::optional<DutyCycleSettings> cycle;
  bool operator==(const LifeSettings&) const = default;
};

// One type's settings, the alternative at its StudyType's index.
using StudySettings = std::variant<PointSettings, LoadSweepSettings, DistressMapSettings, LoadStepSettings,
                                   SlidingChoiceSettings, DistressCurveSettings, SensitivitySettings,
                                   ReliabilitySettings, CalibrationSettings, DutyCycleSettings, LifeSettings>;

// The settings type of a study type.
template <StudyType type>
using SettingsOf = std::variant_alternative_t<static_cast<std::size_t>(type), StudySettings>;
static_assert(std::is_same_v<SettingsOf<StudyType::point>, PointSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::load_sweep>, LoadSweepSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::distress_map>, DistressMapSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::transient>, LoadStepSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::sliding_choice>, SlidingChoiceSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::distress_curve>, DistressCurveSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::sensitivity>, SensitivitySettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::reliability>, ReliabilitySettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::calibration>, CalibrationSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::duty_cycle>, DutyCycleSettings>);
static_assert(std::is_same_v<SettingsOf<StudyType::life>, LifeSettings>);
// (life is the last type: none is without its settings)
static_assert(std::variant_size_v<StudySettings> == static_cast<std::size_t>(StudyType::life) + 1);

struct Study {
  // The scene gave its speeds (study.speeds, or operating.speed where the study names
  // none) in rpm: the figures (run.json's speed_unit), the summaries and the progress
  // lines say rpm too.
  bool speeds_in_rpm = false;
  // The settings of the study's type, which their alternative is (type()): the scene
  // reader sets them once, to the type's defaults (default_settings), before it reads the
  // type's keys.
  StudySettings settings;

  StudyType type() const { return static_cast<StudyType>(settings.index()); }
  // What the machinery every type shares reads of a type's settings, where the type has
  // it: the error bars (point, load_sweep, distress_map, distress_curve; none for the
  // others), the speeds of one search each (load_sweep, distress_map, sliding_choice;
  // empty for the others), the axes of its combinations (load_sweep, distress_map) or of
  // its family (distress_curve; empty for the others).
  const ErrorBarSettings* error_bars() const;
  std::span<const double> speeds() const;
  std::span<const MapAxis> axes() const;
  // (an axis over an input's path gets its unit and values once every input is read)
  std::span<MapAxis> axes();
};

// A type's settings with every default, as the scene reader starts them.
StudySettings default_settings(StudyType type);

}  // namespace twb
