// wattswath diagnose end to end (issue 18): the README's user-defined effect walkthrough - a log
// simulated with motor heating (data/effects/motor_heating.json, k = 0.06, tau = 60 s) is
// "unexplained" by the built-in candidates and "missing_effect: motor_heating" once the user's
// effect file is given - and a malformed effect file is refused with the file, field and value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace {

using wattswath::test::Outcome;
using wattswath::test::runCli;
namespace fs = std::filesystem;

const std::string kEffect = "data/effects/motor_heating.json";

std::string tempPath(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("wattswath_cli_diagnose_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

// Five samples (4 s of an IRIS+ flight) read "nothing_missing: the residual carries none of the
// tested signals" with no signal tested; too little data gets no verdict, in words and in --json.
TEST(CliDiagnose, FiveSamplesCannotTell) {
  const Outcome r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", "tests/data/iris_short5.csv", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("verdict"), "cannot_tell") << j.at("conclusion");
  EXPECT_NE(j.at("conclusion").get<std::string>().find("The data cannot tell: 5 airborne samples"), std::string::npos);
}

// A hover (0.3 m of drift at 0.5 m/s) tests no effect that needs fast flight: the verdict was
// "nothing_missing" while drag, wind and translational lift were marked not determined. It is
// "cannot_tell", naming them and what the data lack, in words and in --json ("untested").
TEST(CliDiagnose, AHoverCannotTellWhatNeedsFastFlight) {
  const std::string path = tempPath("hover_path.txt"), log = tempPath("hover.csv");
  std::ofstream(path) << "0 0 0\n0 0 10\n0.3 0 10\n0 0 10\n0 0 0\n";
  Outcome r = runCli({"simulate", "--vehicle", "data/vehicles/iris.json", "--speed", "0.5", "--path", path, "--seed", "3",
                      "--out", log, "--force"});
  ASSERT_EQ(r.status, 0) << r.err;
  r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--effects", "hover,kinetic", "--log", log, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("verdict"), "cannot_tell") << j.at("conclusion");
  const std::string c = j.at("conclusion");
  EXPECT_NE(c.find("but they cannot test parasitic_drag, wind, translational_lift (0 of"), std::string::npos) << c;
  ASSERT_EQ(j.at("untested").size(), 3u) << j.at("untested");
  EXPECT_EQ(j.at("untested")[0].get<std::string>().rfind("parasitic_drag: 0 of", 0), 0u) << j.at("untested");
}

// One flight under two names: counted twice, or tested on itself. Refused, naming both files.
TEST(CliDiagnose, TheSameFlightTwiceIsRefused) {
  const std::string copy = tempPath("copy.csv");
  fs::copy_file(wattswath::test::sourcePath("tests/data/iris_short5.csv"), copy, fs::copy_options::overwrite_existing);
  Outcome r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", "tests/data/iris_short5.csv", "--log", copy});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("are the same file (identical bytes): one flight given twice"), std::string::npos) << r.err;
  r = runCli({"fit", "--vehicle", "data/vehicles/iris.json", "--log", "tests/data/iris_short5.csv", "--test-log", copy});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("a test log must be a flight the fit did not see"), std::string::npos) << r.err;
}

TEST(CliDiagnose, UserEffectTurnsUnexplainedIntoFound) {
  const std::string log = tempPath("heated.csv");
  Outcome r = runCli({"simulate", "--vehicle", "data/vehicles/iris.json", "--effects",
                      "hover,kinetic,parasitic_drag,motor_heating", "--effect-file", kEffect, "--set",
                      "motor_heating.k=0.06", "--set", "motor_heating.tau=60", "--rate", "5", "--seed", "11", "--path",
                      "data/effects/survey_path.txt", "--out", log, "--force"});
  ASSERT_EQ(r.status, 0) << r.err;
  r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", log, "--json"}, 120);
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("verdict"), "unexplained") << j.at("conclusion");
  EXPECT_TRUE(j.at("found").empty());
  ASSERT_FALSE(j.at("signatures").empty());
  EXPECT_EQ(j.at("signatures")[0].at("signal"), "time") << j.at("conclusion");
  r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", log, "--effect-file", kEffect, "--json"}, 120);
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("verdict"), "missing_effect") << j.at("conclusion");
  ASSERT_EQ(j.at("found").size(), 1u);
  EXPECT_EQ(j.at("found")[0].at("effect"), "motor_heating");
  EXPECT_NEAR(j.at("found")[0].at("coefficients").at("k").get<double>(), 0.06, 0.01);
  EXPECT_LT(j.at("final").at("rmse_w").get<double>(), j.at("baseline").at("rmse_w").get<double>());
  EXPECT_TRUE(j.at("signatures").empty());
}

TEST(CliDiagnose, MalformedEffectFileNamesFileFieldAndValue) {
  const std::string bad = tempPath("bad_effect.json");
  std::ofstream(bad) << R"J({"name": "heat", "power": "k * t", "coefficients": [{"name": "k", "unit": "W/s",
    "value": -1, "lower": 0, "upper": 2}]})J";
  const Outcome r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log",
                            "tests/data/good/log_hover_only.csv", "--effect-file", bad});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(bad + ": effect.coefficients[0].value = -1, expected within lower 0 and upper 2"), std::string::npos)
      << r.err;
}

}  // namespace

// diagnose and fit agree on the effect sets (issue 19): a found wind replaces parasitic_drag, and
// the final set diagnose names is one that fit accepts and fits.
TEST(CliDiagnose, FoundWindNamesAnEffectSetFitAccepts) {
  const std::string log = tempPath("wind.csv");
  Outcome r = runCli({"simulate", "--vehicle", "data/vehicles/iris.json", "--effects", "hover,kinetic,wind", "--set",
                      "wind.wind_east=4", "--set", "wind.wind_north=-2", "--seed", "3", "--out", log, "--force"});
  ASSERT_EQ(r.status, 0) << r.err;
  r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", log, "--json"}, 120);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("found").size(), 1u) << j.at("conclusion");
  EXPECT_EQ(j.at("found")[0].at("effect"), "wind");
  const auto set = j.at("final_effects").get<std::vector<std::string>>();
  EXPECT_EQ(set, (std::vector<std::string>{"hover", "kinetic", "wind"}));
  std::string effects;
  for (const auto& e : set) effects += (effects.empty() ? "" : ",") + e;
  r = runCli({"fit", "--vehicle", "data/vehicles/iris.json", "--effects", effects, "--log", log, "--json"}, 120);
  EXPECT_EQ(r.status, 0) << r.err;
  r = runCli({"diagnose", "--vehicle", "data/vehicles/iris.json", "--log", log}, 120);
  EXPECT_NE(r.out.find("wattswath fit --effects hover,kinetic,wind"), std::string::npos) << r.out;
}
