// readAutopilotParameters(): firmware family, version and parameters of ArduPilot DataFlash and
// PX4 ULog logs. Built-here logs check the value kept when a parameter is logged several times and
// the errors; version texts and release numbers are checked directly.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "log_bytes.hpp"
#include "wattswath/logs/parameters.hpp"

namespace {

using namespace wattswath::test::logbytes;
using wattswath::logs::AutopilotParameters;
using wattswath::logs::isFlightBehaviourParameter;
using wattswath::logs::parseArduPilotVersion;
using wattswath::logs::parsePx4Release;
using wattswath::logs::readAutopilotParametersBytes;

constexpr std::uint8_t kParm = 64, kEv = 65, kMsg = 66;

// A DataFlash log of PARM (Name, Value), EV (Id) and MSG (Message) records without timestamps,
// as ArduCopter 3.3 writes them: only the file order tells what came first.
struct ParmLog {
  DataFlash d;
  ParmLog() {
    d.fmt(kParm, 3 + 16 + 4, "PARM", "Nf", "Name,Value");
    d.fmt(kEv, 3 + 1, "EV", "B", "Id");
    d.fmt(kMsg, 3 + 64, "MSG", "Z", "Message");
  }
  ParmLog& parm(const std::string& name, float value) {
    d.head(kParm);
    putText(d.b, name, 16);
    put<float>(d.b, value);
    return *this;
  }
  ParmLog& ev(std::uint8_t id) {
    d.head(kEv);
    d.b.push_back(id);
    return *this;
  }
  ParmLog& msg(const std::string& text) {
    d.head(kMsg);
    putText(d.b, text, 64);
    return *this;
  }
  AutopilotParameters read(bool lenient = false) const {
    wattswath::logs::LogReadOptions o;
    o.lenient = lenient;
    return readAutopilotParametersBytes(d.b, "built.bin", o);
  }
};

// Appends a ULog 'P' (default_types < 0) or 'Q' parameter message with a float value.
void ulogParameter(ULog& u, const std::string& name, float value, int default_types = -1) {
  Bytes p;
  if (default_types >= 0) p.push_back(static_cast<std::uint8_t>(default_types));
  const std::string key = "float " + name;
  p.push_back(static_cast<std::uint8_t>(key.size()));
  p.insert(p.end(), key.begin(), key.end());
  put<float>(p, value);
  u.msg(default_types >= 0 ? 'Q' : 'P', p);
}

void ulogInfo(ULog& u, std::uint32_t release) {
  const std::string key = "uint32_t ver_sw_release";
  Bytes p{static_cast<std::uint8_t>(key.size())};
  p.insert(p.end(), key.begin(), key.end());
  put<std::uint32_t>(p, release);
  u.msg('I', p);
}

std::string errorOf(const Bytes& bytes, const std::string& source, bool lenient = false) {
  wattswath::logs::LogReadOptions o;
  o.lenient = lenient;
  try {
    readAutopilotParametersBytes(bytes, source, o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Parameters, LastValueBeforeTakeOffIsKeptAndLaterChangesListed) {
  ParmLog log;
  log.msg("APM:Copter V3.3.3 (abcdef12)").msg("Frame: QUAD");
  log.parm("WPNAV_SPEED", 500).parm("WPNAV_ACCEL", 100).parm("WPNAV_SPEED", 800);
  log.ev(10).parm("WPNAV_SPEED", 900);   // after arming, before take-off
  log.ev(28).parm("WPNAV_SPEED", 1200);  // EV 28 NOT_LANDED: take-off
  log.parm("LAND_SPEED", 30).parm("LAND_SPEED", 40).parm("WPNAV_ACCEL", 100);
  const auto p = log.read();
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 900.0);
  EXPECT_EQ(p.parameters.at("WPNAV_ACCEL"), 100.0);  // logged again after take-off, unchanged
  EXPECT_EQ(p.parameters.at("LAND_SPEED"), 30.0);    // only after take-off: the first value
  EXPECT_EQ(p.changed_after_takeoff, (std::vector<std::string>{"LAND_SPEED", "WPNAV_SPEED"}));
  EXPECT_NE(p.selection.find("NOT_LANDED"), std::string::npos) << p.selection;
  EXPECT_EQ(p.firmware.family, "ArduCopter");
  EXPECT_EQ(p.firmware.version, "3.3.3");
  EXPECT_EQ(p.firmware_text, "APM:Copter V3.3.3 (abcdef12)");
  EXPECT_EQ(p.vehicle_type, "QUAD");
  EXPECT_EQ(p.format, "dataflash");
  EXPECT_TRUE(p.defaults.empty());
}

TEST(Parameters, WithoutTakeOffTheLastValueIsKept) {
  ParmLog none;
  none.parm("WPNAV_SPEED", 500).parm("WPNAV_SPEED", 700);
  EXPECT_EQ(none.read().parameters.at("WPNAV_SPEED"), 700.0);
  EXPECT_TRUE(none.read().changed_after_takeoff.empty());
  ParmLog armed;  // arming is the marker when no NOT_LANDED is logged
  armed.parm("WPNAV_SPEED", 500).ev(10).parm("WPNAV_SPEED", 700);
  EXPECT_EQ(armed.read().parameters.at("WPNAV_SPEED"), 500.0);
  ParmLog in_air;  // starts in the air: a landing before the first arming
  in_air.parm("WPNAV_SPEED", 500).ev(18).ev(10).parm("WPNAV_SPEED", 700);
  const auto p = in_air.read();
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 700.0);
  EXPECT_NE(p.selection.find("starts in the air"), std::string::npos) << p.selection;
}

TEST(Parameters, FamilyFromParametersWhenNoVersionText) {
  ParmLog copter;
  copter.parm("SYSID_SW_TYPE", 10).parm("WPNAV_SPEED", 500);
  EXPECT_EQ(copter.read().firmware.family, "ArduCopter");
  EXPECT_TRUE(copter.read().firmware.version.empty());
  EXPECT_EQ(copter.read().firmware.major, -1);
  ParmLog plane;
  plane.parm("SYSID_SW_TYPE", 0);
  EXPECT_EQ(plane.read().firmware.family, "ArduPlane");
  ParmLog unknown;
  unknown.parm("FOO", 1);
  EXPECT_EQ(unknown.read().firmware.family, "unknown");
}

TEST(Parameters, CutFinalRecordIsAcceptedOtherCorruptionNeedsLenient) {
  ParmLog log;
  log.parm("WPNAV_SPEED", 500).parm("WPNAV_ACCEL", 100);
  ParmLog cut = log;
  cut.d.b.resize(cut.d.b.size() - 2);  // the last PARM loses its last 2 bytes
  const auto p = cut.read();
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 500.0);
  EXPECT_FALSE(p.parameters.count("WPNAV_ACCEL"));
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("truncated"), std::string::npos) << p.warnings[0];
  ParmLog garbled = log;
  garbled.d.b.insert(garbled.d.b.end() - 23, {0x00, 0x01, 0x02});  // junk between the two PARMs
  const std::string e = errorOf(garbled.d.b, "garbled.bin");
  EXPECT_NE(e.find("garbled.bin: byte offset"), std::string::npos) << e;
  EXPECT_NE(e.find("use --lenient"), std::string::npos) << e;
  EXPECT_EQ(garbled.read(true).parameters.size(), 2u);
}

