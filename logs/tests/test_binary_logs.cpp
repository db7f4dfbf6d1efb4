// DataFlash and ULog readers on small logs built here byte by byte: the message layouts the four
// shared real logs do not have (ArduPilot 4.x BAT with instances, XKF1 with cores; ULog nested
// types, multi-instance topics, short payloads, appended data) and malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "log_bytes.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/parameters.hpp"
#include "wattswath/logs/ulog.hpp"

namespace {

using namespace wattswath::test::logbytes;

// ArduPilot 4.x style: BAT with two instances (0 reads no voltage), XKF1 with two cores, EV, MODE.
Bytes modernDataFlash(const std::vector<std::pair<double, int>>& events = {{5.0, 28}, {15.0, 18}}) {
  DataFlash d;
  d.fmt(150, 3 + 8 + 1 + 4 + 4, "BAT", "QBff", "TimeUS,Inst,Volt,Curr");
  d.fmt(151, 3 + 8 + 1 + 6 * 4 + 2, "XKF1", "QBffffffC", "TimeUS,C,VN,VE,VD,PN,PE,PD,Yaw");
  d.fmt(152, 3 + 8 + 1, "EV", "QB", "TimeUS,Id");
  d.fmt(153, 3 + 8 + 1 + 1 + 1, "MODE", "QMBB", "TimeUS,Mode,ModeNum,Rsn");
  d.fmt(154, 3 + 8 + 64, "MSG", "QZ", "TimeUS,Message");
  d.head(154);
  put<std::uint64_t>(d.b, 500000);
  putText(d.b, "ArduCopter V4.5.7 (abcdef12)", 64);
  d.head(153);
  put<std::uint64_t>(d.b, 1000000);
  d.b.insert(d.b.end(), {4, 4, 1});
  for (int k = 0; k <= 200; ++k) {  // 10 Hz for 20 s
    const double t = 1.0 + 0.1 * k;
    for (std::uint8_t core : {0, 1}) {
      d.head(151);
      put<std::uint64_t>(d.b, static_cast<std::uint64_t>(std::llround((t - 0.05) * 1e6)));
      d.b.push_back(core);
      for (float v : {0.0f, 2.0f, 0.0f, 0.0f, static_cast<float>(2.0 * (t - 0.05) + 100.0 * core), -10.0f}) put<float>(d.b, v);
      put<std::uint16_t>(d.b, 9000);  // 90.00 deg: heading east
    }
    for (std::uint8_t inst : {0, 1}) {
      d.head(150);
      put<std::uint64_t>(d.b, static_cast<std::uint64_t>(std::llround(t * 1e6)));
      d.b.push_back(inst);
      const bool flying = t >= 5.0 && t <= 15.0;
      put<float>(d.b, inst == 0 ? 0.0f : 22.2f);
      put<float>(d.b, inst == 0 ? 0.0f : (flying ? 10.0f : 1.0f));
    }
  }
  for (auto [t, id] : events) {
    d.head(152);
    put<std::uint64_t>(d.b, static_cast<std::uint64_t>(t * 1e6));
    d.b.push_back(static_cast<std::uint8_t>(id));
  }
  return d.b;
}

TEST(DataFlash, ModernBatInstancesAndXkf1Cores) {
  const auto log = wattswath::logs::readDataFlashBytes(modernDataFlash(), "modern.bin", {});
  EXPECT_EQ(log.format, "dataflash");
  EXPECT_EQ(log.metadata.at("firmware"), "ArduCopter V4.5.7 (abcdef12)");
  EXPECT_NE(log.metadata.at("battery_source").find("BAT instance 1"), std::string::npos) << log.metadata.at("battery_source");
  EXPECT_NE(log.metadata.at("battery_sources_not_used").find("BAT instance 0"), std::string::npos);
  EXPECT_NE(log.metadata.at("position_source").find("XKF1 core 0"), std::string::npos);
  ASSERT_GT(log.samples.size(), 150u);
  for (const auto& s : log.samples) {
    EXPECT_NEAR(s.position.x(), 2.0 * s.t, 1e-4) << s.t;  // core 0 (core 1 is 100 m east)
    EXPECT_NEAR(s.position.y(), 0.0, 1e-9);
    EXPECT_NEAR(s.position.z(), 10.0, 1e-6);  // PD = -10 m: 10 m up
    EXPECT_NEAR(s.velocity.x(), 2.0, 1e-6);
    EXPECT_NEAR(s.yaw, 0.0, 1e-6);  // heading east = ENU yaw 0
    EXPECT_NEAR(s.power, s.voltage * s.current, 1e-9);
  }
  ASSERT_EQ(log.airborne.size(), 1u);  // EV 28 NOT_LANDED at 5 s, EV 18 LAND_COMPLETE at 15 s
  EXPECT_DOUBLE_EQ(log.airborne[0].begin, 5.0);
  EXPECT_DOUBLE_EQ(log.airborne[0].end, 15.0);
  ASSERT_FALSE(log.events.empty());
  EXPECT_EQ(log.events.front().kind, "message");
  EXPECT_EQ(log.events.at(1).text, "GUIDED (4)");
}

// EV 17 LAND_COMPLETE_MAYBE is logged each time the flag sets, nothing when it clears: one followed
// by another 17 was low throttle in flight (it ended the airborne window there, 80 s of a SITL
// flight replayed as on the ground); the one before LAND_COMPLETE is the touch-down.
TEST(DataFlash, ALandCompleteMaybeThatClearedIsNotALanding) {
  const auto log = wattswath::logs::readDataFlashBytes(modernDataFlash({{5.0, 28}, {8.0, 17}, {14.5, 17}, {15.0, 18}}), "maybe.bin", {});
  ASSERT_EQ(log.airborne.size(), 1u);
  EXPECT_DOUBLE_EQ(log.airborne[0].begin, 5.0);
  EXPECT_DOUBLE_EQ(log.airborne[0].end, 14.5);
  // A maybe the log ends after is taken as the touch-down.
  const auto end = wattswath::logs::readDataFlashBytes(modernDataFlash({{5.0, 28}, {15.0, 17}}), "maybe-end.bin", {});
  ASSERT_EQ(end.airborne.size(), 1u);
  EXPECT_DOUBLE_EQ(end.airborne[0].end, 15.0);
}

// One corrupt timestamp far ahead (2^62 us) costs that sample only: keeping the increasing prefix
// dropped every battery sample after it (a SITL log ended at 119 s of 196 s, 22 kJ of 44 kJ).
TEST(DataFlash, OneCorruptTimestampCostsThatSampleOnly) {
  Bytes b = modernDataFlash();
  int seen = 0;
  for (std::size_t k = 0; k + 12 < b.size(); ++k) {
    if (b[k] == 0xA3 && b[k + 1] == 0x95 && b[k + 2] == 150 && b[k + 11] == 1 && ++seen == 60) {
      const std::uint64_t huge = std::uint64_t{1} << 62;
      std::memcpy(&b[k + 3], &huge, sizeof huge);  // the 60th BAT instance 1 record, at 6.9 s
      break;
    }
  }
  ASSERT_EQ(seen, 60);
  const auto log = wattswath::logs::readDataFlashBytes(b, "spike.bin", {});
  EXPECT_GT(log.samples.back().t, 20.5);  // to the end of the log, not 6.8 s
  EXPECT_NE(log.metadata.at("warnings").find("1 battery samples with non-increasing time not used"), std::string::npos)
      << log.metadata.at("warnings");
}

// Positions missing for 4 s (XKF1 records cut out) are interpolated across the gap, and said to be:
// a 45 s gap drew a straight line across a square's corner with no word.
TEST(DataFlash, AGapInThePositionsIsSaid) {
  const Bytes full = modernDataFlash();
  Bytes b;
  for (std::size_t k = 0; k < full.size();) {
    std::uint64_t us = 0;
    if (k + 11 < full.size() && full[k] == 0xA3 && full[k + 1] == 0x95 && full[k + 2] == 151) {
      std::memcpy(&us, &full[k + 3], sizeof us);
      if (us > 8000000 && us < 12000000) {
        k += 3 + 8 + 1 + 6 * 4 + 2;  // one XKF1 record
        continue;
      }
    }
    b.push_back(full[k++]);
  }
  const auto log = wattswath::logs::readDataFlashBytes(b, "gap.bin", {});
  ASSERT_NE(log.metadata.count("warnings"), 0u);
  EXPECT_NE(log.metadata.at("warnings").find("no position sample for 4.1 s, from 7.95 s to 12.05 s"), std::string::npos)
      << log.metadata.at("warnings");
  EXPECT_EQ(wattswath::logs::readDataFlashBytes(full, "full.bin", {}).metadata.count("warnings"), 0u);
}

// A monitor without a current sensor logs Curr as NaN: a battery whose current is measured is taken
// first (instance 0 here reads 22.2 V and NaN A; it was chosen, and every later power unknown).
TEST(DataFlash, ABatteryWhoseCurrentIsMeasuredIsPreferred) {
  Bytes b = modernDataFlash();
  for (std::size_t k = 0; k + 19 < b.size(); ++k) {
    if (b[k] == 0xA3 && b[k + 1] == 0x95 && b[k + 2] == 150 && b[k + 11] == 0) {
      const float volt = 22.2f, curr = std::nanf("");
      std::memcpy(&b[k + 12], &volt, sizeof volt);
      std::memcpy(&b[k + 16], &curr, sizeof curr);
    }
  }
  const auto log = wattswath::logs::readDataFlashBytes(b, "nan-current.bin", {});
  EXPECT_NE(log.metadata.at("battery_source").find("BAT instance 1"), std::string::npos) << log.metadata.at("battery_source");
  EXPECT_NE(log.metadata.at("battery_sources_not_used").find("BAT instance 0 (201 samples), current not measured"), std::string::npos)
      << log.metadata.at("battery_sources_not_used");
}

// The charge the logged current draws (here 10 A for 10 s and 1 A for 10 s, 30.8 mAh) against the
// capacity of the battery used (instance 1: BATT2_CAPACITY): more than the pack holds is said, with
// both possible causes; within it, nothing is said.
TEST(DataFlash, ACurrentDrawingMoreThanTheCapacityIsSaid) {
  const auto withCapacity = [](float batt2_mah) {
    Bytes b = modernDataFlash();
    DataFlash d;
    d.b.clear();
    d.fmt(160, 3 + 8 + 16 + 4, "PARM", "QNf", "TimeUS,Name,Value");
    for (auto [name, value] : {std::pair<const char*, float>{"BATT_CAPACITY", 5.0f}, {"BATT2_CAPACITY", batt2_mah}}) {
      d.head(160);
      put<std::uint64_t>(d.b, 100000);
      putText(d.b, name, 16);
      put<float>(d.b, value);
    }
    b.insert(b.end(), d.b.begin(), d.b.end());
    return wattswath::logs::readDataFlashBytes(b, "capacity.bin", {});
  };
  const auto high = withCapacity(20.0f);
  EXPECT_EQ(high.metadata.at("battery_capacity_mah"), "20");
  EXPECT_EQ(high.metadata.at("charge_drawn_mah"), "31");
  ASSERT_NE(high.metadata.count("warnings"), 0u);
  EXPECT_NE(high.metadata.at("warnings").find("draws 31 mAh, 154 % of the battery's capacity (BATT2_CAPACITY parameter: 20 mAh)"),
            std::string::npos) << high.metadata.at("warnings");
  EXPECT_NE(high.metadata.at("warnings").find("BATT_AMP_PERVLT"), std::string::npos);
  const auto fine = withCapacity(40.0f);  // BATT_CAPACITY 5 mAh is instance 0's, not the one used
  EXPECT_EQ(fine.metadata.at("battery_capacity_mah"), "40");
  EXPECT_EQ(fine.metadata.count("warnings"), 0u) << fine.metadata.at("warnings");
}

TEST(DataFlash, BatteryInstanceOptionAndWindow) {
  wattswath::logs::LogReadOptions o;
  o.battery_instance = 0;  // chosen explicitly, even though it reads 0 V
  EXPECT_EQ(wattswath::logs::readDataFlashBytes(modernDataFlash(), "m.bin", o).samples.front().voltage, 0.0);
  o.battery_instance = 5;
  EXPECT_THROW(wattswath::logs::readDataFlashBytes(modernDataFlash(), "m.bin", o), std::runtime_error);
  o = {};
  o.from_s = 6.0;
  o.to_s = 8.0;
  const auto log = wattswath::logs::readDataFlashBytes(modernDataFlash(), "m.bin", o);
  EXPECT_GE(log.samples.front().t, 6.0);
  EXPECT_LE(log.samples.back().t, 8.0);
  EXPECT_EQ(log.samples.size(), 21u);
  o.from_s = 100.0;
  o.to_s = 200.0;
  try {
    wattswath::logs::readDataFlashBytes(modernDataFlash(), "m.bin", o);
    FAIL() << "empty window accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("window 100 s to 200 s"), std::string::npos) << e.what();
  }
}

TEST(DataFlash, UndefinedTypeNamesOffset) {
  auto b = modernDataFlash();
  const std::size_t at = b.size();
  b.insert(b.end(), {0xA3, 0x95, 200, 1, 2, 3});
  try {
    wattswath::logs::dataflash::Log::parse(b, "x.bin", false);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("byte offset " + std::to_string(at)), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("type 200"), std::string::npos) << e.what();
  }
  const auto lenient = wattswath::logs::dataflash::Log::parse(b, "x.bin", true);
  EXPECT_EQ(lenient.warnings().size(), 1u);
  // The reader the commands use refuses the damaged record, naming it and --lenient, and says
  // nothing of a skip it did not make.
  try {
    wattswath::logs::dataflash::Log::parseAcceptingCutEnd(b, "x.bin", false);
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("byte offset " + std::to_string(at) + ": message type 200"), std::string::npos) << m;
    EXPECT_NE(m.find("use --lenient"), std::string::npos) << m;
    EXPECT_EQ(m.find("skipped"), std::string::npos) << m;
  }
}

