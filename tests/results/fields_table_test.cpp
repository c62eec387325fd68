// fields/state_NNNN.csv (fields_table.h): the documented columns, temperatures in °C,
// one row per node and film, no NaN ever; written for exactly the states that carry
// fields, and stale files of an earlier run removed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "../support/test_files.h"
#include "twb/results/fields_table.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

FilmFields small_film(int number, bool sliding) {
  FilmFields f{number, sliding, FilmMesh(0.005, 0.011, 2, 3), {}, {}, {}, {}, {}, {}, {}};
  for (int k = 0; k < 6; ++k) {
    f.gap.push_back(1e-6 * (k + 1));
    f.pressure.push_back(sliding ? 1000.0 * k : 0.0);
    f.contact_pressure.push_back(k == 0 ? 2.5e7 : 0.0);
    f.film_temperature.push_back(273.15 + 40.0 + k);
    f.surface_temperature.push_back(273.15 + 30.0);
    f.viscosity.push_back(0.03);
  }
  return f;
}

using testing::file_text;

TEST(FieldsTable, ColumnsAndOneRowPerNodeAndFilm) {
  const std::string csv = fields_csv({small_film(1, true), small_film(2, false)});
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s");
  std::getline(in, line);
  EXPECT_EQ(line, "1,1,0.005,0,1e-06,0,25000000,40,30,0.03");
  std::getline(in, line);  // node (0, 1): θ = 2π/3
  EXPECT_EQ(line.rfind("1,1,0.005,2.094395102,2e-06,1000,0,41,30,0.03", 0), 0u) << line;
  int rows = 2;
  std::string last;
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 12);
  EXPECT_EQ(last.rfind("2,0,0.011,4.18879", 0), 0u) << last;
}

// The elastic washer's deflection is a column only where a film has it (physics §21).
TEST(FieldsTable, TheWashersDeflectionOnlyWhereItBends) {
  FilmFields bent = small_film(1, true);
  bent.washer_deflection.assign(6, 2.5e-6);
  const std::string csv = fields_csv({bent, small_film(2, false)});
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s,"
                  "washer_deflection_m");
  std::getline(in, line);
  EXPECT_EQ(line, "1,1,0.005,0,1e-06,0,25000000,40,30,0.03,2.5e-06");
}

TEST(FieldsTable, RefusesNaN) {
  FilmFields f = small_film(1, true);
  f.pressure[3] = std::nan("");
  EXPECT_THROW(fields_csv({f}), std::runtime_error);
}

TEST(FieldsTable, NamesFollowTheStatesRow) {
  EXPECT_EQ(fields_file_name(1), "state_0001.csv");
  EXPECT_EQ(fields_file_name(35), "state_0035.csv");
  EXPECT_EQ(fields_file_name(12345), "state_12345.csv");
}

TEST(FieldsTable, WritesStatesWithFieldsAndRemovesStaleOnes) {
  const fs::path dir = fs::temp_directory_path() / ("twb_fields_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  std::vector<SolvedState> rows(3);
  for (SolvedState& r : rows) r.fields = {small_film(1, true), small_film(2, false)};
  EXPECT_EQ(write_state_fields(dir, rows), 3u);
  for (const char* name : {"state_0001.csv", "state_0002.csv", "state_0003.csv"})
    EXPECT_EQ(file_text(dir / "fields" / name), fields_csv(rows[0].fields)) << name;
  std::ofstream(dir / "fields" / "notes.txt") << "mine";

  // A later run into the same directory with one state: the others would not match
  // its states.csv.
  rows.resize(1);
  EXPECT_EQ(write_state_fields(dir, rows), 1u);
  EXPECT_TRUE(fs::exists(dir / "fields" / "state_0001.csv"));
  EXPECT_FALSE(fs::exists(dir / "fields" / "state_0002.csv"));
  EXPECT_FALSE(fs::exists(dir / "fields" / "state_0003.csv"));
  EXPECT_TRUE(fs::exists(dir / "fields" / "notes.txt")) << "files twb does not write stay";

  // Without fields nothing is written, and the directory goes once it is empty.
  rows[0].fields.clear();
  EXPECT_EQ(write_state_fields(dir, rows), 0u);
  EXPECT_FALSE(fs::exists(dir / "fields" / "state_0001.csv"));
  fs::remove(dir / "fields" / "notes.txt");
  EXPECT_EQ(write_state_fields(dir, rows), 0u);
  EXPECT_FALSE(fs::exists(dir / "fields"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace twb
