// Issue 20, hostile and careless logs: ULog definitions that would spin (zero-size types nested in
// 65535-element arrays) and "info multiple" continuations that were quadratic; DataFlash/ULog
// values beyond the CSV reader's bounds; negative current; gaps between samples. The files are
// built here byte by byte.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "log_bytes.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/logs/ulog.hpp"

namespace {

using namespace wattswath::test::logbytes;
namespace logs = wattswath::logs;

/// `what()` of the std::runtime_error `f` throws ("" when it does not throw).
template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// ------------------------------------------------------------------ ULog definitions

TEST(ULogLimits, ZeroSizeTypesNestedInHugeArraysAreRefusedAtOnce) {
  // 65535^3 zero-byte elements: the size guard never fired and the reader spun forever.
  ULog u;
  u.text('F', "z:uint8_t[0] nothing;");
  u.text('F', "y:z[65535] a;");
  u.text('F', "x:y[65535] b;");
  u.text('F', "topic:uint64_t timestamp;x[65535] c;");
  u.subscribe(0, 1, "topic");
  for (int k = 0; k < 50; ++k) u.data(1, Bytes(8, 0));
  const std::string m = errorOf([&] { logs::ulog::Log::parse(u.b, "zero.ulg", false); });
  EXPECT_NE(m.find("zero.ulg: byte offset"), std::string::npos) << m;
  EXPECT_NE(m.find("type z takes 0 bytes"), std::string::npos) << m;
  // Lenient: each data message is skipped with a warning (the failed layout is remembered).
  const auto L = logs::ulog::Log::parse(u.b, "zero.ulg", true);
  EXPECT_EQ(L.count("topic", 0), 0u);
  EXPECT_FALSE(L.warnings().empty());
}

TEST(ULogLimits, InfoMultipleContinuationsAreLinear) {
  // 20,000 continuations of 1,000 bytes: appending by copy moved 200 GB (minutes); in place, 20 MB.
  ULog u;
  const std::string key = "char[1000] long_text";
  const std::string chunk(1000, 'a');
  for (int k = 0; k < 20000; ++k) {
    Bytes p{static_cast<std::uint8_t>(k > 0), static_cast<std::uint8_t>(key.size())};
    p.insert(p.end(), key.begin(), key.end());
    p.insert(p.end(), chunk.begin(), chunk.end());
    u.msg('M', p);
  }
  const auto L = logs::ulog::Log::parse(u.b, "info.ulg", false);
  EXPECT_EQ(L.info().at("long_text").size(), 20000u * 1000u);
  // A message with is_continued = 0 starts the value again.
  Bytes p{0, static_cast<std::uint8_t>(key.size())};
  p.insert(p.end(), key.begin(), key.end());
  p.insert(p.end(), chunk.begin(), chunk.end());
  u.msg('M', p);
  EXPECT_EQ(logs::ulog::Log::parse(u.b, "info.ulg", false).info().at("long_text").size(), 1000u);
}

// ------------------------------------------------------------------ DataFlash values

/// A DataFlash log: BAT at 10 Hz from 1 s to 21 s (22.2 V, `amps`), XKF1 beside it (2 m/s east).
/// `bad_at` [s]: the BAT sample nearest it carries `bad_amps`, the XKF1 one `bad_pn` [m] as PN.
/// `gap` [s] is added to every time after 11 s (from the 102nd sample on).
Bytes dataflash(double amps, double bad_at = -1.0, double bad_amps = 0.0, double bad_pn = 0.0, double gap = 0.0) {
  DataFlash d;
  d.fmt(150, 3 + 8 + 1 + 4 + 4, "BAT", "QBff", "TimeUS,Inst,Volt,Curr");
  d.fmt(151, 3 + 8 + 1 + 6 * 4 + 2, "XKF1", "QBffffffC", "TimeUS,C,VN,VE,VD,PN,PE,PD,Yaw");
  for (int k = 0; k <= 200; ++k) {
    const double t = 1.0 + 0.1 * k, shifted = k > 100 ? t + gap : t;
    const bool bad = std::abs(t - bad_at) < 0.05;
    d.head(151);
    put<std::uint64_t>(d.b, static_cast<std::uint64_t>(std::llround((shifted - 0.05) * 1e6)));
    d.b.push_back(0);
    for (float v : {0.0f, 2.0f, 0.0f, bad ? static_cast<float>(bad_pn) : 0.0f, static_cast<float>(2.0 * t), -10.0f})
      put<float>(d.b, v);
    put<std::uint16_t>(d.b, 9000);
    d.head(150);
    put<std::uint64_t>(d.b, static_cast<std::uint64_t>(std::llround(shifted * 1e6)));
    d.b.push_back(0);
    put<float>(d.b, 22.2f);
    put<float>(d.b, static_cast<float>(bad ? bad_amps : amps));
  }
  return d.b;
}

logs::LogReadOptions lenient() {
  logs::LogReadOptions o;
  o.lenient = true;
  return o;
}

TEST(LogBounds, DataFlashCurrentBeyondTheCsvBoundIsRefusedNamingMessageFieldAndTime) {
  const Bytes b = dataflash(10.0, 6.0, 3e38);
  const std::string m = errorOf([&] { logs::readDataFlashBytes(b, "amps.bin", {}); });
  EXPECT_NE(m.find("amps.bin: BAT[0].Curr at t = 6 s: 3e+38 A is too large"), std::string::npos) << m;
  EXPECT_NE(m.find("--lenient"), std::string::npos) << m;
  // Lenient: the sample is dropped, named in the warnings, and the log converts to a CSV that reads back.
  const auto log = logs::readDataFlashBytes(b, "amps.bin", lenient());
  EXPECT_NE(log.metadata.at("warnings").find("1 of 201 battery samples out of bounds dropped"), std::string::npos)
      << log.metadata.at("warnings");
  for (const auto& s : log.samples) EXPECT_EQ(s.current, 10.0f) << s.t;
  const auto back = logs::parseCsvLog(logs::writeCsvLog(log), "converted.csv");
  EXPECT_EQ(back.samples.size(), log.samples.size());
}

TEST(LogBounds, DataFlashPositionBeyondTheCsvBoundIsRefused) {
  const Bytes b = dataflash(10.0, 8.0, 10.0, 1e30);
  const std::string m = errorOf([&] { logs::readDataFlashBytes(b, "far.bin", {}); });
  EXPECT_NE(m.find("far.bin: XKF1[core 0].PN at t = 7.95 s: 1e+30 m is too large"), std::string::npos) << m;
  const auto log = logs::readDataFlashBytes(b, "far.bin", lenient());
  for (const auto& s : log.samples) EXPECT_LT(s.position.norm(), 100.0) << s.t;
}

TEST(LogBounds, NegativeCurrentBeyondASensorOffsetIsRefusedAndSmallOffsetsAreKept) {
  const std::string m = errorOf([&] { logs::readDataFlashBytes(dataflash(-5.0), "neg.bin", {}); });
  EXPECT_NE(m.find("BAT[0].Curr at t = 1 s: -5 A is below -1 A"), std::string::npos) << m;
  const auto log = logs::readDataFlashBytes(dataflash(10.0, 4.0, -0.3), "offset.bin", {});
  EXPECT_NE(log.metadata.at("warnings").find("1 battery samples with a small negative current (down to -0.3"),
            std::string::npos)
      << log.metadata.at("warnings");
  // The CSV reader has the same bound.
  const std::string csv = "time_s,x_m,y_m,z_m,voltage_v,current_a\n0,0,0,0,22,1\n1,0,0,0,22,-5\n";
  const std::string c = errorOf([&] { logs::parseCsvLog(csv, "neg.csv"); });
  EXPECT_NE(c.find("neg.csv:3: column 'current_a': value -5 A is below -1 A"), std::string::npos) << c;
}

TEST(LogBounds, AGapBetweenSamplesIsRefusedUnlessAWindowPicksOnePart) {
  const Bytes b = dataflash(10.0, -1.0, 0.0, 0.0, 1e6);
  const std::string m = errorOf([&] { logs::readDataFlashBytes(b, "two.bin", {}); });
  EXPECT_NE(m.find("two.bin: no sample for 1e+06 s, from t = 11 s to t = 1000011.1 s"), std::string::npos) << m;
  EXPECT_NE(m.find("--from / --to"), std::string::npos) << m;
  logs::LogReadOptions first;
  first.to_s = 11.0;
  EXPECT_NEAR(logs::readDataFlashBytes(b, "two.bin", first).duration(), 10.0, 1e-6);
  logs::LogReadOptions wide;
  wide.max_gap_s = 2e6;
  EXPECT_GT(logs::readDataFlashBytes(b, "two.bin", wide).duration(), 1e6);
  // The same check for any log: a CSV read by readFlightLog.
  logs::FlightLog csv = logs::parseCsvLog("time_s,x_m,y_m,z_m,voltage_v,current_a\n0,0,0,0,22,10\n1e6,0,0,0,22,10\n", "gap.csv");
  EXPECT_NE(errorOf([&] { logs::checkSampleGaps(csv, 60.0); }).find("gap.csv: no sample for 1e+06 s"), std::string::npos);
}

// ------------------------------------------------------------------ ULog values

TEST(LogBounds, UlogNanPositionIsRefusedNamingTopicAndField) {
  ULog u;
  u.text('F', "battery_status:uint64_t timestamp;float voltage_v;float current_a;");
  u.text('F', "vehicle_local_position:uint64_t timestamp;float x;float y;float z;float vx;float vy;float vz;");
  u.subscribe(0, 1, "battery_status");
  u.subscribe(0, 2, "vehicle_local_position");
  for (int k = 0; k <= 50; ++k) {
    const auto us = static_cast<std::uint64_t>(1000000 + 100000 * k);
    Bytes p;
    put<std::uint64_t>(p, us);
    put<float>(p, 16.0f);
    put<float>(p, 8.0f);
    u.data(1, p);
    Bytes q;
    put<std::uint64_t>(q, us + 20000);
    const float x = k == 20 ? std::numeric_limits<float>::quiet_NaN() : 1.0f;
    for (float v : {x, 0.0f, -5.0f, 0.0f, 0.0f, 0.0f}) put<float>(q, v);
    u.data(2, q);
  }
  const std::string m = errorOf([&] { logs::readUlogBytes(u.b, "nan.ulg", {}); });
  EXPECT_NE(m.find("nan.ulg: vehicle_local_position[0].x at t = 3.02 s: nan m is not a finite number"), std::string::npos) << m;
  const auto log = logs::readUlogBytes(u.b, "nan.ulg", lenient());
  for (const auto& s : log.samples) EXPECT_TRUE(s.position.allFinite()) << s.t;
}

}  // namespace