TEST(DataFlash, UnknownFormatCharacterOnlyFailsWhenUsed) {
  DataFlash d;
  d.fmt(160, 3 + 4, "ODD", "Iw", "TimeMS,Weird");  // 'w' is no format character
  d.head(160);
  put<std::uint32_t>(d.b, 5);
  const auto log = wattswath::logs::dataflash::Log::parse(d.b, "odd.bin", false);  // still frames (length from FMT)
  EXPECT_EQ(log.count("ODD"), 1u);
  try {
    log.column("ODD", "TimeMS");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown format character 'w'"), std::string::npos) << e.what();
  }
}

// ArduCopter 3.1 as it logged (issue 19): FMT of FMT with 4 column names for 5 format characters,
// CURR without a timestamp in centivolts, PARM, MSG. Read in strict mode; it used to fail at byte 0
// with "FMT redefines FMT itself".
Bytes arduCopter31() {
  DataFlash d("Type,Length,Name,Format");
  d.fmt(129, 3 + 16 + 4, "PARM", "Nf", "Name,Value");
  d.fmt(130, 3 + 64, "MSG", "Z", "Message");
  d.fmt(131, 3 + 2 + 4 + 2 + 2 + 2 + 4, "CURR", "hIhhhf", "Thr,ThrInt,Volt,Curr,Vcc,CurrTot");
  d.head(130);
  putText(d.b, "ArduCopter V3.1.5 (3c57e771)", 64);
  for (auto [name, value] : {std::pair<const char*, float>{"FRAME", 1.0f}, {"WPNAV_SPEED", 500.0f}}) {
    d.head(129);
    putText(d.b, name, 16);
    put<float>(d.b, value);
  }
  for (int k = 0; k < 5; ++k) {
    d.head(131);
    put<std::int16_t>(d.b, 400);
    put<std::uint32_t>(d.b, 1000);
    put<std::int16_t>(d.b, 1230);  // 12.30 V
    put<std::int16_t>(d.b, 1500);  // 15.00 A
    put<std::int16_t>(d.b, 5000);
    put<float>(d.b, 10.0f * k);
  }
  return d.b;
}

