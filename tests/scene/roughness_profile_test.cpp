// surfaces.asperities.profile (docs/physics.md section 13): the summit statistics a scene gets
// from measured profiles, and the located errors of a profile file.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "../../src/scene/roughness_profile.h"
#include "scene_test_support.h"
#include "physics/summit_statistics.h"
#include "twb/scene/scene_inputs.h"

namespace twb {
namespace {

using testing::kMinimalScene;
using testing::load_error;
using testing::source_path;
using testing::TempScene;

constexpr double kPi = std::numbers::pi;
const std::string kExample = "configs/profiles/ground_steel_combined.csv";

// A profile file in the temporary directory, removed with it.
class TempProfile {
 public:
  TempProfile(const std::string& name, const std::string& text)
      : path_((std::filesystem::temp_directory_path() / name).string()) {
    std::ofstream(path_) << text;
  }
  ~TempProfile() { std::filesystem::remove(path_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// n heights of two whole-period modes close in wavenumber (a narrow band), one per row,
// positions in micrometres.
std::string profile_text(int n, const std::string& header = "x [um], z [nm]") {
  std::string text = "# a test profile\n" + header + "\n";
  for (int k = 0; k < n; ++k)
    text += std::to_string(0.5 * k) + ", " +
            std::to_string(300 * std::cos(2 * kPi * 30 * k / n) + 80 * std::sin(2 * kPi * 40 * k / n)) + "\n";
  return text;
}

std::string scene_with_profile(const std::string& profile) {
  return std::string(kMinimalScene) + "surfaces:\n  asperities:\n    profile: " + profile + "\n";
}

TEST(RoughnessProfile, ExampleProfileGivesMcCoolsSummits) {
  const TempScene scene(scene_with_profile(source_path(kExample)));
  const Scene s = load_scene(scene.path());
  const scene_io::RoughnessProfile heights = scene_io::read_roughness_profile(source_path(kExample));
  ASSERT_EQ(heights.heights.size(), 8192u);
  EXPECT_NEAR(heights.spacing, 0.5e-6, 1e-18);
  const SummitStatistics expected = mccool_summits(spectral_moments(heights.heights, heights.spacing));
  EXPECT_EQ(s.asperities.summit_radius, expected.radius);
  EXPECT_EQ(s.asperities.summit_sigma, expected.sigma);
  EXPECT_EQ(s.asperities.summit_density, expected.density);
  ASSERT_TRUE(s.asperities.profile.has_value());
  EXPECT_EQ(s.asperities.profile->samples, std::vector<std::size_t>{8192});
  // What scripts/example_profile.py designed the example for: summits near the model's
  // defaults, a band broad enough for McCool (no warning), the paper's combined Rq to
  // the five decimals of the file.
  EXPECT_NEAR(s.asperities.summit_radius, 20e-6, 3e-6);
  EXPECT_NEAR(s.asperities.eta_r_sigma, 0.05, 0.01);
  EXPECT_GT(s.asperities.profile->bandwidth, mccool_min_bandwidth);
  EXPECT_NEAR(std::sqrt(s.asperities.profile->m0), std::sqrt(2.0) * 0.515e-6, 1e-11);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(RoughnessProfile, RelativePathIsReadFromTheScenesDirectory) {
  const TempProfile profile("twb_relative_profile.csv", profile_text(512));
  const TempScene scene(scene_with_profile("twb_relative_profile.csv"));
  const Scene s = load_scene(scene.path());
  EXPECT_EQ(s.asperities.profile->files.front(), profile.path());
  // The tree the scene keeps names the file as resolved, so the scene read again with an
  // input changed (scene_inputs.h) reads the same file wherever the tree is read from.
  const std::string absolute = std::filesystem::absolute(profile.path()).string();
  EXPECT_NE(s.written.find(absolute), std::string::npos) << s.written;
  const std::pair<std::string, double> set[] = {{"operating.load", 600.0}};
  EXPECT_EQ(with_inputs(s, set).asperities.profile->files.front(), absolute);
  // A narrow band of two modes: legal, with the warning.
  ASSERT_EQ(s.warnings.size(), 2u);  // the band, and an Rq unlike the surfaces'
  EXPECT_NE(s.warnings[0].find("bandwidth"), std::string::npos);
  EXPECT_NE(s.warnings[1].find("Rq"), std::string::npos);
}

TEST(RoughnessProfile, OneProfilePerFaceAddsTheirMoments) {
  const TempScene one(scene_with_profile(source_path(kExample)), "_one");
  const std::string file = source_path(kExample);
  std::string both = "[";  // (built by parts: GCC 12 warns falsely on "[" + string + ...)
  both.append(file).append(", ").append(file).append("]");
  const TempScene two(scene_with_profile(both), "_two");
  const Scene a = load_scene(one.path()), b = load_scene(two.path());
  // The same face twice: every moment doubles; R ∝ m4^-½, η ∝ m4/m2 stays, σs ∝ √m0.
  EXPECT_NEAR(b.asperities.profile->m4, 2 * a.asperities.profile->m4, 1e-15 * b.asperities.profile->m4);
  EXPECT_NEAR(b.asperities.summit_radius, a.asperities.summit_radius / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(b.asperities.summit_density, a.asperities.summit_density, 1e-15 * a.asperities.summit_density);
  EXPECT_NEAR(b.asperities.summit_sigma, a.asperities.summit_sigma * std::sqrt(2.0), 1e-20);
}

TEST(RoughnessProfile, ProfileAndSummitValuesExcludeEachOther) {
  const TempScene scene(std::string(kMinimalScene) + "surfaces:\n  asperities:\n    profile: " +
                        source_path(kExample) + "\n    summit_radius: 20 um\n");
  const InputError e = load_error(scene.path());
  EXPECT_EQ(e.line(), 10);
  EXPECT_EQ(e.column(), 5);
  EXPECT_NE(e.message().find("with a profile"), std::string::npos) << e.what();
}

TEST(RoughnessProfile, ThreeFilesAreRefused) {
  const std::string f = source_path(kExample);
  std::string three = "[";
  three.append(f).append(", ").append(f).append(", ").append(f).append("]");
  const TempScene scene(scene_with_profile(three));
  const InputError e = load_error(scene.path());
  EXPECT_EQ(e.line(), 9);
  EXPECT_NE(e.message().find("one profile of the combined surface or two"), std::string::npos) << e.what();
}

struct BadProfile {
  const char* name;
  std::string text;
  int line, column;
  const char* says;
};

class BadProfileFile : public ::testing::TestWithParam<BadProfile> {};

TEST_P(BadProfileFile, ErrorPointsIntoTheProfile) {
  const BadProfile& bad = GetParam();
  const TempProfile profile(std::string("twb_bad_profile_") + bad.name + ".csv", bad.text);
  const TempScene scene(scene_with_profile(profile.path()));
  const InputError e = load_error(scene.path());
  EXPECT_EQ(e.file(), profile.path());
  EXPECT_EQ(e.line(), bad.line) << e.what();
  EXPECT_EQ(e.column(), bad.column) << e.what();
  EXPECT_NE(e.message().find(bad.says), std::string::npos) << e.what();
}

std::string with_line(const std::string& text, int line, const std::string& replacement) {
  std::size_t start = 0;
  for (int k = 1; k < line; ++k) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  return text.substr(0, start) + replacement + text.substr(end);
}

INSTANTIATE_TEST_SUITE_P(
    Faults, BadProfileFile,
    ::testing::Values(
        BadProfile{"empty", "# nothing\n", 0, 0, "the profile is empty"},
        BadProfile{"no_unit", profile_text(128, "x, z [um]"), 2, 1, "gives no unit"},
        BadProfile{"not_a_length", profile_text(128, "x [um], z [N]"), 2, 12, "the height column's unit 'N'"},
        BadProfile{"three_columns", profile_text(128, "x [um], z [um], y [um]"), 2, 1, "has 3 columns"},
        BadProfile{"short", profile_text(20), 0, 0, "at least 64"},
        BadProfile{"not_a_number", with_line(profile_text(128), 7, "2.5, 0.3x"), 7, 6, "'0.3x' is not a finite number"},
        BadProfile{"nan", with_line(profile_text(128), 7, "2.5, nan"), 7, 6, "is not a finite number"},
        BadProfile{"missing_sample", with_line(profile_text(128), 7, "2.6, 0.3"), 7, 1, "uniform spacing"},
        BadProfile{"one_field", with_line(profile_text(128), 9, "3.5"), 9, 1, "has 1 fields"},
        BadProfile{"decreasing", profile_text(128) + "-100, 0\n", 131, 1, "must increase"}),
    [](const ::testing::TestParamInfo<BadProfile>& info) { return std::string(info.param.name); });

TEST(RoughnessProfile, MissingFileIsNamed) {
  const TempScene scene(scene_with_profile("no_such_profile.csv"));
  const InputError e = load_error(scene.path());
  EXPECT_NE(e.file().find("no_such_profile.csv"), std::string::npos);
  EXPECT_NE(e.message().find("no such regular file"), std::string::npos);
}

TEST(RoughnessProfile, DirectoryOrDeviceIsNotAProfile) {
  // /dev/zero would never end; a directory has no lines.
  for (const std::string& named : {std::string("/dev/zero"), std::filesystem::temp_directory_path().string()}) {
    const TempScene scene(scene_with_profile(named));
    EXPECT_NE(load_error(scene.path()).message().find("no such regular file"), std::string::npos) << named;
  }
}

TEST(RoughnessProfile, DescribedSceneCarriesTheEstimate) {
  const TempScene scene(scene_with_profile(source_path(kExample)));
  const Scene first = load_scene(scene.path());
  const TempScene described(describe_scene(first), "_described");
  const Scene again = load_scene(described.path());
  // The described scene stands alone: the estimate's values, not the file.
  EXPECT_FALSE(again.asperities.profile.has_value());
  EXPECT_EQ(again.asperities.summit_radius, first.asperities.summit_radius);
  EXPECT_EQ(again.asperities.summit_sigma, first.asperities.summit_sigma);
  EXPECT_EQ(again.asperities.summit_density, first.asperities.summit_density);
}

}  // namespace
}  // namespace twb
