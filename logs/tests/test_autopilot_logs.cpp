// The four real autopilot logs of ../shared/data/autopilot-logs: values stated in its README
// (voltage and current ranges, spans, airborne windows, medians), truncated and corrupted copies
// (made in a temporary folder at test time), and the `log info` / `log convert` commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "wattswath/logs/airframe.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/logs/ulog.hpp"
namespace fs = std::filesystem;
using wattswath::test::sharedData;

namespace {

std::string logPath(const std::string& name) { return sharedData("autopilot-logs/" + name); }
const std::string kAc33 = "arducopter-3.3_quad_log171.bin";
const std::string kAc35 = "arducopter-3.5_quad_rtl.bin";
const std::string kPx19 = "px4-1.9_quad_mission_rtl.ulg";
const std::string kPx115 = "px4-1.15_quad_manual_posctl.ulg";

struct Stats {
  double vmin = INFINITY, vmax = -INFINITY, imin = INFINITY, imax = -INFINITY;
  double air_current_median = NAN, air_power_median = NAN, max_hspeed = 0.0, zmin = INFINITY, zmax = -INFINITY;
};

double medianOf(std::vector<double> x) {
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2), x.end());
  return x[x.size() / 2];
}

Stats stats(const wattswath::logs::FlightLog& log) {
  Stats s;
  std::vector<double> ia, pa;
  for (const auto& x : log.samples) {
    s.vmin = std::min(s.vmin, x.voltage);
    s.vmax = std::max(s.vmax, x.voltage);
    s.imin = std::min(s.imin, x.current);
    s.imax = std::max(s.imax, x.current);
    s.max_hspeed = std::max(s.max_hspeed, x.velocity.head<2>().norm());
    s.zmin = std::min(s.zmin, x.position.z());
    s.zmax = std::max(s.zmax, x.position.z());
    for (const auto& w : log.airborne)
      if (x.t >= w.begin && x.t <= w.end) {
        ia.push_back(x.current);
        pa.push_back(x.power);
      }
  }
  if (!ia.empty()) {
    s.air_current_median = medianOf(ia);
    s.air_power_median = medianOf(pa);
  }
  return s;
}

wattswath::logs::LogReadOptions lenientOptions(bool lenient) {
  wattswath::logs::LogReadOptions o;
  o.lenient = lenient;
  return o;
}

wattswath::logs::LogReadOptions window(double from, double to) {
  wattswath::logs::LogReadOptions o;
  o.from_s = from;
  o.to_s = to;
  return o;
}

std::vector<std::uint8_t> bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// README §1: APM:Copter V3.3-dev, CURR centi-units, 11.5-254.1 s, airborne 84 s to the end.
TEST(AutopilotLogs, ArduCopter33_MatchesReadme) {
  const auto log = wattswath::logs::readFlightLog(logPath(kAc33));
  EXPECT_EQ(log.format, "dataflash");
  EXPECT_NE(log.metadata.at("firmware").find("APM:Copter V3.3-dev"), std::string::npos);
  EXPECT_NE(log.metadata.at("vehicle").find("QUAD"), std::string::npos);
  EXPECT_NE(log.metadata.at("battery_source").find("CURR instance 0"), std::string::npos);
  EXPECT_NE(log.metadata.at("position_source").find("EKF1"), std::string::npos);
  const auto s = stats(log);
  EXPECT_NEAR(s.vmin, 14.91, 0.005);   // README: 14.91-16.54 V
  EXPECT_NEAR(s.vmax, 16.54, 0.005);
  EXPECT_NEAR(s.imin, 0.52, 0.005);    // README: 0.52-27.44 A
  EXPECT_NEAR(s.imax, 27.44, 0.005);
  EXPECT_NEAR(log.samples.front().t, 11.5, 0.15);  // README data span 11.5-254.1 s
  EXPECT_NEAR(log.samples.back().t, 254.1, 0.15);
  ASSERT_EQ(log.airborne.size(), 1u);  // README: current > 5 A from 83.4 s to the end (no landing)
  EXPECT_NEAR(log.airborne[0].begin, 83.4, 0.2);
  EXPECT_NEAR(log.airborne[0].end, 254.1, 0.15);
  EXPECT_NEAR(s.air_current_median, 14.6, 0.15);  // README: median 14.6 A in the air
  EXPECT_NEAR(s.air_power_median, 224.0, 5.0);    // README: about 224 W
  EXPECT_NEAR(std::stod(log.metadata.at("battery_rate_hz")), 9.8, 0.2);  // README: CURR 9.8 Hz
  EXPECT_LE(s.max_hspeed, 13.0);  // README: GPS ground speed up to 12.2 m/s
  EXPECT_GE(s.max_hspeed, 7.0);
}

