// The mission of a plan: waypoints never closer than kMinWaypointSpacing, no speed command below
// kMinCommandedSpeed (no 0.1 m/s placeholder), a command only where the speed changes by more than
// kSpeedChangeTolerance, and every sweep-line end still visited within kMinWaypointSpacing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/mission_from_plan.hpp"
#include "mission_fixtures.hpp"
#include "test_util.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::LegRole;
using geometry::Point;
using test::line;
using test::problemOf;
using test::turnInPlace;

namespace {

/// A flown path of `legs` with cruise speeds `cruise` [m/s] (junction speeds unused here).
FlownPath flown(const std::vector<geometry::PathLeg>& legs, const std::vector<double>& cruise) {
  FlownPath f;
  f.path.legs = legs;
  f.speeds.cruise = cruise;
  f.speeds.junction.assign(legs.size() + 1, 0.0);
  return f;
}

/// Checks the mission of `f` (planned for `pr`, converted with `frame`) for the rules of
/// mission_from_plan.hpp, on the waypoints and on the items the writers produce.
void expectHonestMission(const FlownPath& f, const SurveyProblem& pr, const geometry::LocalFrame& frame) {
  const auto pm = missionFromPlan(f, pr, frame, 0.0);
  const auto& wps = pm.mission.waypoints;
  ASSERT_FALSE(wps.empty());
  std::vector<Point> local;
  for (const auto& w : wps) local.push_back(frame.toLocal(w.position.lat_deg, w.position.lon_deg));
  for (size_t k = 0; k + 1 < local.size(); ++k)
    EXPECT_GE((local[k + 1] - local[k]).norm(), kMinWaypointSpacing - 1e-6) << "waypoints " << k << ", " << k + 1;
  for (size_t k = 0; k < wps.size(); ++k) {
    EXPECT_GE(wps[k].speed_mps, kMinCommandedSpeed) << "waypoint " << k;
    if (k > 0 && wps[k].speed_mps != wps[k - 1].speed_mps) {
      EXPECT_GT(std::abs(wps[k].speed_mps - wps[k - 1].speed_mps), kSpeedChangeTolerance) << "waypoint " << k;
    }
  }
  // Every sweep-line end within the spacing tolerance of a written waypoint (a start may be home).
  auto near = [&](const Point& p) {
    for (const auto& q : local)
      if ((p - q).norm() <= kMinWaypointSpacing + 1e-6) return true;
    return (p - pr.home).norm() <= kMinWaypointSpacing;
  };
  for (size_t i = 0; i < f.path.legs.size(); ++i) {
    const auto& leg = f.path.legs[i];
    if (leg.role != LegRole::Sweep) continue;
    EXPECT_TRUE(near(leg.start)) << "start of sweep leg " << i;
    EXPECT_TRUE(near(leg.end)) << "end of sweep leg " << i;
  }
  // The written items: no speed command below the floor (so none of 0.1 m/s), loadable by QGC.
  const std::string text = mission::toQgcPlan(pm.mission);
  EXPECT_TRUE(mission::checkQgcPlan(text).empty());
  const auto plan = nlohmann::json::parse(text);
  int commands = 0;
  for (const auto& item : plan["mission"]["items"]) {
    if (item["command"] != 178) continue;
    ++commands;
    EXPECT_GE(item["params"][1].get<double>(), kMinCommandedSpeed);
  }
  EXPECT_GE(commands, 1);
}

}  // namespace

