// readAutopilotParameters() on the shared logs: the three ArduCopter 4.7.0-dev SITL flights of
// ../shared/data/sitl (stock copter.parm: every value checked here is in their PARM messages) and
// the four real logs of ../shared/data/autopilot-logs (ArduCopter 3.3 and 3.5, PX4 1.9 and 1.15).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_util.hpp"
#include "wattswath/logs/parameters.hpp"

namespace {

using wattswath::logs::AutopilotParameters;
using wattswath::logs::readAutopilotParameters;
using wattswath::test::sharedData;

AutopilotParameters sitl(const std::string& name) { return readAutopilotParameters(sharedData("sitl/" + name + ".BIN")); }
AutopilotParameters real(const std::string& name) { return readAutopilotParameters(sharedData("autopilot-logs/" + name)); }

bool listed(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

void expectFirmware(const AutopilotParameters& p, const std::string& family, const std::string& version, int major, int minor,
                    int patch) {
  EXPECT_EQ(p.firmware.family, family) << p.source;
  EXPECT_EQ(p.firmware.version, version) << p.source;
  EXPECT_EQ(p.firmware.major, major) << p.source;
  EXPECT_EQ(p.firmware.minor, minor) << p.source;
  EXPECT_EQ(p.firmware.patch, patch) << p.source;
}

}  // namespace

TEST(ParametersSitl, StockArduCopter47Parameters) {
  for (const std::string name : {"square_5mps", "square_10mps", "plan_sharp_hold1s"}) {
    SCOPED_TRACE(name);
    const auto p = sitl(name);  // each log ends in a cut final record: accepted, listed in warnings
    expectFirmware(p, "ArduCopter", "4.7.0-dev", 4, 7, 0);
    EXPECT_EQ(p.firmware_text, "ArduCopter V4.7.0-dev (90700977)");
    EXPECT_EQ(p.vehicle_type, "QUAD/PLUS");
    EXPECT_GT(p.parameters.size(), 1300u);
    const auto& v = p.parameters;
    EXPECT_EQ(v.at("WPNAV_SPEED"), 1000.0);   // cm/s
    EXPECT_EQ(v.at("WPNAV_ACCEL"), 250.0);    // cm/s^2
    EXPECT_EQ(v.at("WPNAV_JERK"), 1.0);       // m/s^3
    EXPECT_EQ(v.at("PSC_JERK_XY"), 5.0);      // m/s^3
    EXPECT_EQ(v.at("WPNAV_RADIUS"), 200.0);   // cm
    EXPECT_EQ(v.at("WPNAV_SPEED_UP"), 250.0); // cm/s
    EXPECT_EQ(v.at("WPNAV_SPEED_DN"), 150.0); // cm/s
    EXPECT_EQ(v.at("RTL_ALT"), 1500.0);       // cm
    EXPECT_EQ(v.at("RTL_SPEED"), 0.0);        // 0: WPNAV_SPEED
    EXPECT_EQ(v.at("RTL_LOIT_TIME"), 5000.0); // ms
    EXPECT_EQ(v.at("LAND_SPEED"), 50.0);      // cm/s
    EXPECT_EQ(v.at("LAND_ALT_LOW"), 1000.0);  // cm
    EXPECT_FLOAT_EQ(static_cast<float>(v.at("ATC_INPUT_TC")), 0.15f);  // s
    EXPECT_EQ(v.at("WP_YAW_BEHAVIOR"), 2.0);
    EXPECT_EQ(v.at("ATC_SLEW_YAW"), 6000.0);  // cdeg/s
    EXPECT_EQ(v.at("PILOT_TKOFF_ALT"), 0.0);
    EXPECT_EQ(p.defaults.at("WPNAV_SPEED"), 1000.0);  // 4.x PARM records carry the default
    // MOT_THST_HOVER is learnt in flight and logged again after landing: the value at take-off is kept.
    EXPECT_FLOAT_EQ(static_cast<float>(v.at("MOT_THST_HOVER")), 0.39f);
    EXPECT_TRUE(listed(p.changed_after_takeoff, "MOT_THST_HOVER"));
    EXPECT_NE(p.selection.find("NOT_LANDED"), std::string::npos) << p.selection;
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("truncated"), std::string::npos);
    const auto kept = wattswath::logs::flightBehaviourParameters(p);
    EXPECT_TRUE(kept.count("WPNAV_SPEED") && kept.count("PSC_JERK_XY") && kept.count("TKOFF_SLEW_TIME"));
    EXPECT_TRUE(kept.count("MOT_THST_HOVER"));  // the hover throttle shapes the landing (throttleWindDown)
    EXPECT_FALSE(kept.count("STAT_FLTTIME") || kept.count("MOT_THST_EXPO"));
  }
}