// README §2: ArduCopter ~3.5 RTL, float CURR, NKF1, landing (EV 17) at 452.7 s.
TEST(AutopilotLogs, ArduCopter35_MatchesReadme) {
  const auto log = wattswath::logs::readFlightLog(logPath(kAc35));
  EXPECT_NE(log.metadata.at("firmware").find("version not logged"), std::string::npos);
  EXPECT_NE(log.metadata.at("position_source").find("NKF1"), std::string::npos);
  const auto s = stats(log);
  EXPECT_NEAR(s.vmin, 12.83, 0.005);  // README: 12.83-13.46 V
  EXPECT_NEAR(s.vmax, 13.46, 0.005);
  EXPECT_NEAR(s.imin, 2.31, 0.005);   // README: 2.31-18.14 A
  EXPECT_NEAR(s.imax, 18.14, 0.005);
  EXPECT_NEAR(log.duration(), 50.9, 0.3);  // README: 402.6-453.5 s
  ASSERT_EQ(log.airborne.size(), 1u);      // README: airborne 402.6-452.7 s
  EXPECT_NEAR(log.airborne[0].begin, 402.6, 0.15);
  EXPECT_NEAR(log.airborne[0].end, 452.7, 0.05);
  EXPECT_NEAR(s.air_current_median, 14.5, 0.15);  // README: 14.5 A, about 188 W
  EXPECT_NEAR(s.air_power_median, 188.0, 5.0);
  EXPECT_NEAR(s.zmax - s.zmin, 14.0, 1.5);  // README: RelHomeAlt 1.2-15.3 m
  EXPECT_LE(s.max_hspeed, 5.5);             // README: up to 4.9 m/s
  const auto& e = log.events;
  const bool rtl = std::any_of(e.begin(), e.end(), [](const wattswath::logs::LogEvent& x) { return x.kind == "mode" && x.text == "RTL (6)"; });
  EXPECT_TRUE(rtl);
}

// README §3: PX4 v1.9.0, starts in the air, RTL at 5098.7 s, touchdown ~5118.1 s, landed 5119.4 s.
TEST(AutopilotLogs, Px4_19_MatchesReadme) {
  const auto log = wattswath::logs::readFlightLog(logPath(kPx19));
  EXPECT_EQ(log.format, "ulog");
  EXPECT_NE(log.metadata.at("firmware").find("v1.9.0"), std::string::npos);
  EXPECT_NE(log.metadata.at("firmware").find("IA-release-1"), std::string::npos);
  EXPECT_NE(log.metadata.at("vehicle").find("quadrotor"), std::string::npos);
  EXPECT_NE(log.metadata.at("vehicle").find("PX4_FMU_V3"), std::string::npos);
  const auto s = stats(log);
  EXPECT_NEAR(s.vmin, 21.75, 0.01);  // README: 21.75-22.58 V
  EXPECT_NEAR(s.vmax, 22.58, 0.01);
  EXPECT_NEAR(s.imin, 26.6, 0.1);    // README: 26.6-73.9 A
  EXPECT_NEAR(s.imax, 73.9, 0.1);
  EXPECT_NEAR(s.air_current_median, 57.0, 1.0);  // README: median 57 A, about 1.25 kW
  EXPECT_NEAR(s.air_power_median, 1250.0, 30.0);
  EXPECT_NEAR(std::stod(log.metadata.at("battery_rate_hz")), 1.9, 0.15);
  ASSERT_EQ(log.airborne.size(), 1u);
  EXPECT_LE(log.airborne[0].begin, 5081.5);  // in the air from the first data (5080.5 s)
  EXPECT_GE(log.airborne[0].end, 5118.0);    // touchdown ~5118.1 s, landed flag at 5119.4 s
  EXPECT_LE(log.airborne[0].end, 5119.5);
  EXPECT_LE(s.max_hspeed, 7.0);  // README: loop at about 5 m/s
  EXPECT_GE(s.max_hspeed, 4.0);
  EXPECT_NEAR(log.samples.back().position.z(), 6.5, 0.5);  // touchdown at local z = -6.5 m
  const auto rtl = std::find_if(log.events.begin(), log.events.end(),
                                [](const wattswath::logs::LogEvent& x) { return x.kind == "mode" && x.text == "AUTO_RTL (5)"; });
  ASSERT_NE(rtl, log.events.end());
  EXPECT_NEAR(rtl->t, 5098.7, 0.1);
}

