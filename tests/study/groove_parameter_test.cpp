// A distress map over the washer's grooves (groove_count, groove_width, groove_depth):
// each value's scene is the scene written with those grooves, placed on the grid as the
// reader places them (the circumferential nodes rounded to whole cells per pitch, the
// width to whole cells), and the map's column holds the width the grid resolved, which
// is what was solved.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../scene/scene_test_support.h"
#include "study/searches/study_searches.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

std::string grooved_scene(const std::string& grooves, const std::string& study = "") {
  std::string s = testing::kSceneBodies;
  const std::string washer_end = "thickness: 0.635 mm}";
  s.replace(s.find(washer_end), washer_end.size(), "thickness: 0.635 mm, grooves: {" + grooves + "}}");
  return s + "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"
             "mesh: {circumferential_nodes: 66}\n" +
         study;
}

Scene loaded(const std::string& text) {
  const testing::TempScene file(text);
  return load_scene(file.path());
}

struct GrooveCase {
  const char* name;
  const char* values;                   // the map's
  std::vector<std::string> as_written;  // each value's grooves, as a scene would give them
};

TEST(GrooveParameter, EachValueIsTheSceneWrittenWithThoseGrooves) {
  const std::string base = "count: 6, width: 2 mm, depth: 50 um";
  for (const GrooveCase& c :
       {GrooveCase{"groove_count", "[4, 7, 12]",
                   {"count: 4, width: 2 mm, depth: 50 um", "count: 7, width: 2 mm, depth: 50 um",
                    "count: 12, width: 2 mm, depth: 50 um"}},
        GrooveCase{"groove_width", "[1 mm, 12 deg]",
                   {"count: 6, width: 1 mm, depth: 50 um", "count: 6, width: 12 deg, depth: 50 um"}},
        GrooveCase{"groove_depth", "[10 um, 0.2 mm]",
                   {"count: 6, width: 2 mm, depth: 10 um", "count: 6, width: 2 mm, depth: 0.2 mm"}}}) {
    SCOPED_TRACE(c.name);
    const Scene map = loaded(grooved_scene(
        base, std::string("study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: ") +
                  c.name + ", values: " + c.values + "}}\n"));
    std::vector<std::string> columns;
    const std::vector<Variant> variants = parameter_variants(map, columns);
    ASSERT_EQ(columns.size(), 1u);
    const std::string& column = columns.front();
    ASSERT_EQ(variants.size(), c.as_written.size());
    for (std::size_t k = 0; k < variants.size(); ++k) {
      SCOPED_TRACE(c.as_written[k]);
      const Scene expected = loaded(grooved_scene(c.as_written[k]));
      const Scene& got = *variants[k].scene;
      ASSERT_TRUE(got.washer.grooves);
      EXPECT_EQ(got.mesh.circumferential_nodes, expected.mesh.circumferential_nodes);
      EXPECT_EQ(got.washer.grooves->count, expected.washer.grooves->count);
      EXPECT_EQ(got.washer.grooves->cells, expected.washer.grooves->cells);
      EXPECT_DOUBLE_EQ(got.washer.grooves->width, expected.washer.grooves->width);
      EXPECT_EQ(got.washer.grooves->depth, expected.washer.grooves->depth);
      // The column: the count, the resolved width (rad), the depth (m).
      const double value = c.name == std::string("groove_count")   ? expected.washer.grooves->count
                           : c.name == std::string("groove_width") ? expected.washer.grooves->width
                                                                   : expected.washer.grooves->depth;
      ASSERT_EQ(variants[k].parameters.size(), 1u);
      EXPECT_DOUBLE_EQ(variants[k].parameters.front(), value);
    }
    EXPECT_EQ(column, c.name == std::string("groove_count")   ? "groove_count"
                      : c.name == std::string("groove_width") ? "groove_width_rad"
                                                              : "groove_depth_m");
  }
}

}  // namespace
}  // namespace twb
