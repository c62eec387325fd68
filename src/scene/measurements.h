// A rig's measurements for a calibration study (docs/scenes.md, study type calibration):
// CSV, '#' comment lines, a header naming each column with its unit in brackets, then one
// measured operating point a row:
//   load [N], speed [rpm], torque [N m], T_mean [degC]
//   150, 3000, 0.121, 94.2
// load and speed in every row; torque, f_eff, T_mean, T_max where measured (an empty
// field where a point does not measure one); optionally the oil's ambient temperature at
// each point (`ambient [degC]`; an empty field: the scene's). The results' own column names (load_N,
// speed_rad_s, torque_Nm, T_mean_C, ...) are read too, so a results file is a data file.
#pragma once

#include <string>
#include <vector>

#include "twb/scene/scene.h"

namespace twb::scene_io {

// Reads and checks the file; any fault is an InputError at its line and column in it.
std::vector<MeasuredPoint> read_measurements(const std::string& path);

}  // namespace twb::scene_io
