// Mission writers: the .plan is checked against the keys and types QGroundControl's loader needs
// and against Mission Planner's reader; holds, camera commands, vehicle type and fences written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "wattswath/mission/autopilot.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/flight.hpp"
#include "wattswath/mission/planned_mission.hpp"

using namespace wattswath::mission;

namespace {
PlannedMission sample() {
  PlannedMission m;
  m.home = {43.7200, 10.4200};
  m.home_altitude_amsl_m = 3.0;
  m.takeoff_altitude_m = 10.0;
  m.waypoints = {{{43.7201, 10.4201}, 10.0, 6.5, 0.0, {}}, {{43.7202, 10.4203}, 10.0, 6.5, 0.0, {}}, {{43.7203, 10.4201}, 10.0, 3.0, 0.0, {}}};
  m.no_fly = {{{43.7210, 10.4210}, {43.7211, 10.4210}, {43.7211, 10.4212}}};
  return m;
}

/// sample() as a survey: camera on at waypoint 0, off at waypoint 1 with a 1 s hold there, a
/// hexacopter, an inclusion fence around it all.
PlannedMission survey() {
  PlannedMission m = sample();
  m.waypoints[0].camera_trigger_m = 14.5;
  m.waypoints[1].camera_trigger_m = 0.0;
  m.waypoints[1].hold_s = 1.0;
  m.vehicle_type = *mavTypeOfRotors(6);
  m.cruise_speed_mps = m.hover_speed_mps = 6.5;
  m.fence_inclusion = {{43.7190, 10.4190}, {43.7190, 10.4220}, {43.7220, 10.4220}, {43.7220, 10.4190}};
  return m;
}
}  // namespace

TEST(PlannedMission, QgcPlanLoadsByQgcRules) {
  const std::string text = toQgcPlan(sample());
  EXPECT_TRUE(checkQgcPlan(text).empty()) << checkQgcPlan(text).front();
  EXPECT_TRUE(checkMissionPlannerPlan(text).empty()) << checkMissionPlannerPlan(text).front();
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["fileType"], "Plan");
  EXPECT_EQ(j["mission"]["firmwareType"], 3);
  EXPECT_EQ(j["mission"]["vehicleType"], 2);
  const auto& items = j["mission"]["items"];
  // take-off, speed 6.5, wp, wp, speed 3.0, wp, RTL
  ASSERT_EQ(items.size(), 7u);
  EXPECT_EQ(items[0]["command"], 22);
  EXPECT_EQ(items[1]["command"], 178);
  EXPECT_DOUBLE_EQ(items[1]["params"][1].get<double>(), 6.5);
  EXPECT_EQ(items[2]["command"], 16);
  EXPECT_EQ(items[4]["command"], 178);
  EXPECT_EQ(items[6]["command"], 20);
  for (size_t i = 0; i < items.size(); ++i) EXPECT_EQ(items[i]["doJumpId"], static_cast<int>(i) + 1);
  EXPECT_EQ(j["geoFence"]["polygons"][0]["inclusion"], false);
  EXPECT_EQ(j["geoFence"]["polygons"][0]["polygon"].size(), 3u);
}

TEST(PlannedMission, CheckerFindsBrokenPlans) {
  auto j = nlohmann::json::parse(toQgcPlan(sample()));
  j["mission"]["items"][2].erase("autoContinue");
  j["mission"]["items"][3]["params"] = {1, 2, 3};
  j["fileType"] = "Mission";
  const auto problems = checkQgcPlan(j.dump());
  EXPECT_EQ(problems.size(), 3u);
  EXPECT_FALSE(checkQgcPlan("{not json").empty());
}

TEST(PlannedMission, WplHasHomeRowAndTwelveTabbedColumns) {
  const std::string text = toQgcWpl(sample());
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "QGC WPL 110");
  int rows = 0;
  while (std::getline(in, line)) {
    int tabs = 0;
    for (char c : line) tabs += c == '\t';
    EXPECT_EQ(tabs, 11) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 8);  // home + 7 items
}

