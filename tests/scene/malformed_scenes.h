// The malformed scene fixtures and what their errors must say: shared by the loader's
// table-driven test and the `twb check` CLI test.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scene_test_support.h"

namespace twb::testing {

struct MalformedCase {
  std::string name;  // tests/scene/data/malformed/<name>.yaml
  int line;          // 1-based
  int column;        // 1-based; 0 where yaml-cpp's own position is not meaningful
  std::vector<std::string> message_contains;
};

// gtest prints a parameter by its bytes otherwise.
inline void PrintTo(const MalformedCase& c, std::ostream* os) { *os << c.name; }

inline std::string malformed_path(const MalformedCase& c) {
  return source_path("tests/scene/data/malformed/" + c.name + ".yaml");
}

// Lines and columns point at the defect itself: the offending key for key errors, the
// value for value errors, the map (its '{' or first key) for a missing key.
inline const std::vector<MalformedCase>& malformed_cases() {
  static const std::vector<MalformedCase> cases{
    {"ra_above_rq", 8, 16, {"surfaces.washer.Ra", "larger than Rq", "Ra (the mean |z|) is at most Rq"}},
    {"tilt_beyond_small_angle", 6, 84, {"geometry.gear.tilt", "at most 50 mrad", "small-angle gap"}},
    {"data_sheet_viscosity_rising", 8, 54, {"lubricant.viscosity.kv100", "is not below kv40", "an oil thins as it warms"}},
    {"viscosity_table_one_point", 10, 13, {"lubricant.viscosity.points: 1 point", "needs at least two"}},
    {"viscosity_table_no_oil_follows", 9, 5, {"lubricant.viscosity: the points fit Roelands' law only with G0 = 677.6", "must be in (0, 50]", "check their values and units"}},
    {"data_sheet_without_density", 8, 14, {"'lubricant.viscosity': needs density"}},
    {"unknown_key", 5, 62, {"unknown key 'thicknes' in 'geometry.washer'", "did you mean 'thickness'?", "Allowed: inner_diameter, outer_diameter, thickness"}},
    {"unknown_top_level_key", 12, 1, {"unknown key 'meshes' at the top level", "did you mean 'mesh'?", "Allowed: effects, geometry"}},
    {"unknown_key_without_suggestion", 13, 3, {"unknown key 'banana' in 'solver'", "Allowed: method, residual_tolerance, step_tolerance, max_iterations, cold_start_film, over_relaxation"}},
    {"unknown_effect_option", 3, 21, {"unknown key 'cavitaton'", "did you mean 'cavitation'?", "Allowed: cavitation"}},
    {"option_of_effect_without_options", 4, 20, {"unknown key 'order'", "takes no options"}},
    {"key_not_applicable_to_law", 14, 3, {"key 'coefficient' in 'friction' does not apply with law: empirical", "allowed with law: empirical: law"}},
    {"key_not_applicable_to_study", 12, 22, {"key 'load_start' in 'study' does not apply with type: point", "allowed with type: point: type"}},
    {"key_not_applicable_to_viscosity_model", 13, 50, {"key 'G0' in 'lubricant.viscosity' does not apply with model: constant", "allowed with model: constant: model, value"}},
    {"summit_density_and_eta_r_sigma", 15, 18, {"surfaces.asperities.eta_R_sigma", "either summit_density or eta_R_sigma, not both"}},
    {"wrong_dimension_speed", 9, 10, {"operating.speed: '22.7 mm' has the dimension of length, expected an angular speed convertible to rad/s"}},
    {"wrong_dimension_load", 8, 9, {"operating.load: '500 kg' has the dimension of mass, expected a force convertible to N"}},
    {"wrong_dimension_ambient", 11, 12, {"operating.ambient: '24 m' has the dimension of length, expected a temperature convertible to K"}},
    {"wrong_dimension_tilt", 6, 84, {"geometry.gear.tilt: '2 mm' has the dimension of length, expected an angle convertible to rad"}},
    {"wrong_dimension_reciprocal", 9, 10, {"operating.speed: '10 s' has the dimension of time, expected an angular speed convertible to rad/s"}},
    {"wrong_dimension_youngs_modulus", 13, 28, {"materials.washer.youngs_modulus: '201 kN' has the dimension of force, expected a pressure or stress convertible to Pa"}},
    {"unknown_unit", 4, 24, {"geometry.carrier.thickness: '10 mmm' has an unknown unit 'mmm'", "expected a length convertible to m"}},
    {"unparseable_number", 8, 9, {"operating.load: '5O0 N' is not a number", "expected a force", "e.g. '1000 N'"}},
    {"number_glued_to_unit", 4, 24, {"geometry.carrier.thickness: '10mm' is not a number", "a number, optionally followed by a space and a unit"}},
    {"nan_value", 14, 21, {"materials.gear.youngs_modulus: 'nan' is not a finite number"}},
    {"infinite_value", 8, 9, {"operating.load: '.inf' is not a finite number"}},
    {"negative_thickness", 5, 73, {"geometry.washer.thickness: '-0.635 mm' (= -0.000635 m) is out of range; must be in [1e-05, 0.2] m"}},
    {"negative_diameter", 6, 51, {"geometry.gear.outer_diameter: '-22.7 mm' (= -0.0227 m) is out of range; must be in [0.001, 2] m"}},
    {"poisson_ratio_too_large", 13, 28, {"materials.carrier.poisson_ratio: '0.5' is out of range; must be in (0, 0.5)"}},
    {"poisson_ratio_zero", 14, 20, {"materials.washer.poisson_ratio: '0' is out of range; must be in (0, 0.5)"}},
    {"inner_diameter_not_below_outer", 5, 28, {"geometry.washer.inner_diameter: '22.7 mm' must be less than outer_diameter '22.7 mm'"}},
    {"annuli_do_not_overlap", 6, 26, {"geometry.gear.inner_diameter", "does not overlap the washer annulus", "must overlap"}},
    {"radial_nodes_too_few", 12, 22, {"mesh.radial_nodes: 2 is out of range; must be in [3, 1025]"}},
    {"circumferential_nodes_too_few", 13, 26, {"mesh.circumferential_nodes: 7 is out of range; must be in [8, 8192]"}},
    {"residual_tolerance_zero", 13, 23, {"solver.residual_tolerance: '0' is out of range; must be in (0, 0.01]"}},
    {"step_tolerance_negative", 12, 26, {"solver.step_tolerance: '-1e-14' is out of range; must be in (0, 0.01]"}},
    {"paper_method_for_sweep", 13, 11, {"solver.method: 'paper' solves one operating point (study type: point)", "a load_sweep study needs method: newton"}},
    {"over_relaxation_without_paper", 13, 20, {"solver.over_relaxation", "applies with method: paper"}},
    {"over_relaxation_too_large", 14, 20, {"solver.over_relaxation: '2.0' is out of range; must be in (0, 2)", "SOR converges for 0 < ω < 2"}},
    {"load_zero", 8, 9, {"operating.load: '0 N' is out of range; must be in (0, 1000000] N", "a bearing without load has no steady state"}},
    {"speed_negative", 9, 10, {"operating.speed: '-545 rad/s' is out of range; must be in [0, 100000] rad/s"}},
    {"speed_past_any_bearing", 9, 10, {"operating.speed: '1e300 rad/s' (= 1e+300 rad/s) is out of range; must be in [0, 100000] rad/s", "kilometres per second"}},
    {"load_past_any_bearing", 8, 9, {"operating.load: '2 MN' (= 2000000 N) is out of range; must be in (0, 1000000] N"}},
    {"ambient_past_any_oil", 11, 12, {"operating.ambient: '350 degC' (= 623.15 K) is out of range; must be in (138.15, 573.15] K", "no oil works above 300 degC"}},
    {"mesh_too_fine", 12, 22, {"mesh.radial_nodes: 5000 is out of range; must be in [3, 1025]", "memory"}},
    {"thickness_in_metres", 5, 73, {"geometry.washer.thickness: '0.635 m' is out of range; must be in [1e-05, 0.2] m"}},
    {"tilt_too_large", 6, 84, {"geometry.gear.tilt: '100 mrad' (= 0.1 rad) is out of range; must be in [0, 0.05] rad"}},
    {"tilt_negative", 6, 84, {"geometry.gear.tilt: '-0.002' is out of range; must be in [0, 0.05] rad"}},
    {"ambient_below_roelands_limit", 11, 12, {"operating.ambient: '-140 degC'", "(= 133.15 K) is out of range; must be in (138.15, 573.15] K", "Roelands"}},
    {"sweep_end_not_above_start", 15, 13, {"study.load_end: '100 N' must be greater than load_start '2000 N'"}},
    {"sweep_steps_too_few", 12, 76, {"study.load_steps: 1 is out of range; must be in [2, 10000]"}},
    {"distress_map_without_speeds", 14, 11, {"study.speeds: the list is empty", "give at least one speed"}},
    {"distress_map_unknown_parameter", 17, 21, {"study.parameter.name: unknown value 'viscosity'", "allowed: friction_coefficient, gear_tilt, roughness, groove_count, groove_width, groove_depth"}},
    {"distress_map_friction_with_empirical_law", 19, 11, {"friction_coefficient varies the constant friction law's coefficient", "set friction.law: constant"}},
    {"distress_map_without_loads", 13, 3, {"missing required key 'load_start' in 'study'"}},
    {"distress_curve_unknown_parameter", 12, 42, {"study.parameter: unknown value 'viscosity'", "allowed: speed, friction_coefficient, gear_tilt, ambient_temperature, viscosity_scale, roughness"}},
    {"distress_curve_empty_range", 12, 70, {"study.to: '545 rad/s' must differ from 'from'"}},
    {"distress_curve_with_load_steps", 12, 82, {"key 'load_steps' in 'study' does not apply with type: distress_curve", "allowed with type: distress_curve: type, parameter, from, to, load_start, load_end, bracket_width, family"}},
    {"error_estimate_unknown", 12, 95, {"study.error_estimate: unknown value 'extrapolated'", "allowed: none, richardson, every_state"}},
    {"every_state_on_a_point", 12, 38, {"study.error_estimate: every_state", "is for load_sweep and distress_map", "with type: point use richardson or none"}},
    {"bracket_width_too_wide", 12, 94, {"study.bracket_width: '0.5' is out of range; must be in (0, 0.1]"}},
    {"transient_duration_wrong_dimension", 12, 72, {"study.duration: '60 mm' has the dimension of length, expected a time"}},
    {"transient_without_thermal", 12, 15, {"study.type: a transient study marches the heat balance", "add 'thermal' to effects"}},
    {"load_sweep_without_speeds", 17, 11, {"study.speeds: the list is empty", "give at least one speed"}},
    {"load_sweep_speed_wrong_dimension", 12, 100, {"study.speeds[1]: '953 mm' has the dimension of length, expected an angular speed"}},
    {"load_sweep_friction_with_empirical_law", 18, 21, {"study.parameter.name: friction_coefficient varies the constant friction law's coefficient", "set friction.law: constant"}},
    {"load_sweep_negative_friction_coefficient", 20, 20, {"study.parameter.values[1]: '-0.1' is out of range; must be in [0, 5]"}},
    {"sliding_choice_with_parameter", 18, 3, {"key 'parameter' in 'study' does not apply with type: sliding_choice", "allowed with type: sliding_choice: type, load_start, load_end, load_steps, speeds, bracket_width"}},
    {"sliding_choice_without_load_steps", 12, 8, {"missing required key 'load_steps' in 'study'", "a whole number in [2, 10000]"}},
    {"sliding_choice_load_end_below_start", 15, 13, {"study.load_end: '100 N' must be greater than load_start '1750 N'"}},
    {"distress_map_speed_wrong_dimension", 12, 49, {"study.speeds[1]: '545 mm' has the dimension of length, expected an angular speed"}},
    {"empty_effects_list", 2, 10, {"effects: the list is empty", "allowed: hydrodynamics, flow_factors, asperity_contact, thermal"}},
    {"missing_required_key", 5, 11, {"missing required key 'outer_diameter' in 'geometry.washer'", "allowed: inner_diameter, outer_diameter, thickness"}},
    {"missing_required_key_block", 8, 3, {"missing required key 'speed' in 'operating'", "an angular speed", "allowed: load, speed, sliding, ambient"}},
    {"missing_required_section", 2, 1, {"missing required key 'operating' at the top level", "allowed: effects, geometry"}},
    {"missing_gear", 4, 3, {"missing required key 'gear' in 'geometry'", "allowed: carrier, washer, gear"}},
    {"empty_required_value", 8, 3, {"operating.load: expected a force", "got no value"}},
    {"map_where_scalar_expected", 8, 9, {"operating.load: expected a force", "got a map"}},
    {"list_where_map_expected", 5, 11, {"'geometry.washer' must be a map (allowed keys: inner_diameter, outer_diameter, thickness, grooves); got a list"}},
    {"scalar_where_list_expected", 2, 10, {"effects: expected a list of effects (hydrodynamics, flow_factors, asperity_contact, thermal, thermal_deformation, convection); got the value 'hydrodynamics'"}},
    {"scalar_where_map_expected", 12, 7, {"'mesh' must be a map (allowed keys: radial_nodes, circumferential_nodes, contact_quadrature, flat_contact_quadrature); got the value '17'"}},
    {"not_a_whole_number", 12, 22, {"mesh.radial_nodes: '9.5' is not a whole number", "expected a whole number in [3, 1025]"}},
    {"not_a_boolean", 12, 18, {"output.fields: 'yes' is not a boolean; allowed: true, false"}},
    {"empty_output_directory", 13, 14, {"output.directory: must not be empty"}},
    {"duplicate_key", 10, 3, {"duplicate key 'load' in 'operating' (first given on line 8)", "each key may appear once"}},
    {"duplicate_section", 13, 1, {"duplicate key 'mesh' at the top level", "each key may appear once"}},
    {"duplicate_key_in_flow_map", 4, 31, {"duplicate key 'thickness' in 'geometry.carrier'"}},
    {"flow_factors_without_hydrodynamics", 2, 11, {"effects[0]: effect 'flow_factors' needs 'hydrodynamics'"}},
    {"thermal_without_heat_source", 3, 5, {"effects[0]: effect 'thermal' needs 'hydrodynamics' or 'asperity_contact'", "nothing generates heat"}},
    {"thermal_deformation_without_thermal", 2, 44, {"effects[2]: effect 'thermal_deformation' needs 'thermal'"}},
    {"unknown_face_expansion", 6, 43, {"effects[3].thermal_deformation.face_expansion: unknown value 'clamped'", "allowed: free, constrained"}},
    {"paper_method_with_deformation", 9, 11, {"solver.method: 'paper' solves the paper's rigid bearing", "use method: newton"}},
    {"thermal_expansion_too_large", 8, 32, {"materials.carrier.thermal_expansion", "must be in [0, 0.0003] 1/K"}},
    {"cavity_pressure_with_reynolds", 3, 43, {"key 'cavity_pressure' in 'effects[0].hydrodynamics' does not apply with cavitation: reynolds"}},
    {"cavity_pressure_above_ambient", 3, 55, {"effects[0].hydrodynamics.cavity_pressure: '0.2 bar' (= 20000 Pa) is out of range", "[-101325, 0] Pa"}},
    {"paper_method_with_jfo", 9, 11, {"solver.method: 'paper' solves the Reynolds cavitation condition", "with cavitation: jfo use method: newton"}},
    {"unknown_effect", 2, 11, {"effects[0]: unknown effect 'hydrodinamics'", "did you mean 'hydrodynamics'?", "Allowed: hydrodynamics, flow_factors, asperity_contact, thermal"}},
    {"duplicate_effect", 2, 44, {"effects[2]: effect 'hydrodynamics' is listed twice"}},
    {"unknown_sliding_film", 10, 12, {"operating.sliding: unknown value 'carrier-washer'", "did you mean 'carrier_washer'? Allowed: carrier_washer, washer_gear"}},
    {"unknown_friction_law", 12, 17, {"friction.law: unknown value 'emprical'", "did you mean 'empirical'? Allowed: empirical, constant"}},
    {"unknown_study_type", 13, 9, {"study.type: unknown value 'parameter_scan'", "allowed: point, load_sweep, distress_map, transient, sliding_choice"}},
    {"unknown_viscosity_model", 14, 12, {"lubricant.viscosity.model: unknown value 'roeland'", "did you mean 'roelands'? Allowed: roelands, constant"}},
    {"unknown_cavitation_model", 3, 33, {"unknown value 'elrod'", "allowed: reynolds, jfo"}},
    {"unknown_viscosity_temperature", 5, 38, {"unknown value 'film'", "allowed: surface_mean, film_node"}},
    {"unknown_carrier_temperature", 5, 36, {"unknown value 'rotating'", "allowed: load_frame, axisymmetric"}},
    {"yaml_unclosed_flow_sequence", 3, 0, {"YAML syntax error"}},
    {"yaml_bad_indentation", 9, 0, {"YAML syntax error"}},
    {"yaml_tab_indentation", 9, 0, {"YAML syntax error", "tab"}},
    {"yaml_stray_comma", 2, 1, {"YAML syntax error: unexpected ','"}},
    {"scene_not_a_map", 2, 1, {"the scene must be a map (allowed keys: effects, geometry", "got a list"}},
    {"grooves_on_a_turning_washer", 9, 14, {"geometry.washer.grooves", "needs operating.sliding: washer_gear"}},
    {"groove_width_without_unit", 9, 32, {"geometry.washer.grooves.width: '0.2' has no unit", "a length", "an angle"}},
    {"land_with_two_shapes", 13, 13, {"geometry.washer.grooves.land", "expected one shape", "taper and step"}},
    {"groove_wider_than_pitch", 9, 33, {"geometry.washer.grooves.width", "leave no land", "the pitch is 30 deg"}},
    {"groove_through_the_washer", 9, 45, {"geometry.washer.grooves.depth", "cut through the washer", "0.635 mm thick"}},
    {"sensitivity_parameter_not_an_input", 15, 36, {"study.parameters[1]: 'geometry.gear.tillt' names no number of the bearing", "did you mean 'geometry.gear.tilt'?"}},
    {"sensitivity_parameter_outside_the_bearing", 16, 7, {"study.parameters[0]: 'mesh.radial_nodes' is not in the bearing's sections", "geometry, materials, surfaces, lubricant, limits, operating, friction"}},
    {"sensitivity_parameter_derived_default", 15, 16, {"study.parameters[0]: 'surfaces.asperities.summit_density' cannot be set in this scene", "give either summit_density or eta_R_sigma"}},
    {"reliability_input_not_an_input", 15, 26, {"study.inputs.geometry.gear.tillt: 'geometry.gear.tillt' names no number of the bearing", "did you mean 'geometry.gear.tilt'?"}},
    {"reliability_normal_reaches_refused_value", 15, 25, {"study.inputs.geometry.gear.tilt: normal(mean 0.0005 rad, sd 0.0002 rad) reaches -0.0003 rad within 4 standard deviations, which the scene refuses", "bound it (truncated_normal with lower and upper)"}},
    {"reliability_uniform_bounds_reversed", 15, 71, {"study.inputs.operating.ambient.upper: '20 degC' must be greater than lower '30 degC'"}},
    {"reliability_unknown_distribution", 15, 39, {"study.inputs.operating.ambient.distribution: unknown value 'weibull'", "normal, lognormal, uniform, truncated_normal"}},
    {"reliability_operating_load_outside_range", 13, 13, {"study.load_end: the operating load 500 N must lie between load_start and load_end"}},
    {"reliability_no_inputs", 14, 11, {"study.inputs: no uncertain inputs; give a map from input paths to distributions"}},
    {"calibration_start_outside_bounds", 14, 33, {"study.fit.geometry.gear.tilt.start: the fit's start 0.003 rad lies outside its bounds [0.0005, 0.0025] rad"}},
    {"calibration_sd_missing", 16, 7, {"study.sd: no standard deviation for T_mean, which the data measure", "or leave sd out to fit relative residuals"}},
    {"calibration_fits_the_load", 14, 21, {"study.fit.operating.load: each measured point has its own load; it is not fitted"}},
    {"calibration_data_missing", 12, 9, {"study.data: cannot read the measurements", "no_such_rig.csv': no such regular file"}},
    {"calibration_fits_the_points_ambient", 14, 24, {"study.fit.operating.ambient: the data give measured points their own ambient temperature; it is not fitted"}},
    {"calibration_bound_refused", 14, 25, {"study.fit.geometry.gear.tilt: the fit may reach -0.001 rad, which the scene refuses", "narrow the bounds"}},
    {"input_axis_is_the_speed", 15, 21, {"study.parameter.name: operating.speed is an axis of every search already", "study.speeds"}},
    {"input_axis_value_out_of_range", 17, 26, {"study.parameter.values[1]: materials.carrier.conductivity: '-5 W/(m K)'", "out of range"}},
    {"input_axis_not_an_input", 15, 21, {"study.parameter.name: 'geometry.gear.tlt' names no number of the bearing", "did you mean 'geometry.gear.tilt'?"}},
    {"groove_parameter_without_grooves", 19, 21, {"study.parameter.name: groove_count varies the washer's grooves", "the scene has none"}},
    {"groove_width_value_wider_than_pitch", 20, 51, {"study.parameter.values[1]", "12 grooves 40 deg wide leave no land", "the pitch is 30 deg"}},
    {"groove_count_value_leaves_no_land", 21, 47, {"study.parameter.values[1]", "40 grooves 10 deg wide", "the pitch is 9 deg"}},
    {"groove_depth_value_through_the_washer", 20, 51, {"study.parameter.values[1]", "1 mm deep would cut through the washer"}},
    {"convection_without_thermal", 2, 44, {"effect 'convection' needs 'thermal' and 'hydrodynamics'", "add thermal"}},
    {"supply_temperature_above_flash_point", 9, 42, {"lubricant.supply.temperature", "flash point"}},
    {"supply_temperature_below_pour_point", 8, 42, {"lubricant.supply.temperature", "pour point"}},
    {"supply_into_missing_grooves", 8, 33, {"lubricant.supply.at", "needs grooves to feed", "at: inner_radius"}},
    {"supply_into_grooves_of_the_standing_film", 13, 33, {"lubricant.supply.at: oil supplied at 'both'", "sliding film's face"}},
  };
  return cases;
}

}  // namespace twb::testing