// README §4: PX4 v1.15.0, take-off 49.2 s, landing 123.5 s, manual flight up to ~20 m/s.
TEST(AutopilotLogs, Px4_115_MatchesReadme) {
  const auto log = wattswath::logs::readFlightLog(logPath(kPx115));
  EXPECT_NE(log.metadata.at("firmware").find("v1.15.0"), std::string::npos);
  EXPECT_NE(log.metadata.at("vehicle").find("NXP_MR_TROPIC"), std::string::npos);
  const auto s = stats(log);
  EXPECT_NEAR(s.vmin, 22.96, 0.01);  // README: 22.96-24.89 V (the first samples precede the position data)
  EXPECT_GE(s.vmax, 24.8);
  EXPECT_LE(s.vmax, 24.89 + 1e-6);
  EXPECT_NEAR(s.imax, 36.8, 0.05);   // README: 0.19-36.8 A
  EXPECT_LE(s.imin, 0.35);
  EXPECT_NEAR(std::stod(log.metadata.at("battery_rate_hz")), 5.0, 0.1);
  ASSERT_EQ(log.airborne.size(), 1u);  // the 0.1 s landing blip at 114.1 s is merged
  EXPECT_NEAR(log.airborne[0].begin, 49.2, 0.05);
  EXPECT_NEAR(log.airborne[0].end, 123.5, 0.05);
  EXPECT_NEAR(s.air_current_median, 8.6, 0.2);  // README: median 8.6 A, about 207 W
  EXPECT_NEAR(s.air_power_median, 207.0, 6.0);
  EXPECT_NEAR(s.max_hspeed, 20.0, 2.0);  // README: up to about 20 m/s
  EXPECT_LE(s.zmax, 19.0);               // README: up to 18 m above the origin
}

// README: "Current > 5 A gives the same windows" as the take-off and landing events.
TEST(AutopilotLogs, CurrentThresholdAgreesWithLandedEvents) {
  for (const auto& name : {kPx115, kAc35}) {
    const auto log = wattswath::logs::readFlightLog(logPath(name));
    std::vector<double> t, i;
    for (const auto& x : log.samples) {
      t.push_back(x.t);
      i.push_back(x.current);
    }
    const auto w = wattswath::logs::detectAirborne(t, i, {}, wattswath::logs::AirborneSettings{});
    ASSERT_FALSE(w.empty()) << name;
    for (const auto& x : w) std::cerr << name << ": current > 5 A from " << x.begin << " to " << x.end << " s\n";
    EXPECT_NEAR(w.front().begin, log.airborne[0].begin, 1.0) << name;
    EXPECT_NEAR(w.back().end, log.airborne[0].end, 1.0) << name;
  }
}

TEST(AutopilotLogs, TimeWindowAndAirborneOnly) {
  wattswath::logs::LogReadOptions o;
  o.from_s = 410.0;
  o.to_s = 425.0;
  auto log = wattswath::logs::readFlightLog(logPath(kAc35), o);
  EXPECT_GE(log.samples.front().t, 410.0);
  EXPECT_LE(log.samples.back().t, 425.0);
  EXPECT_NEAR(log.duration(), 15.0, 0.2);
  ASSERT_EQ(log.airborne.size(), 1u);
  EXPECT_DOUBLE_EQ(log.airborne[0].begin, 410.0);
  EXPECT_DOUBLE_EQ(log.airborne[0].end, 425.0);
  o = {};
  o.airborne_only = true;
  log = wattswath::logs::readFlightLog(logPath(kPx115), o);
  EXPECT_GE(log.samples.front().t, 49.2);
  EXPECT_LE(log.samples.back().t, 123.5);
}