TEST(PlannedMission, InvalidMissionsAreRejectedWithTheField) {
  PlannedMission m = sample();
  m.waypoints[1].position.lat_deg = 95.0;
  try {
    toQgcPlan(m);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("waypoint 1 latitude"), std::string::npos) << e.what();
  }
  m = sample();
  m.waypoints.clear();
  EXPECT_THROW(toQgcWpl(m), std::invalid_argument);
  m = sample();
  m.waypoints[0].speed_mps = 0.0;
  EXPECT_THROW(toQgcPlan(m), std::invalid_argument);
}

TEST(PlannedMission, CsvCarriesSpeedAndEnergy) {
  LegRecord l;
  l.start = {43.72, 10.42};
  l.end = {43.721, 10.421};
  l.kind = "line";
  l.role = "sweep";
  l.length_m = 120.0;
  l.speed_cruise_mps = 8.0;
  l.energy_j = 3000.0;
  const std::string csv = toLegCsv({l});
  EXPECT_EQ(csv.substr(0, 4), "leg,");
  EXPECT_NE(csv.find("3000.00"), std::string::npos);
  EXPECT_NE(csv.find("\n1,line,sweep,"), std::string::npos) << csv;  // numbered from 1, as the plan report counts
}

TEST(PlannedMission, CameraCommandsHoldsVehicleTypeAndFences) {
  const std::string text = toQgcPlan(survey());
  EXPECT_TRUE(checkQgcPlan(text).empty()) << checkQgcPlan(text).front();
  EXPECT_TRUE(checkMissionPlannerPlan(text).empty()) << checkMissionPlannerPlan(text).front();
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["mission"]["vehicleType"], 13);
  // Integers, as Mission Planner's MissionFile.Mission declares them: 6.5 m/s is written 7 (rounded).
  EXPECT_TRUE(j["mission"]["cruiseSpeed"].is_number_integer());
  EXPECT_EQ(j["mission"]["cruiseSpeed"], 7);
  EXPECT_EQ(j["mission"]["hoverSpeed"], 7);
  const auto& items = j["mission"]["items"];
  // take-off, speed 6.5, wp 0, camera 14.5, wp 1 (hold 1), camera 0, speed 3.0, wp 2, RTL
  ASSERT_EQ(items.size(), 9u);
  const std::vector<int> commands = {22, 178, 16, 206, 16, 206, 178, 16, 20};
  for (size_t i = 0; i < items.size(); ++i) EXPECT_EQ(items[i]["command"], commands[i]) << "item " << i;
  EXPECT_DOUBLE_EQ(items[3]["params"][0].get<double>(), 14.5);
  EXPECT_EQ(items[3]["params"][2], 1);  // one photo at once, as QGC's survey
  EXPECT_EQ(items[3]["frame"], 2);
  EXPECT_DOUBLE_EQ(items[5]["params"][0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(items[2]["params"][0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(items[4]["params"][0].get<double>(), 1.0);  // the hold
  const auto& fence = j["geoFence"]["polygons"];
  ASSERT_EQ(fence.size(), 2u);
  EXPECT_TRUE(fence[0]["inclusion"].get<bool>());
  EXPECT_EQ(fence[0]["polygon"].size(), 4u);
  EXPECT_FALSE(fence[1]["inclusion"].get<bool>());
}

TEST(PlannedMission, SurveyReadsBackWithTheMissionReaders) {
  const Mission a = parseQgcPlan(toQgcPlan(survey()), "survey.plan");
  const Mission b = parseQgcWpl(toQgcWpl(survey()), "survey.waypoints");
  ASSERT_EQ(a.items.size(), 9u);
  ASSERT_EQ(b.items.size(), 9u);
  for (size_t i = 0; i < a.items.size(); ++i) {
    EXPECT_EQ(a.items[i].command, b.items[i].command);
    EXPECT_DOUBLE_EQ(a.items[i].param[0], b.items[i].param[0]) << "item " << i;
  }
  EXPECT_EQ(a.items[3].command, static_cast<int>(Command::DoSetCamTriggDist));
  EXPECT_DOUBLE_EQ(a.items[3].param[0], 14.5);
  EXPECT_DOUBLE_EQ(a.items[4].param[0], 1.0);
  EXPECT_EQ(a.vehicle_type, 13);
  EXPECT_DOUBLE_EQ(a.plan_cruise_speed_mps, 7.0);
}

TEST(PlannedMission, VehicleTypeFollowsTheRotorCount) {
  EXPECT_EQ(mavTypeOfRotors(3), 15);
  EXPECT_EQ(mavTypeOfRotors(4), 2);
  EXPECT_EQ(mavTypeOfRotors(6), 13);
  EXPECT_EQ(mavTypeOfRotors(8), 14);
  EXPECT_FALSE(mavTypeOfRotors(5).has_value());
  EXPECT_FALSE(mavTypeOfRotors(0).has_value());
}

TEST(PlannedMission, PlanSpeedFieldsAreWholeMetresPerSecondAtLeastOne) {
  EXPECT_EQ(planSpeedField(12.04), 12);
  EXPECT_EQ(planSpeedField(6.5), 7);
  EXPECT_EQ(planSpeedField(5.49), 5);
  EXPECT_EQ(planSpeedField(1.0), 1);
  EXPECT_EQ(planSpeedField(0.3), 1);
}

TEST(PlannedMission, MissionPlannerCheckerFollowsJsonNet) {
  auto j = nlohmann::json::parse(toQgcPlan(survey()));
  EXPECT_TRUE(checkMissionPlannerPlan(j.dump()).empty());
  // The writer before issue 17 wrote the fastest speed as a real: Json.NET refuses it for an int.
  auto old = j;
  old["mission"]["cruiseSpeed"] = 12.040983853753623;
  auto p = checkMissionPlannerPlan(old.dump());
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("plan.mission.cruiseSpeed"), std::string::npos) << p[0];
  EXPECT_NE(p[0].find("int"), std::string::npos) << p[0];
  old["mission"]["cruiseSpeed"] = 5.0;  // a whole real is refused too ("Input string '5.0' is not a valid integer")
  EXPECT_EQ(checkMissionPlannerPlan(old.dump()).size(), 1u);
  EXPECT_TRUE(checkQgcPlan(old.dump()).empty());  // QGC reads either
  // Nulls where C# has no null, lists too short for ConvertToLocationwps.
  auto bad = j;
  bad["mission"]["items"][2]["autoContinue"] = nullptr;
  EXPECT_EQ(checkMissionPlannerPlan(bad.dump()).size(), 1u);
  bad = j;
  bad["mission"]["items"][2]["params"] = {0, 0, 0, nullptr};
  p = checkMissionPlannerPlan(bad.dump());
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("params[0..6]"), std::string::npos) << p[0];
  bad = j;
  bad["mission"]["plannedHomePosition"] = {43.7, nullptr, 3};
  EXPECT_EQ(checkMissionPlannerPlan(bad.dump()).size(), 1u);
  bad = j;
  bad["geoFence"]["polygons"][0]["inclusion"] = 1;
  EXPECT_EQ(checkMissionPlannerPlan(bad.dump()).size(), 1u);
  EXPECT_FALSE(checkMissionPlannerPlan("[1, 2]").empty());
  EXPECT_FALSE(checkMissionPlannerPlan("{not json").empty());
}

TEST(PlannedMission, InvalidHoldsTriggersVehicleTypesAndFencesAreRejected) {
  auto expectThrowNaming = [](const PlannedMission& m, const std::string& needle) {
    try {
      toQgcPlan(m);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  PlannedMission m = survey();
  m.waypoints[2].hold_s = -1.0;
  expectThrowNaming(m, "waypoint 2 hold_s");
  m = survey();
  m.waypoints[0].camera_trigger_m = -3.0;
  expectThrowNaming(m, "waypoint 0 camera_trigger_m");
  m = survey();
  m.vehicle_type = 1;
  expectThrowNaming(m, "vehicle_type = 1");
  m = survey();
  m.fence_inclusion.resize(2);
  expectThrowNaming(m, "inclusion fence has 2 vertices");
}

// Issue 20: MAVLink counts a mission's items in 16 bits and ArduPilot uploads home as item 0, so
// a written mission holds at most 65,534 items after home; more is refused before any text.
TEST(MissionItemLimit, WritersRefuseMoreItemsThanMavlinkCanCount) {
  Mission m;
  m.home = {43.72, 10.42, 3.0};
  m.home_known = true;
  MissionItem wp;
  wp.command = 16;
  wp.lat_deg = 43.7201;
  wp.lon_deg = 10.4201;
  wp.alt_m = 10.0;
  m.items.assign(kMaxMissionItems, wp);
  for (std::size_t k = 0; k < m.items.size(); ++k) m.items[k].seq = static_cast<int>(k) + 1;
  EXPECT_NO_THROW(toQgcWpl(m));  // the largest mission that fits
  m.items.push_back(wp);
  m.items.back().seq = static_cast<int>(m.items.size());
  using Writer = std::string (*)(const Mission&);
  for (Writer write : {static_cast<Writer>(toQgcPlan), static_cast<Writer>(toQgcWpl)}) {
    try {
      write(m);
      ADD_FAILURE() << "65,535 items after home written";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("mission: 65535 items after home, more than the 65534 a MAVLink mission can hold"),
                std::string::npos)
          << e.what();
    }
  }
  // The planner's writer: take-off, a speed command, the waypoints and RTL count too.
  PlannedMission p = sample();
  p.waypoints.assign(kMaxMissionItems - 2, p.waypoints.front());
  EXPECT_THROW(toQgcPlan(p), std::invalid_argument);
  EXPECT_THROW(toQgcWpl(p), std::invalid_argument);
  p.waypoints.resize(kMaxMissionItems - 3);  // + take-off, speed, RTL = 65,534
  EXPECT_NO_THROW(toQgcWpl(p));
}

TEST(PlannedMission, AFirstSpeedChangeWrittenTwiceIsFlownByArduCopter43) {
  // ArduCopter 4.1-4.4 drops a DO_CHANGE_SPEED that is the first DO item after the take-off (the
  // first waypoint restarts the waypoint controller at WPNAV_SPEED, 10 m/s): written once, the
  // 500 m first leg is flown at 10 m/s; written twice (repeat_first_speed_change), the repeat runs
  // after the restart and the leg is flown at the planned 4 m/s. Both read back as the same mission
  // for 4.5, which keeps either.
  PlannedMission m;
  m.home = {43.7200, 10.4200};
  m.takeoff_altitude_m = 10.0;
  m.waypoints = {{{43.7245, 10.4200}, 10.0, 4.0, 0.0, {}}, {{43.7245, 10.4262}, 10.0, 4.0, 0.0, {}}};
  const auto topSpeed = [](const PlannedMission& pm, const std::string& version) {
    const Mission read = parseQgcWpl(toQgcWpl(pm), "m.waypoints");
    const AutopilotConfig ap = parseAutopilot(R"({"firmware":"ArduCopter","version":")" + version + R"("})", "test");
    const FlownMission f = flyMission(sequenceMission(read), ap);
    double top = 0.0;
    for (const auto& s : f.samples)
      if (s.phase == FlightPhase::Mission && s.position.y() < 400.0) top = std::max(top, s.velocity.head<2>().norm());
    return top;
  };
  EXPECT_NEAR(topSpeed(m, "4.3"), 10.0, 0.05);
  EXPECT_NEAR(topSpeed(m, "4.5"), 4.0, 0.05);
  m.repeat_first_speed_change = true;
  const Mission twice = parseQgcWpl(toQgcWpl(m), "m.waypoints");
  ASSERT_GE(twice.items.size(), 3u);
  EXPECT_EQ(twice.items[1].command, 178);
  EXPECT_EQ(twice.items[2].command, 178);
  EXPECT_NEAR(topSpeed(m, "4.3"), 4.0, 0.05);
  EXPECT_NEAR(topSpeed(m, "4.5"), 4.0, 0.05);
}
