// A duty cycle's schedule (scene/read_schedule.cpp): in the scene or a CSV file, a field
// a point leaves out is the point before's (the first point's the scene's operating point
// and gear tilt), units converted, the resolved scene self-contained, and every fault
// located: in the scene at its key, in the file at its line and column.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "scene_test_support.h"
#include "twb/input_error.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using testing::TempScene;

// The paper's scene with a duty cycle whose schedule is `schedule` (YAML).
std::string cycle_scene(const std::string& schedule) {
  return "extends: " + testing::source_path("configs/jackson_green_2006.yaml") +
         "\nstudy: !replace\n  type: duty_cycle\n  schedule: " + schedule + "\n";
}

// A duty cycle scene's settings.
const DutyCycleSettings& cycle(const Scene& scene) { return std::get<DutyCycleSettings>(scene.study.settings); }

TEST(Schedule, FieldsLeftOutAreThePointBeforesAndTheFirstPointsTheScenes) {
  const TempScene file(cycle_scene("\n    - {t: 0 s, load: 100 N}\n    - {t: 1 min, speed: 3000 rpm}\n"
                                   "    - {t: 90 s, ambient: 80 degC, tilt: 1 mrad}\n"));
  const Scene s = load_scene(file.path());
  ASSERT_EQ(cycle(s).schedule.size(), 3u);
  const SchedulePoint& a = cycle(s).schedule[0];
  const SchedulePoint& b = cycle(s).schedule[1];
  const SchedulePoint& c = cycle(s).schedule[2];
  EXPECT_EQ(a.time, 0.0);
  EXPECT_EQ(a.load, 100.0);
  EXPECT_EQ(a.speed, s.operating.speed);
  EXPECT_EQ(a.ambient, s.operating.ambient);
  EXPECT_EQ(a.tilt, s.gear.tilt);
  EXPECT_EQ(b.time, 60.0);
  EXPECT_EQ(b.load, 100.0);
  EXPECT_NEAR(b.speed, 3000.0 * 2.0 * M_PI / 60.0, 1e-12);
  EXPECT_EQ(c.load, 100.0);
  EXPECT_EQ(c.speed, b.speed);
  EXPECT_NEAR(c.ambient, 353.15, 1e-12);
  EXPECT_NEAR(c.tilt, 1e-3, 1e-18);
  EXPECT_EQ(a.line, 5);  // the scene's line of the point
  EXPECT_EQ(a.file, file.path());
}

// The failure search at the worst moment is on unless the scene turns it off; the
// resolved scene says which.
TEST(Schedule, TheFailureLoadAtTheWorstMomentMayBeLeftOut) {
  const TempScene on(cycle_scene("[{t: 0 s}, {t: 1 s}]"));
  EXPECT_TRUE(cycle(load_scene(on.path())).failure_load_at_worst);
  const TempScene off(cycle_scene("[{t: 0 s}, {t: 1 s}]\n  failure_load_at_worst: false"), "_off");
  const Scene s = load_scene(off.path());
  EXPECT_FALSE(cycle(s).failure_load_at_worst);
  const TempScene resolved(describe_scene(s), "_resolved");
  EXPECT_FALSE(cycle(load_scene(resolved.path())).failure_load_at_worst);
}

// The march's relative tolerance: 1e-6 by default, a looser one read and kept by the
// resolved scene, one outside its range located at its key.
TEST(Schedule, TheMarchsToleranceMayBeSet) {
  const TempScene plain(cycle_scene("[{t: 0 s}, {t: 1 s}]"));
  EXPECT_EQ(cycle(load_scene(plain.path())).march_tolerance, 1e-6);
  const TempScene loose(cycle_scene("[{t: 0 s}, {t: 1 s}]\n  relative_tolerance: 1e-4"), "_loose");
  const Scene s = load_scene(loose.path());
  EXPECT_EQ(cycle(s).march_tolerance, 1e-4);
  const TempScene resolved(describe_scene(s), "_resolved");
  EXPECT_EQ(cycle(load_scene(resolved.path())).march_tolerance, 1e-4);
  const TempScene wrong(cycle_scene("[{t: 0 s}, {t: 1 s}]\n  relative_tolerance: 0.5"), "_wrong");
  const InputError e = testing::load_error(wrong.path());
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(std::string(e.what()).find("from 1e-10 to 1e-3"), std::string::npos) << e.what();
}