TEST(AutopilotLogs, SecondEkfCoreAgreesWithFirst) {
  wattswath::logs::LogReadOptions o;
  o.position_source = "NKF6";
  const auto core1 = wattswath::logs::readFlightLog(logPath(kAc35), o);
  const auto core0 = wattswath::logs::readFlightLog(logPath(kAc35));
  ASSERT_EQ(core0.samples.size(), core1.samples.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < core0.samples.size(); ++k)
    worst = std::max(worst, (core0.samples[k].position - core1.samples[k].position).norm());
  EXPECT_LT(worst, 3.0);
  o.position_source = "GPS";
  EXPECT_THROW(wattswath::logs::readFlightLog(logPath(kAc35), o), std::runtime_error);
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wattswath_autopilot_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::vector<std::uint8_t>& b) {
    const auto p = (dir_ / name).string();
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
    return p;
  }
  fs::path dir_;
};

std::string errorOf(const std::string& path, const wattswath::logs::LogReadOptions& o = {}) {
  try {
    wattswath::logs::readFlightLog(path, o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// A log cut inside its last record (as ArduPilot's logger leaves it, and pymavlink reads) is read
// without --lenient; the cut is named in the warnings (issue 19).
TEST_F(TempDir, TruncatedDataFlashNamesOffsetAndMessage) {
  auto b = bytesOf(logPath(kAc35));
  b.resize(b.size() / 2 + 7);  // cut inside a message
  const auto p = write("cut.bin", b);
  EXPECT_EQ(errorOf(p), "");
  const auto log = wattswath::logs::readFlightLog(p, {});
  EXPECT_NE(log.metadata.at("warnings").find("byte offset"), std::string::npos);
  EXPECT_NE(log.metadata.at("warnings").find("message (type"), std::string::npos);
  EXPECT_GT(log.samples.size(), 200u);
  EXPECT_NE(log.metadata.at("warnings").find("truncated"), std::string::npos);
}

TEST_F(TempDir, CorruptDataFlashHeaderNamesOffset) {
  auto b = bytesOf(logPath(kAc35));
  const std::size_t at = 300000;
  const std::uint8_t head[2] = {0xA3, 0x95};
  auto next = std::search(b.begin() + at, b.end(), std::begin(head), std::end(head));
  const auto off = static_cast<std::size_t>(next - b.begin());
  b[off] = 0x00;
  const auto err = errorOf(write("bad.bin", b));
  EXPECT_NE(err.find("byte offset " + std::to_string(off) + ": expected message header 0xA3 0x95, found 0x00 0x95"),
            std::string::npos) << err;
  wattswath::logs::LogReadOptions o;
  o.lenient = true;
  EXPECT_NO_THROW(wattswath::logs::readFlightLog(write("bad2.bin", b), o));
}

TEST_F(TempDir, TruncatedUlogNamesOffsetAndMessage) {
  auto b = bytesOf(logPath(kPx19));
  b.resize(b.size() - 1000);
  const auto err = errorOf(write("cut.ulg", b));
  EXPECT_NE(err.find("byte offset"), std::string::npos) << err;
  EXPECT_NE(err.find("message"), std::string::npos) << err;
  EXPECT_NE(err.find("truncated"), std::string::npos) << err;
  b.resize(12);
  EXPECT_NE(errorOf(write("header.ulg", b)).find("shorter than the 16-byte ULog header"), std::string::npos);
}

// Issue 19: a real ULog with a 12-byte zero-filled stretch in the middle of its flight. Strict mode
// names it and --lenient; lenient mode resynchronises on the next valid message and reads to the
// end (landing included), listing the gap.
TEST_F(TempDir, UlogZeroGapIsSkippedToTheEnd) {
  auto b = bytesOf(logPath(kPx115));
  const auto whole = wattswath::logs::readFlightLog(logPath(kPx115));
  // The start of a message near the middle: walk the messages from the end of the header section.
  std::size_t pos = 16, mid = 0;
  while (pos + 3 <= b.size() && pos < b.size() / 2) {
    mid = pos;
    pos += 3 + (b[pos] | (b[pos + 1] << 8));
  }
  b.insert(b.begin() + static_cast<std::ptrdiff_t>(mid), 12, 0);
  const std::string p = write("gap.ulg", b);
  const auto err = errorOf(p);
  EXPECT_NE(err.find("byte offset " + std::to_string(mid)), std::string::npos) << err;
  EXPECT_NE(err.find("use --lenient"), std::string::npos) << err;
  wattswath::logs::LogReadOptions o;
  o.lenient = true;
  const auto log = wattswath::logs::readFlightLog(p, o);
  EXPECT_DOUBLE_EQ(log.samples.back().t, whole.samples.back().t);
  EXPECT_EQ(log.samples.size(), whole.samples.size());
  EXPECT_NE(log.metadata.at("gaps").find("1 skipped: byte offset " + std::to_string(mid) + ", 12 bytes"), std::string::npos)
      << log.metadata.at("gaps");
  EXPECT_EQ(log.metadata.count("ends_airborne"), 0u);  // it lands
}

// The ArduCopter 3.3 log ends with the motors at hover output (README): the reader says so.
TEST(AutopilotLogs, LogEndingInTheAirSaysSo) {
  const auto ac33 = wattswath::logs::readFlightLog(logPath(kAc33));
  EXPECT_EQ(ac33.metadata.at("ends_airborne"), "yes");
  EXPECT_NE(ac33.metadata.at("warnings").find("the log ends while airborne (at 254.07"), std::string::npos)
      << ac33.metadata.at("warnings");
  for (const auto& name : {kAc35, kPx19, kPx115}) {
    EXPECT_EQ(wattswath::logs::readFlightLog(logPath(name)).metadata.count("ends_airborne"), 0u) << name;
  }
}

// The 3.5 and PX4 1.9 logs begin in the air (README: an RTL, a mission's end): the reader says the
// take-off is not in the log, and the airborne windows, found on the battery's clock, stay inside
// the samples (the PX4 window began 0.5 s before the first sample, the 3.3 one ended after the last).
TEST(AutopilotLogs, LogStartingInTheAirSaysSoAndWindowsStayInsideTheSamples) {
  for (const auto& name : {kAc35, kPx19}) {
    const auto log = wattswath::logs::readFlightLog(logPath(name));
    EXPECT_EQ(log.metadata.at("starts_airborne"), "yes") << name;
    EXPECT_NE(log.metadata.at("warnings").find("the log starts while airborne"), std::string::npos) << name;
  }
  for (const auto& name : {kAc33, kAc35, kPx19, kPx115}) {
    const auto log = wattswath::logs::readFlightLog(logPath(name));
    for (const auto& w : log.airborne) {
      EXPECT_GE(w.begin, log.samples.front().t) << name;
      EXPECT_LE(w.end, log.samples.back().t) << name;
    }
  }
  EXPECT_EQ(wattswath::logs::readFlightLog(logPath(kAc33)).metadata.count("starts_airborne"), 0u);  // takes off in it
  EXPECT_EQ(wattswath::logs::readFlightLog(logPath(kPx115)).metadata.count("starts_airborne"), 0u);
}

// `log info` reads as text, not as JSON leftovers, and says when a current is in mA.
TEST_F(TempDir, LogInfoTextSaysWhatIsNotLoggedAndCatchesMilliamperes) {
  using wattswath::test::cliBinary;
  using wattswath::test::run;
  const std::string csv = sharedData("iris-flights/2017-10-18_1436_energy14.csv");
  const auto r = run(cliBinary() + " log info " + csv + " 2>&1");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("null"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("firmware:  not in the log"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("power:     158.6 to 294.7 W"), std::string::npos) << r.output;
  // The same log with its current in mA (the header keeps its name, the values are 1000 times larger).
  std::ifstream in(csv);
  std::ostringstream out;
  std::string line;
  int current_col = -1;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || current_col == -2) {
      out << line << "\n";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c.substr(0, c.find('\r')));
    if (current_col < 0) {
      current_col = static_cast<int>(std::find(cells.begin(), cells.end(), "current_a") - cells.begin());
      ASSERT_LT(current_col, static_cast<int>(cells.size())) << line;
      out << line << "\n";
      continue;
    }
    cells[current_col] = std::to_string(1000.0 * std::stod(cells[current_col]));
    for (std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << cells[k];
    out << "\n";
  }
  const std::string text = out.str();
  const std::string ma = write("ma.csv", std::vector<std::uint8_t>(text.begin(), text.end()));
  const auto m = run(cliBinary() + " log info " + ma + " --json 2>&1");
  EXPECT_EQ(m.status, 0) << m.output;
  EXPECT_NE(m.output.find("is current_a logged in mA?"), std::string::npos) << m.output;
}

// Seeded random corruption: every outcome is a log or an exception with a message, never a crash.
TEST_F(TempDir, RandomCorruptionNeverCrashes) {
  std::mt19937 rng(42);
  for (const auto& name : {kAc35, kPx19}) {
    const auto original = bytesOf(logPath(name));
    for (int trial = 0; trial < 12; ++trial) {
      auto b = original;
      std::uniform_int_distribution<std::size_t> pos(0, b.size() - 1);
      for (int k = 0; k < 20; ++k) b[pos(rng)] = static_cast<std::uint8_t>(rng());
      if (trial % 3 == 0) b.resize(pos(rng));
      for (bool lenient : {false, true}) {
        try {
          if (name == kAc35) wattswath::logs::readDataFlashBytes(b, name, lenientOptions(lenient));
          else wattswath::logs::readUlogBytes(b, name, lenientOptions(lenient));
        } catch (const std::exception& e) {
          EXPECT_GT(std::string(e.what()).size(), 10u);
        }
      }
    }
  }
}

TEST_F(TempDir, CliInfoJsonAndConvertRoundTrip) {
  using wattswath::test::cliBinary;
  using wattswath::test::run;
  const auto r = run(cliBinary() + " log info " + logPath(kPx115) + " --json");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j.at("format"), "ulog");
  EXPECT_NE(j.at("firmware").get<std::string>().find("v1.15.0"), std::string::npos);
  ASSERT_EQ(j.at("airborne_windows").size(), 1u);
  EXPECT_NEAR(j["airborne_windows"][0]["begin_s"].get<double>(), 49.2, 0.05);
  EXPECT_NEAR(j["airborne_windows"][0]["end_s"].get<double>(), 123.5, 0.05);
  EXPECT_NEAR(j["sample_rates_hz"]["battery"].get<double>(), 5.0, 0.1);
  for (const char* k : {"vehicle", "duration_s", "battery_source", "position_source", "voltage_v", "current_a"})
    EXPECT_TRUE(j.contains(k)) << k;

  const auto out = (dir_ / "flight.csv").string();
  const auto c = run(cliBinary() + " log convert " + logPath(kAc35) + " --out " + out + " --from 405 --to 450 2>&1");
  ASSERT_EQ(c.status, 0) << c.output;
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("# source_file: " + logPath(kAc35)), std::string::npos);
  EXPECT_NE(text.find("# battery_source: CURR instance 0"), std::string::npos);
  const auto back = wattswath::logs::readCsvLog(out);
  const auto direct = wattswath::logs::readFlightLog(logPath(kAc35), window(405.0, 450.0));
  ASSERT_EQ(back.samples.size(), direct.samples.size());
  EXPECT_NEAR(back.samples.back().voltage, direct.samples.back().voltage, 1e-9);
  EXPECT_NEAR(back.samples.back().position.x(), direct.samples.back().position.x(), 1e-9);

  const auto bad = run(cliBinary() + " log info " + logPath(kAc35) + " --from 600 --to 700 2>&1");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("data span"), std::string::npos) << bad.output;
}

