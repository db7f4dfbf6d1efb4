// The energy commands' JSON contract (keys named in issue 2) and their errors on bad arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sourcePath;

namespace {

std::string iris() { return sourcePath("data/vehicles/iris.json"); }

nlohmann::json runJson(const std::string& args) {
  const auto r = run(cliBinary() + " " + args + " --vehicle " + iris() + " --json 2>/dev/null");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.output;
  return nlohmann::json::parse(r.output);  // exactly one JSON object on stdout
}

void expectError(const std::string& args, const std::string& needle) {
  const auto r = run(cliBinary() + " " + args + " 2>&1");
  EXPECT_NE(r.status, 0) << args;
  EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
}

}  // namespace

TEST(CliEnergy, LegJsonKeys) {
  const auto j = runJson("leg --distance 600 --speed 14.9");
  ASSERT_TRUE(j.contains("energy_j"));
  ASSERT_TRUE(j.contains("time_s"));
  const auto& b = j.at("breakdown");
  EXPECT_EQ(b.size(), 3u);
  const double sum = b.at("hover").get<double>() + b.at("kinetic").get<double>() + b.at("parasitic_drag").get<double>();
  EXPECT_NEAR(sum, j.at("energy_j").get<double>(), 1e-9 * sum);
  EXPECT_NEAR(j.at("time_s").get<double>(), 600.0 / 14.9 + 14.9, 1e-9);  // Eq. 7: d/v + v/a
  const auto paper = runJson("leg --distance 600 --speed 14.9 --drag paper --entry-speed 2 --exit-speed 3");
  EXPECT_GT(paper.at("breakdown").at("parasitic_drag").get<double>(), 0.0);
}

TEST(CliEnergy, VoptJsonKeysAndWithout) {
  const auto j = runJson("vopt --distance 600 --max-speed 40 --drag paper");
  EXPECT_NEAR(j.at("v_opt_mps").get<double>(), 14.845, 0.01);  // Marins Eq. 10 root
  EXPECT_GT(j.at("energy_j").get<double>(), 0.0);
  const auto nk = runJson("vopt --distance 600 --max-speed 40 --drag paper --without kinetic");
  EXPECT_NEAR(nk.at("v_opt_mps").get<double>(), 15.546, 0.01);
  const auto nd = runJson("vopt --distance 600 --max-speed 40 --without parasitic_drag");
  EXPECT_NEAR(nd.at("v_opt_mps").get<double>(), 20.526, 0.01);
  const auto capped = runJson("vopt --distance 1200");  // IRIS file: 16 m/s limit
  EXPECT_DOUBLE_EQ(capped.at("v_opt_mps").get<double>(), 16.0);
  EXPECT_TRUE(capped.at("at_speed_limit").get<bool>());
}

TEST(CliEnergy, TurnsJsonKeys) {
  const auto j = runJson("turns --distance 600 --angle 45");
  const double e1 = j.at("sharp_stop").at("energy_j").get<double>();
  const double e2 = j.at("rounded").at("energy_j").get<double>();
  EXPECT_NEAR(j.at("saving_pct").get<double>(), 100.0 * (e1 - e2) / e1, 1e-9);
  const auto hover = runJson("hover");
  EXPECT_TRUE(hover.contains("p0_w"));
  EXPECT_TRUE(hover.contains("p_hover_w"));
}

TEST(CliEnergy, BadArgumentsGiveClearErrors) {
  const std::string v = " --vehicle " + iris();
  expectError("leg --distance -5 --speed 3" + v, "--distance = -5");
  expectError("leg --distance 100 --speed 0" + v, "--speed = 0");
  expectError("leg --distance 10 --speed 5 --exit-speed 12" + v, "leg too short");
  expectError("vopt --distance 0" + v, "--distance = 0");
  expectError("vopt --distance 100 --without hover" + v, "--without");
  expectError("turns --distance 100 --angle 190" + v, "--angle = 190");
  expectError("turns --distance 100 --angle 0" + v, "--angle = 0");
  expectError("turns --distance 100 --angle 45 --drag fancy" + v, "--drag");
  expectError("leg --distance 100 --speed 5 --vehicle /nonexistent.json", "nonexistent");
}

TEST(CliEnergy, ReproduceMarinsEveryDifferenceOver1PercentIsExplained) {
  const auto r = run(cliBinary() + " reproduce --out /tmp/wattswath_test_reproduction.md --force --json 2>/dev/null");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.output).at("marins");
  int rows = 0;
  for (const char* table : {"hover", "optimal_velocity", "strategies_600m_45deg", "table5"}) {
    for (const auto& row : j.at(table)) {
      ++rows;
      if (std::abs(row.at("diff_pct").get<double>()) > 1.0) {
        EXPECT_TRUE(row.contains("note")) << row.dump();
      }
    }
  }
  EXPECT_EQ(rows, 29);  // 3 hover + 2 optimal velocity + 12 strategy + 12 Table V rows
  EXPECT_NEAR(j.at("eq4_over_ideal").get<double>(), 2.0, 1e-12);
  // A share (a saving in %) differs in points: 23.87 % against 17.34 % is +6.53 points, not +37.6 %.
  for (const auto& row : j.at("strategies_600m_45deg")) {
    if (row.at("unit") != "%") continue;
    EXPECT_DOUBLE_EQ(row.at("diff_points").get<double>(), row.at("ours").get<double>() - row.at("paper").get<double>());
  }
  const auto md = run("cat /tmp/wattswath_test_reproduction.md");
  EXPECT_NE(md.output.find("| Saving of strategy 2 | 17.34 % | 23.87 % | +6.53 points |"), std::string::npos);
  const auto spiral = nlohmann::json::parse(r.output).at("spiral_case");
  EXPECT_EQ(spiral.at("tolerance_pct").get<double>(), 3.0);
  EXPECT_TRUE(spiral.at("within_tolerance").get<bool>());
}