TEST(ParametersReal, ArduCopter33) {
  const auto p = real("arducopter-3.3_quad_log171.bin");
  expectFirmware(p, "ArduCopter", "3.3-dev", 3, 3, 0);
  EXPECT_EQ(p.firmware_text, "APM:Copter V3.3-dev (ae3192b8)");
  EXPECT_EQ(p.vehicle_type, "QUAD");
  EXPECT_EQ(p.parameters.size(), 491u);
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 1500.0);
  EXPECT_EQ(p.parameters.at("WPNAV_ACCEL"), 500.0);
  EXPECT_EQ(p.parameters.at("WPNAV_RADIUS"), 200.0);
  EXPECT_EQ(p.parameters.at("RTL_ALT"), 2500.0);
  EXPECT_EQ(p.parameters.at("LAND_SPEED"), 50.0);
  EXPECT_EQ(p.parameters.at("BATT_CAPACITY"), 5200.0);  // stated in the README
  EXPECT_EQ(p.parameters.at("FRAME"), 1.0);
  EXPECT_TRUE(p.defaults.empty());  // 3.3 PARM has no Default column
  EXPECT_NE(p.selection.find("NOT_LANDED"), std::string::npos) << p.selection;  // PARM has no time: file order
}

TEST(ParametersReal, ArduCopter35WithoutVersionText) {
  const auto p = real("arducopter-3.5_quad_rtl.bin");
  expectFirmware(p, "ArduCopter", "", -1, -1, -1);  // from SYSID_SW_TYPE = 10; the log names no version
  EXPECT_TRUE(p.firmware_text.empty());
  EXPECT_EQ(p.vehicle_type, "FRAME_CLASS=1, FRAME_TYPE=1");
  EXPECT_EQ(p.parameters.at("WPNAV_SPEED"), 500.0);
  EXPECT_EQ(p.parameters.at("BATT_CAPACITY"), 5300.0);
  EXPECT_EQ(p.parameters.at("FRAME_CLASS"), 1.0);
  EXPECT_NE(p.selection.find("starts in the air"), std::string::npos) << p.selection;
}

TEST(ParametersReal, Px419) {
  const auto p = real("px4-1.9_quad_mission_rtl.ulg");
  expectFirmware(p, "PX4", "1.9.0-beta", 1, 9, 0);  // ver_sw_release 0x01090080
  EXPECT_EQ(p.format, "ulog");
  EXPECT_EQ(p.vehicle_type, "quadrotor");
  EXPECT_NE(p.firmware_text.find("IA-release-1"), std::string::npos) << p.firmware_text;
  EXPECT_EQ(p.parameters.size(), 759u);
  EXPECT_EQ(p.parameters.at("MPC_XY_CRUISE"), 5.0);
  EXPECT_EQ(p.parameters.at("NAV_ACC_RAD"), 4.0);
  EXPECT_EQ(p.parameters.at("RTL_RETURN_ALT"), 10.0);
  EXPECT_TRUE(p.defaults.empty());  // no 'Q' messages in this log
}

TEST(ParametersReal, Px4115WithDefaults) {
  const auto p = real("px4-1.15_quad_manual_posctl.ulg");
  expectFirmware(p, "PX4", "1.15.0-beta", 1, 15, 0);  // ver_sw_release 0x010F0080
  EXPECT_EQ(p.vehicle_type, "quadrotor");             // vehicle_status.system_type
  EXPECT_EQ(p.parameters.size(), 969u);
  EXPECT_EQ(p.parameters.at("MPC_XY_CRUISE"), 15.0);
  EXPECT_EQ(p.parameters.at("MPC_ACC_HOR"), 3.0);
  EXPECT_EQ(p.parameters.at("MPC_JERK_AUTO"), 4.0);
  // The README's "BAT1_N_CELLS = 0, MAV_TYPE and CA_ROTOR_COUNT read 0" are the 'Q' defaults; the
  // 'P' values are 6, 2 and 4 (checked with an independent parse of the file).
  EXPECT_EQ(p.parameters.at("BAT1_N_CELLS"), 6.0);
  EXPECT_EQ(p.parameters.at("MAV_TYPE"), 2.0);
  EXPECT_EQ(p.parameters.at("CA_ROTOR_COUNT"), 4.0);
  EXPECT_EQ(p.defaults.at("BAT1_N_CELLS"), 0.0);
  EXPECT_EQ(p.defaults.at("MAV_TYPE"), 0.0);
  EXPECT_EQ(p.defaults.at("MPC_XY_CRUISE"), 5.0);
  const auto kept = wattswath::logs::flightBehaviourParameters(p);
  EXPECT_TRUE(kept.count("MPC_XY_CRUISE") && kept.count("NAV_ACC_RAD") && kept.count("RTL_RETURN_ALT"));
  EXPECT_FALSE(kept.count("BAT1_N_CELLS"));
}
