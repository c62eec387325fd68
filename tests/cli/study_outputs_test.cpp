// `twb run` on the shipped study scenes (coarsened to 5×24 nodes so they run in
// seconds): each writes the files the issue names, with the columns, and
// exits 0 (a distress found is a result, not a failure).
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace twb {
namespace {

namespace fs = std::filesystem;

int run_twb(const std::string& scene, const std::string& out, const std::string& extra) {
  const std::string command = std::string("'") + TWB_BINARY + "' run '" + TWB_SOURCE_DIR + "/configs/studies/" +
                              scene + "' --out '" + out + "' -q --set mesh.radial_nodes=5 " +
                              "--set mesh.circumferential_nodes=24 " + extra + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("twb_study_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(StudyOutputs, DistressMapWritesOneRowPerSpeed) {
  const fs::path dir = scratch("map");
  ASSERT_EQ(run_twb("distress_map.yaml", dir, "--set 'study.speeds=[136 rad/s, 545 rad/s]' --set study.load_end='600 N'"), 0);
  const auto rows = lines_of(dir / "distress.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0],
            "speed_rad_s,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N,W_fail_meshes,W_fail_order,"
            "W_fail_tolerance_met,W_d_N,bracket_low_N,bracket_high_N,"
            "fold_N,W_d_fine_N,W_d_extrapolated_N,W_d_error_N,W_d_meshes,W_d_order,W_oil_temperature_N,W_oil_peak_temperature_N,"
            "W_material_temperature_carrier_N,W_material_temperature_washer_N,W_material_temperature_gear_N,"
            "W_film_ratio_N,W_pv_N,W_scuffing_N,W_modulus_data_carrier_N,W_modulus_data_washer_N,W_modulus_data_gear_N,"
            "W_oil_temperature_error_N,W_oil_peak_temperature_error_N,"
            "W_material_temperature_carrier_error_N,W_material_temperature_washer_error_N,"
            "W_material_temperature_gear_error_N,W_film_ratio_error_N,W_pv_error_N,W_scuffing_error_N,"
            "W_modulus_data_carrier_error_N,W_modulus_data_washer_error_N,W_modulus_data_gear_error_N,"
            "W_oil_temperature_extrapolated_N,"
            "W_oil_peak_temperature_extrapolated_N,W_material_temperature_carrier_extrapolated_N,"
            "W_material_temperature_washer_extrapolated_N,W_material_temperature_gear_extrapolated_N,"
            "W_film_ratio_extrapolated_N,W_pv_extrapolated_N,W_scuffing_extrapolated_N,"
            "W_modulus_data_carrier_extrapolated_N,W_modulus_data_washer_extrapolated_N,"
            "W_modulus_data_gear_extrapolated_N,failure,method");
  EXPECT_EQ(rows[1].rfind("136,", 0), 0u);
  EXPECT_EQ(rows[2].rfind("545,", 0), 0u);
  EXPECT_EQ(rows[2].find("nan"), std::string::npos);
  // The error bar is on by default: at 545 rad/s the failure load, its criterion, its
  // error bar and every number of W_d up to its error bar are there (the first twelve
  // cells), and W_d fails first.
  std::size_t at = 0;
  for (int cell = 0; cell < 12; ++cell) {
    const std::size_t comma = rows[2].find(',', at);
    ASSERT_NE(comma, std::string::npos) << rows[2];
    EXPECT_GT(comma, at) << "cell " << cell << " is empty: " << rows[2];
    at = comma + 1;
  }
  EXPECT_NE(rows[2].find(",distress,"), std::string::npos) << rows[2];
  EXPECT_TRUE(fs::exists(dir / "states.csv"));
  fs::remove_all(dir);
}

TEST(StudyOutputs, TransientWritesTheTrajectory) {
  const fs::path dir = scratch("transient");
  ASSERT_EQ(run_twb("transient_step_545.yaml", dir, ""), 0);
  const auto rows = lines_of(dir / "trajectory.csv");
  ASSERT_GT(rows.size(), 10u);
  EXPECT_EQ(rows[0], "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,regime,heat_generated_W,heat_to_ambient_W");
  EXPECT_EQ(rows[1].rfind("0,", 0), 0u);  // starts at the step
  EXPECT_EQ(lines_of(dir / "states.csv").size(), 3u);  // before and after the step
  fs::remove_all(dir);
}

TEST(StudyOutputs, LoadSweepWritesStatesDistressAndTheRunaway) {
  const fs::path dir = scratch("sweep");
  ASSERT_EQ(run_twb("load_sweep_545.yaml", dir, "--set study.load_steps=4"), 0);
  EXPECT_GE(lines_of(dir / "states.csv").size(), 5u);
  const auto distress = lines_of(dir / "distress.csv");
  ASSERT_EQ(distress.size(), 2u);
  EXPECT_NE(distress[1].find("fold at"), std::string::npos) << distress[1];
  EXPECT_GT(lines_of(dir / "trajectory.csv").size(), 10u);
  fs::remove_all(dir);
}

// The rows of a fold_curve.csv that mark a cusp.
long cusp_rows(const std::vector<std::string>& rows) {
  return std::count_if(rows.begin(), rows.end(), [](const std::string& r) { return r.find(",cusp,") != std::string::npos; });
}

// The distress curve on its shipped scene, and the safe region in one command
// (scripts/safe_region.sh runs twb and draws the figure): a cusp per family member, the
// curve's file, the figure.
TEST(StudyOutputs, DistressCurveAndSafeRegionInOneCommand) {
  const fs::path dir = scratch("curve");
  // (the single refinement's bars: the tolerance's sequence to 33 x 264 would cost 30 s
  // here, and distress_curve_test.cpp checks it on the coarse mesh)
  ASSERT_EQ(run_twb("distress_curve.yaml", dir, "--set study.load_end='1000 N' --set study.tolerance=none"), 0);
  const auto rows = lines_of(dir / "fold_curve.csv");
  ASSERT_GT(rows.size(), 5u);
  EXPECT_EQ(rows[0],
            "speed_rad_s,W_fold_N,fold,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,W_fold_fine_N,"
            "W_fold_extrapolated_N,W_fold_error_N,W_fold_meshes,W_fold_order,W_fold_tolerance_met");
  EXPECT_EQ(cusp_rows(rows), 1);
  fs::remove_all(dir);

  const fs::path region = scratch("region");
  const std::string command = std::string("'") + TWB_SOURCE_DIR + "/scripts/safe_region.sh' --twb '" + TWB_BINARY +
                              "' --out '" + region.string() + "' --set mesh.radial_nodes=5 --set " +
                              "mesh.circumferential_nodes=24 --set 'study.family.values=[0.1, 0.3]' " +
                              "--set study.load_end='1000 N' --set study.error_estimate=none >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  const auto curve = lines_of(region / "fold_curve.csv");
  ASSERT_FALSE(curve.empty());
  EXPECT_EQ(curve[0].rfind("friction_coefficient,speed_rad_s,", 0), 0u) << curve[0];
  EXPECT_EQ(cusp_rows(curve), 2);
  EXPECT_TRUE(fs::exists(region / "figures" / "fold_curve.png"));
  fs::remove_all(region);
}

std::string header(const fs::path& p) {
  const auto rows = lines_of(p);
  return rows.empty() ? std::string() : rows.front();
}

// A shipped load-grid scene cut to 100, 200 and 300 N at the given speeds.
int run_cut(const std::string& scene, const fs::path& dir, const std::string& speeds) {
  return run_twb(scene, dir, "--set 'study.speeds=[" + speeds + "]' --set study.load_end='300 N' --set study.load_steps=3");
}

// The paper's four load sweeps, cut to 100-300 N at two speeds: every state names its
// speed, one distress row per speed, the runaway's trajectory names its speed.
TEST(StudyOutputs, PaperLoadSweepsWriteEverySpeed) {
  const fs::path dir = scratch("paper_sweeps");
  ASSERT_EQ(run_cut("paper_load_sweeps.yaml", dir, "136 rad/s, 545 rad/s"), 0);
  const auto states = lines_of(dir / "states.csv");
  EXPECT_EQ(states[0].rfind("load_N,speed_rad_s,T_mean_C,", 0), 0u) << states[0];
  EXPECT_TRUE(std::any_of(states.begin(), states.end(), [](const std::string& r) { return r.rfind("300,136,", 0) == 0; }));
  EXPECT_TRUE(std::any_of(states.begin(), states.end(), [](const std::string& r) { return r.rfind("300,545,", 0) == 0; }));
  const auto distress = lines_of(dir / "distress.csv");
  ASSERT_EQ(distress.size(), 3u);
  EXPECT_EQ(distress[1].rfind("136,", 0), 0u);
  EXPECT_EQ(distress[2].rfind("545,", 0), 0u);
  EXPECT_EQ(header(dir / "trajectory.csv"), "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,regime,heat_generated_W,heat_to_ambient_W");
  fs::remove_all(dir);
}

// Fig. 15's scene at one speed: states, distress rows and trajectory carry the
// coefficient.
TEST(StudyOutputs, FrictionCoefficientSweepNamesTheCoefficient) {
  const fs::path dir = scratch("friction");
  ASSERT_EQ(run_cut("friction_coefficient.yaml", dir, "136 rad/s"), 0);
  EXPECT_EQ(header(dir / "states.csv").rfind("load_N,speed_rad_s,friction_coefficient,T_mean_C,", 0), 0u);
  const auto distress = lines_of(dir / "distress.csv");
  ASSERT_EQ(distress.size(), 4u);  // three coefficients
  EXPECT_EQ(distress[0].rfind("speed_rad_s,friction_coefficient,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N,W_fail_meshes,", 0), 0u);
  EXPECT_EQ(distress[1].rfind("136,0.05,", 0), 0u);
  EXPECT_EQ(distress[3].rfind("136,0.2,", 0), 0u);
  for (const std::string& row : lines_of(dir / "states.csv")) EXPECT_EQ(row.find("nan"), std::string::npos);
  fs::remove_all(dir);
}

// The sliding comparison: sliding.csv has both configurations at every load, one of
// them chosen; states.csv the chosen one, with its sliding film.
TEST(StudyOutputs, SlidingChoiceWritesBothConfigurations) {
  const fs::path dir = scratch("sliding");
  ASSERT_EQ(run_cut("sliding_choice.yaml", dir, "545 rad/s"), 0);
  const auto sliding = lines_of(dir / "sliding.csv");
  ASSERT_EQ(sliding.size(), 7u);
  EXPECT_EQ(sliding[0],
            "speed_rad_s,load_N,sliding,film_area_m2,fluid_force_N,fluid_share,contact_share,torque_Nm,f_eff,"
            "hmin_over_sigma,T_mean_C,chosen");
  EXPECT_EQ(sliding[1].rfind("545,100,carrier_washer,", 0), 0u);
  EXPECT_EQ(sliding[2].rfind("545,100,washer_gear,", 0), 0u);
  const auto states = lines_of(dir / "states.csv");
  ASSERT_EQ(states.size(), 4u);
  EXPECT_EQ(states[0].rfind("load_N,speed_rad_s,sliding,T_mean_C,", 0), 0u);
  const auto distress = lines_of(dir / "distress.csv");
  ASSERT_EQ(distress.size(), 3u);
  EXPECT_EQ(distress[1].rfind("545,carrier_washer,", 0), 0u);
  EXPECT_EQ(distress[2].rfind("545,washer_gear,", 0), 0u);
  fs::remove_all(dir);
}

// Without the thermal effect there is no transient: the sweep still runs, and says
// there is no thermo-viscous distress rather than failing.
TEST(StudyOutputs, IsothermalLoadSweepRunsWithoutTransient) {
  const fs::path dir = scratch("isothermal");
  ASSERT_EQ(run_twb("load_sweep_545.yaml", dir, "--set 'effects=[hydrodynamics, flow_factors, asperity_contact]'"), 0);
  const auto distress = lines_of(dir / "distress.csv");
  ASSERT_EQ(distress.size(), 2u);
  EXPECT_NE(distress[1].find("no thermal effect"), std::string::npos) << distress[1];
  EXPECT_FALSE(fs::exists(dir / "trajectory.csv"));
  fs::remove_all(dir);
}

// output.fields: a point study writes fields/state_0001.csv with the documented columns,
// one row per node of both films (2 × 5 × 24); without it there is no fields directory.
TEST(StudyOutputs, PointStudyWritesFieldsOnRequest) {
  const fs::path dir = scratch("fields");
  const std::string point = "--set 'study={type: point}' --set operating.load='150 N' ";
  ASSERT_EQ(run_twb("../jackson_green_2006.yaml", dir, point + "--set output.fields=true"), 0);
  const auto rows = lines_of(dir / "fields" / "state_0001.csv");
  ASSERT_EQ(rows.size(), 241u);
  EXPECT_EQ(rows[0], "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s");
  EXPECT_EQ(rows[1].rfind("1,1,0.00555,0,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[240].rfind("2,0,0.01135,", 0), 0u) << rows[240];
  for (const std::string& row : rows) EXPECT_EQ(row.find("nan"), std::string::npos) << row;
  EXPECT_FALSE(fs::exists(dir / "fields" / "state_0002.csv"));

  ASSERT_EQ(run_twb("../jackson_green_2006.yaml", dir, point), 0);
  EXPECT_FALSE(fs::exists(dir / "fields")) << "a run without fields leaves none of an earlier run";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace twb