// A speed may turn negative (the washer turns back); the points join in a straight line.
TEST(Schedule, ASpeedMayTurnBack) {
  const TempScene file(cycle_scene("[{t: 0 s}, {t: 10 s, speed: -100 rad/s}]"));
  EXPECT_EQ(cycle(load_scene(file.path())).schedule[1].speed, -100.0);
}

TEST(Schedule, FromACsvFileWithUnitsOrTheResultsOwnNames) {
  const TempScene csv("# a launch\nt [s], load [kN], speed [rpm], ambient [degC]\n0, 0.1, 0, 40\n2, 0.3, 3000, \n"
                      "10, , 3000, 60\n",
                      "_data", ".csv");
  const TempScene file(cycle_scene(csv.path()));
  const Scene s = load_scene(file.path());
  ASSERT_EQ(cycle(s).schedule.size(), 3u);
  EXPECT_EQ(cycle(s).schedule_file, csv.path());
  EXPECT_DOUBLE_EQ(cycle(s).schedule[0].load, 100.0);
  EXPECT_EQ(cycle(s).schedule[0].speed, 0.0);
  EXPECT_NEAR(cycle(s).schedule[1].ambient, 313.15, 1e-12);  // an empty field: the point before's
  EXPECT_DOUBLE_EQ(cycle(s).schedule[2].load, 300.0);
  EXPECT_NEAR(cycle(s).schedule[2].ambient, 333.15, 1e-12);
  EXPECT_EQ(cycle(s).schedule[2].tilt, s.gear.tilt);  // no column: the scene's
  EXPECT_EQ(cycle(s).schedule[2].line, 5);

  // A duty cycle's trajectory.csv is a schedule.
  // (Its steps closer than its ten digits tell apart: the first of them stands for all.)
  const TempScene results("t_s,load_N,speed_rad_s,ambient_C,tilt_rad,T_mean_C\n0,100,545,24,0.002,30\n"
                          "5,120,545,24,0.002,31\n5,120.0000001,545,24,0.002,31\n",
                          "_results", ".csv");
  const TempScene again(cycle_scene(results.path()), "_again");
  const Scene r = load_scene(again.path());
  ASSERT_EQ(cycle(r).schedule.size(), 2u);
  EXPECT_EQ(cycle(r).schedule[1].load, 120.0);
}

// The resolved scene carries the schedule itself: read again it is the same.
TEST(Schedule, TheResolvedSceneHoldsEveryPoint) {
  const TempScene csv("t [s], load [N], speed [rpm]\n0, 100, 3000\n7.5, 180, 2000\n", "_data", ".csv");
  const TempScene file(cycle_scene(csv.path()));
  const Scene s = load_scene(file.path());
  const TempScene resolved(describe_scene(s), "_resolved");
  const Scene r = load_scene(resolved.path());
  ASSERT_EQ(cycle(r).schedule.size(), cycle(s).schedule.size());
  for (std::size_t k = 0; k < cycle(s).schedule.size(); ++k) {
    EXPECT_EQ(cycle(r).schedule[k].time, cycle(s).schedule[k].time);
    EXPECT_EQ(cycle(r).schedule[k].load, cycle(s).schedule[k].load);
    EXPECT_EQ(cycle(r).schedule[k].speed, cycle(s).schedule[k].speed);
    EXPECT_EQ(cycle(r).schedule[k].ambient, cycle(s).schedule[k].ambient);
    EXPECT_EQ(cycle(r).schedule[k].tilt, cycle(s).schedule[k].tilt);
  }
}

struct SceneFault {
  const char* schedule;
  int line, column;
  const char* says;
};

// The message's last line is its caret, under the column it names (a fault located at a
// line alone has none): a user reading a backwards schedule's error once met a blank one.
void expect_caret_at_column(const InputError& e) {
  if (e.column() <= 0) return;
  const std::string what = e.what();
  const std::string caret = what.substr(what.rfind('\n') + 1);
  const std::size_t bar = caret.find(" | ");
  ASSERT_NE(bar, std::string::npos) << what;
  EXPECT_EQ(caret.find('^'), bar + 3 + std::size_t(e.column() - 1)) << what;
  EXPECT_EQ(caret.back(), '^') << what;
}

