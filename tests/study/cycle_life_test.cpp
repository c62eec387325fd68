// A washer's life through a duty cycle repeated (study type life with a schedule,
// docs/physics.md section 20, "A repeated duty cycle"): a cycle that does not change is
// the life at its operating point, the cycles jumped stay within the depth tolerance of
// every cycle marched, and the scene's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/input_error.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {
namespace {

// The paper's washer with wear (configs/effects/wear.yaml) on a coarse mesh, its faces
// wearing a hundred times faster than the shipped scale so that a short life runs in.
Scene cycle_scene(const std::string& study, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                     "surfaces.carrier.wear_rate=1.4e-15 m^3/(N m)",
                                     "surfaces.washer.wear_rate=1.4e-15 m^3/(N m)", "study=" + study};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/effects/wear.yaml", overrides);
}

StudyOutcome lived(const Scene& s) {
  BearingModel model(s);
  StudyOutcome out = run_study(model, {});
  EXPECT_FALSE(out.solver_failed) << out.message;
  EXPECT_FALSE(std::get<LifeOutcome>(out.own).rows.empty());
  return out;
}

const WornWasher& worn_at_end(const StudyOutcome& out) { return std::get<LifeOutcome>(out.own).worn.back(); }

// The largest difference of depth between two washers worn on the same mesh (m).
double largest_difference(const WornWasher& a, const WornWasher& b) {
  double most = 0.0;
  for (std::size_t n = 0; n < a.rest.size(); ++n) most = std::max(most, std::abs(a.rest[n] - b.rest[n]));
  for (std::size_t i = 0; i < a.turn.size(); ++i) most = std::max(most, std::abs(a.turn[i] - b.turn[i]));
  return most;
}

// A cycle whose inputs never change holds the steady bearing (the march starts from it
// and stays), so that each cycle wears T times the operating point's rate: the life is
// the one at that operating point. Both lives keep their depths within their own
// tolerance of the exact ones (1 nm each), so they differ by at most 2 nm.
TEST(CycleLife, ACycleThatDoesNotChangeWearsAsTheOperatingPoint) {
  const std::string common = "duration: 10 h, report_every: 10 h, tolerance: 1 nm, failure_load: false";
  const StudyOutcome point = lived(cycle_scene("{type: life, " + common + "}", {"operating.load=150 N"}));
  const StudyOutcome cycle = lived(
      cycle_scene("{type: life, " + common +
                      ", schedule: [{t: 0 s, load: 150 N, speed: 545 rad/s}, {t: 60 s, load: 150 N, speed: 545 rad/s}]}",
                  {"operating.load=150 N"}));
  const std::vector<LifeRow>& rows = std::get<LifeOutcome>(cycle.own).rows;
  EXPECT_EQ(rows.back().event, "end");
  EXPECT_DOUBLE_EQ(rows.back().time, 10 * 3600.0);
  EXPECT_GT(worn_at_end(point).rest.front() + rows.back().rest.deepest, 0.1e-6);  // it did wear
  EXPECT_LT(largest_difference(worn_at_end(point), worn_at_end(cycle)), 2e-9);
}

// A cycle that starts at rest under load has no film to start a march from, and each
// later cycle would start from the last one's end at rest: the life marches it from its
// first point where the washer turns, the same periodic cycle shifted. So it is, to the
// last bit, the life of that shifted schedule written out; and it lasts its duration where
// a march from rest does not start.
TEST(CycleLife, ACycleFromRestIsMarchedFromWhereTheWasherTurns) {
  const std::string common = "duration: 100 s, report_every: 100 s, tolerance: 1 nm, failure_load: false";
  const StudyOutcome from_rest = lived(cycle_scene(
      "{type: life, " + common +
      ", schedule: [{t: 0 s, load: 60 N, speed: 0 rad/s}, {t: 2 s, speed: 545 rad/s}, {t: 8 s}, {t: 10 s, speed: 0 rad/s}]}"));
  const StudyOutcome shifted = lived(cycle_scene(
      "{type: life, " + common +
      ", schedule: [{t: 0 s, load: 60 N, speed: 545 rad/s}, {t: 6 s}, {t: 8 s, speed: 0 rad/s}, {t: 10 s, speed: 545 rad/s}]}"));
  const std::vector<LifeRow>& rows = std::get<LifeOutcome>(from_rest.own).rows;
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back().event, "end");
  EXPECT_GT(rows.back().rest.deepest, 0.0);
  EXPECT_EQ(worn_at_end(from_rest).rest, worn_at_end(shifted).rest);
  EXPECT_EQ(worn_at_end(from_rest).turn, worn_at_end(shifted).turn);
}

// The cycles jumped (Heun's steps of many cycles) against every cycle marched: the
// reference's tolerance, 0.1 nm, is below what one cycle wears, so it marches every one
// (its summary says how many: the 18 cycles and the one after the last, whose march gives
// the end's row); the jumped life marches fewer and its depths stay within its tolerance
// of the reference's.
TEST(CycleLife, TheCyclesJumpedStayWithinTheToleranceOfEveryCycleMarched) {
  const std::string cycle =
      ", duration: 0.05 h, report_every: 0.05 h, failure_load: false, schedule: [{t: 0 s, load: 120 N, speed: 545 "
      "rad/s}, {t: 2 s, load: 170 N}, {t: 5 s}, {t: 7 s, load: 120 N}, {t: 10 s}]}";
  auto marched = [](const StudyOutcome& out) {
    for (const std::string& line : out.summary)
      if (line.starts_with("life: ") && line.ends_with(" cycles marched in real time"))
        return std::stoi(line.substr(6));
    return -1;
  };
  // (wearing ten times slower than the other tests: a cycle's wear changes from one cycle
  // to the next by less than 0.4 nm, which a step of two cycles at 10 nm allows)
  const std::vector<std::string> slower{"surfaces.carrier.wear_rate=1.4e-16 m^3/(N m)",
                                        "surfaces.washer.wear_rate=1.4e-16 m^3/(N m)"};
  const StudyOutcome every = lived(cycle_scene("{type: life, tolerance: 0.1 nm" + cycle, slower));
  ASSERT_EQ(marched(every), 19);
  const StudyOutcome jumped = lived(cycle_scene("{type: life, tolerance: 10 nm" + cycle, slower));
  EXPECT_LT(marched(jumped), 19);
  EXPECT_LT(largest_difference(worn_at_end(every), worn_at_end(jumped)), 10e-9);
}

// What the scene refuses, where.
TEST(CycleLife, ACycleThatDoesNotEndWhereItStartsIsRefusedAtItsSchedule) {
  try {
    cycle_scene("{type: life, duration: 1 h, schedule: [{t: 0 s, load: 120 N}, {t: 10 s, load: 170 N}]}");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a life repeats its schedule, so the cycle must end where it starts"),
              std::string::npos)
        << e.what();
  }
  try {
    cycle_scene("{type: life, duration: 1 h, relative_tolerance: 1e-5}");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give the life a schedule"), std::string::npos) << e.what();
  }
  try {
    cycle_scene("{type: life, duration: 1 h, schedule: [{t: 0 s, load: 120 N}, {t: 10 s}]}",
                {"effects=[hydrodynamics, flow_factors, asperity_contact, wear]"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a life through a duty cycle marches the bodies' heat"), std::string::npos)
        << e.what();
  }
  try {
    cycle_scene("{type: life, duration: 10 s, schedule: [{t: 0 s, load: 120 N}, {t: 60 s}]}");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("longer than the life's duration"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace twb
