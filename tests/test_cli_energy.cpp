// The energy commands' JSON contract (keys named in issue 2) and their errors on bad arguments.
#include <gtest/gtest.h>
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
