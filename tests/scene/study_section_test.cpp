// The study section every shipped scene is written back with, word for word.
//
// Why exact text: run.json keeps the resolved scene, and a run resumed from its journal
// compares the scene it is given with the one the journal was written for as text. A
// change of key order or number format in the writer would make every unfinished run
// unresumable and every run.json differ, although the scene means the same (the round
// trip in scene_loader_test only checks that what is written reads back the same). The
// expected sections were written by the writer before study types got their own files;
// to change one on purpose, set TWB_WRITE_STUDY_SECTIONS=1, run this test and review the
// diff of tests/scene/data/study_sections.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_names.h"
#include "scene/studies/study_section.h"
#include "scene_test_support.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

namespace fs = std::filesystem;
using testing::source_path;

// The scenes under configs/ that run a study (a washer file without one is only a base).
std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(source_path("configs"))) {
    if (e.path().extension() != ".yaml") continue;
    std::ifstream in(e.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("\nstudy:") != std::string::npos || text.starts_with("study:")) scenes.push_back(e.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

// From "study:" to the next top-level key, with the source tree's place (a calibration's
// data file is written as an absolute path) spelt "<source>".
std::string study_section(const std::string& described) {
  const std::size_t begin = described.find("\nstudy:\n");
  const std::size_t end = described.find("\noutput:\n", begin);
  std::string section = described.substr(begin + 1, end - begin);
  const std::string root = fs::path(TWB_SOURCE_DIR).lexically_normal().string();
  for (std::size_t at = section.find(root); at != std::string::npos; at = section.find(root, at))
    section.replace(at, root.size(), "<source>");
  return section;
}

fs::path expected_path(const fs::path& scene) {
  std::string name = fs::relative(scene, source_path("configs")).replace_extension(".txt").string();
  std::replace(name.begin(), name.end(), '/', '.');
  return fs::path(source_path("tests/scene/data/study_sections")) / name;
}

TEST(StudySection, ShippedScenesAreWrittenBackAsBefore) {
  const std::vector<fs::path> scenes = shipped_scenes();
  ASSERT_GE(scenes.size(), 30u);  // every study type is among them (checked below)
  const bool write = std::getenv("TWB_WRITE_STUDY_SECTIONS") != nullptr;
  std::set<StudyType> types;
  for (const fs::path& scene : scenes) {
    SCOPED_TRACE(scene.string());
    const Scene loaded = load_scene(scene.string());
    types.insert(loaded.study.type());
    const std::string section = study_section(describe_scene(loaded));
    const fs::path expected_file = expected_path(scene);
    if (write) {
      fs::create_directories(expected_file.parent_path());
      std::ofstream(expected_file) << section;
      continue;
    }
    std::ifstream in(expected_file);
    ASSERT_TRUE(in) << "no expected section " << expected_file;
    std::stringstream expected;
    expected << in.rdbuf();
    EXPECT_EQ(section, expected.str());
  }
  EXPECT_EQ(types.size(), 11u);  // point, load_sweep, ..., duty_cycle, life: each type's writer is checked
}


// The study map admits kStudyKeys before its type is known: every key a type reads must
// be among them (else the map refuses it as unknown before the type's own check), and
// every one of them some type's.
TEST(StudySection, StudyKeysAreTheTypesKeys) {
  std::set<std::string_view> of_types;
  for (const StudyType type : scene_io::kStudyTypes.values)
    for (const std::string_view key : scene_io::study_section(type).keys) {
      EXPECT_NE(std::find(std::begin(scene_io::kStudyKeys), std::end(scene_io::kStudyKeys), key),
                std::end(scene_io::kStudyKeys))
          << key << " of type " << scene_io::kStudyTypes.name(type);
      of_types.insert(key);
    }
  for (const std::string_view key : scene_io::kStudyKeys) EXPECT_TRUE(of_types.count(key)) << key;
}

// The writer's choices no shipped scene makes, each with the section it must write.
struct SectionCase {
  const char* name;
  const char* study;     // the scene's study line
  const char* expected;  // its study section written back
};
void PrintTo(const SectionCase& c, std::ostream* os) { *os << c.name; }

class StudySectionOf : public ::testing::TestWithParam<SectionCase> {};

TEST_P(StudySectionOf, ChoiceIsWrittenBackAsBefore) {
  const testing::TempScene scene(std::string(testing::kMinimalScene) + GetParam().study);
  EXPECT_EQ(study_section(describe_scene(load_scene(scene.path()))), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Choices, StudySectionOf,
    ::testing::Values(
        SectionCase{"point_without_an_error_bar", "study: {type: point, error_estimate: none}\n",
                    "study:\n  type: point\n  error_estimate: none\n"},
        SectionCase{"point_to_a_tolerance", "study: {type: point, tolerance: 2 %}\n",
                    "study:\n  type: point\n  tolerance: 0.02\n"},
        SectionCase{"distress_map_to_its_end_without_a_tolerance",
                    "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                    "        tolerance: none, search_past_failure: none}\n",
                    "study:\n  type: distress_map\n  load_start: 50 N\n  load_end: 1000 N\n  speeds: [545 rad/s]\n"
                    "  bracket_width: 0.002\n  error_estimate: richardson\n  tolerance: none\n  search_past_failure: none\n"},
        SectionCase{"distress_map_every_state",
                    "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                    "        error_estimate: every_state}\n",
                    "study:\n  type: distress_map\n  load_start: 50 N\n  load_end: 1000 N\n  speeds: [545 rad/s]\n"
                    "  bracket_width: 0.002\n  error_estimate: every_state\n  tolerance: 0.01\n  search_past_failure: 2\n"},
        SectionCase{"sensitivity_at_the_point",
                    "study: {type: sensitivity, parameters: [geometry.gear.tilt, surfaces.washer.Rq]}\n",
                    "study:\n  type: sensitivity\n  bracket_width: 0.002\n  parameters: [geometry.gear.tilt, surfaces.washer.Rq]\n"},
        SectionCase{"sensitivity_with_a_load_range",
                    "study: {type: sensitivity, load_start: 100 N, load_end: 400 N, bracket_width: 0.001}\n",
                    "study:\n  type: sensitivity\n  load_start: 100 N\n  load_end: 400 N\n  bracket_width: 0.001\n"},
        SectionCase{"distress_curve_family",
                    "study: {type: distress_curve, parameter: gear_tilt, from: 1 mrad, to: 3 mrad,\n"
                    "        load_start: 100 N, load_end: 2000 N, error_estimate: none,\n"
                    "        family: {name: roughness, values: [0.3 um, 0.5 um]}}\n",
                    "study:\n  type: distress_curve\n  load_start: 100 N\n  load_end: 2000 N\n  error_estimate: none\n"
                    "  parameter: gear_tilt\n  from: 0.001 rad\n  to: 0.003 rad\n  bracket_width: 0.002\n  family:\n"
                    "    name: roughness\n    values: [3e-07 m, 5e-07 m]\n"}));

}  // namespace
}  // namespace twb