namespace {

TEST(ULogLimits, LenientResynchronisationOverPrintableGarbageIsLinear) {
  // 6 MB of 'F': at every byte a plausible 'F' header of 17,990 printable bytes; checking each
  // whole payload for a ':' was 1e11 byte reads (2 MB took 23 s). Only the 'name:' prefix is
  // looked at now (the 60 s watchdog of this program catches a return to the old scan).
  ULog u;
  u.b.insert(u.b.end(), 6000000, 'F');
  const std::string m = errorOf([&] { logs::ulog::Log::parse(u.b, "garbage.ulg", false); });
  EXPECT_NE(m.find("garbage.ulg: byte offset 59: 'F' message"), std::string::npos) << m;
  const auto L = logs::ulog::Log::parse(u.b, "garbage.ulg", true);
  ASSERT_EQ(L.gaps().size(), 1u);
  EXPECT_EQ(L.gaps().front().offset, 59u);
  EXPECT_TRUE(L.gaps().front().to_end);
}

}  // namespace

namespace {

TEST(CsvLimits, AWideHeaderIsCheckedForDuplicatesInLinearTime) {
  // 300,000 extra columns: comparing each name with every earlier one was 4.5e10 string
  // comparisons (80,000 columns took 9.8 s); a hash of the names seen makes it linear (the 60 s
  // watchdog of this program catches a return to the pairwise scan).
  const int extra = 300000;
  std::string header = "time_s,x_m,y_m,z_m,voltage_v,current_a";
  for (int c = 0; c < extra; ++c) header += ",c" + std::to_string(c);
  const std::string blanks(extra, ',');
  std::string text = header + "\n0,0,0,10,12,20" + blanks + "\n1,1,0,10,12,20" + blanks + "\n2,2,0,10,12,20" + blanks + "\n";
  const auto log = logs::parseCsvLog(text, "wide.csv", {});
  ASSERT_EQ(log.extra_columns.size(), static_cast<size_t>(extra));
  EXPECT_EQ(log.extra_columns.back(), "c299999");
  ASSERT_EQ(log.samples.size(), 3u);
  // A duplicate far apart is still found, naming both fields.
  const std::string dup = errorOf([&] { logs::parseCsvLog(header + ",c7\n0,0,0,10,12,20" + blanks + ",\n", "dup.csv", {}); });
  EXPECT_NE(dup.find("dup.csv:1: column 'c7' appears twice (fields 14 and 300007)"), std::string::npos) << dup;
}

}  // namespace