TEST(Parameters, LogsWithoutParametersAreClearErrors) {
  ParmLog empty;
  empty.ev(10);
  const std::string df = errorOf(empty.d.b, "flight.bin");
  EXPECT_NE(df.find("flight.bin: no parameters in the log (no PARM messages)"), std::string::npos) << df;
  ULog u;
  ulogInfo(u, 0x010F00FF);
  const std::string ul = errorOf(u.b, "flight.ulg");
  EXPECT_NE(ul.find("flight.ulg: no parameters in the log (no ULog 'P' messages)"), std::string::npos) << ul;
  const std::string text = "time_s,x_m\n0,0\n";
  const std::string csv = errorOf(Bytes(text.begin(), text.end()), "flight.csv");
  EXPECT_NE(csv.find("flight.csv: not an ArduPilot DataFlash (.bin) or PX4 ULog (.ulg) log"), std::string::npos) << csv;
  EXPECT_THROW(wattswath::logs::readAutopilotParameters("/nonexistent/flight.bin"), std::runtime_error);
}

TEST(Parameters, UlogParametersDefaultsAndVersion) {
  ULog u;
  ulogInfo(u, 0x010F00FF);
  ulogParameter(u, "MPC_XY_CRUISE", 12.0f);
  ulogParameter(u, "MPC_ACC_HOR", 3.0f);
  ulogParameter(u, "MPC_XY_CRUISE", 5.0f, 1);  // system-wide default
  ulogParameter(u, "MPC_ACC_HOR", 4.0f, 2);    // airframe default only
  const auto p = readAutopilotParametersBytes(u.b, "built.ulg");
  EXPECT_EQ(p.format, "ulog");
  EXPECT_EQ(p.firmware.family, "PX4");
  EXPECT_EQ(p.firmware.version, "1.15.0");
  EXPECT_EQ(p.parameters.at("MPC_XY_CRUISE"), 12.0);
  EXPECT_EQ(p.defaults.at("MPC_XY_CRUISE"), 5.0);
  EXPECT_FALSE(p.defaults.count("MPC_ACC_HOR"));
}

