// Output files (issue 8): every command that writes a file refuses to replace an existing one
// without --force, never overwrites one of its inputs (even with --force), checks this before any
// work, and writes through a temporary file and a rename (no partial file, no temporary left).
// Issue 20: `plan --force` never overwrites an input in --out; the temporary is created
// exclusively under an unpredictable name (writeTextFileAtomic, linked in from apps/cli.cpp).
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "../apps/cli.hpp"

#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using wattswath::apps::writeTextFileAtomic;
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
  const Outcome r = runCli({"simulate", "--vehicle", kVehicle, "--out", path("new.csv")});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("new.csv")));
  EXPECT_FALSE(temporaryLeft());
}

// An output's folder is not created: a typo in a path (predict --samples-out /nonexistent/dir/s.csv,
// --report) made the folders and wrote there; it is an error naming the first missing folder, before
// any work. plan's --out folder, which a run is meant to make, still is made (PlanNeverOverwrites...).
TEST_F(OutputSafety, AnOutputIntoAMissingFolderIsAnErrorNamingTheFolder) {
  const std::string mission = "tests/data/good/mission_survey.plan";
  for (const std::string& option : {std::string("--samples-out"), std::string("--report")}) {
    const std::string out = path("typo/deeper/out.file");
    const Outcome r = runCli({"predict", mission, "--vehicle", kVehicle, option, out});
    EXPECT_NE(r.status, 0) << option;
    EXPECT_NE(r.err.find(out + ": the folder " + path("typo") + " does not exist"), std::string::npos) << option << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("typo"))) << option;
  }
  const Outcome sim = runCli({"simulate", "--vehicle", kVehicle, "--out", path("sub/new.csv")});
  EXPECT_NE(sim.status, 0);
  EXPECT_NE(sim.err.find("the folder " + path("sub") + " does not exist"), std::string::npos) << sim.err;
  EXPECT_FALSE(fs::exists(path("sub")));
  // --report-svg makes its own folder, not a missing parent.
  const Outcome svg = runCli({"predict", mission, "--vehicle", kVehicle, "--report-svg", path("figs")});
  ASSERT_EQ(svg.status, 0) << svg.err;
  EXPECT_TRUE(fs::is_directory(path("figs")));
  const Outcome svg2 = runCli({"predict", mission, "--vehicle", kVehicle, "--report-svg", path("no/figs")});
  EXPECT_NE(svg2.status, 0);
  EXPECT_NE(svg2.err.find("the folder " + path("no") + " does not exist"), std::string::npos) << svg2.err;
  // An existing folder is written into.
  const Outcome ok = runCli({"predict", mission, "--vehicle", kVehicle, "--samples-out", path("s.csv")});
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(fs::exists(path("s.csv")));
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

