// What the mission encodes beyond waypoints and speeds: photos (trigger distance from the camera
// and the frontal overlap, camera on along each sweep and off on transits, the photo count), holds
// at planned stops, the vehicle type, and the no-fly margin and inclusion fence that every flown
// point keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/clearance.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/planner/camera.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/margin.hpp"
#include "wattswath/planner/mission_from_plan.hpp"
#include "mission_fixtures.hpp"
#include "test_util.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::LegRole;
using geometry::Point;
using geometry::PrimitiveKind;
using test::line;
using test::problemOf;
using test::turnInPlace;

namespace {

/// Home (0, 0), up to the first sweep, two sweeps of 100 m joined by a 15 m turn, back home; the
/// planned speed at the end of each leg in `end_speeds` (the start is a stop).
FlownPath twoSweeps(const std::vector<double>& end_speeds) {
  FlownPath f;
  f.path.legs = {line({0, 0}, {0, 10}, LegRole::Transit),   line({0, 10}, {100, 10}, LegRole::Sweep),
                 line({100, 10}, {100, 25}, LegRole::Turn), line({100, 25}, {0, 25}, LegRole::Sweep),
                 line({0, 25}, {0, 0}, LegRole::Transit)};
  f.speeds.cruise = {5.0, 8.0, 3.0, 8.0, 6.0};
  f.speeds.junction = {0.0};
  f.speeds.junction.insert(f.speeds.junction.end(), end_speeds.begin(), end_speeds.end());
  return f;
}

}  // namespace

