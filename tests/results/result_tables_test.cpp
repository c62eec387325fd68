// distress.csv and trajectory.csv: the columns, empty cells for values that do
// not exist, and no NaN ever written.
#include <gtest/gtest.h>

#include <cmath>

#include "twb/results/distress_table.h"
#include "twb/results/trajectory_table.h"

namespace twb {
namespace {

TEST(DistressTable, ColumnsWithAndWithoutSecondParameter) {
  DistressRow found{545.0, 0.1, 185.25, 185.0, 185.5, 185.3, "runaway; fold"};
  DistressRow none{136.0, 0.2, std::nullopt, std::nullopt, std::nullopt, std::nullopt, "not reached below 2000 N"};
  EXPECT_EQ(distress_csv({found, none}, "friction_coefficient"),
            "speed_rad_s,friction_coefficient,W_d_N,bracket_low_N,bracket_high_N,fold_N,method\n"
            "545,0.1,185.25,185,185.5,185.3,runaway; fold\n"
            "136,0.2,,,,,not reached below 2000 N\n");
  found.parameter.reset();
  EXPECT_EQ(distress_csv({found}, ""),
            "speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method\n"
            "545,185.25,185,185.5,185.3,runaway; fold\n");
}

TEST(DistressTable, QuotesAMethodWithCommas) {
  DistressRow row{545.0, std::nullopt, 1.0, 1.0, 1.0, std::nullopt, "a, \"b\""};
  EXPECT_EQ(distress_csv({row}, ""), "speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method\n"
                                     "545,1,1,1,,\"a, \"\"b\"\"\"\n");
}

TEST(DistressTable, RefusesNaN) {
  DistressRow bad{545.0, std::nullopt, std::nan(""), 1.0, 2.0, std::nullopt, "x"};
  EXPECT_THROW(distress_csv({bad}, ""), std::runtime_error);
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
  EXPECT_EQ(trajectory_csv({s}),
            "t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N\n"
            "1.5,30,45,3.2,0.01,0.03,180\n");
  s.state.f_eff = INFINITY;
  EXPECT_THROW(trajectory_csv({s}), std::runtime_error);
}

}  // namespace
}  // namespace twb