// Regression: writing a report through a temporary file and a rename once replaced /dev/null
// with a plain file. Non-regular targets must be refused and left as they are.
TEST(CliEnergy, ReproduceOutDevNullIsRefusedAndDevNullSurvives) {
  const auto r = run(cliBinary() + " reproduce --out /dev/null 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("/dev/null: exists and is not a regular file"), std::string::npos) << r.output;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

// Hwang's model with a Marins vehicle file (no extensions.hwang) hovers at the file's own P_hov: its
// eta_mot x eta_prop goes with Marins Eq. 4, twice ideal momentum theory, so endurance halves it
// (it promised the IRIS 25.9 min at 107.5 W, half of `hover`'s 215.1 W and of the 225 W measured).
TEST(CliEnergy, EnduranceOfAMarinsVehicleHoversAtItsHoverPowerAndSaysWhy) {
  const auto hover = runJson("hover");
  const auto e = runJson("endurance --speed 0");
  EXPECT_NEAR(e["power_w"].get<double>(), hover["p_hover_w"].get<double>(), 0.01 * hover["p_hover_w"].get<double>());
  ASSERT_EQ(e["notes"].size(), 1u);
  EXPECT_NE(e["notes"][0].get<std::string>().find("twice ideal momentum theory"), std::string::npos) << e["notes"];
  EXPECT_TRUE(hover["note"].is_null());
  // A file fitted for Hwang's model says that Eq. 4 doubles its hover power.
  const auto r = run(cliBinary() + " hover --vehicle " + sourcePath("data/vehicles/hwang-hexacopter.json") + " --json");
  const auto hex = nlohmann::json::parse(r.output);
  EXPECT_NEAR(hex["p_hover_w"].get<double>(), 2.0 * hex["p_hover_hwang_w"].get<double>(), 1.0);
  EXPECT_FALSE(hex["note"].is_null());
}

// The best speed of a coarse --speed range is refined between its neighbours, not a grid point (the
// hexacopter's 0:100:10 said 0 m/s, where 5 m/s flies longer), and speeds above max_speed_mps are said.
TEST(CliEnergy, EnduranceRefinesTheBestSpeedAndSaysWhatCannotBeFlown) {
  const std::string hex = " --vehicle " + sourcePath("data/vehicles/hwang-hexacopter.json") + " --json";
  const auto coarse = nlohmann::json::parse(run(cliBinary() + " endurance --speed 0:100:10" + hex).output);
  const auto at5 = nlohmann::json::parse(run(cliBinary() + " endurance --speed 5" + hex).output);
  EXPECT_GT(coarse["max_endurance_speed_mps"].get<double>(), 1.0);
  EXPECT_LT(coarse["max_endurance_speed_mps"].get<double>(), 10.0);
  EXPECT_GE(coarse["max_endurance_min"].get<double>(), at5["endurance_min"].get<double>());
  EXPECT_FALSE(coarse["max_endurance_at_range_end"].get<bool>());
  std::string notes = coarse["notes"].dump();
  EXPECT_NE(notes.find("above the vehicle's max_speed_mps (20 m/s)"), std::string::npos) << notes;
  const auto edge = nlohmann::json::parse(run(cliBinary() + " endurance --speed 0:3:1" + hex).output);
  EXPECT_TRUE(edge["max_endurance_at_range_end"].get<bool>());
  EXPECT_NE(edge["notes"].dump().find("highest speed given"), std::string::npos) << edge["notes"];
}

// A leg too short for its cruise speed says the speed it peaks at (it was labelled "at 8.0 m/s" while
// flying 3.16 m/s), and a speed above the vehicle's limit is said to be one.
TEST(CliEnergy, LegSaysTheSpeedItReallyReaches) {
  const auto j = runJson("leg --distance 10 --speed 8");
  EXPECT_NEAR(j["peak_speed_mps"].get<double>(), std::sqrt(10.0), 0.01);  // sqrt(a d), a = 1 m/s^2
  ASSERT_EQ(j["notes"].size(), 1u);
  EXPECT_NE(j["notes"][0].get<std::string>().find("peaks at 3.16 m/s"), std::string::npos) << j["notes"];
  const auto fast = runJson("leg --distance 1000 --speed 30");
  EXPECT_NEAR(fast["peak_speed_mps"].get<double>(), 30.0, 1e-6);
  EXPECT_NE(fast["notes"].dump().find("above the vehicle's max_speed_mps (16.0 m/s)"), std::string::npos) << fast["notes"];
  EXPECT_TRUE(runJson("leg --distance 600 --speed 10")["notes"].empty());
}