TEST(Schedule, FaultsInTheSceneAreLocated) {
  const SceneFault faults[] = {
      {"[{t: 0 s}, {t: 0 s, load: 120 N}]", 4, 28, "the times must increase strictly"},
      {"[{t: 5 s}, {t: 2 s}]", 4, 28, "the times must increase strictly"},
      {"[{t: 0 s}, {t: 2 s, load: -10 N}]", 4, 39, "positive load"},
      {"[{t: 0 s}, {t: 2 s, load: 0 N}]", 4, 39, "axial play"},
      {"[{t: 0 s}, {t: 2 s, load: 10 rad}]", 4, 39, "a force"},
      {"[{t: 0 s}, {load: 10 N}]", 4, 24, "missing required key 't'"},
      {"[{t: 0 s}, {t: 1 s, sped: 3 rpm}]", 4, 33, "sped"},
      {"[{t: 0 s}]", 4, 13, "at least two"},
      {"[{t: 0 s, ambient: 160 degC}, {t: 1 s}]", 4, 14, "past the oil's maximum temperature"},
      {"{t: 0 s}", 4, 13, "a list of points"},
  };
  for (const SceneFault& f : faults) {
    SCOPED_TRACE(f.schedule);
    const TempScene file(cycle_scene(f.schedule));
    const InputError e = testing::load_error(file.path());
    EXPECT_EQ(e.line(), f.line);
    EXPECT_EQ(e.column(), f.column);
    EXPECT_NE(std::string(e.what()).find(f.says), std::string::npos) << e.what();
    expect_caret_at_column(e);
  }
}

TEST(Schedule, FaultsInTheFileAreLocated) {
  const SceneFault faults[] = {
      {"t [s], load [N]\n0, 100\n0, 120\n", 3, 1, "the times must increase strictly"},
      {"t [s], load [N]\n0, 100\n1, -5\n", 3, 4, "out of range"},
      {"t, load [N]\n0, 100\n1, 120\n", 1, 1, "the column 't' gives no unit"},
      {"t [s], load [K]\n0, 100\n1, 120\n", 1, 14, "the load column's unit 'K'"},
      {"t [s], wear [um]\n0, 1\n1, 2\n", 1, 8, "the column 'wear' is none a schedule reads"},
      {"load [N]\n100\n120\n", 1, 1, "no time column"},
      {"t [s], load [N]\n0, 100\n", 0, 0, "at least two"},
      {"t [s], load [N]\n0, 100\n1\n", 3, 1, "this row has 1 field and the header 2 columns"},
      {"t [s], load [N]\n0, 100\n, 120\n", 3, 1, "the time is empty"},
      {"t [s], ambient [degC]\n0, 200\n1, 30\n", 2, 1, "past the oil's maximum temperature"},
  };
  for (const SceneFault& f : faults) {
    SCOPED_TRACE(f.schedule);
    const TempScene csv(f.schedule, "_data", ".csv");
    const TempScene file(cycle_scene(csv.path()));
    const InputError e = testing::load_error(file.path());
    EXPECT_EQ(e.file(), csv.path());
    EXPECT_EQ(e.line(), f.line);
    EXPECT_EQ(e.column(), f.column);
    EXPECT_NE(std::string(e.what()).find(f.says), std::string::npos) << e.what();
    expect_caret_at_column(e);
  }
}