TEST(DataFlash, ArduCopter31FmtOfFmtWithFourColumnNamesReadsStrictly) {
  const auto log = wattswath::logs::dataflash::Log::parse(arduCopter31(), "ac31.bin", false);
  EXPECT_TRUE(log.warnings().empty());
  const auto* fmt = log.format("FMT");
  ASSERT_NE(fmt, nullptr);
  EXPECT_TRUE(fmt->decodable) << fmt->problem;
  EXPECT_EQ(fmt->columns, (std::vector<std::string>{"Type", "Length", "Name", "Format", "Columns"}));
  EXPECT_EQ(log.count("FMT"), 4u);
  EXPECT_EQ(log.textColumn("FMT", "Name").at(3), "CURR");
  EXPECT_EQ(log.textColumn("MSG", "Message").at(0), "ArduCopter V3.1.5 (3c57e771)");
  EXPECT_EQ(log.count("CURR"), 5u);
  EXPECT_EQ(log.column("CURR", "Volt").at(0), 1230.0);
  const auto p = wattswath::logs::readAutopilotParametersBytes(arduCopter31(), "ac31.bin", {});
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 500.0);
  // The flight itself: 3.1 logs no EKF position, and the reader says that, not "FMT redefines FMT".
  try {
    wattswath::logs::readDataFlashBytes(arduCopter31(), "ac31.bin", {});
    FAIL() << "read without a position source";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).find("FMT"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("CURR here without one (ArduCopter <= 3.1)"), std::string::npos) << e.what();
  }
}

