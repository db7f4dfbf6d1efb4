// Output files (issue 8): every command that writes a file refuses to replace an existing one
// without --force, never overwrites one of its inputs (even with --force), checks this before any
// work, and writes through a temporary file and a rename (no partial file, no temporary left).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using wattswath::test::fingerprint;
using wattswath::test::Outcome;
using wattswath::test::readAll;
using wattswath::test::runCli;

/// A fresh folder under the system temporary folder, removed at the end of the test.
class OutputSafety : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("wattswath_out_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  bool temporaryLeft() const {
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().find(".tmp.") != std::string::npos) return true;
    return false;
  }
  fs::path dir_;
};

const std::string kVehicle = "data/vehicles/iris.json";

TEST_F(OutputSafety, SimulateRefusesExistingOutWithoutForce) {
  const std::string out = write("log.csv", "precious user data\n");
  const auto before = fingerprint(out);
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--out", out});
  EXPECT_FALSE(r.signalled);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(out + ": already exists; use --force"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(out), before);
  EXPECT_FALSE(temporaryLeft());
}

TEST_F(OutputSafety, SimulateReplacesExistingOutWithForce) {
  const std::string out = write("log.csv", "old\n");
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--out", out, "--force"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readAll(out).find("time_s,"), std::string::npos);
  EXPECT_FALSE(temporaryLeft());
}

TEST_F(OutputSafety, SimulateWritesNewOutWithoutForce) {
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--out", path("sub/new.csv")});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("sub/new.csv")));
  EXPECT_FALSE(temporaryLeft());
}

TEST_F(OutputSafety, SimulateNeverOverwritesItsPathInputEvenWithForce) {
  const std::string wp = write("path.txt", "0 0 10\n30 0 10\n");
  const auto before = fingerprint(wp);
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--path", wp, "--out", wp, "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("is also an input file"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(wp), before);
}

TEST_F(OutputSafety, SimulateRefusesAFolderAsOut) {
  fs::create_directories(path("folder"));
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--out", path("folder"), "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("is a folder"), std::string::npos) << r.err;
}

TEST_F(OutputSafety, ReplaySamplesOutRefusesExistingAndNeverItsLog) {
  const std::string log = path("log.csv");
  ASSERT_EQ(runCli({"simulate", "--vehicle", kVehicle, "--out", log}).status, 0);
  const std::string out = write("samples.csv", "keep me\n");
  const auto before = fingerprint(out);
  Outcome r = runCli({"replay", "--vehicle", kVehicle, "--log", log, "--samples-out", out});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("already exists; use --force"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("reading"), std::string::npos) << "checked after doing the work:\n" << r.err;
  EXPECT_EQ(fingerprint(out), before);
  const auto log_before = fingerprint(log);
  r = runCli({"replay", "--vehicle", kVehicle, "--log", log, "--samples-out", log, "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(fingerprint(log), log_before);
  r = runCli({"replay", "--vehicle", kVehicle, "--log", log, "--samples-out", out, "--force"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readAll(out).find("measured_w"), std::string::npos);
}

TEST_F(OutputSafety, LogConvertRefusesExistingOutAndNeverItsInput) {
  const std::string log = path("log.csv");
  ASSERT_EQ(runCli({"simulate", "--vehicle", kVehicle, "--out", log}).status, 0);
  const auto before = fingerprint(log);
  Outcome r = runCli({"log", "convert", log, "--out", log, "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("is also an input file"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(log), before);
  const std::string out = write("converted.csv", "keep\n");
  r = runCli({"log", "convert", log, "--out", out});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("already exists; use --force"), std::string::npos) << r.err;
  r = runCli({"log", "convert", log, "--out", out, "--force"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readAll(out).find("time_s,"), std::string::npos);
}

TEST_F(OutputSafety, ReproduceOutRefusesExistingWithoutForce) {
  const std::string out = write("report.md", "my notes\n");
  const auto before = fingerprint(out);
  const Outcome r = runCli({"reproduce", "--out", out});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("already exists; use --force"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(out), before);
}

TEST_F(OutputSafety, ReportRefusesExistingHtmlWithoutForceAndNeverTheVehicle) {
  const std::string html = write("report.html", "<p>mine</p>\n");
  const auto before = fingerprint(html);
  Outcome r = runCli({"vopt", "--vehicle", kVehicle, "--distance", "100", "--report", html});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(html + ": already exists; use --force"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(html), before);
  const std::string vehicle = path("v.json");
  fs::copy_file(wattswath::test::sourcePath(kVehicle), vehicle);
  const auto v_before = fingerprint(vehicle);
  r = runCli({"vopt", "--vehicle", vehicle, "--distance", "100", "--report", vehicle, "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("is also an input file"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(vehicle), v_before);
  r = runCli({"vopt", "--vehicle", kVehicle, "--distance", "100", "--report", html, "--force"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readAll(html).find("<svg"), std::string::npos);
}

}  // namespace
