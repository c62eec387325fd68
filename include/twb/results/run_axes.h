// The axes that tell a study's runs apart besides the speed (a map's or sweep's
// parameters, a grid's every axis): one column each in the results, named by the
// study (e.g. friction_coefficient, geometry.gear.tilt_rad), and a run's values in the
// same order, SI.
#pragma once

#include <string>
#include <vector>

namespace twb {

// ", friction_coefficient = 0.1, geometry.gear.tilt_rad = 0.001" for a run's values (as
// progress lines and summaries name a run); "parameter" names a column not given.
std::string run_axes_text(const std::vector<std::string>& columns, const std::vector<double>& values);

// A speed given in rad/s as the scene gave its speeds: "4000 rpm" where it gave them in
// rpm (Study::speeds_in_rpm), else "418.879 rad/s"; six significant digits.
std::string speed_text(double rad_per_s, bool in_rpm);

}  // namespace twb
