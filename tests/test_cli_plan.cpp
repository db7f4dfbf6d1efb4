// The `plan` command end to end: the JSON keys, the three mission files (the .plan passes
// the QGroundControl format check), the plan never costing more than a baseline, clear errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "wattswath/mission/planned_mission.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sourcePath;

namespace {

std::string iris() { return sourcePath("data/vehicles/iris.json"); }

std::string outDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("wattswath_test_plan_" + name);
  std::filesystem::remove_all(d);
  return d.string();
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

nlohmann::json planJson(const std::string& area, const std::string& out, const std::string& extra) {
  const auto r = run(cliBinary() + " plan " + area + " --vehicle " + iris() + " --out " + out + " " + extra +
                     " --json 2>/dev/null");
  EXPECT_EQ(r.status, 0) << area << " " << extra << "\n" << r.output;
  return nlohmann::json::parse(r.output);  // exactly one JSON object on stdout
}

void expectError(const std::string& args, const std::string& needle) {
  const auto r = run(cliBinary() + " " + args + " 2>&1");
  EXPECT_NE(r.status, 0) << args;
  EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
}

// Checks the JSON contract of issue 5 and the written files.
void checkPlanOutput(const nlohmann::json& j, const std::string& out) {
  for (const char* k : {"energy_j", "time_s", "length_m", "sweep_angle_deg", "coverage_pct", "lower_bound_j"})
    EXPECT_TRUE(j.contains(k) && j.at(k).is_number()) << k;
  EXPECT_TRUE(j.at("pattern") == "boustrophedon" || j.at("pattern") == "spiral" || j.at("pattern") == "mixed")
      << j.at("pattern");
  // Every angle of the one-angle search, and the per-cell choices when the per-cell search won.
  EXPECT_GE(j.at("sweep_scan").size(), 18u);
  for (const auto& a : j.at("sweep_scan")) EXPECT_TRUE(a.at("sweep_angle_deg").is_number());
  if (j.at("pattern") == "mixed") {
    EXPECT_GE(j.at("cell_plans").size(), 2u);
  }
  for (const auto& c : j.at("cell_plans")) {
    EXPECT_TRUE(c.at("pattern") == "boustrophedon" || c.at("pattern") == "spiral");
    EXPECT_GT(c.at("energy_j").get<double>(), 0.0);
  }
  EXPECT_GE(j.at("coverage_pct").get<double>(), 99.0);
  const double e = j.at("energy_j").get<double>();
  EXPECT_GT(e, 0.0);
  EXPECT_GT(j.at("lower_bound_j").get<double>(), 0.0);
  EXPECT_LE(j.at("lower_bound_j").get<double>(), e);
  const auto& b = j.at("baselines");
  for (const char* name : {"shortest_path", "ground_station_default", "best_spiral"}) {
    ASSERT_TRUE(b.contains(name)) << name;
    if (b.at(name).is_null()) continue;  // best_spiral may be absent (noted)
    for (const char* k : {"energy_j", "time_s", "length_m"}) EXPECT_TRUE(b.at(name).at(k).is_number()) << name << k;
    EXPECT_LE(e, b.at(name).at("energy_j").get<double>() * (1 + 1e-12)) << name;
  }
  EXPECT_TRUE(j.contains("battery"));
  for (const char* f : {"mission.plan", "mission.waypoints", "path.geojson"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / f)) << f;
  const auto problems = wattswath::mission::checkQgcPlan(slurp(out + "/mission.plan"));
  EXPECT_TRUE(problems.empty()) << (problems.empty() ? "" : problems.front());
  EXPECT_EQ(slurp(out + "/mission.waypoints").rfind("QGC WPL 110", 0), 0u);
  const auto gj = nlohmann::json::parse(slurp(out + "/path.geojson"));
  EXPECT_EQ(gj.at("type"), "FeatureCollection");
  EXPECT_EQ(gj.at("features").at(0).at("geometry").at("type"), "LineString");
  // The HTML plan report is on by default with --out: map, Table III-style breakdown, candidates.
  const std::string html = slurp(out + "/report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("Energy by part and effect"), std::string::npos);
  EXPECT_NE(html.find("Candidate plans"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

}  // namespace

TEST(CliPlan, IrisAreaWithNoFlyZone) {
  const auto out = outDir("iris");
  const auto j = planJson(sourcePath("data/areas/iris_area.geojson"), out, "--spacing 15");
  checkPlanOutput(j, out);
  // The no-fly zone of the area is a geofence exclusion polygon in the .plan.
  const auto plan = nlohmann::json::parse(slurp(out + "/mission.plan"));
  EXPECT_EQ(plan.at("geoFence").at("polygons").size(), 1u);
  EXPECT_FALSE(plan.at("geoFence").at("polygons").at(0).at("inclusion").get<bool>());
}

TEST(CliPlan, NoSpiralFliesStraightLinesOnly) {
  const auto out = outDir("nospiral");
  const auto j = planJson(sourcePath("data/areas/espiral_rectangle.geojson"), out, "--spacing 20 --no-spiral");
  checkPlanOutput(j, out);
  EXPECT_EQ(j.at("pattern"), "boustrophedon");
  EXPECT_TRUE(j.at("baselines").at("best_spiral").is_null());
  for (const auto& c : j.at("per_cell").at("cell_plans")) EXPECT_EQ(c.at("pattern"), "boustrophedon");
}

TEST(CliPlan, CameraFootprintAndCornerStrategy) {
  const auto out = outDir("camera");
  const auto j = planJson(sourcePath("data/areas/espiral_rectangle.geojson"), out,
                          "--altitude 20 --fov 60 --overlap 0.2 --corner-strategy sharp --home 43.7187,10.4326");
  checkPlanOutput(j, out);
  EXPECT_EQ(j.at("corners").at("rounded").get<int>(), 0);  // sharp: every corner a stop
}

TEST(CliPlan, RefusesToOverwriteWithoutForce) {
  const auto out = outDir("force");
  const std::string area = sourcePath("data/areas/espiral_rectangle.geojson");
  planJson(area, out, "--spacing 30");
  expectError("plan " + area + " --vehicle " + iris() + " --spacing 30 --out " + out, "--force");
  planJson(area, out, "--spacing 30 --force");
}

TEST(CliPlan, ClearErrors) {
  const std::string area = sourcePath("data/areas/espiral_rectangle.geojson");
  const std::string base = "plan " + area + " --vehicle " + iris() + " --out " + outDir("errors");
  expectError(base, "--spacing");
  expectError(base + " --spacing 10 --fov 60 --overlap 0.2", "not both");
  expectError(base + " --fov 60 --overlap 1.5", "--overlap");
  expectError(base + " --spacing 10 --home 43.7", "LAT,LON");
  expectError(base + " --spacing 10 --home 95,10", "lat");
  expectError(base + " --spacing 10 --corner-strategy wiggly", "corner-strategy");
  expectError("plan " + sourcePath("data/vehicles/iris.json") + " --vehicle " + iris() + " --spacing 10 --out " +
                  outDir("errors2"),
              "iris.json");
}

#ifdef WATTSWATH_TEST_SHARED_DATA
TEST(CliPlanShared, EspiralRectangleWaypoints) {
  const auto out = outDir("espiral");
  const auto j = planJson(wattswath::test::sharedData("espiral/area__rectangle.waypoints"), out, "--spacing 20");
  checkPlanOutput(j, out);
}

TEST(CliPlanShared, EveryESpiralAreaWithTheESpiralCamera) {
  // The six E-Spiral survey areas at the E-Spiral camera (10 m, 100 deg, 10 % overlap): valid
  // plans, never dearer than a baseline (checkPlanOutput), and well below the ground-station default.
  for (const char* name : {"area01", "polygon", "rectangle", "rectangle02", "spiral_concave", "spiral_polygon"}) {
    SCOPED_TRACE(name);
    const auto out = outDir(std::string("espiral_") + name);
    const auto j = planJson(wattswath::test::sharedData(std::string("espiral/area__") + name + ".waypoints"), out,
                            "--altitude 10 --fov 100 --overlap 0.1");
    checkPlanOutput(j, out);
    EXPECT_LT(j.at("energy_j").get<double>(),
              0.8 * j.at("baselines").at("ground_station_default").at("energy_j").get<double>());
  }
}

TEST(CliPlanShared, IrisWaypointsWithNoFlyFile) {
  const auto out = outDir("iris_wpl");
  const auto j = planJson(wattswath::test::sharedData("iris-flights/plan__real_flight_area.waypoints"), out,
                          "--no-fly " + wattswath::test::sharedData("iris-flights/plan__real_flight_obstacles.waypoints") +
                              " --spacing 15");
  checkPlanOutput(j, out);
}
#endif

TEST(CliPlan, BatteryWhenTheVehicleHasOne) {
  const auto out = outDir("battery");
  const auto r = run(cliBinary() + " plan " + sourcePath("data/areas/espiral_rectangle.geojson") + " --vehicle " +
                     sourcePath("data/vehicles/hwang-hexacopter.json") + " --spacing 30 --out " + out + " --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  const auto& b = j.at("battery");
  ASSERT_TRUE(b.is_object());
  for (const char* k : {"usable_energy_j", "mission_energy_j", "margin_j", "margin_pct", "remaining_pct"})
    EXPECT_TRUE(b.at(k).is_number()) << k;
  EXPECT_NEAR(b.at("mission_energy_j").get<double>(), j.at("energy_j").get<double>(), 1e-6);
  EXPECT_NEAR(b.at("margin_j").get<double>(),
              b.at("usable_energy_j").get<double>() - b.at("mission_energy_j").get<double>(), 1e-6);
  EXPECT_EQ(b.at("fits").get<bool>(), b.at("warning").is_null());
  // The IRIS vehicle file has no battery: null, not a guess.
  EXPECT_TRUE(planJson(sourcePath("data/areas/espiral_rectangle.geojson"), outDir("battery2"), "--spacing 30")
                  .at("battery")
                  .is_null());
}
