// The columns of the CSV files a results directory holds, as twb writes them: made by
// the very functions that write the tables, so that the Python plotting reads the
// names from them (python/twb/plot/columns.json, `twb columns`) instead of a copy.
#pragma once

#include <string>

namespace twb {

// JSON: for each table (states, distress, sliding, fold_curve, trajectory, fields) its
// columns in file order, which of them are counts and which text (the others are
// numbers), and which are optional (only some studies write them: a second parameter,
// the sliding film, error bars); "<parameter>" and "<family>" stand for a study's parameter columns,
// whose names follow (run_parameters, curve_parameters), with the text columns' values
// (sliding_films, branches, failure_criteria, fold_kinds).
std::string result_columns_json();

}  // namespace twb