TEST(DataFlash, OtherFmtOfFmtRedefinitionsStillFail) {
  DataFlash d("Type,Length,Name");  // 3 names: not the old layout
  EXPECT_THROW(wattswath::logs::dataflash::Log::parse(d.b, "bad.bin", false), std::runtime_error);
}

TEST(DataFlash, NotADataFlashFile) {
  EXPECT_THROW(wattswath::logs::dataflash::Log::parse(Bytes{}, "empty.bin", false), std::runtime_error);
  EXPECT_THROW(wattswath::logs::dataflash::Log::parse(Bytes{'h', 'e', 'l', 'l', 'o'}, "t.bin", false), std::runtime_error);
}


void definitions(ULog& u) {
  u.text('F', "esc_report:uint32_t esc_rpm;float esc_voltage;");
  u.text('F', "esc_status:uint64_t timestamp;uint8_t esc_count;uint8_t[3] _padding0;esc_report[2] esc;");
  u.text('F', "battery_status:uint64_t timestamp;float voltage_v;float current_a;bool connected;uint8_t[3] _padding0;");
  u.text('F', "vehicle_local_position:uint64_t timestamp;float x;float y;float z;float vx;float vy;float vz;"
              "float heading;bool xy_valid;bool z_valid;uint8_t[6] _padding0;");
  u.text('F', "vehicle_land_detected:uint64_t timestamp;bool landed;uint8_t[7] _padding0;");
  Bytes info{static_cast<std::uint8_t>(std::string("uint32_t ver_sw_release").size())};
  const std::string key = "uint32_t ver_sw_release";
  info.insert(info.end(), key.begin(), key.end());
  put<std::uint32_t>(info, 0x010F00FF);
  u.msg('I', info);
  u.subscribe(0, 1, "battery_status");
  u.subscribe(1, 2, "battery_status");
  u.subscribe(0, 3, "vehicle_local_position");
  u.subscribe(0, 4, "esc_status");
  u.subscribe(0, 5, "vehicle_land_detected");
}

