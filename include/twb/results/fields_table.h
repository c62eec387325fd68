// fields/state_NNNN.csv: the fields of one solved state on the films' polar grids
// (output.fields; docs/scenes.md), NNNN its 1-based row in states.csv.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "twb/results/states_table.h"
#include "twb/results/result_table.h"

namespace twb {

// The table a fields file is written from (result_table.h).
ResultTable fields_table(const std::vector<FilmFields>& films);

// One row per node, film 1 then film 2, radius outer loop and angle inner loop:
// film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s
std::string fields_csv(const std::vector<FilmFields>& films);

// The file name of state `row` (1-based): "state_0007.csv".
std::string fields_file_name(std::size_t row);

// Writes DIR/fields/state_NNNN.csv, atomically, for every state that carries fields,
// and removes the state_*.csv files an earlier run left there that this one did not
// write (they would belong to another states.csv); the directory goes when empty.
// Returns how many files were written.
std::size_t write_state_fields(const std::filesystem::path& dir, const std::vector<SolvedState>& rows,
                               int significant_digits = 10);

}  // namespace twb