TEST(MissionFromPlan, MergesShortLegsHoldsSmallChangesAndRaisesSlowSpeeds) {
  const auto f = flown({line({0, 0}, {100, 0}),                          // 0: sweep at 8
                        turnInPlace({100, 0}),                              // 1: no waypoint
                        line({100, 0}, {100, 0.001}, LegRole::Transit),     // 2: 1 mm join, merged
                        line({100, 0.001}, {100, 15}, LegRole::Transit),    // 3: 8.03, held at 8
                        line({100, 15}, {95, 15}),                          // 4: 0.05 -> 1 m/s, noted
                        line({95, 15}, {94.7, 15}),                         // 5: 0.3 m, merged
                        line({94.7, 15}, {0, 15})},                         // 6: 6 m/s
                       {8.0, 0.0, 2.7, 8.03, 0.05, 0.3, 6.0});
  const auto m = missionWaypoints(f);
  ASSERT_EQ(m.waypoints.size(), 4u);
  const std::vector<int> legs = {0, 3, 4, 6};
  const std::vector<double> speeds = {8.0, 8.0, kMinCommandedSpeed, 6.0};
  for (size_t k = 0; k < legs.size(); ++k) {
    EXPECT_EQ(m.waypoints[k].leg, legs[k]);
    EXPECT_DOUBLE_EQ(m.waypoints[k].speed_mps, speeds[k]) << "waypoint " << k;
    EXPECT_EQ(m.waypoints[k].position, f.path.legs[legs[k]].end);
  }
  EXPECT_DOUBLE_EQ(m.waypoints[1].planned_speed_mps, 8.03);
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_NE(m.notes[0].find("leg 4;"), std::string::npos) << m.notes[0];
  EXPECT_NE(m.notes[0].find("1.0 m/s"), std::string::npos) << m.notes[0];
  // The writer puts a speed command only where the speed changes: 8, 1, 6.
  SurveyProblem pr;
  const geometry::LocalFrame frame({43.7, 10.4, 0.0});
  const auto pm = missionFromPlan(f, pr, frame, 3.0);
  EXPECT_DOUBLE_EQ(pm.mission.cruise_speed_mps, 8.03);
  const auto plan = nlohmann::json::parse(mission::toQgcPlan(pm.mission));
  int commands = 0;
  for (const auto& item : plan["mission"]["items"])
    commands += item["command"] == 178;
  EXPECT_EQ(commands, 3);
  expectHonestMission(f, pr, frame);
}

// Speed commands a waypoint early never raise a leg flown with the camera on to a transit's speed,
// whether the autopilot flies a command on its own leg or the next (a sortie's last sweep was flown
// at its transit home's 10.5 m/s where the trigger interval capped the sweeps at 5.25: a photo every
// 21 m for 10.5 m); between two camera legs they are still raised.
TEST(MissionFromPlan, EarlySpeedsKeepACameraLegAtItsOwnSpeed) {
  const auto f = flown({line({0, -20}, {0, 0}, LegRole::Transit),     // 0: 12 m/s, camera on at its end
                        line({0, 0}, {50, 0}),                          // 1: sweep at 4
                        line({50, 0}, {100, 0}),                        // 2: sweep at 5
                        line({100, 0}, {100, 50}, LegRole::Transit)},  // 3: home at 12
                       {12.0, 4.0, 5.0, 12.0});
  MissionOptions o;
  o.trigger_distance_m = 10.0;
  o.speeds_a_waypoint_early = true;
  const auto m = missionWaypoints(f, o);
  ASSERT_EQ(m.waypoints.size(), 4u);
  EXPECT_DOUBLE_EQ(m.waypoints[0].speed_mps, 4.0);   // into the first sweep: flown on it by a 3.x autopilot
  EXPECT_DOUBLE_EQ(m.waypoints[1].speed_mps, 5.0);   // a camera leg raised to the next camera leg's speed
  EXPECT_DOUBLE_EQ(m.waypoints[2].speed_mps, 5.0);   // the last sweep: not 12
  EXPECT_DOUBLE_EQ(*m.waypoints[2].camera_trigger_m, 0.0);
}

// A sweep stub shorter than the least waypoint spacing is merged into the waypoint that turned the
// camera on: that run takes no photo and writes no command, where "on" was overwritten by "off"
// (a stray DO_SET_CAM_TRIGG_DIST 0 with no "on" before it, and a photo the count missed).
TEST(MissionFromPlan, AMergedSweepStubWritesNoStrayCameraOff) {
  const auto f = flown({line({0, -20}, {0, 0}, LegRole::Transit),     // 0: to the stub
                        line({0, 0}, {0.3, 0}),                         // 1: a 0.3 m sweep, merged
                        line({0.3, 0}, {0, 20}, LegRole::Turn),         // 2
                        line({0, 20}, {100, 20}),                       // 3: a real sweep
                        line({100, 20}, {100, 40}, LegRole::Transit)},  // 4
                       {8.0, 5.0, 5.0, 5.0, 8.0});
  MissionOptions o;
  o.trigger_distance_m = 10.0;
  const auto m = missionWaypoints(f, o);
  bool on = false;
  int runs = 0;
  for (const auto& w : m.waypoints) {
    if (!w.camera_trigger_m) continue;
    if (*w.camera_trigger_m > 0.0) {
      EXPECT_FALSE(on);
      on = true;
      ++runs;
    } else {
      EXPECT_TRUE(on) << "a camera off with no camera on before it";
      on = false;
    }
  }
  EXPECT_FALSE(on);
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(m.camera_runs, 1);
  // A run ending where a stub starts (the turn between them merged too): the stub gives back the
  // "off" that ended the run before (it left the camera on through the transit that followed).
  const auto g = flown({line({0, 0}, {50, 0}),                          // 0: sweep A from home
                        line({50, 0}, {50, 0.3}, LegRole::Turn),        // 1: merged: "off" at (50, 0)
                        line({50, 0.3}, {50.2, 0.3}),                   // 2: stub, merged
                        line({50.2, 0.3}, {50, 20}, LegRole::Turn),     // 3
                        line({50, 20}, {50, 60}, LegRole::Transit)},    // 4
                       {5.0, 5.0, 5.0, 5.0, 8.0});
  const auto n = missionWaypoints(g, o);
  on = false;
  for (const auto& w : n.waypoints) {
    if (!w.camera_trigger_m) continue;
    EXPECT_EQ(*w.camera_trigger_m > 0.0, !on) << "camera commands alternate on, off";
    on = *w.camera_trigger_m > 0.0;
  }
  EXPECT_FALSE(on) << "the camera is left on";
}