void samples(ULog& u, double t0, double t1) {
  for (double t = t0; t <= t1 + 1e-9; t += 0.1) {
    const auto us = static_cast<std::uint64_t>(std::llround(t * 1e6));
    for (std::uint16_t id : {1, 2}) {
      Bytes p;
      put<std::uint64_t>(p, us);
      put<float>(p, id == 1 ? 0.0f : 16.0f);
      put<float>(p, id == 1 ? 0.0f : 8.0f);
      p.push_back(id == 1 ? 0 : 1);  // instance 0 disconnected; trailing padding dropped (13 of 16 B)
      u.data(id, p);
    }
    Bytes p;
    put<std::uint64_t>(p, us + 20000);
    for (float v : {3.0f * static_cast<float>(t), 0.0f, -5.0f, 3.0f, 0.0f, -1.0f, 0.0f}) put<float>(p, v);
    p.push_back(1);
    p.push_back(1);  // 38 of 44 bytes: padding dropped
    u.data(3, p);
    Bytes e;
    put<std::uint64_t>(e, us);
    e.push_back(2);
    e.insert(e.end(), {0, 0, 0});
    put<std::uint32_t>(e, 1000);
    put<float>(e, 16.0f);
    put<std::uint32_t>(e, 2000);
    put<float>(e, 15.5f);
    u.data(4, e);
  }
}