// The README walkthrough on the ArduCopter 3.3 flight (clean airborne part 84-236 s, estimated
// Solo vehicle): fitted on 84-160 s, tested on 160-236 s. README numbers: held-out RMSE 65.7 W
// with the paper's model as given, 31.6 W refitted, 23.9 W with load_efficiency added.
TEST_F(TempDir, Walkthrough_Solo_FitLowersHeldOutError) {
  using wattswath::test::cliBinary;
  using wattswath::test::run;
  using wattswath::test::sourcePath;
  const std::string train = (dir_ / "train.csv").string(), test = (dir_ / "test.csv").string();
  ASSERT_EQ(run(cliBinary() + " log convert " + logPath(kAc33) + " --out " + train + " --from 84 --to 160 2>/dev/null").status, 0);
  ASSERT_EQ(run(cliBinary() + " log convert " + logPath(kAc33) + " --out " + test + " --from 160 --to 236 2>/dev/null").status, 0);
  auto fit = [&](const std::string& effects) {
    const auto r = run(cliBinary() + " fit --vehicle " + sourcePath("data/vehicles/solo.json") + " --effects " + effects +
                       " --log " + train + " --test-log " + test + " --json 2>/dev/null");
    EXPECT_EQ(r.status, 0) << r.output;
    return nlohmann::json::parse(r.output);
  };
  const auto paper = fit("hover,kinetic,parasitic_drag");
  const auto lift = fit("hover,kinetic,parasitic_drag,load_efficiency");
  const double before = paper["test"]["before"]["rmse_w"], refit = paper["test"]["rmse_w"], added = lift["test"]["rmse_w"];
  EXPECT_NEAR(before, 65.7, 1.0);
  EXPECT_NEAR(refit, 31.6, 1.0);
  EXPECT_NEAR(added, 23.9, 1.0);
  EXPECT_LT(added, refit);
  EXPECT_NEAR(paper["test"]["before"]["energy_error_pct"].get<double>(), 25.2, 0.5);
}

}  // namespace

