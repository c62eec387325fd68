// distress.csv, trajectory.csv, sliding.csv and the run columns of states.csv: the columns, empty cells for values that do
// not exist, and no NaN ever written.
#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include "twb/results/distress_table.h"
#include "twb/results/sliding_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"

namespace twb {
namespace {

// Every failure criterion's load, in kFailureCriteria order.
#define kCriteria                                                                                         \
  "W_oil_temperature_N,W_oil_peak_temperature_N,W_material_temperature_carrier_N,W_material_temperature_washer_N," \
  "W_material_temperature_gear_N,W_film_ratio_N,W_pv_N,W_scuffing_N,W_modulus_data_carrier_N,"                   \
  "W_modulus_data_washer_N,W_modulus_data_gear_N,W_oil_temperature_error_N,"                                     \
  "W_oil_peak_temperature_error_N," \
  "W_material_temperature_carrier_error_N,W_material_temperature_washer_error_N,"                               \
  "W_material_temperature_gear_error_N,W_film_ratio_error_N,W_pv_error_N,W_scuffing_error_N,"                     \
  "W_modulus_data_carrier_error_N,W_modulus_data_washer_error_N,W_modulus_data_gear_error_N,"                    \
  "W_oil_temperature_extrapolated_N," \
  "W_oil_peak_temperature_extrapolated_N,W_material_temperature_carrier_extrapolated_N,"                          \
  "W_material_temperature_washer_extrapolated_N,W_material_temperature_gear_extrapolated_N,"                   \
  "W_film_ratio_extrapolated_N,W_pv_extrapolated_N,W_scuffing_extrapolated_N,W_modulus_data_carrier_extrapolated_N," \
  "W_modulus_data_washer_extrapolated_N,W_modulus_data_gear_extrapolated_N,"

// How W_fail's and W_d's mesh-converged values were reached (study.tolerance).
#define kFailConvergence "W_fail_meshes,W_fail_order,W_fail_tolerance_met,"
#define kFoldConvergence "W_d_meshes,W_d_order,"

// A row of distress.csv's leading fields, the rest (W_fail, criteria, bars) empty.
DistressRow distress_row(double speed, std::vector<double> parameters, std::optional<double> w_d,
                         std::optional<double> low, std::optional<double> high, std::optional<double> fold,
                         std::string method, std::optional<SlidingFilm> sliding = std::nullopt) {
  DistressRow row;
  row.speed = speed;
  row.parameters = std::move(parameters);
  row.distress_load = w_d;
  row.bracket_low = low;
  row.bracket_high = high;
  row.fold_load = fold;
  row.method = std::move(method);
  row.sliding = sliding;
  return row;
}

TEST(DistressTable, ColumnsWithAndWithoutSecondParameter) {
  DistressRow found = distress_row(545.0, {0.1}, 185.25, 185.0, 185.5, 185.3, "runaway; fold");
  DistressRow none = distress_row(136.0, {0.2}, std::nullopt, std::nullopt, std::nullopt, std::nullopt, "not reached below 2000 N");
  EXPECT_EQ(distress_csv({found, none}, {"friction_coefficient"}),
            "speed_rad_s,friction_coefficient,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N," kFailConvergence "W_d_N,bracket_low_N,bracket_high_N,fold_N,"
            "W_d_fine_N,W_d_extrapolated_N,W_d_error_N," kFoldConvergence kCriteria "failure,method\n"
            "545,0.1,,,,,,,,185.25,185,185.5,185.3,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,runaway; fold\n"
            "136,0.2,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,not reached below 2000 N\n");
  found.parameters.clear();
  EXPECT_EQ(distress_csv({found}, {}),
            "speed_rad_s,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N," kFailConvergence "W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,W_d_extrapolated_N,"
            "W_d_error_N," kFoldConvergence kCriteria "failure,method\n"
            "545,,,,,,,,185.25,185,185.5,185.3,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,runaway; fold\n");
  found.fine_fold_load = 195.0;
  found.extrapolated_load = 198.25;
  found.discretization_error = 4.0625;
  found.failure_load = 185.25;
  found.criterion = FailureCriterion::thermo_viscous_distress();
  found.criterion_loads[1] = 300.5;  // oil_peak_temperature
  found.failure = "fails at 185.25 N by thermo-viscous distress";
  EXPECT_EQ(distress_csv({found}, {}),
            "speed_rad_s,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N," kFailConvergence "W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,W_d_extrapolated_N,"
            "W_d_error_N," kFoldConvergence kCriteria "failure,method\n"
            "545,185.25,distress,,,,,,185.25,185,185.5,185.3,195,198.25,4.0625,,,,300.5,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,"
            "fails at 185.25 N by thermo-viscous distress,runaway; fold\n");
}

TEST(DistressTable, QuotesAMethodWithCommas) {
  DistressRow row = distress_row(545.0, {}, 1.0, 1.0, 1.0, std::nullopt, "a, \"b\"");
  EXPECT_EQ(distress_csv({row}, {}),
            "speed_rad_s,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N," kFailConvergence "W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,W_d_extrapolated_N,"
            "W_d_error_N," kFoldConvergence kCriteria "failure,method\n"
            "545,,,,,,,,1,1,1,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,\"a, \"\"b\"\"\"\n");
}

TEST(DistressTable, RefusesNaN) {
  DistressRow bad = distress_row(545.0, {}, std::nan(""), 1.0, 2.0, std::nullopt, "x");
  EXPECT_THROW(distress_csv({bad}, {}), std::runtime_error);
}

TEST(TrajectoryTable, ColumnsInCelsius) {
  TrajectorySample s;
  s.time = 1.5;
  s.state.washer_mean_temperature = 273.15 + 30.0;
  s.state.max_film_temperature = 273.15 + 45.0;
  s.state.hmin_over_sigma = 3.2;
  s.state.contact_share = 0.01;
  s.state.f_eff = 0.03;
  s.state.load = 180.0;
  s.state.speed = 545.0;
  s.state.torque = 0.04;
  s.state.fluid_share = 0.99;
  s.state.heat_generated = 20.0;
  s.state.heat_to_ambient = 19.5;
  EXPECT_EQ(trajectory_csv({s}),
            "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,regime,"
            "heat_generated_W,heat_to_ambient_W\n"
            "1.5,30,45,3.2,0.01,0.03,180,545,0.04,0.99,mixed,20,19.5\n");
  // A duty cycle's columns: the schedule's ambient (in Celsius) and tilt, the least
  // margin, the gear's stop's reaction (empty without the stop).
  s.ambient = 273.15 + 40.0;
  s.tilt = 0.002;
  s.least_margin = 0.25;
  s.least_criterion = LimitKind::oil_peak_temperature;
  const std::string header =
      "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,regime,"
      "heat_generated_W,heat_to_ambient_W,ambient_C,tilt_rad,least_margin,least_margin_criterion,stop_reaction_N\n";
  EXPECT_EQ(trajectory_table({s}, {}, false, true).csv(),
            header + "1.5,30,45,3.2,0.01,0.03,180,545,0.04,0.99,mixed,20,19.5,40,0.002,0.25,oil_peak_temperature,\n");
  s.state.stop_reaction = 0.5;
  EXPECT_EQ(trajectory_table({s}, {}, false, true).csv(),
            header + "1.5,30,45,3.2,0.01,0.03,180,545,0.04,0.99,mixed,20,19.5,40,0.002,0.25,oil_peak_temperature,0.5\n");
  s.state.f_eff = INFINITY;
  EXPECT_THROW(trajectory_csv({s}), std::runtime_error);
}

// A study of several runs (speeds × parameter values, or sliding films) names each row's
// run in columns after the speed; the trajectory puts them last.
TEST(RunColumns, ParameterAndSlidingFilmNameTheRun) {
  SolvedState a;
  a.state.load = 150.0;
  a.state.speed = 545.0;
  a.state.washer_mean_temperature = a.state.max_film_temperature = 273.15 + 24.0;
  a.converged = true;
  a.parameters = {0.2};
  a.sliding = SlidingFilm::washer_gear;
  const std::string states = states_csv({a}, {"friction_coefficient"}, true);
  EXPECT_EQ(states.rfind("load_N,speed_rad_s,friction_coefficient,sliding,T_mean_C,", 0), 0u) << states;
  EXPECT_NE(states.find("\n150,545,0.2,washer_gear,24,24,"), std::string::npos) << states;
  EXPECT_EQ(states_csv({a}).rfind("load_N,speed_rad_s,T_mean_C,", 0), 0u);
  // The branch, the failure criteria passed and the limits close the row: empty for a
  // state no branch was followed to and for one within every limit.
  EXPECT_NE(states.find(",wall_ms,branch,fails_by,limits\n"), std::string::npos) << states;
  EXPECT_EQ(states.back(), '\n');
  EXPECT_EQ(states.substr(states.size() - 4), ",,,\n") << "empty branch, fails_by and limits cells";
  a.branch = Branch::hot;
  a.state.limits = {{LimitKind::oil_temperature, 500.0, 423.15}, {LimitKind::oil_peak_temperature, 900.0, 453.15}};
  const std::string hot = states_csv({a});
  EXPECT_TRUE(hot.ends_with(",hot,oil_temperature;oil_peak_temperature,oil_temperature;oil_peak_temperature\n")) << hot;
  // fails_by keeps the failure criteria only; limits has every limit.
  a.state.limits.push_back({LimitKind::contact_pressure, 3e9, 2.8e9});
  EXPECT_TRUE(states_csv({a}).ends_with(",hot,oil_temperature;oil_peak_temperature,"
                                        "oil_temperature;oil_peak_temperature;contact_pressure\n"));
  // A run without its parameter's value is a bug upstream: an empty cell, never NaN.
  a.parameters.clear();
  EXPECT_NE(states_csv({a}, {"friction_coefficient"}).find("\n150,545,,24,"), std::string::npos);

  TrajectorySample t;
  t.state = a.state;
  t.parameters = {0.05};
  t.sliding = SlidingFilm::carrier_washer;
  const std::string trajectory = trajectory_csv({t}, {"friction_coefficient"}, true);
  EXPECT_EQ(trajectory.substr(0, trajectory.find('\n')),
            "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,regime,"
            "heat_generated_W,heat_to_ambient_W,friction_coefficient,sliding");
  EXPECT_NE(trajectory.find(",0.05,carrier_washer\n"), std::string::npos) << trajectory;

  DistressRow row = distress_row(953.0, {}, 400.0, 399.0, 401.0, 400.5, "runaway", SlidingFilm::washer_gear);
  EXPECT_EQ(distress_csv({row}, {}, true),
            "speed_rad_s,sliding,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N," kFailConvergence "W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,"
            "W_d_extrapolated_N,W_d_error_N," kFoldConvergence kCriteria "failure,method\n"
            "953,washer_gear,,,,,,,,400,399,401,400.5,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,runaway\n");
}

TEST(SlidingTable, OneRowPerConfigurationWithTheChoiceMarked) {
  SlidingRow row;
  row.solved.state.speed = 545.0;
  row.solved.state.load = 200.0;
  row.solved.state.fluid_force = 190.0;
  row.solved.state.fluid_share = 0.95;
  row.solved.state.contact_share = 0.05;
  row.solved.state.torque = 0.02;
  row.solved.state.f_eff = 0.011;
  row.solved.state.hmin_over_sigma = 3.5;
  row.solved.state.washer_mean_temperature = 273.15 + 40.0;
  row.solved.sliding = SlidingFilm::carrier_washer;
  row.film_area = 3.0793e-4;
  row.chosen = true;
  EXPECT_EQ(sliding_csv({row}),
            "speed_rad_s,load_N,sliding,film_area_m2,fluid_force_N,fluid_share,contact_share,torque_Nm,f_eff,"
            "hmin_over_sigma,T_mean_C,chosen\n"
            "545,200,carrier_washer,0.00030793,190,0.95,0.05,0.02,0.011,3.5,40,1\n");
  row.solved.state.torque = NAN;
  EXPECT_THROW(sliding_csv({row}), std::runtime_error);
}

}  // namespace
}  // namespace twb