TEST(ULog, NestedMultiInstanceShortPayloads) {
  ULog u;
  definitions(u);
  samples(u, 1.0, 10.0);
  const auto L = wattswath::logs::ulog::Log::parse(u.b, "syn.ulg", false);
  EXPECT_EQ(L.instances("battery_status"), (std::vector<int>{0, 1}));
  const auto rpm = L.column("esc_status", 0, "esc[1].esc_rpm");
  ASSERT_FALSE(rpm.empty());
  EXPECT_EQ(rpm.front(), 2000.0);
  EXPECT_EQ(L.column("esc_status", 0, "esc[1].esc_voltage").front(), 15.5);

  const auto log = wattswath::logs::readUlogBytes(u.b, "syn.ulg", {});
  EXPECT_NE(log.metadata.at("battery_source").find("battery_status[1]"), std::string::npos);
  EXPECT_NE(log.metadata.at("firmware").find("v1.15.0 (release)"), std::string::npos) << log.metadata.at("firmware");
  ASSERT_GT(log.samples.size(), 80u);
  for (const auto& s : log.samples) {
    EXPECT_NEAR(s.position.y(), 3.0 * (s.t - 0.02), 1e-4);  // NED x north -> ENU y
    EXPECT_NEAR(s.position.z(), 5.0, 1e-6);                  // z down -5 m -> 5 m up
    EXPECT_NEAR(s.velocity.y(), 3.0, 1e-6);
    EXPECT_NEAR(s.velocity.z(), 1.0, 1e-6);
    EXPECT_NEAR(s.voltage, 16.0, 1e-6);
    EXPECT_NEAR(s.power, 128.0, 1e-4);
  }
}

TEST(ULog, AppendedDataAfterAnIncompleteMessage) {
  ULog u(true, 0);
  definitions(u);
  samples(u, 1.0, 5.0);
  // An incomplete message (declares 500 bytes) right before the appended data.
  put<std::uint16_t>(u.b, 500);
  u.b.push_back('D');
  u.b.insert(u.b.end(), {1, 0, 7, 7});
  const std::uint64_t appended_at = u.b.size();
  std::memcpy(u.b.data() + u.appendedOffsetPos(), &appended_at, 8);
  samples(u, 5.1, 8.0);
  ULog reference;
  definitions(reference);
  samples(reference, 1.0, 5.0);
  samples(reference, 5.1, 8.0);
  const auto L = wattswath::logs::ulog::Log::parse(u.b, "app.ulg", false);
  EXPECT_TRUE(L.appendedData());
  EXPECT_EQ(L.count("battery_status", 1), wattswath::logs::ulog::Log::parse(reference.b, "ref.ulg", false).count("battery_status", 1));
  EXPECT_GT(L.count("battery_status", 1), 60u);
  ASSERT_EQ(L.warnings().size(), 1u);
  EXPECT_NE(L.warnings()[0].find("appended data"), std::string::npos) << L.warnings()[0];
}

