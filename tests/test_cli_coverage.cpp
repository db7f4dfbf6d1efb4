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