TEST(MissionFromPlan, ExampleAreaMissionHasNoPlaceholderSpeedsOrDegenerateWaypoints) {
  // scripts/example.sh: the bundled IRIS+ area with its no-fly zone, 15 m spacing.
  const auto area = geometry::readSurveyArea(test::sourcePath("data/areas/iris_area.geojson"));
  ASSERT_TRUE(area.frame);
  const auto pr = problemOf(area, 15.0);
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  const auto r = planCoverage(pr, v, energy::marinsModel(v));
  ASSERT_TRUE(r.plan.valid);
  expectHonestMission(r.plan.flown, pr, *area.frame);
}

TEST(MissionFromPlan, ReferenceAreaMissionsKeepTheRules) {
  // The E-Spiral areas whose missions had 0.1 m/s commands and waypoints 0 m apart, both searches.
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  const auto model = energy::marinsModel(v);
  for (const std::string name : {"rectangle", "area01", "polygon", "spiral_concave", "spiral_polygon"}) {
    const auto file = test::sharedData("espiral/area__" + name + ".waypoints");
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
    const auto area = geometry::readSurveyArea(file);
    ASSERT_TRUE(area.frame);
    const auto pr = problemOf(area, 0.0);
    for (bool spirals : {true, false}) {
      SCOPED_TRACE(name + (spirals ? "" : ", no spirals"));
      PlannerSettings ps;
      ps.spirals = spirals;
      const auto r = planCoverage(pr, v, model, ps);
      ASSERT_TRUE(r.plan.valid);
      expectHonestMission(r.plan.flown, pr, *area.frame);
    }
  }
}

// An arc written as waypoints along it: every chord within kArcChordSagitta of the arc; as
// chords (the default) one waypoint at its end, the autopilot's cornering doing the rest.
TEST(MissionFromPlan, ArcsAsWaypointsKeepEveryChordWithinTheSagitta) {
  geometry::PathLeg arc;
  arc.kind = geometry::PrimitiveKind::Arc;
  arc.role = LegRole::Turn;
  arc.center = {100, 7.5};
  arc.radius = 7.5;
  arc.start = {100, 0};
  arc.end = {100, 15};
  arc.turn_angle = M_PI;  // a U-turn of 7.5 m radius: a single chord would pass 7.5 m inside it
  const auto f = flown({line({0, 0}, {100, 0}), arc, line({100, 15}, {0, 15})}, {8.0, 3.0, 8.0});
  MissionOptions o;
  EXPECT_EQ(missionWaypoints(f, o).waypoints.size(), 3u);
  o.arc_waypoints = true;
  const auto m = missionWaypoints(f, o);
  ASSERT_GT(m.waypoints.size(), 4u);
  for (size_t k = 1; k < m.waypoints.size(); ++k) {
    const geometry::Point a = m.waypoints[k - 1].position, b = m.waypoints[k].position;
    if ((a - arc.center).norm() > arc.radius + 1e-6 || (b - arc.center).norm() > arc.radius + 1e-6) continue;  // sweep legs
    EXPECT_NEAR((a - arc.center).norm(), arc.radius, 1e-6);
    EXPECT_LE(arc.radius - (0.5 * (a + b) - arc.center).norm(), kArcChordSagitta + 1e-9) << "chord " << k;
    EXPECT_GE((b - a).norm(), kMinWaypointSpacing);
  }
}