namespace {

TEST(LogFileLimits, ALogLargerThanTheLimitIsRefusedBeforeItIsRead) {
  // Logs are read whole: a file beyond LogReadOptions::max_file_bytes is refused up front with
  // its size, the limit and the option, in every format.
  const std::string dir = ::testing::TempDir();
  const std::string csv = dir + "/limit.csv", bin = dir + "/limit.bin";
  {
    std::ofstream f(csv, std::ios::binary);
    f << "time_s,x_m,y_m,z_m,voltage_v,current_a\n";
    for (int i = 0; i < 200; ++i) f << i << ",0,0,10,12,20\n";
  }
  {
    std::ofstream f(bin, std::ios::binary);
    f << std::string("\xA3\x95", 2) << std::string(5000, '\0');
  }
  logs::LogReadOptions o;
  o.max_file_bytes = 1000;
  for (const std::string& path : {csv, bin}) {
    const std::string m = errorOf([&] { logs::readFlightLog(path, o); });
    EXPECT_NE(m.find(path + ": the file is "), std::string::npos) << m;
    EXPECT_NE(m.find("at most 1 MiB"), std::string::npos) << m;
    EXPECT_NE(m.find("--max-log-size"), std::string::npos) << m;
  }
  o.max_file_bytes = logs::tol::kLogMaxFileBytes;
  EXPECT_EQ(logs::readFlightLog(csv, o).samples.size(), 200u);
}

}  // namespace