// The airframe's response from the position controller's target acceleration against the one its
// lean angles give (PSCN/PSCE): the three SITL flights of one quad fit the lag of ArduCopter's
// attitude input shaping, ATC_INPUT_TC 0.15 s in their parameters, within 0.02 s, the lag
// explaining over 99 % of the variance; a 3.5 log (no PSCN/PSCE) is not determined, with the reason.
TEST(AirframeResponse, SitlFlightsFitTheAttitudeTimeConstantAndOlderLogsSayWhyNot) {
  const std::string dir = std::string(WATTSWATH_SHARED_DATA_DIR);
  for (const char* name : {"square_5mps", "square_10mps", "plan_sharp_hold1s"}) {
    const auto a = wattswath::logs::estimateAirframe(dir + "/sitl/" + name + ".BIN");
    ASSERT_TRUE(a.response.determined) << name << ": " << a.response.reason;
    EXPECT_NEAR(a.response.response_s, 0.15, 0.02) << name;
    EXPECT_GT(a.response.r2, 0.99) << name;
    EXPECT_TRUE(a.drag.determined) << name;  // one reading gives both
  }
  const auto old = wattswath::logs::estimateAirframe(dir + "/autopilot-logs/arducopter-3.5_quad_rtl.bin");
  EXPECT_FALSE(old.response.determined);
  EXPECT_NE(old.response.reason.find("PSCN"), std::string::npos) << old.response.reason;
}