// A 12-byte zero-filled stretch between two messages (issue 19): strict mode names it and --lenient;
// lenient mode resynchronises on the next valid message header, as pyulog does, reads to the end,
// lists the gap, and says the log ends in the air (current above 5 A to the last sample).
TEST(ULog, LenientResynchronisesAfterAZeroGapAndListsIt) {
  ULog u;
  definitions(u);
  samples(u, 1.0, 10.0);
  const std::size_t gap_at = u.b.size();
  u.b.insert(u.b.end(), 12, 0);
  samples(u, 10.1, 20.0);
  try {
    wattswath::logs::ulog::Log::parse(u.b, "gap.ulg", false);
    FAIL() << "strict mode read past the gap";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("gap.ulg: byte offset " + std::to_string(gap_at) + ": "), std::string::npos) << m;
    EXPECT_NE(m.find("zero-filled"), std::string::npos) << m;
    EXPECT_NE(m.find("use --lenient"), std::string::npos) << m;
  }
  const auto L = wattswath::logs::ulog::Log::parse(u.b, "gap.ulg", true);
  ASSERT_EQ(L.gaps().size(), 1u);
  EXPECT_EQ(L.gaps()[0].offset, gap_at);
  EXPECT_EQ(L.gaps()[0].length, 12u);
  EXPECT_FALSE(L.gaps()[0].to_end);
  ULog whole;
  definitions(whole);
  samples(whole, 1.0, 10.0);
  samples(whole, 10.1, 20.0);
  EXPECT_EQ(L.count("battery_status", 1), wattswath::logs::ulog::Log::parse(whole.b, "w.ulg", false).count("battery_status", 1));

  wattswath::logs::LogReadOptions o;
  o.lenient = true;
  const auto log = wattswath::logs::readUlogBytes(u.b, "gap.ulg", o);
  EXPECT_NEAR(log.samples.back().t, 20.0, 0.05);  // read to the end, not stopped at 10 s
  EXPECT_NE(log.metadata.at("gaps").find("1 skipped: byte offset " + std::to_string(gap_at) + ", 12 bytes"), std::string::npos)
      << log.metadata.at("gaps");
  EXPECT_NE(log.metadata.at("warnings").find("skipped 12 bytes to the next valid message"), std::string::npos);
  EXPECT_EQ(log.metadata.at("ends_airborne"), "yes");
  EXPECT_NE(log.metadata.at("warnings").find("the log ends while airborne"), std::string::npos) << log.metadata.at("warnings");
}

