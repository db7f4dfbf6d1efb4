// The item model: commands and frames, DO_JUMP unrolled in ArduPilot's order, and the writers:
// read(write(m)) == m for a mission with every supported command, in both formats.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "wattswath/mission/files.hpp"
#include "wattswath/mission/planned_mission.hpp"

using namespace wattswath::mission;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

MissionItem item(int seq, Command c, int frame, std::initializer_list<double> params, double lat = 0, double lon = 0,
                 double alt = 0) {
  MissionItem it;
  it.seq = seq;
  it.command = static_cast<int>(c);
  it.frame = frame;
  int k = 0;
  for (double p : params) it.param[k++] = p;
  it.lat_deg = lat;
  it.lon_deg = lon;
  it.alt_m = alt;
  it.where = "item " + std::to_string(seq);
  return it;
}

/// Home at Pisa and one item of every supported command, in every frame a file may use.
Mission everyCommand() {
  Mission m;
  m.source = "every";
  m.home = {43.7160040, 10.4613040, 7.15};
  m.home_known = true;
  m.firmware_type = 3;
  m.vehicle_type = 2;
  m.plan_cruise_speed_mps = 12.5;
  m.plan_hover_speed_mps = 4.0;
  const double lat = 43.7161, lon = 10.4614;
  int s = 0;
  m.items = {
      item(++s, Command::NavTakeoff, 3, {0, 0, 0, kNaN}, lat, lon, 10),
      item(++s, Command::DoChangeSpeed, 2, {1, 6.5, -1, 0}),
      item(++s, Command::NavWaypoint, 3, {2, 1.5, 0, kNaN}, lat + 1e-4, lon, 12.25),
      item(++s, Command::NavSplineWaypoint, 6, {0, 0, 0, 0}, lat + 2e-4, lon + 1e-4, 15),
      item(++s, Command::NavLoiterTime, 0, {5, 0, 0, 0}, lat + 3e-4, lon, 40.5),
      item(++s, Command::NavLoiterTurns, 3, {2, 0, -25, 0}, lat + 6e-4, lon, 40.5),
      item(++s, Command::NavWaypoint, 10, {0, 0, 0, 0}, 43.71613579, 10.46161234, 20),
      item(++s, Command::NavWaypoint, 5, {0, 0, 0, 0}, 43.7162, 10.4617, 30),
      item(++s, Command::NavWaypoint, 11, {0, 0, 0, 0}, 43.7163, 10.4618, 25),
      item(++s, Command::NavDelay, 2, {3, -1, -1, -1}),
      item(++s, Command::ConditionDelay, 2, {2, 0, 0, 0}),
      item(++s, Command::ConditionYaw, 2, {90, 20, 1, 0}),
      item(++s, Command::DoSetCamTriggDist, 2, {25, 0, 1, 0}),
      item(++s, Command::DoSetRelay, 2, {0, 1, 0, 0}),
      item(++s, Command::DoSetServo, 2, {9, 1900, 0, 0}),
      item(++s, Command::DoSetRoi, 3, {0, 0, 0, 0}, lat, lon, 0),
      item(++s, Command::DoDigicamControl, 2, {0, 0, 0, 0}, 1, 0, 0),
      item(++s, Command::DoMountControl, 2, {-90, 0, 0, 0}, 0, 0, 2),
      item(++s, Command::DoGimbalManagerPitchyaw, 2, {-45, 0, kNaN, kNaN}, 0, 0, 0),
      item(++s, Command::SetCameraMode, 2, {0, 1, kNaN, kNaN}),
      item(++s, Command::ImageStartCapture, 2, {0, 2, 0, 0}),
      item(++s, Command::ImageStopCapture, 2, {0, 0, 0, 0}),
      item(++s, Command::VideoStartCapture, 2, {0, 1, 0, 0}),
      item(++s, Command::VideoStopCapture, 2, {0, 0, 0, 0}),
      item(++s, Command::DoJump, 2, {3, 2, 0, 0}),
      item(++s, Command::NavReturnToLaunch, 2, {0, 0, 0, 0}),
      item(++s, Command::NavLand, 3, {0, 0, 0, kNaN}, 0, 0, 0),
      item(++s, static_cast<Command>(195), 3, {0, 0, 0, 0}, lat, lon, 5),  // DO_SET_ROI_LOCATION (QGroundControl ROI)
      item(++s, static_cast<Command>(189), 0, {0, 0, 0, 0}, 0, 0, 0),     // DO_LAND_START (a marker)
      item(++s, static_cast<Command>(114), 2, {30, 0, 0, 0}),             // CONDITION_DISTANCE
  };
  m.items[5].autocontinue = false;
  return m;
}

}  // namespace

TEST(MissionItems, CommandsAndFrames) {
  EXPECT_EQ(commandName(16), "NAV_WAYPOINT");
  EXPECT_EQ(commandName(31337), "MAV_CMD 31337");
  EXPECT_TRUE(isNavCommand(22));
  EXPECT_FALSE(isNavCommand(178));
  EXPECT_TRUE(isSupportedCommand(206));
  EXPECT_TRUE(isSupportedCommand(17));    // loiter forever: the prediction ends on arrival
  EXPECT_FALSE(isSupportedCommand(31));   // loiter to an altitude: not modelled
  EXPECT_TRUE(isSupportedCommand(18));    // loiter turns: flown by the ArduCopter models
  EXPECT_TRUE(isSupportedCommand(197));   // DO_SET_ROI_NONE: does not move the vehicle
  EXPECT_FALSE(isSupportedCommand(211));  // DO_GRIPPER: a released payload changes the mass
  EXPECT_FALSE(isSupportedCommand(179));  // DO_SET_HOME moves the return point
  EXPECT_EQ(altitudeFrame(6), AltitudeFrame::Relative);
  EXPECT_EQ(altitudeFrame(11), AltitudeFrame::Terrain);
  EXPECT_THROW(altitudeFrame(1), std::invalid_argument);
}

