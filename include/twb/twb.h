// twb's public API in one include (docs/api.md): load a scene, build the bearing, solve
// points or run the scene's study, and write or read the results tables.
#pragma once

#include "twb/bearing.h"
#include "twb/model/bearing_state.h"
#include "twb/model/film_fields.h"
#include "twb/model/unknown_block.h"
#include "twb/results/distress_table.h"
#include "twb/results/fields_table.h"
#include "twb/results/fold_curve_table.h"
#include "twb/results/limit_notes.h"
#include "twb/results/result_table.h"
#include "twb/results/run_timings.h"
#include "twb/results/scene_record.h"
#include "twb/results/sliding_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "twb/scene/input_error.h"
#include "twb/scene/scene.h"
#include "twb/scene/scene_loader.h"
#include "twb/solver_failure.h"
#include "twb/study/study_outcome.h"
#include "twb/version.h"