// A load of zero needs the gear's stop (geometry.gear.axial_play, physics §19) and the
// film's pressure; unloaded and at rest together (the washer and gear held where they came
// to rest, physics §19) is a schedule like any other, at a point or where an unloaded
// washer's speed turns back.
TEST(Schedule, ALoadOfZeroNeedsTheGearsStopAndTheFilm) {
  const std::string play = "geometry: {gear: {axial_play: 100 um}}\n";
  const TempScene fine(cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N}, {t: 3 s, load: 50 N, speed: -3000 rpm}]") + play);
  const Scene s = load_scene(fine.path());
  ASSERT_EQ(cycle(s).schedule.size(), 3u);
  EXPECT_EQ(cycle(s).schedule[1].load, 0.0);
  ASSERT_TRUE(s.gear.axial_play);
  EXPECT_NEAR(*s.gear.axial_play, 1e-4, 1e-16);
  // The resolved scene keeps the play.
  const TempScene resolved(describe_scene(s), "_resolved");
  const Scene r = load_scene(resolved.path());
  ASSERT_TRUE(r.gear.axial_play);
  EXPECT_EQ(*r.gear.axial_play, *s.gear.axial_play);

  const TempScene at_rest(cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N, speed: 0 rpm}]") + play);
  const Scene rest = load_scene(at_rest.path());
  ASSERT_EQ(cycle(rest).schedule.size(), 2u);
  EXPECT_EQ(cycle(rest).schedule[1].load, 0.0);
  EXPECT_EQ(cycle(rest).schedule[1].speed, 0.0);

  // A cycle starts loaded (its steady state is reached by raising the load), and a load of
  // zero needs the film's pressure to lift the washer.
  const TempScene unloaded_start(cycle_scene("[{t: 0 s, load: 0 N}, {t: 2 s, load: 100 N}]") + play);
  EXPECT_NE(std::string(testing::load_error(unloaded_start.path()).what()).find("starts unloaded"), std::string::npos);
  const TempScene contact_only(cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N}]") + play +
                               "effects: !replace [asperity_contact, thermal]\n");
  EXPECT_NE(std::string(testing::load_error(contact_only.path()).what()).find("needs the hydrodynamics effect"),
            std::string::npos);
  // Come to rest with its load, the washer may not leave the rest with its speed alone
  // (the gear is off its stop: physics §19); it may where it came to rest unloaded.
  const TempScene speed_alone(
      cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N, speed: 0 rpm}, {t: 3 s, speed: 3000 rpm}]") + play);
  const InputError e = testing::load_error(speed_alone.path());
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.column(), 59);  // the third point, where the speed alone leaves the rest
  EXPECT_NE(std::string(e.what()).find("leaves a rest with its speed alone"), std::string::npos) << e.what();
  const TempScene stopped_unloaded(cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N}, {t: 3 s, speed: 0 rpm}, "
                                               "{t: 4 s, speed: 3000 rpm}, {t: 5 s, load: 100 N}]") +
                                   play);
  EXPECT_EQ(cycle(load_scene(stopped_unloaded.path())).schedule.size(), 5u);
  const TempScene no_play(cycle_scene("[{t: 0 s}, {t: 2 s, load: 0 N, speed: 0 rpm}]"));
  EXPECT_NE(std::string(testing::load_error(no_play.path()).what()).find("axial_play"), std::string::npos);

  const TempScene csv("t [s], load [N], speed [rpm]\n0, 100, 3000\n1, 0, 3000\n2, 0, -3000\n", "_data", ".csv");
  const TempScene through(cycle_scene(csv.path()) + play);
  const Scene turned = load_scene(through.path());
  ASSERT_EQ(cycle(turned).schedule.size(), 3u);
  const TempScene csv_alone("t [s], load [N], speed [rpm]\n0, 100, 3000\n1, 0, 0\n2, 0, 0\n3, 0, 3000\n", "_alone",
                            ".csv");
  const InputError f = testing::load_error(TempScene(cycle_scene(csv_alone.path()) + play, "_alone_scene").path());
  EXPECT_EQ(f.file(), csv_alone.path());
  EXPECT_EQ(f.line(), 5);
  EXPECT_NE(std::string(f.what()).find("leaves a rest with its speed alone"), std::string::npos) << f.what();
  // (udunits2's rpm in rad/s, to its rounding.)
  EXPECT_NEAR(cycle(turned).schedule[2].speed, -100.0 * std::numbers::pi, 1e-12 * 100.0 * std::numbers::pi);
}

// A schedule file that is not there is the scene's fault, at its key.
TEST(Schedule, AMissingFileIsTheScenesFault) {
  const TempScene file(cycle_scene("no-such-cycle.csv"));
  const InputError e = testing::load_error(file.path());
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(std::string(e.what()).find("cannot read the schedule"), std::string::npos) << e.what();
}

// The march needs the bodies' heat: a duty cycle without the thermal effect is refused.
TEST(Schedule, ADutyCycleNeedsTheThermalEffect) {
  const TempScene file(cycle_scene("[{t: 0 s}, {t: 1 s}]") + "effects: [hydrodynamics, asperity_contact]\n");
  const InputError e = testing::load_error(file.path());
  EXPECT_NE(std::string(e.what()).find("needs the thermal effect"), std::string::npos) << e.what();
}

// The film's squeeze is solved with the Reynolds cavitation condition only: with the
// mass-conserving model the run is refused at the study's type, and says what to use.
TEST(Schedule, ADutyCycleRefusesTheMassConservingCavitationModel) {
  const TempScene file(cycle_scene("[{t: 0 s}, {t: 1 s}]") +
                       "effects: !replace [{hydrodynamics: {cavitation: jfo}}, asperity_contact, thermal]\n");
  const InputError e = testing::load_error(file.path());
  EXPECT_EQ(e.line(), 3);
  EXPECT_NE(std::string(e.what()).find("cavitation: reynolds"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace twb