TEST(MissionItems, UnrollJumpsFollowsArduPilot) {
  Mission m = everyCommand();
  m.items.resize(4);  // take-off, speed, waypoint, spline
  m.items.push_back(item(5, Command::DoJump, 2, {3, 2, 0, 0}));  // back to the waypoint, twice
  m.items.push_back(item(6, Command::NavWaypoint, 3, {0, 0, 0, 0}, 43.7161, 10.4614, 10));
  m.items.push_back(item(7, Command::DoJump, 2, {6, 1, 0, 0}));  // item 6 once more
  m.items.push_back(item(8, Command::NavReturnToLaunch, 2, {0, 0, 0, 0}));
  std::vector<int> order;
  for (const auto& it : unrollJumps(m)) order.push_back(it.seq);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3, 4, 3, 4, 3, 4, 6, 6, 8}));
  // Each DO_JUMP keeps its count for the whole mission: an inner loop runs on the first outer pass only.
  m.items[6] = item(7, Command::DoJump, 2, {1, 1, 0, 0});  // outer loop back to the take-off
  order.clear();
  for (const auto& it : unrollJumps(m)) order.push_back(it.seq);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3, 4, 3, 4, 3, 4, 6, 1, 2, 3, 4, 6, 8}));
  ReadOptions o;
  o.max_unrolled_items = 10;
  EXPECT_THROW(unrollJumps(m, o), MissionError);
  m.items[4].param[1] = -1;
  EXPECT_THROW(unrollJumps(m), MissionError);
}

TEST(MissionItems, EveryCommandRoundTripsThroughThePlanFormat) {
  const Mission m = everyCommand();
  Mission checked = m;
  checkMission(checked);
  EXPECT_TRUE(checked.warnings.empty());
  const std::string text = toQgcPlan(m);
  EXPECT_TRUE(checkQgcPlan(text).empty()) << checkQgcPlan(text).front();
  const Mission back = parseQgcPlan(text, "back.plan");
  EXPECT_EQ(back, m);
  for (size_t i = 0; i < m.items.size(); ++i) EXPECT_EQ(back.items[i], m.items[i]) << "item " << i + 1;
}

TEST(MissionItems, EveryCommandRoundTripsThroughTheWaypointsFormat) {
  Mission m = everyCommand();
  const Mission back = parseQgcWpl(toQgcWpl(m), "back.waypoints");
  // A .waypoints file carries no plan speeds, firmware or vehicle type.
  m.plan_cruise_speed_mps = m.plan_hover_speed_mps = 0.0;
  m.firmware_type = m.vehicle_type = 0;
  EXPECT_EQ(back, m);
  for (size_t i = 0; i < m.items.size(); ++i) EXPECT_EQ(back.items[i], m.items[i]) << "item " << i + 1;
}

TEST(MissionItems, WritersRenumberAndFollowJumpTargets) {
  Mission m = everyCommand();
  for (auto& it : m.items) it.seq += 10;  // e.g. after a lenient read dropped items
  m.items[24].param[0] = 13;              // the DO_JUMP to the waypoint, now item 13
  const Mission back = parseQgcPlan(toQgcPlan(m), "renumbered.plan");
  EXPECT_EQ(back, everyCommand());
}

TEST(MissionItems, PlannedMissionFilesReadBack) {
  PlannedMission p;
  p.home = {43.7200, 10.4200};
  p.home_altitude_amsl_m = 3.0;
  p.waypoints = {{{43.7201, 10.4201}, 10.0, 6.5, 0.0, {}}, {{43.7202, 10.4203}, 10.0, 3.0, 0.0, {}}};
  const Mission a = parseQgcPlan(toQgcPlan(p), "planned.plan");
  const Mission b = parseQgcWpl(toQgcWpl(p), "planned.waypoints");
  ASSERT_EQ(a.items.size(), 6u);  // take-off, speed, waypoint, speed, waypoint, return
  ASSERT_EQ(b.items.size(), a.items.size());
  for (size_t i = 0; i < a.items.size(); ++i) {
    EXPECT_EQ(a.items[i].command, b.items[i].command);
    EXPECT_NEAR(a.items[i].lat_deg, b.items[i].lat_deg, 1e-8);
  }
  EXPECT_DOUBLE_EQ(a.items[3].param[1], 3.0);
  EXPECT_DOUBLE_EQ(b.home.alt_m, 3.0);
}

TEST(MissionItems, WholePlanSpeedsAreWrittenAsIntegersForMissionPlanner) {
  Mission m = everyCommand();
  m.plan_cruise_speed_mps = 5.0;
  m.plan_hover_speed_mps = 3.0;
  const std::string text = toQgcPlan(m);
  const auto j = nlohmann::json::parse(text);
  EXPECT_TRUE(j["mission"]["cruiseSpeed"].is_number_integer());
  EXPECT_TRUE(j["mission"]["hoverSpeed"].is_number_integer());
  for (const auto& p : checkMissionPlannerPlan(text)) EXPECT_EQ(p.find("Speed"), std::string::npos) << p;
  EXPECT_DOUBLE_EQ(parseQgcPlan(text, "whole.plan").plan_cruise_speed_mps, 5.0);
  m.plan_cruise_speed_mps = 5.25;  // not whole: kept exactly (read(write(m)) == m), which Mission Planner refuses
  EXPECT_DOUBLE_EQ(parseQgcPlan(toQgcPlan(m), "real.plan").plan_cruise_speed_mps, 5.25);
}
