// A washer a life wore (twb/results/worn_washer.h): written and read back exactly, held
// on another mesh of its annulus with the same worn faces, refused where it does not fit
// the scene, and a life continued from it (twb run --continue-from) ending where the
// whole life ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "model/wear_effect.h"
#include "study/study_runner.h"
#include "twb/results/worn_washer.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

Scene wear_scene(const std::string& study, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study=" + study,
                                     "operating.load=150 N"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/effects/wear.yaml", overrides);
}

template <class Act>
std::string refusal(Act act) {
  try {
    act();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

// A worn washer on a scene's sliding film (film 1 of configs/effects/wear.yaml), its
// faces worn in a shape that is neither flat nor symmetric: the face at rest deepest at
// the outer rim near θ = 0, the turning face's depth growing with the radius squared.
WornWasher shaped_washer(const Scene& s, int nr, int nt, double time) {
  WornWasher w;
  w.time = time;
  w.film = 1;
  w.inner_radius = s.washer.inner_radius;
  w.outer_radius = s.washer.outer_radius;
  w.radial_nodes = nr;
  w.circumferential_nodes = nt;
  for (int i = 0; i < nr; ++i) {
    const double x = double(i) / (nr - 1);
    for (int j = 0; j < nt; ++j) w.rest.push_back(1e-6 * x * (1.0 + std::cos(2.0 * std::numbers::pi * j / nt)));
    w.turn.push_back(0.3e-6 * x * x);
  }
  w.source = "the test's washer";
  return w;
}

// The depths the model's wear rows hold (m), through carry_from, which writes them.
std::vector<double> held(const BearingModel& model, bool rest) {
  const WearEffect& wear = *model.effect<WearEffect>();
  std::vector<double> u(std::size_t(model.size()), 0.0);
  wear.carry_from(model, wear, u, u);
  return rest ? wear.rest_depths(u) : wear.turn_depths(u);
}

TEST(WornWasher, ItsFileGivesBackEveryDepthExactly) {
  const Scene s = wear_scene("{type: point}");
  WornWasher w = shaped_washer(s, 5, 24, 1234.5 * 3600.0);
  w.rest[7] = 1.0 / 3.0 * 1e-6;  // a double no short decimal writes
  const WornWasher back = worn_washer_of(worn_washer_json(w), "here");
  EXPECT_EQ(back.time, w.time);
  EXPECT_EQ(back.film, w.film);
  EXPECT_EQ(back.inner_radius, w.inner_radius);
  EXPECT_EQ(back.outer_radius, w.outer_radius);
  EXPECT_EQ(back.radial_nodes, 5);
  EXPECT_EQ(back.circumferential_nodes, 24);
  EXPECT_EQ(back.rest, w.rest);
  EXPECT_EQ(back.turn, w.turn);
  EXPECT_EQ(back.source, "here");
}

TEST(WornWasher, AMalformedFileIsRefusedSayingWhy) {
  const Scene s = wear_scene("{type: point}");
  const std::string good = worn_washer_json(shaped_washer(s, 5, 24, 0.0));
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const std::pair<std::string, std::string> cases[] = {
      {"not JSON at all", "JSON"},
      {with("\"twb-worn-washer 1\"", "\"twb-worn-washer 9\""), "this twb reads"},
      {with("\"radial_nodes\": 5", "\"radial_nodes\": 6"), "face at rest depths"},
      {with("\"film\": 1", "\"film\": 3"), "film 3"},
      {with("\"time_s\": 0.0", "\"time_s\": -1.0"), "not a time"},
      {with("\"inner_radius_m\"", "\"inner_radius\""), "inner_radius_m"},
      {with("\"turn_m\": [\n  0.0", "\"turn_m\": [\n  \"deep\""), "turn_m"},
  };
  for (const auto& [text, why] : cases) {
    const std::string message = refusal([&] { worn_washer_of(text, "worn.json"); });
    EXPECT_NE(message.find("worn.json: not a worn washer"), std::string::npos) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
  }
  EXPECT_NE(refusal([] { read_worn_washer("/nonexistent/worn_washer.json"); }).find("cannot read it"),
            std::string::npos);
}

// A mesh twice as fine in both directions has every node of the washer's grid among its
// nodes, and bilinear interpolation of a bilinear cell is exact: the finer mesh holds the
// same piecewise-bilinear faces, so the same deepest depths and, the nodes' areas being
// the exact integrals of their hats, the same worn volume, to rounding.
TEST(WornWasher, AFinerMeshHoldsTheSameWornFaces) {
  Scene coarse = wear_scene("{type: point}");
  const WornWasher w = shaped_washer(coarse, 5, 24, 0.0);
  set_worn_washer(coarse, w, "the test");
  Scene fine = coarse;
  fine.mesh.radial_nodes = 9;
  fine.mesh.circumferential_nodes = 48;
  const BearingModel on_coarse(coarse), on_fine(fine);
  // (held in σ_ref and given back in metres: equal to rounding)
  const std::vector<double> rest = held(on_coarse, true), turn = held(on_coarse, false);
  for (std::size_t n = 0; n < rest.size(); ++n) EXPECT_NEAR(rest[n], w.rest[n], 1e-15 * 2e-6) << n;
  for (std::size_t i = 0; i < turn.size(); ++i) EXPECT_NEAR(turn[i], w.turn[i], 1e-15 * 2e-6) << i;
  for (const BearingModel* m : {&on_coarse, &on_fine}) {
    const std::vector<double> r = held(*m, true), t = held(*m, false);
    EXPECT_NEAR(*std::max_element(r.begin(), r.end()), 2e-6, 1e-15 * 2e-6);
    EXPECT_NEAR(*std::max_element(t.begin(), t.end()), 0.3e-6, 1e-15 * 2e-6);
  }
  auto volumes = [](const BearingModel& m) {
    const WearEffect& wear = *m.effect<WearEffect>();
    std::vector<double> u(std::size_t(m.size()), 0.0);
    wear.carry_from(m, wear, u, u);
    const auto faces = wear.worn(u);
    return std::array<double, 2>{faces[0].volume, faces[1].volume};
  };
  const auto a = volumes(on_coarse), b = volumes(on_fine);
  EXPECT_NEAR(b[0], a[0], 1e-13 * a[0]);
  EXPECT_NEAR(b[1], a[1], 1e-13 * a[1]);
}

// A steady study of the worn washer holds its depths: the state's gap is the worn one,
// and it reports the deepest depth it holds.
TEST(WornWasher, AStudyOfTheWornWasherHoldsItsDepths) {
  Scene s = wear_scene("{type: point}");
  set_worn_washer(s, shaped_washer(s, 5, 24, 0.0), "the test");
  BearingModel model(s);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_NEAR(out.states.back().state.reported_value("worn_depth_rest_um").value_or(0.0), 2.0, 1e-12);
  EXPECT_NEAR(out.states.back().state.reported_value("worn_depth_turn_um").value_or(0.0), 0.3, 1e-12);
}

TEST(WornWasher, IsRefusedWhereItDoesNotFitTheScene) {
  const Scene s = wear_scene("{type: point}");
  const WornWasher w = shaped_washer(s, 5, 24, 500 * 3600.0);
  auto refused = [&](Scene scene, const WornWasher& worn) {
    return refusal([&] { set_worn_washer(scene, worn, "--continue-from"); });
  };
  Scene without_wear = s;
  without_wear.effects.wear = false;
  EXPECT_NE(refused(without_wear, w).find("add wear to the scene's effects"), std::string::npos);
  Scene other_film = s;
  other_film.operating.sliding = SlidingFilm::washer_gear;
  EXPECT_NE(refused(other_film, w).find("this scene's sliding film is film 2"), std::string::npos);
  WornWasher wider = w;
  wider.outer_radius *= 1.01;
  EXPECT_NE(refused(s, wider).find("belong to another washer"), std::string::npos);
  const Scene shorter = wear_scene("{type: life, duration: 400 h}");
  EXPECT_NE(refused(shorter, w).find("a continued life needs a longer one"), std::string::npos);
  EXPECT_NE(refused(shorter, w).find("--continue-from the test's washer"), std::string::npos);
  EXPECT_EQ(refused(wear_scene("{type: life, duration: 600 h}"), w), "");
}

// A directory without a worn washer, and the run's own results directory, are refused.
TEST(WornWasher, ADirectoryWithoutOneOrTheRunsOwnIsRefused) {
  const fs::path from = fs::path(::testing::TempDir()) / "twb_worn_washer_from";
  fs::remove_all(from);
  fs::create_directories(from);
  Scene s = wear_scene("{type: point}");
  EXPECT_NE(refusal([&] { continue_from(s, from.string(), "", "--continue-from"); }).find("no worn_washer.json there"),
            std::string::npos);
  std::ofstream(from / "worn_washer.json") << worn_washer_json(shaped_washer(s, 5, 24, 0.0));
  EXPECT_NE(refusal([&] { continue_from(s, from.string(), (from / ".").string(), "--continue-from"); })
                .find("replace the washer it starts from"),
            std::string::npos);
  EXPECT_FALSE(continue_from(s, from.string(), "", "--continue-from"));
  ASSERT_TRUE(s.worn);
  EXPECT_EQ(s.worn->source, (from / "worn_washer.json").string());
  fs::remove_all(from);
}

}  // namespace
}  // namespace twb
