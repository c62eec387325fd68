// How the scene file spells the choices of scene.h; shared by the reader and the writer
// so that what is written loads back.
#pragma once

#include <algorithm>
#include <string_view>

#include "scene_node.h"
#include "twb/scene/scene.h"

namespace twb::scene_io {

inline constexpr EnumNames<SlidingFilm, 2> kSlidingFilms{
    {"carrier_washer", "washer_gear"}, {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}};

inline constexpr EnumNames<CavitationModel, 2> kCavitationModels{{"reynolds", "jfo"},
                                                                 {CavitationModel::reynolds, CavitationModel::jfo}};

inline constexpr EnumNames<ViscosityTemperature, 2> kViscosityTemperatures{
    {"surface_mean", "film_node"},
    {ViscosityTemperature::surface_mean, ViscosityTemperature::film_node}};

inline constexpr EnumNames<CarrierTemperature, 2> kCarrierTemperatures{
    {"load_frame", "axisymmetric"}, {CarrierTemperature::load_frame, CarrierTemperature::axisymmetric}};

inline constexpr EnumNames<FaceExpansion, 2> kFaceExpansions{
    {"free", "constrained"}, {FaceExpansion::free, FaceExpansion::constrained}};

inline constexpr EnumNames<SupplyInlet, 3> kSupplyInlets{
    {"inner_radius", "grooves", "both"}, {SupplyInlet::inner_radius, SupplyInlet::grooves, SupplyInlet::both}};

inline constexpr EnumNames<GrooveOpening, 2> kGrooveOpenings{
    {"inner_radius", "outer_radius"}, {GrooveOpening::inner_radius, GrooveOpening::outer_radius}};

// The lubricant's keys: read with the operating point, and again by the grooves, which
// check that a supply into the grooves has grooves to feed.
inline constexpr std::string_view kLubricantKeys[] = {"conductivity", "viscosity", "max_temperature",
                                                       "flash_temperature", "supply", "density",
                                                       "density_expansion", "specific_heat"};
inline constexpr std::string_view kStudyKeys[] = {"type",          "load_start", "load_end", "load_steps",
                                                   "speeds",        "parameter",  "bracket_width", "duration",
                                                   "error_estimate", "from",       "to",       "family",
                                                   "parameters", "inputs", "probabilities", "monte_carlo",
                                                   "data", "fit", "sd", "max_iterations", "method",
                                                   "schedule", "failure_load_at_worst", "relative_tolerance",
                                                   "tolerance", "search_past_failure", "report_every",
                                                   "failure_load"};
inline constexpr std::string_view kOperatingKeys[] = {"load", "speed", "sliding", "ambient"};
inline constexpr std::string_view kSupplyKeys[] = {"pressure", "at", "temperature", "carry_over"};

inline constexpr EnumNames<ViscosityModel, 2> kViscosityModels{
    {"roelands", "constant"}, {ViscosityModel::roelands, ViscosityModel::constant}};

inline constexpr EnumNames<FrictionLaw, 2> kFrictionLaws{
    {"empirical", "constant"}, {FrictionLaw::empirical, FrictionLaw::constant}};

inline constexpr EnumNames<StudyType, 11> kStudyTypes{
    {"point", "load_sweep", "distress_map", "transient", "sliding_choice", "distress_curve", "sensitivity",
     "reliability", "calibration", "duty_cycle", "life"},
    {StudyType::point, StudyType::load_sweep, StudyType::distress_map, StudyType::transient,
     StudyType::sliding_choice, StudyType::distress_curve, StudyType::sensitivity, StudyType::reliability,
     StudyType::calibration, StudyType::duty_cycle, StudyType::life}};
// A calibration's measured quantities: their names in the scene's `sd` and the data
// file's header (MeasuredQuantity's order).
inline constexpr std::string_view kMeasuredNames[] = {"torque", "f_eff", "T_mean", "T_max"};
inline constexpr EnumNames<InputDistribution, 4> kInputDistributions{
    {"normal", "lognormal", "uniform", "truncated_normal"},
    {InputDistribution::normal, InputDistribution::lognormal, InputDistribution::uniform,
     InputDistribution::truncated_normal}};

inline constexpr EnumNames<CurveParameter, 6> kCurveParameters{
    {"speed", "friction_coefficient", "gear_tilt", "ambient_temperature", "viscosity_scale", "roughness"},
    {CurveParameter::speed, CurveParameter::friction_coefficient, CurveParameter::gear_tilt,
     CurveParameter::ambient_temperature, CurveParameter::viscosity_scale, CurveParameter::roughness}};

inline constexpr EnumNames<SolverMethod, 2> kSolverMethods{{"newton", "paper"},
                                                           {SolverMethod::newton, SolverMethod::paper}};

inline constexpr EnumNames<MapMethod, 2> kMapMethods{{"search", "follow"}, {MapMethod::search, MapMethod::follow}};
inline constexpr EnumNames<ErrorEstimate, 3> kErrorEstimates{
    {"none", "richardson", "every_state"},
    {ErrorEstimate::none, ErrorEstimate::richardson, ErrorEstimate::every_state}};

inline constexpr EnumNames<MapParameter, 6> kMapParameters{
    {"friction_coefficient", "gear_tilt", "roughness", "groove_count", "groove_width", "groove_depth"},
    {MapParameter::friction_coefficient, MapParameter::gear_tilt, MapParameter::roughness, MapParameter::groove_count,
     MapParameter::groove_width, MapParameter::groove_depth}};

// Effects in the order the model stacks them.
inline constexpr std::string_view kHydrodynamics = "hydrodynamics";
inline constexpr std::string_view kFlowFactors = "flow_factors";
inline constexpr std::string_view kAsperityContact = "asperity_contact";
inline constexpr std::string_view kThermal = "thermal";
inline constexpr std::string_view kThermalDeformation = "thermal_deformation";
inline constexpr std::string_view kConvection = "convection";
inline constexpr std::string_view kWear = "wear";
inline constexpr std::string_view kElasticWasher = "elastic_washer";
inline constexpr std::array<std::string_view, 8> kEffectNames{kHydrodynamics, kFlowFactors,        kAsperityContact,
                                                              kThermal,       kThermalDeformation, kConvection,
                                                              kWear,          kElasticWasher};

// The three bodies, in stacking order along z.
inline constexpr std::array<std::string_view, 3> kComponentNames{"carrier", "washer", "gear"};

// A body's material named alone (`materials.washer: peek`) stands for `{material: peek}`:
// an override of one of its fields, or a derived scene's map of fields, opens it into
// that map (docs/scenes.md, materials).
inline bool is_library_shorthand(std::string_view path) {
  constexpr std::string_view prefix = "materials.";
  if (path.substr(0, prefix.size()) != prefix) return false;
  const std::string_view body = path.substr(prefix.size());
  return std::find(kComponentNames.begin(), kComponentNames.end(), body) != kComponentNames.end();
}

// The key of a body's material that `key` stands in for: a constant modulus and a modulus
// over temperature (docs/physics.md section 23) replace each other, so a derived scene or
// an override that gives one drops the other its base gives. Empty for any other key.
inline std::string_view replaced_material_key(std::string_view key) {
  if (key == "youngs_modulus") return "modulus_by_temperature";
  if (key == "modulus_by_temperature") return "youngs_modulus";
  return {};
}

}  // namespace twb::scene_io
