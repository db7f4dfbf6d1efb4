// Mission writers: the .plan is checked against the keys and types QGroundControl's loader needs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "wattswath/mission/planned_mission.hpp"

using namespace wattswath::mission;

namespace {
PlannedMission sample() {
  PlannedMission m;
  m.home = {43.7200, 10.4200};
  m.home_altitude_amsl_m = 3.0;
  m.takeoff_altitude_m = 10.0;
  m.waypoints = {{{43.7201, 10.4201}, 10.0, 6.5}, {{43.7202, 10.4203}, 10.0, 6.5}, {{43.7203, 10.4201}, 10.0, 3.0}};
  m.no_fly = {{{43.7210, 10.4210}, {43.7211, 10.4210}, {43.7211, 10.4212}}};
  return m;
}
}  // namespace

TEST(PlannedMission, QgcPlanLoadsByQgcRules) {
  const std::string text = toQgcPlan(sample());
  EXPECT_TRUE(checkQgcPlan(text).empty()) << checkQgcPlan(text).front();
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
}
