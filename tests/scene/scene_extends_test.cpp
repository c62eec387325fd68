// Scenes that extend scenes (docs/scenes.md): the base's keys under the file's, maps
// merged key by key, lists and scalars replaced, `!replace` maps standing alone, every
// error and every value traced to the file and line that wrote it.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "scene_test_support.h"

namespace twb {
namespace {

namespace fs = std::filesystem;
using testing::load_error;
using testing::source_path;

// A directory of scene files written by the test, removed with it.
class SceneDir {
 public:
  SceneDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("twb_extends_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "studies");
  }
  ~SceneDir() { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

// The body of a described scene (its header names the source file).
std::string body(const Scene& s) {
  const std::string d = describe_scene(s);
  return d.substr(d.find("\neffects:"));
}

const std::string kPaper = "configs/jackson_green_2006.yaml";

TEST(SceneExtends, AFileOfOneValueIsTheBaseWithThatValue) {
  SceneDir dir;
  std::ifstream in(source_path(kPaper));
  const std::string base = dir.write("paper.yaml", std::string(std::istreambuf_iterator<char>(in), {}));
  const std::string derived = dir.write("studies/heavy.yaml", "extends: ../paper.yaml\noperating: {load: 800 N}\n");
  EXPECT_EQ(body(load_scene(derived)), body(load_scene(base, {"operating.load=800 N"})));
}

TEST(SceneExtends, MapsMergeListsAndScalarsReplace) {
  SceneDir dir;
  dir.write("base.yaml", std::string(testing::kSceneBodies) +
                             "operating: {load: 500 N, speed: 545 rad/s, ambient: 30 degC}\n"
                             "study: {type: distress_map, speeds: [136 rad/s, 545 rad/s], load_start: 100 N, load_end: 1 kN}\n");
  const std::string derived = dir.write(
      "derived.yaml",
      "extends: base.yaml\n"
      "effects: [hydrodynamics, asperity_contact, thermal]\n"  // a list: replaced
      "operating: {speed: 953 rad/s}\n"                        // a map: merged
      "study: {speeds: [1367 rad/s]}\n"                        // a list in a merged map: replaced
      "geometry: {gear: {tilt: 1 mrad}}\n");                   // two levels down
  const Scene s = load_scene(derived);
  EXPECT_TRUE(s.effects.thermal);
  EXPECT_EQ(s.operating.speed, 953.0);
  EXPECT_EQ(s.operating.load, 500.0);
  EXPECT_NEAR(s.operating.ambient, 303.15, 1e-12);
  ASSERT_EQ(s.study.type(), StudyType::distress_map);
  const DistressMapSettings& map = std::get<DistressMapSettings>(s.study.settings);
  EXPECT_EQ(map.speeds, std::vector<double>{1367.0});
  EXPECT_EQ(map.search.loads.end, 1000.0);
  EXPECT_NEAR(s.gear.tilt, 1e-3, 1e-18);
  EXPECT_NEAR(s.gear.outer_radius, 22.7e-3 / 2, 1e-15);  // the gear's other keys stay
}

TEST(SceneExtends, ReplaceTagDropsTheBasesKeys) {
  SceneDir dir;
  dir.write("base.yaml", std::string(testing::kSceneBodies) +
                             "operating: {load: 500 N, speed: 545 rad/s}\n"
                             "study: {type: load_sweep, load_start: 100 N, load_end: 400 N, load_steps: 4}\n");
  // Merged, the base's sweep keys would not apply to a point study (located in the base).
  const std::string merged = dir.write("merged.yaml", "extends: base.yaml\nstudy: {type: point}\n");
  const InputError e = load_error(merged);
  EXPECT_NE(e.message().find("does not apply with type: point"), std::string::npos) << e.what();
  EXPECT_EQ(fs::path(e.file()).filename(), "base.yaml");
  const std::string replaced = dir.write("replaced.yaml", "extends: base.yaml\nstudy: !replace {type: point}\n");
  EXPECT_EQ(load_scene(replaced).study.type(), StudyType::point);
}

TEST(SceneExtends, ErrorsPointIntoTheFileThatWroteTheValue) {
  SceneDir dir;
  const std::string base = dir.write("base.yaml", std::string(testing::kSceneBodies) +
                                                      "operating: {load: 500 N, speed: 545 rad/s}\n"
                                                      "mesh: {radial_nodes: 2}\n");  // line 7: illegal
  const std::string derived = dir.write("studies/derived.yaml", "extends: ../base.yaml\n\noperating: {load: -5 N}\n");
  const InputError e = load_error(derived);
  // The first error the reader meets: the derived file's load (operating before mesh).
  EXPECT_EQ(e.file(), derived);
  EXPECT_EQ(e.line(), 3);
  const std::string fine = dir.write("studies/fine.yaml", "extends: ../base.yaml\n");
  const InputError b = load_error(fine);
  EXPECT_EQ(fs::path(b.file()), fs::path(base));
  EXPECT_EQ(b.line(), 7);
  EXPECT_NE(b.message().find("mesh.radial_nodes"), std::string::npos) << b.what();
  // An unknown key of a base merged under the file's map is still located in the base.
  dir.write("typo.yaml", std::string(testing::kSceneBodies) + "operating: {load: 500 N, speed: 545 rad/s, sped: 1}\n");
  const InputError t = load_error(dir.write("over_typo.yaml", "extends: typo.yaml\noperating: {load: 600 N}\n"));
  EXPECT_EQ(fs::path(t.file()), fs::path(dir.path("typo.yaml")));
  EXPECT_EQ(t.line(), 6);
}

TEST(SceneExtends, DuplicateKeysOfTheFileAreStillRefused) {
  SceneDir dir;
  dir.write("base.yaml", std::string(testing::kSceneBodies) + "operating: {load: 500 N, speed: 545 rad/s}\n");
  const std::string derived = dir.write("d.yaml", "extends: base.yaml\noperating:\n  load: 600 N\n  load: 700 N\n");
  const InputError e = load_error(derived);
  EXPECT_EQ(e.file(), derived);
  EXPECT_NE(e.message().find("'load'"), std::string::npos) << e.what();
}

TEST(SceneExtends, ChainsResolveAndCyclesAndMissingBasesAreLocated) {
  SceneDir dir;
  dir.write("a.yaml", std::string(testing::kSceneBodies) + "operating: {load: 500 N, speed: 545 rad/s}\n");
  dir.write("b.yaml", "extends: a.yaml\noperating: {speed: 953 rad/s}\n");
  const Scene c = load_scene(dir.write("c.yaml", "extends: b.yaml\noperating: {load: 700 N}\n"));
  EXPECT_EQ(c.operating.speed, 953.0);
  EXPECT_EQ(c.operating.load, 700.0);

  dir.write("x.yaml", "extends: y.yaml\n");
  const std::string y = dir.write("y.yaml", "extends: x.yaml\n");
  const InputError cycle = load_error(y);
  EXPECT_NE(cycle.message().find("extends"), std::string::npos) << cycle.what();
  EXPECT_EQ(cycle.line(), 1);

  const std::string missing = dir.write("m.yaml", "# no base\nextends: nowhere.yaml\n");
  const InputError gone = load_error(missing);
  EXPECT_EQ(gone.file(), missing);
  EXPECT_EQ(gone.line(), 2);
  EXPECT_EQ(gone.column(), 10);
  EXPECT_NE(gone.message().find("no such file"), std::string::npos);

  // Not a path, and a device rather than a file.
  EXPECT_EQ(load_error(dir.write("n.yaml", "extends: [a.yaml]\n")).line(), 1);
  EXPECT_NE(load_error(dir.write("z.yaml", "extends: /dev/zero\n")).message().find("no such file"), std::string::npos);
}

TEST(SceneExtends, ValueSourcesNameTheFileAndLineOrTheOverride) {
  SceneDir dir;
  const std::string base = dir.write("base.yaml", std::string(testing::kSceneBodies) +
                                                      "operating:\n  load: 500 N\n  speed: 545 rad/s\n");
  const std::string derived = dir.write("d.yaml", "extends: base.yaml\noperating:\n  speed: 953 rad/s\n");
  const std::vector<ValueSource> sources = scene_value_sources(derived, {"operating.ambient=30 degC"});
  auto find = [&](const std::string& path) {
    return *std::find_if(sources.begin(), sources.end(), [&](const ValueSource& v) { return v.path == path; });
  };
  EXPECT_EQ(fs::path(find("operating.load").file), fs::path(base));
  EXPECT_EQ(find("operating.load").line, 7);
  EXPECT_EQ(find("operating.speed").file, derived);
  EXPECT_EQ(find("operating.speed").line, 3);
  EXPECT_EQ(find("operating.ambient").file, "--set operating.ambient");
  EXPECT_EQ(find("operating.ambient").line, 0);
  EXPECT_EQ(find("effects").line, 1);
}

TEST(SceneExtends, ShippedScenesExtendThePaperScene) {
  int checked = 0;
  for (const std::string folder : {"configs/studies", "configs/effects"}) {
    for (const fs::directory_entry& e : fs::directory_iterator(source_path(folder))) {
      if (e.path().extension() != ".yaml") continue;
      ++checked;
      SCOPED_TRACE(e.path().string());
      // Everything a shipped scene does not write itself is the paper's.
      for (const ValueSource& v : scene_value_sources(e.path().string())) {
        if (v.file != e.path().string()) {
          EXPECT_EQ(fs::path(v.file).filename(), "jackson_green_2006.yaml") << v.path;
        }
      }
      const Scene s = load_scene(e.path().string());
      EXPECT_NEAR(s.gear.tilt, 2e-3, 1e-18);  // Table 1, from the base
    }
  }
  EXPECT_GE(checked, 13);
}

}  // namespace
}  // namespace twb
