// `wattswath coverage` end to end on the E-Spiral rectangle (contract keys of issue 4).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_util.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sharedData;

namespace {

nlohmann::json coverageJson(const std::string& args) {
  const auto r = run(cliBinary() + " coverage " + sharedData("espiral/area__rectangle.waypoints") + " " + args +
                     " --json 2>/dev/null");
  EXPECT_EQ(r.status, 0) << args;
  return nlohmann::json::parse(r.output);  // exactly one JSON object on stdout
}

}  // namespace

TEST(CliCoverage, SpiralFromCameraSettingsReportsTheContractKeys) {
  const std::string out = std::string(::testing::TempDir()) + "/spiral.geojson";
  const auto j = coverageJson("--pattern spiral --altitude 10 --fov 100 --overlap 0.1 --corners rounded --radius 2.095 --force --out " + out);
  for (const char* key : {"legs", "length_m", "turns", "coverage_pct", "cells"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["spacing_m"].get<double>(), 21.45, 0.01);
  EXPECT_EQ(j["cells"].get<int>(), 1);
  EXPECT_GE(j["coverage_pct"].get<double>(), 99.0);
  EXPECT_TRUE(j["problems"].empty());
  std::ifstream f(out);
  ASSERT_TRUE(f.good());
  const auto geo = nlohmann::json::parse(f);
  EXPECT_EQ(geo["type"], "FeatureCollection");
}

TEST(CliCoverage, BoustrophedonAtAnAngle) {
  const auto j = coverageJson("--pattern boustrophedon --angle 30 --spacing 20");
  EXPECT_GE(j["coverage_pct"].get<double>(), 99.0);
  EXPECT_GE(j["cells"].get<int>(), 1);
  EXPECT_GT(j["length_m"].get<double>(), 0.0);
  EXPECT_TRUE(j["problems"].empty());
}

TEST(CliCoverage, MissingSpacingIsAnError) {
  const auto r = run(cliBinary() + " coverage " + sharedData("espiral/area__rectangle.waypoints") + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--spacing"), std::string::npos) << r.output;
}

// A spacing of 0 said "not in range 0.000000 to 1797693134862315708...", 300 digits; a field of view
// of 0 blamed a sensor width the user never gave, one of 180 deg answered in radians.
TEST(CliCoverage, BadNumbersAreNamedInTheUnitsGiven) {
  const std::string area = sharedData("espiral/area__rectangle.waypoints");
  auto r = run(cliBinary() + " coverage " + area + " --spacing 0 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--spacing: expected a number > 0, got 0"), std::string::npos) << r.output;
  EXPECT_LT(r.output.size(), 200u) << r.output;
  for (const char* fov : {"0", "180"}) {
    r = run(cliBinary() + " coverage " + area + " --altitude 10 --overlap 0.1 --fov " + fov + " 2>&1");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find(std::string("--fov = ") + fov + " deg, expected a field of view in (0, 180) deg"), std::string::npos)
        << r.output;
  }
}

// Issue 22: on every area of ../shared/data, no flown point of `coverage` (any pattern) or `plan`
// is outside the area or inside a hole or no-fly zone (outside_area_m and in_no_fly_m, measured by
// geometry::checkContainment: exact for lines, 1 mm tolerance at the boundary).
TEST(CliCoverage, NoFlownPointOutsideTheSharedAreas) {
  const std::string obstacles = " --no-fly " + sharedData("iris-flights/plan__real_flight_obstacles.waypoints");
  const std::vector<std::pair<std::string, std::string>> areas = {
      {"espiral/area__area01.waypoints", ""},       {"espiral/area__polygon.waypoints", ""},
      {"espiral/area__rectangle.waypoints", ""},    {"espiral/area__rectangle02.waypoints", ""},
      {"espiral/area__spiral_concave.waypoints", ""}, {"espiral/area__spiral_polygon.waypoints", ""},
      {"iris-flights/plan__real_flight_area.waypoints", obstacles}};
  const std::string out = std::string(::testing::TempDir()) + "/inside";
  for (const auto& [file, extra] : areas) {
    const std::string area = sharedData(file);
    for (const std::string args : {"--pattern boustrophedon --angle 30", "--pattern boustrophedon --angle 90",
                                   "--pattern spiral"}) {
      const auto r = run(cliBinary() + " coverage " + area + extra + " --spacing 15 " + args + " --json 2>/dev/null");
      ASSERT_EQ(r.status, 0) << file << " " << args;
      const auto j = nlohmann::json::parse(r.output);
      EXPECT_EQ(j.at("outside_area_m").get<double>(), 0.0) << file << " " << args;
      EXPECT_EQ(j.at("in_no_fly_m").get<double>(), 0.0) << file << " " << args;
    }
    const auto r = run(cliBinary() + " plan " + area + extra + " --vehicle " +
                       wattswath::test::sourcePath("data/vehicles/iris.json") + " --spacing 15 --no-report --force --out " +
                       out + " --json 2>/dev/null");
    ASSERT_EQ(r.status, 0) << file;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("outside_area_m").get<double>(), 0.0) << file;
    EXPECT_EQ(j.at("in_no_fly_m").get<double>(), 0.0) << file;
    EXPECT_GE(j.at("coverage_pct").get<double>(), 99.0) << file;
    const auto& trade = j.at("line_count_trade");  // null when only one line count was built
    if (!trade.is_null()) {
      EXPECT_TRUE(trade.at("lines_delta") == 1 || trade.at("lines_delta") == -1) << file;
      EXPECT_GT(trade.at("energy_j").get<double>(), 0.0) << file;
    }
  }
}

// A --radius that cannot fit between passes is said, with the radius the arcs use (50 m asked, 9.99 m
// flown, nothing said); rounded corners without a radius are refused (they came out sharp); the
// passes, spread evenly, are said to be closer than the spacing asked (19.67 m for 21.45 m).
TEST(CliCoverage, RoundedCornersAndPassesSayWhatIsFlown) {
  const std::string out = std::string(::testing::TempDir()) + "/r50.geojson";
  const auto j = coverageJson("--spacing 21.45 --corners rounded --radius 50 --force --out " + out);
  ASSERT_EQ(j["notes"].size(), 1u) << j["notes"];
  EXPECT_NE(j["notes"][0].get<std::string>().find("--radius 50 m does not fit: the arcs use at most"), std::string::npos);
  EXPECT_LE(j["widest_pass_gap_m"].get<double>(), 21.45);
  EXPECT_NEAR(j["widest_pass_gap_m"].get<double>(), 19.67, 0.05);
  EXPECT_TRUE(coverageJson("--spacing 21.45 --corners rounded --radius 3 --force --out " + out)["notes"].empty());
  const auto r = run(cliBinary() + " coverage " + sharedData("espiral/area__rectangle.waypoints") +
                     " --spacing 21.45 --corners rounded --out " + out + " --force 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--corners rounded needs --radius M > 0"), std::string::npos) << r.output;
  EXPECT_TRUE(coverageJson("--pattern spiral --spacing 21.45")["widest_pass_gap_m"].is_null());
}