TEST(Parameters, ArduPilotVersionTexts) {
  struct Case {
    std::string text, family, version;
    int major, minor, patch;
  };
  for (const Case& c : {Case{"ArduCopter V4.7.0-dev (90700977)", "ArduCopter", "4.7.0-dev", 4, 7, 0},
                        Case{"ArduCopter V3.3.3 (d4b9a8b8)", "ArduCopter", "3.3.3", 3, 3, 3},
                        Case{"APM:Copter V3.1.5", "ArduCopter", "3.1.5", 3, 1, 5},
                        Case{"APM:Copter V3.3-dev (ae3192b8)", "ArduCopter", "3.3-dev", 3, 3, 0},
                        Case{"ArduPlane V4.5.7 (2a3dc4b7)", "ArduPlane", "4.5.7", 4, 5, 7},
                        Case{"APM:Plane V3.4.0", "ArduPlane", "3.4.0", 3, 4, 0},
                        Case{"ArduRover v3.1.0", "ArduRover", "3.1.0", 3, 1, 0},
                        Case{"APMrover2 v2.51", "ArduRover", "2.51", 2, 51, 0},
                        Case{"ArduCopter", "ArduCopter", "", -1, -1, -1},
                        Case{"PX4: 60133536 NuttX: 1e53bc3d", "unknown", "", -1, -1, -1},
                        Case{"Frame: QUAD", "unknown", "", -1, -1, -1}}) {
    const auto v = parseArduPilotVersion(c.text);
    EXPECT_EQ(v.family, c.family) << c.text;
    EXPECT_EQ(v.version, c.version) << c.text;
    EXPECT_EQ(v.major, c.major) << c.text;
    EXPECT_EQ(v.minor, c.minor) << c.text;
    EXPECT_EQ(v.patch, c.patch) << c.text;
  }
}

TEST(Parameters, Px4ReleaseNumbers) {
  EXPECT_EQ(parsePx4Release(0x010F00FF).version, "1.15.0");
  EXPECT_EQ(parsePx4Release(0x01090080).version, "1.9.0-beta");
  EXPECT_EQ(parsePx4Release(0x010E03C0).version, "1.14.3-rc");
  EXPECT_EQ(parsePx4Release(0x010E0040).version, "1.14.0-alpha");
  EXPECT_EQ(parsePx4Release(0x010E0000).version, "1.14.0-dev");
  const auto v = parsePx4Release(0x010F0201);
  EXPECT_EQ(v.family, "PX4");
  EXPECT_EQ(v.major, 1);
  EXPECT_EQ(v.minor, 15);
  EXPECT_EQ(v.patch, 2);
  EXPECT_TRUE(parsePx4Release(0).version.empty());
  EXPECT_EQ(parsePx4Release(0).major, -1);
}

TEST(Parameters, FlightBehaviourSelection) {
  for (const char* n : {"WPNAV_SPEED", "WPNAV_JERK", "PSC_JERK_XY", "ATC_INPUT_TC", "ATC_ACCEL_R_MAX", "ATC_RATE_Y_MAX",
                        "ATC_SLEW_YAW", "WP_YAW_BEHAVIOR", "RTL_ALT", "LAND_SPEED_HIGH", "PILOT_SPEED_UP",
                        "PILOT_TKOFF_ALT", "TKOFF_SLEW_TIME", "WP_NAVALT_MIN", "LOIT_SPEED", "ANGLE_MAX", "PSC_VELXY_P", "PSC_POSXY_P",
                        "MOT_THST_HOVER", "PSC_ACCZ_P", "PSC_VELZ_P", "THR_MID", "THR_ACCEL_I", "MOT_SPOOL_TIME", "CIRCLE_RATE"})
    EXPECT_TRUE(isFlightBehaviourParameter("ArduCopter", n)) << n;
  for (const char* n : {"MOT_THST_EXPO", "STAT_FLTTIME", "ATC_RAT_RLL_P", "BATT_CAPACITY", "ATC_ACCEL_R_FILT", "MPC_XY_CRUISE"})
    EXPECT_FALSE(isFlightBehaviourParameter("ArduCopter", n)) << n;
  for (const char* n : {"MPC_XY_CRUISE", "MPC_ACC_HOR", "MPC_JERK_AUTO", "MPC_TKO_SPEED", "MPC_LAND_SPEED", "NAV_ACC_RAD",
                        "NAV_MC_ALT_RAD", "RTL_RETURN_ALT", "MIS_TAKEOFF_ALT", "COM_SPOOLUP_TIME"})
    EXPECT_TRUE(isFlightBehaviourParameter("PX4", n)) << n;
  for (const char* n : {"MC_ROLL_P", "BAT1_N_CELLS", "WPNAV_SPEED", "NAV_DLL_ACT"})
    EXPECT_FALSE(isFlightBehaviourParameter("PX4", n)) << n;
  EXPECT_TRUE(isFlightBehaviourParameter("unknown", "WPNAV_SPEED"));
}

TEST(Parameters, FlightBehaviourParametersFilterTheMap) {
  AutopilotParameters p;
  p.firmware.family = "ArduCopter";
  p.parameters = {{"WPNAV_SPEED", 1000}, {"STAT_FLTTIME", 3600}, {"RTL_ALT", 1500}};
  const auto kept = wattswath::logs::flightBehaviourParameters(p);
  EXPECT_EQ(kept.size(), 2u);
  EXPECT_TRUE(kept.count("WPNAV_SPEED") && kept.count("RTL_ALT"));
}