// Two outputs of one run given the same name: the report silently replaced the samples CSV (or the
// other way round). Refused before any work, for new files as for old ones.
TEST_F(OutputSafety, TwoOutputsOfOneRunWithTheSameNameAreRefused) {
  const std::string log = path("log.csv");
  ASSERT_EQ(runCli({"simulate", "--vehicle", kVehicle, "--out", log}).status, 0);
  const std::string same = path("same.out");
  Outcome r = runCli({"replay", "--vehicle", kVehicle, "--log", log, "--samples-out", same, "--report", same});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("is named twice in this run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(same));
  // Spelled differently, the same file.
  r = runCli({"replay", "--vehicle", kVehicle, "--log", log, "--samples-out", same, "--report",
              (dir_ / "." / "same.out").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_FALSE(fs::exists(same));
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

// Issue 20: `reproduce` with no arguments used to write into the checkout's docs/reproduction.md
// (a compiled-in path) without --force; without --out it now writes nothing.
TEST_F(OutputSafety, ReproduceWithoutOutWritesNothingIntoTheCheckout) {
  const fs::path doc = wattswath::test::sourcePath("docs/reproduction.md");
  const auto before = fs::last_write_time(doc);
  const Outcome r = runCli({"reproduce", "--json"}, 300);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fs::last_write_time(doc), before);
  EXPECT_EQ(r.err.find("wrote "), std::string::npos) << r.err;
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

namespace {

// Issue 20: `plan --force` overwrote its own area file when it sat in --out under an output's name.
TEST_F(OutputSafety, PlanNeverOverwritesItsAreaInOutEvenWithForce) {
  // The E-Spiral rectangle (data/areas/espiral_rectangle.geojson) as a QGC WPL area.
  const std::string wpl =
      "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t43.718699\t10.432632\t20\t1\n"
      "1\t0\t0\t16\t0\t0\t0\t0\t43.717946\t10.430821\t10\t1\n2\t0\t0\t16\t0\t0\t0\t0\t43.717931\t10.433954\t10\t1\n"
      "3\t0\t0\t16\t0\t0\t0\t0\t43.718985\t10.433954\t10\t1\n4\t0\t0\t16\t0\t0\t0\t0\t43.718993\t10.430843\t10\t1\n";
  for (const char* name : {"path.geojson", "mission.waypoints"}) {
    const std::string area = path(name);
    if (std::string(name) == "path.geojson") {
      fs::copy_file(wattswath::test::sourcePath("data/areas/espiral_rectangle.geojson"), area);
    } else {
      write(name, wpl);
    }
    const auto before = fingerprint(area);
    const Outcome r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", dir_.string(), "--force"});
    EXPECT_NE(r.status, 0) << name;
    EXPECT_NE(r.err.find(area + ": is also an input file"), std::string::npos) << r.err;
    EXPECT_EQ(fingerprint(area), before) << name;
    EXPECT_FALSE(fs::exists(path("mission.plan"))) << "refused after writing: " << name;
    fs::remove(area);
  }
}

// Issue 20: the CLI's atomic writer (apps/cli.cpp writeTextFileAtomic, linked in here) creates its
// temporary with an unpredictable name and exclusively, so a symlink planted at the old predictable
// name `<out>.tmp.<pid>` is never followed; a failed write leaves the old file and no temporary.
int temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().find(".tmp.") != std::string::npos;
  return n;
}

TEST_F(OutputSafety, AtomicWriteAPlantedSymlinkAtThePredictableNameIsNeverFollowed) {
  const fs::path victim = dir_ / "victim.txt", out = dir_ / "out.txt";
  std::ofstream(victim) << "unrelated file\n";
  const fs::path trap = out.string() + ".tmp." + std::to_string(::getpid());
  fs::create_symlink(victim, trap);
  writeTextFileAtomic(out.string(), "new text\n");
  EXPECT_EQ(readAll(victim), "unrelated file\n");
  EXPECT_EQ(readAll(out), "new text\n");
  EXPECT_FALSE(fs::is_symlink(out));
  EXPECT_TRUE(fs::is_symlink(trap));  // the planted link is left alone
  EXPECT_EQ(temporaries(dir_), 1);        // ... and is the only ".tmp." name there
}

TEST_F(OutputSafety, AtomicWriteAFailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path out = dir_ / "out.txt";
  std::ofstream(out) << "old\n";
  // A 4 KiB file-size limit makes the 1 MB write fail part way (EFBIG; SIGXFSZ ignored).
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeTextFileAtomic(out.string(), std::string(1 << 20, 'x'));
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, handler);
  EXPECT_NE(message.find(out.string() + ": write failed"), std::string::npos) << message;
  EXPECT_EQ(readAll(out), "old\n");
  EXPECT_EQ(temporaries(dir_), 0);
}

TEST_F(OutputSafety, AtomicWriteASignalDuringTheWriteLeavesNoTemporary) {
  // A child process writes 1 MB under a 4 KiB file-size limit with SIGXFSZ at its default (the
  // process dies part way, as on Ctrl-C): the handler removes the temporary before it dies.
  const fs::path out = dir_ / "out.txt";
  std::ofstream(out) << "old\n";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_DFL);
    rlimit small{};
    ::getrlimit(RLIMIT_FSIZE, &small);
    small.rlim_cur = 4096;
    ::setrlimit(RLIMIT_FSIZE, &small);
    try {
      writeTextFileAtomic(out.string(), std::string(1 << 20, 'x'));
    } catch (...) {
    }
    ::_exit(0);  // not reached: SIGXFSZ ends the child
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGXFSZ);
  EXPECT_EQ(readAll(out), "old\n");
  EXPECT_EQ(temporaries(dir_), 0);
}

TEST_F(OutputSafety, AtomicWriteReplacesASymlinkedTargetNameRatherThanWritingThroughIt) {
  // rename() replaces the name: a symlink at the output path is refused up front (not a regular file).
  const fs::path victim = dir_ / "victim.txt", out = dir_ / "out.txt";
  std::ofstream(victim) << "unrelated file\n";
  fs::create_symlink(victim, out);
  EXPECT_THROW(writeTextFileAtomic(out.string(), "new\n"), std::runtime_error);
  EXPECT_EQ(readAll(victim), "unrelated file\n");
  EXPECT_EQ(temporaries(dir_), 0);
}

}  // namespace

