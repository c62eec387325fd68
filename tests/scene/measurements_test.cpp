// A calibration's data file (scene/measurements.h): units converted from the header,
// the results' own column names read, empty fields as quantities not measured, and every
// fault located at its line and column in the file.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../../src/scene/measurements.h"
#include "scene_test_support.h"
#include "twb/input_error.h"

namespace twb {
namespace {

using testing::TempScene;

std::vector<MeasuredPoint> read(const std::string& text) {
  const TempScene file(text, "", ".csv");
  return scene_io::read_measurements(file.path());
}

TEST(Measurements, UnitsFromTheHeader) {
  const std::vector<MeasuredPoint> p =
      read("# a rig\nload [kN], speed [rpm], torque [N mm], T_mean [degC], f_eff []\n0.15, 3000, 121, 94.2, 0.04\n"
           "0.3, 3000, , 101.5, 0.05\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].load, 150.0);
  EXPECT_NEAR(p[0].speed, 3000.0 * 2.0 * M_PI / 60.0, 1e-12);
  EXPECT_NEAR(p[0].values[std::size_t(MeasuredQuantity::torque)], 0.121, 1e-15);
  EXPECT_NEAR(p[0].values[std::size_t(MeasuredQuantity::T_mean)], 94.2 + 273.15, 1e-12);
  EXPECT_DOUBLE_EQ(p[0].values[std::size_t(MeasuredQuantity::f_eff)], 0.04);
  EXPECT_TRUE(std::isnan(p[0].values[std::size_t(MeasuredQuantity::T_max)]));  // no column
  EXPECT_TRUE(std::isnan(p[1].values[std::size_t(MeasuredQuantity::torque)]));  // an empty field
  EXPECT_EQ(p[0].line, 3);
  EXPECT_EQ(p[1].line, 4);
}

// A point's own oil temperature, where the data give one; the scene's (0) where not.
TEST(Measurements, AnAmbientColumn) {
  const std::vector<MeasuredPoint> p = read("load [N], speed [rpm], ambient [degC], torque [N m]\n150, 3000, 80, 0.1\n"
                                            "150, 3000, , 0.1\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].ambient, 353.15, 1e-12);
  EXPECT_EQ(p[1].ambient, 0.0);
}

// A results file is a data file: its columns' names carry their units.
TEST(Measurements, TheResultsOwnColumns) {
  const std::vector<MeasuredPoint> p = read("load_N,speed_rad_s,torque_Nm,T_max_C\n120,545,0.05,40\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].speed, 545.0);
  EXPECT_NEAR(p[0].values[std::size_t(MeasuredQuantity::T_max)], 313.15, 1e-12);
}

// Each reading's own standard deviation: a `<quantity>_sd` column in a unit of its
// quantity's kind, a temperature's a difference (1 degC = 1 K, no offset), f_eff's
// without one; NaN for the quantities without such a column and where a row measures none.
TEST(Measurements, EachReadingsOwnDeviation) {
  const std::vector<MeasuredPoint> p =
      read("load [N], speed [rpm], torque [N m], torque_sd [N mm], T_mean [degC], T_mean_sd [degC], f_eff, f_eff_sd\n"
           "150, 3000, 0.121, 2, 94.2, 1.5, 0.04, 0.002\n"
           "300, 3000, , , 101.5, 0.5, 0.05, 0.001\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].sd[std::size_t(MeasuredQuantity::torque)], 2e-3);
  EXPECT_DOUBLE_EQ(p[0].sd[std::size_t(MeasuredQuantity::T_mean)], 1.5);
  EXPECT_DOUBLE_EQ(p[1].sd[std::size_t(MeasuredQuantity::T_mean)], 0.5);
  EXPECT_DOUBLE_EQ(p[0].sd[std::size_t(MeasuredQuantity::f_eff)], 0.002);
  EXPECT_TRUE(std::isnan(p[1].sd[std::size_t(MeasuredQuantity::torque)]));  // no torque read there
  EXPECT_TRUE(std::isnan(p[0].sd[std::size_t(MeasuredQuantity::T_max)]));   // no column
}

struct Fault {
  const char* text;
  int line, column;
  const char* says;
};

TEST(Measurements, FaultsAreLocated) {
  const Fault faults[] = {
      {"load [N], speed [rpm], wear [um]\n1, 2, 3\n", 1, 24, "the column 'wear' is none a calibration reads"},
      {"load [N], speed, torque [N m]\n1, 2, 3\n", 1, 11, "the column 'speed' gives no unit"},
      {"load [N], speed [rpm], torque [N]\n1, 2, 3\n", 1, 32, "the torque column's unit 'N'"},
      {"load [N], speed [rpm], torque [N m], torque [N mm]\n1, 2, 3, 4\n", 1, 38, "a second torque column"},
      {"speed [rpm], torque [N m]\n2, 3\n", 1, 1, "no load column"},
      {"load [N], speed [rpm]\n1, 2\n", 1, 1, "no measured quantity"},
      {"load [N], speed [rpm], torque [N m]\n1, 2\n", 2, 1, "this row has 2 fields and the header 3 columns: every row needs one field for each column"},
      {"load [N], speed [rpm], torque [N m]\n1, 2, 0.1o\n", 2, 7, "the torque '0.1o' is not a finite number"},
      {"load [N], speed [rpm], torque [N m]\n-1, 2, 0.1\n", 2, 1, "the load '-1' must be positive"},
      {"load [N], speed [rpm], torque [N m]\n1, 2, \n", 2, 1, "the row measures nothing"},
      {"load [N], speed [rpm], T_mean [degC]\n1, 2, -300\n", 2, 7, "the T_mean '-300' must be positive"},
      {"load [N], speed [rpm], torque [N m], T_mean_sd [K]\n1, 2, 3, 1\n", 1, 38, "a T_mean_sd column without a T_mean column"},
      {"load [N], speed [rpm], torque [N m], torque_sd [K]\n1, 2, 3, 1\n", 1, 49, "the torque_sd column's unit 'K'"},
      {"load [N], speed [rpm], torque [N m], torque_sd [N m]\n1, 2, 3, \n", 2, 10, "the torque reading has no standard deviation"},
      {"load [N], speed [rpm], torque [N m], T_mean [K], torque_sd [N m]\n1, 2, , 300, 0.1\n", 2, 14, "a standard deviation for no torque reading"},
      {"load [N], speed [rpm], torque [N m], torque_sd [N m]\n1, 2, 3, 0\n", 2, 10, "the torque_sd '0' must be positive"},
  };
  for (const Fault& f : faults) {
    SCOPED_TRACE(f.text);
    try {
      read(f.text);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), f.line);
      EXPECT_EQ(e.column(), f.column);
      EXPECT_NE(std::string(e.what()).find(f.says), std::string::npos) << e.what();
    }
  }
}

TEST(Measurements, AnEmptyFileOrOneWithoutRowsSaysWhatItNeeds) {
  for (const char* text : {"# nothing\n", "load [N], speed [rpm], torque [N m]\n"}) {
    try {
      read(text);
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("load [N], speed [rpm], torque [N m], T_mean [degC]"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace twb
