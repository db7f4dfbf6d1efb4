// Data-driven robustness test (issue 8): runs the CLI on every malformed or degenerate input of
// tests/data/bad/ as listed in tests/data/bad/EXPECTED.tsv and checks that it answers with a
// clear error: a non-zero exit status, never a signal (crash, sanitizer abort or the hang
// watchdog), stderr naming the file, the line or field and what was expected, and the input file
// byte-for-byte unchanged afterwards.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_corpus.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using wattswath::test::Case;
using wattswath::test::fingerprint;
using wattswath::test::loadCases;
using wattswath::test::Outcome;
using wattswath::test::readAll;
using wattswath::test::runCli;
using wattswath::test::sourcePath;

std::vector<std::string> argsOf(const std::string& command, const std::string& file) {
  std::vector<std::string> args;
  std::istringstream is(command);
  std::string a;
  while (is >> a) {
    const size_t at = a.find("{}");
    if (at != std::string::npos) a.replace(at, 2, file);
    args.push_back(a);
  }
  return args;
}


class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, ClearErrorNoSignalInputUnchanged) {
  const Case& c = GetParam();
  ASSERT_FALSE(c.file.empty()) << "EXPECTED.tsv:" << c.line << ": empty file column";
  ASSERT_FALSE(c.command.empty()) << "EXPECTED.tsv:" << c.line << ": empty command column";
  ASSERT_FALSE(c.substrings.empty()) << "EXPECTED.tsv:" << c.line << ": no expected substrings";
  const std::string rel = "tests/data/bad/" + c.file;
  ASSERT_TRUE(fs::exists(sourcePath(rel))) << rel;
  const auto before = fingerprint(sourcePath(rel));
  const Outcome r = runCli(argsOf(c.command, rel));
  EXPECT_FALSE(r.signalled) << c.file << ": killed by signal " << r.signal << " (" << strsignal(r.signal)
                            << ")\nstderr:\n"
                            << r.err;
  EXPECT_NE(r.status, 0) << c.file << ": accepted a bad input\nstdout:\n" << r.out;
  for (const auto& s : c.substrings) {
    EXPECT_NE(r.err.find(s), std::string::npos) << c.file << ": stderr lacks '" << s << "'\nstderr:\n" << r.err;
  }
  EXPECT_EQ(fingerprint(sourcePath(rel)), before) << c.file << " was modified";
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string n = info.param.file + "_" + std::to_string(info.param.line);
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(loadCases()), caseName);

// Every file of the corpus is exercised: a fixture without an expectation is a test nobody runs.
TEST(BadInputCorpus, EveryFileHasAnExpectation) {
  std::set<std::string> listed;
  for (const auto& c : loadCases()) listed.insert(c.file);
  ASSERT_GT(listed.size(), 40u);
  for (const auto& c : loadCases("LIBRARY_EXPECTED.tsv")) listed.insert(c.file);
  for (const auto& e : fs::directory_iterator(sourcePath("tests/data/bad"))) {
    const std::string n = e.path().filename().string();
    if (n == "EXPECTED.tsv" || n == "LIBRARY_EXPECTED.tsv" || n == "README.md") continue;
    EXPECT_TRUE(listed.count(n)) << "tests/data/bad/" << n << " has no row in EXPECTED.tsv or LIBRARY_EXPECTED.tsv";
  }
}

// The same vehicle with a UTF-8 byte-order mark and CRLF line ends reads as the plain file.
TEST(GoodVariants, VehicleWithBomAndCrlfReadsLikePlainFile) {
  const Outcome plain = runCli({"hover", "--json", "--vehicle", "data/vehicles/iris.json"});
  const Outcome bom = runCli({"hover", "--json", "--vehicle", "tests/data/good/vehicle_bom_crlf.json"});
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(bom.status, 0) << bom.err;
  EXPECT_NE(plain.out.find("p_hover_w"), std::string::npos);
  auto withoutName = [](const std::string& s) {
    std::string r;
    std::istringstream is(s);
    std::string l;
    while (std::getline(is, l))
      if (l.find("\"vehicle\"") == std::string::npos) r += l + "\n";
    return r;
  };
  EXPECT_EQ(withoutName(bom.out), withoutName(plain.out));
}

// A geodetic log with a BOM and CRLF line ends replays (the reader's own test checks the values).
TEST(GoodVariants, LogWithBomAndCrlfReplays) {
  const Outcome r =
      runCli({"replay", "--vehicle", "data/vehicles/iris.json", "--log", "tests/data/good/bom_crlf_geodetic.csv"});
  EXPECT_FALSE(r.signalled);
  EXPECT_EQ(r.status, 0) << r.err;
}


// A position estimate that diverges late is cut there, the cut stated in the text and JSON output (issue 19).
TEST(GoodVariants, LateDivergenceIsCutWithTheReason) {
  const std::string log = "tests/data/good/log_position_diverges_late.csv";
  Outcome r = runCli({"replay", "--vehicle", "data/vehicles/iris.json", "--log", log});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: " + log + ": the position estimate is not a multirotor's at t = 29 s (vertical speed"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("the 11 samples from there on (10 s) are not used"), std::string::npos) << r.out;
  r = runCli({"replay", "--vehicle", "data/vehicles/iris.json", "--log", log, "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["measurement"]["logs"][0]["position_cut_at_s"], 29.0) << r.out;
}

// --trust-power uses an implausible power and says so, in text and in JSON (issue 19).
TEST(GoodVariants, TrustPowerOverridesAndSaysSo) {
  const std::string log = "tests/data/bad/log_current_zero.csv";
  Outcome r = runCli({"replay", "--vehicle", "data/vehicles/iris.json", "--log", log, "--trust-power"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: " + log + ": measured power used only because of --trust-power: the battery current reads 0 A"),
            std::string::npos)
      << r.out;
  r = runCli({"fit", "--vehicle", "data/vehicles/iris.json", "--log", log, "--trust-power", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  auto m = nlohmann::json::parse(r.out)["measurement"];
  EXPECT_EQ(m["trust_power"], true);
  EXPECT_EQ(m["logs"][0]["power"], "implausible, used because of --trust-power");
  EXPECT_EQ(m["logs"][0]["median_current_a"], 0.0);
  r = runCli({"replay", "--vehicle", "data/vehicles/iris.json", "--log", "tests/data/good/bom_crlf_geodetic.csv", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  m = nlohmann::json::parse(r.out)["measurement"];
  EXPECT_EQ(m["trust_power"], false);
  EXPECT_EQ(m["logs"][0]["power"], "plausible");
}

}  // namespace

namespace {
// A hole touching the outer boundary at one vertex is a valid polygon with holes (CGAL) and is read.
TEST(GoodVariants, HoleTouchingTheBorderAtOneVertexIsRead) {
  const Outcome r = runCli({"area", "info", "tests/data/good/geo_hole_touching_border.geojson"});
  EXPECT_FALSE(r.signalled);
  EXPECT_EQ(r.status, 0) << r.err;
}
}  // namespace