// The airframe's drag from the lean angle against the EKF velocity: the three ArduCopter SITL
// flights of the same simulated quad agree (drag deceleration at 8 m/s within 10 % of each other,
// the fit explaining > 99 % of its variance); a real 3.3 log flown by hand in wind is refused with
// the reason.
TEST(AirframeDrag, SitlFlightsOfOneQuadAgreeAndARealWindyLogIsNotDetermined) {
  const std::string dir = std::string(WATTSWATH_SHARED_DATA_DIR);
  std::vector<double> at8;
  for (const char* name : {"square_5mps", "square_10mps", "plan_sharp_hold1s"}) {
    const auto d = wattswath::logs::estimateAirframeDrag(dir + "/sitl/" + name + ".BIN");
    ASSERT_TRUE(d.determined) << name << ": " << d.reason;
    EXPECT_GT(d.r2, 0.99) << name;
    EXPECT_EQ(d.velocity_source, "XKF1");
    at8.push_back(d.drag_linear_per_s * 8.0 + d.drag_quadratic_per_m * 64.0);
  }
  const auto [lo, hi] = std::minmax_element(at8.begin(), at8.end());
  EXPECT_LT(*hi / *lo, 1.10);
  EXPECT_GT(*lo, 3.0);  // [m/s^2] the SITL quad leans about 20 degrees at 8 m/s
  const auto real = wattswath::logs::estimateAirframeDrag(dir + "/autopilot-logs/arducopter-3.3_quad_log171.bin");
  EXPECT_FALSE(real.determined);
  EXPECT_NE(real.reason.find("variance"), std::string::npos) << real.reason;
  EXPECT_THROW(wattswath::logs::estimateAirframeDrag(dir + "/autopilot-logs/px4-1.9_quad_mission_rtl.ulg"), std::runtime_error);
}