TEST(Photos, TriggerDistanceOfAWorkedExampleAsQgcComputesIt) {
  // QGC's camera list: Sony ILCE-QX1, 23.2 x 15.4 mm sensor, 5456 x 3632 px, 16 mm lens; at 50 m.
  // GSD = 50 * 23.2 / (5456 * 16) = 1.3288 cm/px; side footprint 5456 px * GSD = 72.5 m; frontal
  // footprint 3632 px * GSD = 48.26 m; 70 % side and 80 % frontal overlap.
  const auto cam = Camera::fromSensor(23.2, 15.4, 16.0, 5456, 3632);
  const auto g = photoGeometry(cam, 50.0, 0.7, 0.8);
  EXPECT_NEAR(g.gsd_m, 50.0 * 23.2 / (5456.0 * 16.0), 1e-12);
  EXPECT_NEAR(g.footprint_across_m, 72.5, 1e-9);
  EXPECT_NEAR(g.footprint_along_m, 3632.0 * 50.0 * 23.2 / (5456.0 * 16.0), 1e-9);
  EXPECT_NEAR(g.line_spacing_m, 0.3 * 72.5, 1e-9);
  EXPECT_NEAR(g.trigger_distance_m, 0.2 * 48.262463343108504, 1e-9);  // 9.65 m between photos
  // Without the image size the sensor height gives the frontal footprint (50 * 15.4 / 16 m).
  EXPECT_NEAR(photoGeometry(Camera::fromSensor(23.2, 15.4, 16.0), 50.0, 0.7, 0.8).footprint_along_m, 48.125, 1e-9);
  // Fields of view: the E-Spiral camera (100 deg, square footprint) at 10 m, 10 % side, 60 % frontal.
  Camera wide;
  wide.fov_across_rad = wide.fov_along_rad = 100.0 * M_PI / 180.0;
  const auto e = photoGeometry(wide, 10.0, 0.1, 0.6);
  EXPECT_NEAR(e.footprint_across_m, 20.0 * std::tan(50.0 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(e.line_spacing_m, 21.452, 1e-3);
  EXPECT_NEAR(e.trigger_distance_m, 0.4 * e.footprint_along_m, 1e-12);
  EXPECT_EQ(e.gsd_m, 0.0);  // image width unknown
}

TEST(Photos, BadCamerasAndOverlapsAreRefused) {
  EXPECT_THROW(Camera::fromSensor(0.0, 15.4, 16.0), std::invalid_argument);
  EXPECT_THROW(Camera::fromSensor(23.2, 15.4, -1.0), std::invalid_argument);
  const auto cam = Camera::fromSensor(23.2, 15.4, 16.0);
  EXPECT_THROW(photoGeometry(cam, 50.0, 0.7, 1.0), std::invalid_argument);
  EXPECT_THROW(photoGeometry(cam, 50.0, -0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(photoGeometry(cam, 0.0, 0.7, 0.5), std::invalid_argument);
  Camera flat;
  flat.fov_across_rad = M_PI;
  flat.fov_along_rad = 1.0;
  EXPECT_THROW(photoGeometry(flat, 10.0, 0.1, 0.1), std::invalid_argument);
}

TEST(Photos, CountIsOneAtTheStartOnePerDistanceAndOneAtTheEnd) {
  EXPECT_EQ(photosAlong(100.0, 10.0), 11);  // 0, 10, ..., 100
  EXPECT_EQ(photosAlong(95.0, 10.0), 11);   // 0, 10, ..., 90 and 95
  EXPECT_EQ(photosAlong(100.0 - 1e-12, 10.0), 11);
  EXPECT_EQ(photosAlong(0.0, 10.0), 1);
  EXPECT_EQ(photosAlong(50.0, 0.0), 0);
}

TEST(MissionPhotos, CameraOnAlongEachSweepOffOnTurnsAndTransits) {
  MissionOptions o;
  o.trigger_distance_m = 10.0;
  const auto m = missionWaypoints(twoSweeps({0, 3, 3, 0, 0}), o);
  ASSERT_EQ(m.waypoints.size(), 5u);
  const std::vector<double> camera = {10.0, 0.0, 10.0, 0.0};
  for (size_t k = 0; k < camera.size(); ++k) {
    ASSERT_TRUE(m.waypoints[k].camera_trigger_m) << "waypoint " << k;
    EXPECT_DOUBLE_EQ(*m.waypoints[k].camera_trigger_m, camera[k]) << "waypoint " << k;
  }
  EXPECT_FALSE(m.waypoints[4].camera_trigger_m);  // home: no camera command
  EXPECT_EQ(m.camera_runs, 2);
  EXPECT_EQ(m.photos, 22);  // 11 per 100 m sweep
  EXPECT_DOUBLE_EQ(m.camera_length_m, 200.0);
  // Without a trigger distance there is no camera command at all.
  const auto none = missionWaypoints(twoSweeps({0, 3, 3, 0, 0}));
  for (const auto& w : none.waypoints) EXPECT_FALSE(w.camera_trigger_m);
  EXPECT_EQ(none.photos, 0);
  // Written as QGC's survey writes it: the sweep's first waypoint, then DO_SET_CAM_TRIGG_DIST.
  SurveyProblem pr;
  const geometry::LocalFrame frame({43.7, 10.4, 0.0});
  const auto pm = missionFromPlan(twoSweeps({0, 3, 3, 0, 0}), pr, frame, 0.0, o);
  EXPECT_EQ(pm.photos, 22);
  const std::string text = mission::toQgcPlan(pm.mission);
  EXPECT_TRUE(mission::checkQgcPlan(text).empty());
  EXPECT_TRUE(mission::checkMissionPlannerPlan(text).empty());
  const auto plan = nlohmann::json::parse(text);
  std::vector<int> commands;
  for (const auto& item : plan["mission"]["items"]) commands.push_back(item["command"]);
  const std::vector<int> expected = {22, 178, 16, 206, 178, 16, 206, 178, 16, 206, 178, 16, 206, 178, 16, 20};
  EXPECT_EQ(commands, expected);
}

TEST(MissionPhotos, ATurnInPlaceInsideASweepRunKeepsTheCameraOn) {
  FlownPath f;
  f.path.legs = {line({0, 0}, {0, 10}, LegRole::Transit), line({0, 10}, {50, 10}, LegRole::Sweep),
                 turnInPlace({50, 10}, LegRole::Sweep), line({50, 10}, {50, 60}, LegRole::Sweep),
                 line({50, 60}, {0, 0}, LegRole::Transit)};
  f.speeds.cruise = {5.0, 8.0, 0.0, 8.0, 6.0};
  f.speeds.junction = {0, 0, 0, 0, 0, 0};
  MissionOptions o;
  o.trigger_distance_m = 20.0;
  const auto m = missionWaypoints(f, o);
  EXPECT_EQ(m.camera_runs, 1);
  EXPECT_EQ(m.photos, photosAlong(100.0, 20.0));
  EXPECT_FALSE(m.waypoints[1].camera_trigger_m);  // the corner: neither on nor off
  EXPECT_DOUBLE_EQ(m.waypoints[1].hold_s, kStopHoldSeconds);  // but a stop
}

TEST(MissionHolds, PlannedStopsHoldFlownThroughJunctionsDoNot) {
  // Stops after the transit and the second sweep; the turn is flown through at 3 m/s.
  const auto m = missionWaypoints(twoSweeps({0, 3, 3, 0, 0}));
  ASSERT_EQ(m.waypoints.size(), 5u);
  const std::vector<double> holds = {kStopHoldSeconds, 0, 0, kStopHoldSeconds, 0};  // home last: RTL stops there
  for (size_t k = 0; k < holds.size(); ++k) EXPECT_DOUBLE_EQ(m.waypoints[k].hold_s, holds[k]) << "waypoint " << k;
  EXPECT_EQ(m.holds, 2);
  MissionOptions o;
  o.stop_hold_s = 0.0;
  EXPECT_EQ(missionWaypoints(twoSweeps({0, 3, 3, 0, 0}), o).holds, 0);
  o.stop_hold_s = -1.0;
  EXPECT_THROW(missionWaypoints(twoSweeps({0, 3, 3, 0, 0}), o), std::invalid_argument);
}

TEST(MissionVehicle, VehicleTypeFollowsTheRotorCount) {
  SurveyProblem pr;
  const geometry::LocalFrame frame({43.7, 10.4, 0.0});
  MissionOptions o;
  o.rotor_count = 6;
  EXPECT_EQ(missionFromPlan(twoSweeps({0, 3, 3, 0, 0}), pr, frame, 0.0, o).mission.vehicle_type, 13);
  o.rotor_count = 5;
  const auto pm = missionFromPlan(twoSweeps({0, 3, 3, 0, 0}), pr, frame, 0.0, o);
  EXPECT_EQ(pm.mission.vehicle_type, 2);
  ASSERT_FALSE(pm.notes.empty());
  EXPECT_NE(pm.notes.back().find("5 rotors"), std::string::npos) << pm.notes.back();
}

TEST(NoFlyMargin, ZonesGrowByTheMarginAndNotchTheBoundary) {
  SurveyProblem pr;
  pr.area.outer = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  pr.area.holes = {{{40, 40}, {40, 60}, {60, 60}, {60, 40}}};
  pr.no_fly = {{{90, 45}, {110, 45}, {110, 55}, {90, 55}}};  // crosses the east edge
  pr.home = {5, 5};
  EXPECT_EQ(withNoFlyMargin(pr, 0.0).area.holes, pr.area.holes);
  const auto m = withNoFlyMargin(pr, 2.0);
  ASSERT_EQ(m.area.holes.size(), 1u);
  ASSERT_EQ(m.no_fly.size(), 2u);
  // Every point within 2 m of the hole is in the grown hole; the notch takes the zone plus 2 m.
  const Point c(40, 40);
  for (const Point& p : {Point(38.1, 50), Point(61.9, 50), Point(50, 38.1), Point(50, 61.9),
                         Point(c - Point(1.9, 1.9) / std::sqrt(2.0))})
    EXPECT_TRUE(geometry::insideRing(m.area.holes[0], p)) << p.transpose();
  EXPECT_FALSE(geometry::insideRing(m.area.outer, {88.1, 50}));
  // Areas: each grown square corner is a quarter of the 16-gon of inradius g (geometry::inflateRings).
  const double g = 2.0 + kMarginPad, corner = g * g * (1.0 - 4.0 * std::tan(M_PI / 16.0));
  const double hole = (20 + 2 * g) * (20 + 2 * g) - 4 * corner, notch = (10 + g) * (10 + 2 * g) - 2 * corner;
  EXPECT_NEAR(geometry::area(m.area), 10000.0 - hole - notch, 1e-6);
  // Home within the margin of a zone: refused, naming the distance.
  pr.home = {39, 50};
  try {
    withNoFlyMargin(pr, 2.0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("1.00 m from no-fly zone 0"), std::string::npos) << e.what();
  }
  pr.home = {5, 5};
  EXPECT_THROW(withNoFlyMargin(pr, -1.0), std::invalid_argument);
  EXPECT_THROW(withNoFlyMargin(pr, 60.0), std::invalid_argument);  // nothing left of the area
}

TEST(NoFlyMargin, ExampleAreaPlanKeepsTheMarginAndTheFence) {
  // scripts/example.sh: the bundled IRIS+ area, its no-fly zone a hole, 15 m spacing. Without the
  // margin the plan's legs pass under 2 m from the zone (issue 17); with it none does.
  const auto area = geometry::readSurveyArea(test::sourcePath("data/areas/iris_area.geojson"));
  ASSERT_TRUE(area.frame);
  const auto pr = problemOf(area, 15.0);
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  const auto model = energy::marinsModel(v);
  const auto zones = noFlyZones(pr);
  const auto bare = planCoverage(pr, v, model);
  EXPECT_FALSE(geometry::marginViolations(bare.plan.flown.path, zones, kDefaultNoFlyMargin).empty());
  const auto kept = planCoverage(withNoFlyMargin(pr, kDefaultNoFlyMargin), v, model);
  ASSERT_TRUE(kept.plan.valid);
  EXPECT_GE(kept.plan.coverage_pct, 99.0);
  const auto& path = kept.plan.flown.path;
  const auto close = geometry::marginViolations(path, zones, kDefaultNoFlyMargin);
  EXPECT_TRUE(close.empty()) << "leg " << close.front().leg << " at " << close.front().distance_m << " m";
  EXPECT_TRUE(checkPlan(pr, path).empty());
  // The inclusion fence keeps every flown point 2 m inside it, home included.
  const auto fence = inclusionFence(pr, path, kDefaultNoFlyMargin);
  EXPECT_TRUE(geometry::fenceViolations(path, fence.ring, kDefaultNoFlyMargin).empty());
  EXPECT_TRUE(geometry::insideRing(fence.ring, pr.home, kDefaultNoFlyMargin));
  EXPECT_GE(fence.distance_m, kDefaultNoFlyMargin);
  // The mission: the fence first, the zone, holds at the planned stops; both loaders accept it.
  MissionOptions o;
  o.fence_margin_m = o.no_fly_margin_m = kDefaultNoFlyMargin;
  const auto pm = missionFromPlan(kept.plan.flown, pr, *area.frame, 0.0, o);
  EXPECT_EQ(pm.legs_within_margin, 0);  // the chords between the waypoints keep it too
  EXPECT_EQ(pm.mission.fence_inclusion.size(), fence.ring.size());
  EXPECT_EQ(pm.mission.no_fly.size(), 1u);
  EXPECT_GT(pm.holds, 0);
  const std::string text = mission::toQgcPlan(pm.mission);
  EXPECT_TRUE(mission::checkQgcPlan(text).empty());
  EXPECT_TRUE(mission::checkMissionPlannerPlan(text).empty());
}

TEST(NoFlyMargin, SharedIrisAreaWithObstacleFileKeepsTheMargin) {
  const auto file = test::sharedData("iris-flights/plan__real_flight_area.waypoints");
  const auto zones_file = test::sharedData("iris-flights/plan__real_flight_obstacles.waypoints");
  if (!std::filesystem::exists(file) || !std::filesystem::exists(zones_file)) GTEST_SKIP() << "no shared data";
  geometry::ReadOptions ro;
  ro.no_fly_files = {zones_file};
  const auto area = geometry::readSurveyArea(file, ro);
  const auto pr = problemOf(area, 15.0);
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  const auto r = planCoverage(withNoFlyMargin(pr, kDefaultNoFlyMargin), v, energy::marinsModel(v));
  ASSERT_TRUE(r.plan.valid);
  EXPECT_TRUE(geometry::marginViolations(r.plan.flown.path, noFlyZones(pr), kDefaultNoFlyMargin).empty());
}

TEST(NoFlyMargin, AChordThatCutsIntoTheMarginIsNoted) {
  // A half circle of radius 10 around a zone 1-3 m east of its centre: the arc keeps 6.8 m, the
  // chord the autopilot flies between its ends passes 1 m from the zone.
  FlownPath f;
  f.path.legs = {line({-20, -10}, {0, -10}, LegRole::Sweep)};
  geometry::PathLeg a;
  a.kind = PrimitiveKind::Arc;
  a.role = LegRole::Turn;
  a.center = {0, 0};
  a.radius = 10.0;
  a.turn_angle = M_PI;
  a.start = {0, -10};
  a.end = {0, 10};
  f.path.legs.push_back(a);
  f.path.legs.push_back(line({0, 10}, {-20, 10}, LegRole::Sweep));
  f.speeds.cruise = {5.0, 3.0, 5.0};
  f.speeds.junction = {0.0, 3.0, 3.0, 0.0};
  SurveyProblem pr;
  pr.home = {-20, -10};
  pr.no_fly = {{{1, -1}, {3, -1}, {3, 1}, {1, 1}}};
  EXPECT_TRUE(geometry::marginViolations(f.path, pr.no_fly, 2.0).empty());
  MissionOptions o;
  o.no_fly_margin_m = 2.0;
  const auto pm = missionFromPlan(f, pr, geometry::LocalFrame({43.7, 10.4, 0.0}), 0.0, o);
  EXPECT_EQ(pm.legs_within_margin, 1);
  ASSERT_FALSE(pm.notes.empty());
  EXPECT_NE(pm.notes.back().find("waypoint 2 (of 3) passes 1.00 m from no-fly zone 0"), std::string::npos)
      << pm.notes.back();
}