// Zeros over the start of a message and a corrupt stretch of random-looking bytes: each is skipped to
// the next valid message and listed; a log that lands says nothing about ending in the air.
TEST(ULog, LenientSkipsEachCorruptStretchToTheNextValidMessage) {
  ULog u;
  definitions(u);
  samples(u, 1.0, 5.0);
  const std::size_t zero_at = u.b.size();
  samples(u, 5.1, 5.1);  // one round of messages, its first (a 22-byte battery message) zeroed below
  std::fill(u.b.begin() + static_cast<std::ptrdiff_t>(zero_at), u.b.begin() + static_cast<std::ptrdiff_t>(zero_at) + 12, 0);
  samples(u, 5.2, 8.0);
  const std::size_t junk_at = u.b.size();
  for (int k = 0; k < 40; ++k) u.b.push_back(static_cast<std::uint8_t>(0xE7 ^ (k * 37)));
  samples(u, 8.1, 9.0);
  Bytes landed;
  put<std::uint64_t>(landed, 9000000);
  landed.push_back(1);
  u.data(5, landed);
  const auto L = wattswath::logs::ulog::Log::parse(u.b, "corrupt.ulg", true);
  ASSERT_EQ(L.gaps().size(), 2u) << (L.warnings().empty() ? "" : L.warnings()[0]);
  EXPECT_EQ(L.gaps()[0].offset, zero_at);
  EXPECT_EQ(L.gaps()[0].length, 22u);  // the zeroed battery message, to the next one
  EXPECT_EQ(L.gaps()[1].offset, junk_at);
  EXPECT_EQ(L.gaps()[1].length, 40u);
  wattswath::logs::LogReadOptions o;
  o.lenient = true;
  const auto log = wattswath::logs::readUlogBytes(u.b, "corrupt.ulg", o);
  EXPECT_NEAR(log.samples.back().t, 9.0, 0.05);
  EXPECT_EQ(log.metadata.count("ends_airborne"), 0u);  // landed at the last sample
}

TEST(ULog, MalformedInputNamesOffsetAndMessage) {
  ULog u;
  definitions(u);
  samples(u, 1.0, 2.0);
  const std::size_t at = u.b.size();
  u.data(99, Bytes{1, 2, 3});
  try {
    wattswath::logs::ulog::Log::parse(u.b, "bad.ulg", false);
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.ulg: byte offset " + std::to_string(at) + ": 'D' message"), std::string::npos) << m;
    EXPECT_NE(m.find("msg_id 99"), std::string::npos) << m;
  }
  // Unknown incompatible flag bits must stop the reader.
  ULog f;
  f.b[16 + 3 + 8] = 0x02;
  EXPECT_THROW(wattswath::logs::ulog::Log::parse(f.b, "flags.ulg", true), std::runtime_error);
  // A recursive nested definition.
  ULog r;
  r.text('F', "loop:uint64_t timestamp;loop inner;");
  r.subscribe(0, 1, "loop");
  r.data(1, Bytes(8, 0));
  try {
    wattswath::logs::ulog::Log::parse(r.b, "loop.ulg", false);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nests deeper"), std::string::npos) << e.what();
  }
  EXPECT_THROW(wattswath::logs::ulog::Log::parse(Bytes{'U', 'L', 'o', 'g'}, "short.ulg", false), std::runtime_error);
}

TEST(Airborne, EventsOverrideCurrentAndWindowsMerge) {
  std::vector<double> t, i;
  for (int k = 0; k <= 300; ++k) {
    t.push_back(0.1 * k);
    i.push_back((t.back() > 3 && t.back() < 10) || (t.back() > 10.5 && t.back() < 20) ? 12.0 : 1.0);
  }
  wattswath::logs::AirborneSettings s;
  auto w = wattswath::logs::detectAirborne(t, i, {}, s);
  ASSERT_EQ(w.size(), 1u);  // the 0.5 s dip is merged
  EXPECT_NEAR(w[0].begin, 3.0, 0.1);
  EXPECT_NEAR(w[0].end, 20.0, 0.1);
  s.merge_gap_s = 0.1;
  EXPECT_EQ(wattswath::logs::detectAirborne(t, i, {}, s).size(), 2u);
  // A landing logged at 22 s: the current window ending at 20 s runs up to it.
  w = wattswath::logs::detectAirborne(t, i, {{22.0, true, "landed"}}, wattswath::logs::AirborneSettings{});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_DOUBLE_EQ(w[0].end, 22.0);
  // Take-off at 25 s, no landing: airborne to the end.
  w = wattswath::logs::detectAirborne(t, i, {{22.0, true, "landed"}, {25.0, false, "takeoff"}}, wattswath::logs::AirborneSettings{});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_DOUBLE_EQ(w[1].begin, 25.0);
  EXPECT_DOUBLE_EQ(w[1].end, 30.0);
}

}  // namespace