namespace twb {
namespace {

// The regime is who carries the load (docs/physics.md section 19): the film alone below
// 1 % on the asperities, the asperities almost alone below 10 % on the film.
TEST(TrajectoryTable, TheRegimeIsWhoCarriesTheLoad) {
  BearingState s;
  s.load = 100.0, s.speed = 545.0;
  s.contact_share = 0.009, s.fluid_share = 0.991;
  EXPECT_EQ(regime_of(s), Regime::full_film);
  s.contact_share = 0.011, s.fluid_share = 0.989;
  EXPECT_EQ(regime_of(s), Regime::mixed);
  s.contact_share = 0.89, s.fluid_share = 0.11;
  EXPECT_EQ(regime_of(s), Regime::mixed);
  s.contact_share = 0.91, s.fluid_share = 0.09;
  EXPECT_EQ(regime_of(s), Regime::boundary);
  EXPECT_EQ(regime_name(Regime::boundary), "boundary");
  // Unloaded and standing still, whatever the shares (physics §19); either alone is not.
  s.load = 0.0;
  EXPECT_EQ(regime_of(s), Regime::boundary);
  s.speed = 0.0;
  EXPECT_EQ(regime_of(s), Regime::at_rest);
  EXPECT_EQ(regime_name(Regime::at_rest), "at_rest");
  s.load = 100.0;
  EXPECT_EQ(regime_of(s), Regime::boundary);
}

}  // namespace
}  // namespace twb