namespace {

// Issue 20: plan's files are one set. A run that fails after its mission files are written (here:
// the battery cannot fly one sortie) leaves the previous run's files exactly as they were, and no
// temporaries; a second run into a folder another run holds is refused at once.
TEST_F(OutputSafety, PlanFailingMidwayKeepsThePreviousRunsFilesAsASet) {
  const std::string area = wattswath::test::sourcePath("data/areas/espiral_rectangle.geojson");
  Outcome r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", dir_.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  std::map<std::string, std::string> before;
  for (const char* f : {"mission.plan", "mission.waypoints", "path.geojson", "legs.csv", "report.html"})
    before[f] = readAll(path(f));
  r = runCli({"plan", area, "--vehicle", "tests/data/iris-small-battery.json", "--spacing", "10", "--sorties", "1",
              "--out", dir_.string(), "--force"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("no split into 1"), std::string::npos) << r.err;
  for (const auto& [f, text] : before) EXPECT_EQ(readAll(path(f)), text) << f << " changed by a run that failed";
  EXPECT_FALSE(fs::exists(path("sortie_01.plan")));
  EXPECT_FALSE(temporaryLeft());
}

TEST_F(OutputSafety, PlanIntoAFolderAnotherRunHoldsIsRefused) {
  const int fd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as a running plan holds it
  const Outcome r = runCli({"plan", wattswath::test::sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle",
                            kVehicle, "--spacing", "20", "--out", dir_.string()});
  ::close(fd);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(dir_.string() + ": another wattswath run is writing into this folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("mission.plan")));
}

// Issue 20 follow-up: the output set used to be committed by renaming its files one after another,
// so a power cut between two renames left part of one run's files beside part of another's. The
// files are now listed in the folder's journal (.wattswath-commit, flushed) before the renames; the
// next run into the folder completes an interrupted commit before anything else.
TEST_F(OutputSafety, PlanCompletesTheCommitAnEarlierRunLeftHalfDone) {
  const std::string area = wattswath::test::sourcePath("data/areas/espiral_rectangle.geojson");
  Outcome r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", dir_.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(path(".wattswath-commit")));  // a finished commit leaves no journal
  // As a crash would leave it: the journal, one temporary still to rename, one already renamed,
  // and entries that are not this program's temporaries (left alone).
  write("notes.txt", "old\n");
  write("notes.txt.tmp.0123456789abcdef", "new\n");
  write("other.txt", "untouched\n");
  write(".wattswath-commit",
        "# wattswath: files of an interrupted run\n"
        "notes.txt.tmp.0123456789abcdef\tnotes.txt\n"
        "legs.csv.tmp.00000000000000aa\tlegs.csv\n"
        "other.txt\tnotes.txt\n"
        "../other.txt.tmp.0123456789abcdef\t../other.txt\n");
  r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", dir_.string(), "--force"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("completed the interrupted commit of an earlier run (1 file(s)"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(path("notes.txt")), "new\n");
  EXPECT_EQ(readAll(path("other.txt")), "untouched\n");
  EXPECT_FALSE(fs::exists(path(".wattswath-commit")));
  EXPECT_FALSE(temporaryLeft());
}

// A --report outside the plan folder is part of the same commit: the folder's journal lists it by
// absolute path before any rename, so a crash midway is completed for it too; entries elsewhere
// that are not this program's temporary of their target, or not absolute, are left alone.
TEST_F(OutputSafety, PlanJournalsAReportOutsideItsFolderAndCompletesItAfterACrash) {
  const std::string area = wattswath::test::sourcePath("data/areas/espiral_rectangle.geojson");
  const fs::path out = dir_ / "plan", elsewhere = dir_ / "reports";
  fs::create_directories(elsewhere);
  const std::string report = (elsewhere / "survey.html").string();
  Outcome r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", out.string(), "--report", report});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(report));
  EXPECT_FALSE(fs::exists(out / ".wattswath-commit"));
  // As a crash right after the journal would leave it: the report's temporary still to rename.
  std::ofstream(report + ".tmp.00000000000000ab") << "new report\n";
  std::ofstream((elsewhere / "keep.txt").string()) << "untouched\n";
  std::ofstream((elsewhere / "keep.txt.tmp.zzzzzzzzzzzzzzzz").string()) << "not ours\n";
  std::ofstream((out / ".wattswath-commit").string())
      << "# wattswath: files of an interrupted run\n"
      << report << ".tmp.00000000000000ab\t" << report << "\n"
      << (elsewhere / "keep.txt.tmp.zzzzzzzzzzzzzzzz").string() << "\t" << (elsewhere / "keep.txt").string() << "\n"
      << "reports/keep.txt.tmp.00000000000000ab\treports/keep.txt\n";
  r = runCli({"plan", area, "--vehicle", kVehicle, "--spacing", "20", "--out", out.string(), "--force", "--no-report"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("completed the interrupted commit of an earlier run (1 file(s)"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(report), "new report\n");
  EXPECT_EQ(readAll((elsewhere / "keep.txt").string()), "untouched\n");
  EXPECT_FALSE(fs::exists(out / ".wattswath-commit"));
}

}  // namespace
