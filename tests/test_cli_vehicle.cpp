// `wattswath vehicle params`: a vehicle file written from a SITL log's firmware and parameters, its
// --json summary, --all, and the output-file safety (no overwrite without --force, never an input).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using wattswath::test::cliBinary;
using wattswath::test::fingerprint;
using wattswath::test::readAll;
using wattswath::test::run;
using wattswath::test::sharedData;
using wattswath::test::sourcePath;

std::string iris() { return sourcePath("data/vehicles/iris.json"); }
std::string sitlLog() { return sharedData("sitl/square_5mps.BIN"); }

class CliVehicle : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wattswath_cli_vehicle_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string out(const std::string& name) const { return (dir_ / name).string(); }
  /// Runs `vehicle params LOG --vehicle BASE --out OUT EXTRA` with stderr merged into the output.
  wattswath::test::RunResult params(const std::string& log, const std::string& base, const std::string& out_path,
                                    const std::string& extra = "") const {
    return run(cliBinary() + " vehicle params " + log + " --vehicle " + base + " --out " + out_path + " " + extra + " 2>&1");
  }
  fs::path dir_;
};

}  // namespace

TEST_F(CliVehicle, WritesBaseWithTheLogsAutopilotObject) {
  const auto r = params(sitlLog(), iris(), out("v.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + out("v.json")), std::string::npos) << r.output;
  const auto v = nlohmann::json::parse(readAll(out("v.json")));
  const auto base = nlohmann::json::parse(readAll(iris()));
  for (const auto& [key, value] : base.items()) EXPECT_EQ(v.at(key), value) << key;  // BASE kept
  const auto& a = v.at("autopilot");
  EXPECT_EQ(a.at("firmware"), "ArduCopter");
  EXPECT_EQ(a.at("version"), "4.7.0-dev");
  const auto& p = a.at("parameters");
  EXPECT_EQ(p.at("WPNAV_SPEED").get<double>(), 1000.0);
  EXPECT_EQ(p.at("WPNAV_ACCEL").get<double>(), 250.0);
  EXPECT_EQ(p.at("PSC_JERK_XY").get<double>(), 5.0);
  EXPECT_EQ(p.at("ATC_INPUT_TC").dump(), "0.15");  // the logged float 0.150000006 written as the user set it
  EXPECT_FLOAT_EQ(p.at("MOT_THST_HOVER").get<float>(), 0.39f);  // the landing's throttle wind-down
  EXPECT_FALSE(p.contains("MOT_THST_EXPO"));                      // not a flight-behaviour parameter
  EXPECT_FALSE(p.contains("STAT_FLTTIME"));
  // The airframe the log determines: its drag and its response (ATC_INPUT_TC's lag).
  const auto& airframe = v.at("extensions").at("airframe");
  EXPECT_GT(airframe.at("drag_quadratic_per_m").get<double>(), 0.0);
  EXPECT_NEAR(airframe.at("response_s").get<double>(), 0.15, 0.02);
  EXPECT_NE(r.output.find("airframe response (extensions.airframe.response_s)"), std::string::npos) << r.output;
  // The file written is a valid vehicle file.
  const auto hover = run(cliBinary() + " hover --vehicle " + out("v.json") + " --json 2>&1");
  EXPECT_EQ(hover.status, 0) << hover.output;
}

TEST_F(CliVehicle, JsonSummaryAndAll) {
  const auto r = run(cliBinary() + " vehicle params " + sitlLog() + " --vehicle " + iris() + " --out " + out("all.json") +
                     " --all --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);  // exactly one JSON object on stdout
  EXPECT_EQ(j.at("firmware"), "ArduCopter");
  EXPECT_EQ(j.at("version"), "4.7.0-dev");
  EXPECT_GT(j.at("parameter_count").get<int>(), 1300);
  EXPECT_EQ(j.at("kept").size(), j.at("parameter_count").get<std::size_t>());
  const auto v = nlohmann::json::parse(readAll(out("all.json")));
  EXPECT_EQ(v.at("autopilot").at("parameters").size(), j.at("parameter_count").get<std::size_t>());
  EXPECT_TRUE(v.at("autopilot").at("parameters").contains("MOT_THST_HOVER"));
  const auto& response = j.at("airframe").at("response");
  EXPECT_TRUE(response.at("determined").get<bool>()) << response.dump();
  EXPECT_NEAR(response.at("response_s").get<double>(), v.at("extensions").at("airframe").at("response_s").get<double>(), 1e-12);
}

TEST_F(CliVehicle, RefusesToOverwriteWithoutForceAndNeverAnInput) {
  ASSERT_EQ(params(sitlLog(), iris(), out("v.json")).status, 0);
  const auto before = fingerprint(out("v.json"));
  const auto again = params(sitlLog(), iris(), out("v.json"));
  EXPECT_NE(again.status, 0);
  EXPECT_NE(again.output.find(out("v.json") + ": already exists; use --force to replace it"), std::string::npos) << again.output;
  EXPECT_EQ(fingerprint(out("v.json")), before);
  EXPECT_EQ(params(sitlLog(), iris(), out("v.json"), "--force").status, 0);
  // BASE as the output: refused even with --force, BASE unchanged.
  fs::copy_file(iris(), out("base.json"));
  const auto base_before = fingerprint(out("base.json"));
  const auto self = params(sitlLog(), out("base.json"), out("base.json"), "--force");
  EXPECT_NE(self.status, 0);
  EXPECT_NE(self.output.find("is also an input file"), std::string::npos) << self.output;
  EXPECT_EQ(fingerprint(out("base.json")), base_before);
  for (const auto& e : fs::directory_iterator(dir_))  // written through a temporary file and a rename
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

TEST_F(CliVehicle, ClearErrors) {
  const auto csv = params(sourcePath("tests/data/bad/log_empty.csv"), iris(), out("v.json"));
  EXPECT_NE(csv.status, 0);
  EXPECT_NE(csv.output.find("not an ArduPilot DataFlash (.bin) or PX4 ULog (.ulg) log"), std::string::npos) << csv.output;
  const auto none = params(sourcePath("tests/data/bad/params_ulog_no_parameters.ulg"), iris(), out("v.json"));
  EXPECT_NE(none.status, 0);
  EXPECT_NE(none.output.find("no parameters in the log"), std::string::npos) << none.output;
  EXPECT_FALSE(fs::exists(out("v.json")));
  const auto help = run(cliBinary() + " vehicle params --help 2>&1");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("WPNAV_*"), std::string::npos) << help.output;
}

TEST_F(CliVehicle, Px4LogAndArduCopter35WithoutVersion) {
  const auto px4 = params(sharedData("autopilot-logs/px4-1.15_quad_manual_posctl.ulg"), iris(), out("px4.json"));
  ASSERT_EQ(px4.status, 0) << px4.output;
  const auto a = nlohmann::json::parse(readAll(out("px4.json"))).at("autopilot");
  EXPECT_EQ(a.at("firmware"), "PX4");
  EXPECT_EQ(a.at("version"), "1.15.0-beta");
  EXPECT_EQ(a.at("parameters").at("MPC_XY_CRUISE").get<double>(), 15.0);
  EXPECT_FALSE(a.at("parameters").contains("BAT1_N_CELLS"));
  const auto ac35 = params(sharedData("autopilot-logs/arducopter-3.5_quad_rtl.bin"), iris(), out("ac35.json"));
  ASSERT_EQ(ac35.status, 0) << ac35.output;
  EXPECT_NE(ac35.output.find("does not say the firmware version"), std::string::npos) << ac35.output;
  const auto b = nlohmann::json::parse(readAll(out("ac35.json"))).at("autopilot");
  EXPECT_EQ(b.at("firmware"), "ArduCopter");
  EXPECT_FALSE(b.contains("version"));
}

// A file written from a log without a firmware version is flown by predict as ArduCopter 4.5, and
// predict now says so (it said nothing); vehicle params says it too, in text and JSON.
TEST_F(CliVehicle, AFileWithoutAVersionIsSaidToBeFlownAsTheDefault) {
  const auto w = params(sharedData("autopilot-logs/arducopter-3.5_quad_rtl.bin"), iris(), out("nover.json"), "--json");
  ASSERT_EQ(w.status, 0) << w.output;
  const auto p = run(cliBinary() + " predict " + sharedData("sitl/square_5mps.waypoints") + " --vehicle " + out("nover.json") +
                     " --json 2>/dev/null");
  ASSERT_EQ(p.status, 0) << p.output;
  EXPECT_NE(p.output.find("gives no version: flown as ArduCopter 4.5"), std::string::npos) << p.output;
  const auto given = run(cliBinary() + " predict " + sharedData("sitl/square_5mps.waypoints") + " --vehicle " +
                         sourcePath("data/vehicles/iris-plus-arducopter3.json") + " --json 2>/dev/null");
  EXPECT_EQ(given.output.find("gives no version"), std::string::npos);
}

// A calibration in BASE was fitted with BASE's parameters: it is left out of the file written, with
// a note (it was kept beside the log's parameters, and predict flew the old per-flight values); a
// BASE airframe is kept and said to be used when the log does not determine one.
TEST_F(CliVehicle, BasesCalibrationIsLeftOutAndItsAirframeIsSaidToBeKept) {
  auto base = nlohmann::json::parse(readAll(iris()));
  base["extensions"]["calibration"] = {{"effects", {"hover"}}, {"coefficients", {{"hover", {{"hover_power", 200.0}}}}}};
  base["extensions"]["airframe"] = {{"drag_linear_per_s", 0.2}, {"drag_quadratic_per_m", 0.03}};
  const std::string base_path = out("base.json");
  std::ofstream(base_path) << base.dump(2);
  const auto r = params(sharedData("autopilot-logs/arducopter-3.3_quad_log171.bin"), base_path, out("written.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto written = nlohmann::json::parse(readAll(out("written.json")));
  EXPECT_FALSE(written["extensions"].contains("calibration"));
  EXPECT_NE(r.output.find("calibration (extensions.calibration) was fitted with its own autopilot parameters"), std::string::npos)
      << r.output;
  if (!r.output.empty() && r.output.find("airframe drag not determined") != std::string::npos) {
    EXPECT_TRUE(written["extensions"].contains("airframe"));
    EXPECT_NE(r.output.find("extensions.airframe, kept in the file"), std::string::npos) << r.output;
  }
}
