// `wattswath endurance`, `models` and the reproduce JSON contract `hwang_table3`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sourcePath;

TEST(CliEndurance, SingleSpeedJsonKeys) {
  const auto r = run(cliBinary() + " endurance --vehicle " + sourcePath("data/vehicles/hwang-hexacopter.json") +
                     " --speed 0 --json");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  for (const char* k : {"endurance_min", "power_w", "thrust_n", "induced_velocity_mps", "tilt_deg"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_NEAR(j["tilt_deg"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["endurance_min"].get<double>(), 22.57, 0.02);  // eta 0.571 fitted to the measured hovers
}

TEST(CliEndurance, RangeGivesCurveAndBestSpeedAndPayloadShortensIt) {
  const std::string base = cliBinary() + " endurance --vehicle " + sourcePath("data/vehicles/hwang-hexacopter.json") +
                           " --speed 0:20:0.5 --json";
  const auto r = run(base), p = run(base + " --payload 10 --battery 2S");
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_EQ(p.status, 0) << p.output;
  const auto j = nlohmann::json::parse(r.output), jp = nlohmann::json::parse(p.output);
  EXPECT_EQ(j["curve"].size(), 41u);
  EXPECT_GT(j["max_endurance_speed_mps"].get<double>(), 2.0);
  EXPECT_LT(jp["max_endurance_min"].get<double>(), j["max_endurance_min"].get<double>());
  EXPECT_GT(jp["max_endurance_speed_mps"].get<double>(), j["max_endurance_speed_mps"].get<double>());
}

TEST(CliEndurance, BadInputGivesClearErrors) {
  const std::string v = sourcePath("data/vehicles/hwang-hexacopter.json");
  auto r = run(cliBinary() + " endurance --vehicle " + v + " --speed 5:1:1 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--speed '5:1:1'"), std::string::npos) << r.output;
  r = run(cliBinary() + " endurance --vehicle " + v + " --battery 2X 2>&1");
  EXPECT_NE(r.output.find("'2X'"), std::string::npos) << r.output;
  r = run(cliBinary() + " endurance --vehicle " + sourcePath("tests/data/iris-no-battery.json") + " 2>&1");
  EXPECT_NE(r.output.find("no 'battery'"), std::string::npos) << r.output;
}

TEST(CliModels, EveryModelSideBySide) {
  const auto r = run(cliBinary() + " models --vehicle " + sourcePath("data/vehicles/iris.json") + " --speed 0:16:2 --json");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["speeds_mps"].size(), 9u);
  EXPECT_EQ(j["models"].size(), 5u);
  for (const auto& m : j["models"]) EXPECT_EQ(m["power_w"].size(), 9u) << m["name"];
}

TEST(Table3, ReproduceJsonContract) {
  // Write the report to a scratch file (never to a device: the writer renames a temporary over it).
  const auto r = run(cliBinary() + " reproduce --out " + ::testing::TempDir() + "wattswath_repro_test.md --force --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto rows = nlohmann::json::parse(r.output).at("hwang_table3");
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& row : rows) {
    for (const char* k : {"packs", "weight_kg", "speed_mps", "paper_estimate_min", "measured_min", "ours_min"}) {
      EXPECT_TRUE(row.contains(k)) << k;
    }
  }
  // Hover rows with the vehicle file's eta (fitted to the measured hovers) are within 2 %.
  for (int k : {0, 3, 6}) {
    EXPECT_NEAR(rows[k]["ours_min"].get<double>(), rows[k]["measured_min"].get<double>(),
                0.02 * rows[k]["measured_min"].get<double>());
  }
  // The paper's reading (radius 558.8 mm) reproduces its 1.4 m/s estimates within 0.3 %.
  for (int k : {1, 4, 7}) {
    EXPECT_NEAR(rows[k]["paper_reading_min"].get<double>(), rows[k]["paper_estimate_min"].get<double>(),
                0.003 * rows[k]["paper_estimate_min"].get<double>());
  }
}
