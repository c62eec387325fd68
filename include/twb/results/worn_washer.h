// A worn washer's files (twb/scene/worn_washer.h): worn_washer.json, the washer a life
// study ends with, which a run goes on from (twb run --continue-from DIR), and
// worn_profile.csv, the washer at every reported time of the life.
#pragma once

#include <string>
#include <vector>

#include "twb/results/result_table.h"
#include "twb/scene/worn_washer.h"

namespace twb {

std::string worn_washer_json(const WornWasher& worn);
// std::invalid_argument naming `path` and what is wrong (not there, not JSON, a field
// missing, of the wrong kind or size, a depth that is not a finite number).
WornWasher read_worn_washer(const std::string& path);
// The same from the file's text; `where` names it in errors.
WornWasher worn_washer_of(const std::string& json, const std::string& where);

// worn_profile.csv: the depths at every reported time, one row per node of the sliding
// film (radius outer loop, angle inner), with each face's Rq there:
//   t_h, r_m, theta_rad, worn_rest_um, worn_turn_um, rq_rest_um, rq_turn_um
ResultTable worn_profile_table(const std::vector<WornWasher>& along_life);

}  // namespace twb