// The part of a log that flew a mission (logs::missionSpan), as calibrate and replay --mission
// compare it: the SITL square from the switch to AUTO (where its NAV_TAKEOFF starts; the quad lifts
// off 3.2 s later, its throttle slewing up) to LAND_COMPLETE, the landing a prediction's detector
// gives (the airborne window ends 0.8 s earlier, at LAND_COMPLETE_MAYBE); the PX4 1.9 log, which begins in the air
// in AUTO_MISSION, to its landing, said to start in the air; the 3.5 log, all RTL, has none; a CSV
// never has one (its rows are taken as given).
TEST(MissionSpan, FromTheSwitchIntoTheMissionModeToTheLanding) {
  const std::string dir = std::string(WATTSWATH_SHARED_DATA_DIR);
  const auto sitl = wattswath::logs::readFlightLog(dir + "/sitl/square_5mps.BIN");
  const auto s = wattswath::logs::missionSpan(sitl);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->from_s, 54.099, 0.002);
  EXPECT_NEAR(s->liftoff_s, 57.35, 0.01);
  EXPECT_NEAR(s->to_s, 181.144, 0.002);  // LAND_COMPLETE, 0.8 s after LAND_COMPLETE_MAYBE ends the airborne window
  EXPECT_NE(s->to_what.find("LAND_COMPLETE at 181.14 s"), std::string::npos) << s->to_what;
  EXPECT_FALSE(s->started_airborne);
  EXPECT_NE(s->from_what.find("AUTO (3)"), std::string::npos) << s->from_what;

  const auto px4 = wattswath::logs::readFlightLog(logPath(kPx19));
  const auto p = wattswath::logs::missionSpan(px4);
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(p->started_airborne);
  EXPECT_TRUE(std::isnan(p->liftoff_s));
  EXPECT_NEAR(p->to_s, 5119.4, 0.2);  // vehicle_land_detected.landed

  EXPECT_FALSE(wattswath::logs::missionSpan(wattswath::logs::readFlightLog(logPath(kAc35))).has_value());
  EXPECT_FALSE(wattswath::logs::missionSpan(wattswath::logs::readFlightLog(dir + "/iris-flights/2017-10-18_1436_energy14.csv")).has_value());
}

// A 1 Hz log whose time is in milliseconds: every step is 1000 "s". It was called a stopped logger
// ("no sample for 1001 s"); it is a unit, and said so.
TEST_F(TempDir, TimeInMillisecondsIsSaidToBeOne) {
  std::string text = "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,ax_mps2,ay_mps2,az_mps2,yaw_rad,voltage_v,current_a\n";
  for (int k = 0; k < 20; ++k) text += std::to_string(1000 * k) + ",0,0,10,0,0,0,0,0,0,0,12.0,20.0\n";
  const std::string p = write("ms.csv", std::vector<std::uint8_t>(text.begin(), text.end()));
  const std::string e = errorOf(p);
  EXPECT_NE(e.find("median 1000 s apart"), std::string::npos) << e;
  EXPECT_NE(e.find("is time_s logged in milliseconds"), std::string::npos) << e;
}
