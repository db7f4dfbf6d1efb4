#include "wattswath/mission/autopilot.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wattswath::mission {
namespace {

// ArduCopter 4.x defaults (AC_WPNav, AC_PosControl, AC_AttitudeControl, ArduCopter/config.h,
// Parameters.cpp; docs/autopilots.md), in the autopilot's units.
const std::map<std::string, double> kArduCopter4 = {
    {"WPNAV_SPEED", 1000},       {"WPNAV_SPEED_UP", 250}, {"WPNAV_SPEED_DN", 150}, {"WPNAV_ACCEL", 250},
    {"WPNAV_ACCEL_Z", 100},      {"WPNAV_JERK", 1.0},     {"WPNAV_RADIUS", 200},   {"WPNAV_ACCEL_C", 0},
    {"PSC_JERK_Z", 5.0},         {"PSC_POSZ_P", 1.0},     {"ATC_INPUT_TC", 0.15},  {"ATC_ACCEL_R_MAX", 110000},
    {"ATC_ACCEL_P_MAX", 110000}, {"ATC_RATE_R_MAX", 0},   {"ATC_RATE_P_MAX", 0},   {"ATC_SLEW_YAW", 6000},
    {"WP_YAW_BEHAVIOR", 2},      {"RTL_ALT", 1500},       {"RTL_ALT_FINAL", 0},    {"RTL_CLIMB_MIN", 0},
    {"RTL_SPEED", 0},            {"RTL_LOIT_TIME", 5000}, {"RTL_CONE_SLOPE", 3.0}, {"LAND_SPEED", 50},
    {"LAND_SPEED_HIGH", 0},      {"LAND_ALT_LOW", 1000},  {"MOT_SPOOL_TIME", 0.5},   {"TKOFF_SLEW_TIME", 2.0},
    {"TKOFF_THR_MAX", 0.9},      {"PSC_POSXY_P", 1.0},        {"PSC_VELXY_P", 2.0},    {"PSC_VELXY_I", 1.0},    {"PSC_VELXY_IMAX", 1000},
    {"PSC_VELXY_D", 0.25},       {"PSC_VELXY_FLTE", 5.0}, {"PSC_VELXY_FLTD", 5.0},
    {"ANGLE_MAX", 3000},         {"PSC_ANGLE_MAX", 0},
    {"MOT_THST_HOVER", 0.35},    {"PSC_VELZ_P", 5.0},     {"PSC_ACCZ_P", 0.5},     {"PSC_ACCZ_I", 1.0},
    {"PSC_JERK_XY", 5.0},        {"CIRCLE_RATE", 20.0},
};

// ArduCopter 3.x defaults (AC_WPNav.h of 3.2-3.6, AC_PosControl).
const std::map<std::string, double> kArduCopter3 = {
    {"WPNAV_SPEED", 500},   {"WPNAV_SPEED_UP", 250}, {"WPNAV_SPEED_DN", 150},  {"WPNAV_ACCEL", 100},
    {"WPNAV_ACCEL_Z", 100}, {"WPNAV_RADIUS", 200},   {"POS_XY_P", 1.0},        {"POS_Z_P", 1.0},
    {"VEL_XY_P", 1.0},      {"VEL_XY_I", 0.5},       {"VEL_XY_IMAX", 1000},    {"ANGLE_MAX", 4500},      {"RTL_ALT", 1500},
    {"RTL_ALT_FINAL", 0},   {"RTL_CLIMB_MIN", 0},    {"RTL_LOIT_TIME", 5000},  {"LAND_SPEED", 50},
    {"LAND_ALT_LOW", 1000}, {"MOT_SPOOL_TIME", 0.5}, {"ATC_SLEW_YAW", 6000},   {"WP_YAW_BEHAVIOR", 2},
    {"THR_MID", 500},       {"VEL_Z_P", 5.0},        {"ACCEL_Z_P", 0.5},       {"ACCEL_Z_I", 1.0},
    {"CIRCLE_RATE", 20.0},  {"PSC_ACC_XY_FILT", 2.0},
};

// PX4 multicopter defaults (FlightTaskAuto, mc_pos_control, navigator params).
const std::map<std::string, double> kPx4 = {
    {"MPC_XY_CRUISE", 5.0},    {"MPC_XY_VEL_MAX", 12.0},   {"MPC_ACC_HOR", 3.0},     {"MPC_JERK_AUTO", 4.0},
    {"MPC_XY_TRAJ_P", 0.5},    {"MPC_Z_V_AUTO_UP", 3.0},   {"MPC_Z_V_AUTO_DN", 1.5}, {"MPC_ACC_UP_MAX", 4.0},
    {"MPC_ACC_DOWN_MAX", 3.0}, {"MPC_Z_VEL_MAX_DN", 1.5},  {"MPC_TKO_SPEED", 1.5},   {"MPC_TKO_RAMP_T", 3.0},
    {"MPC_LAND_SPEED", 0.7},   {"MPC_LAND_ALT1", 10.0},    {"MPC_LAND_ALT2", 5.0},   {"NAV_ACC_RAD", 10.0},
    {"NAV_MC_ALT_RAD", 0.8},   {"MIS_TAKEOFF_ALT", 2.5},   {"RTL_RETURN_ALT", 60.0}, {"RTL_DESCEND_ALT", 30.0},
    {"RTL_LAND_DELAY", 0.0},   {"MPC_YAWRAUTO_MAX", 45.0}, {"COM_SPOOLUP_TIME", 1.0},  {"RTL_CONE_ANG", 45.0},
    {"RTL_MIN_DIST", 10.0},    {"MIS_YAW_ERR", 12.0},
};

// Major and minor version numbers of "4.5.7", "V3.3.3", "v1.14.0-dev" (0, 0 when none).
std::pair<int, int> majorMinor(const std::string& v) {
  int major = 0, minor = 0;
  const std::size_t start = v.find_first_of("0123456789");
  if (start == std::string::npos) return {0, 0};
  std::sscanf(v.c_str() + start, "%d.%d", &major, &minor);
  return {major, minor};
}

}  // namespace

const char* toString(AutopilotFamily f) {
  switch (f) {
    case AutopilotFamily::ArduCopterSCurve: return "arducopter-scurve";
    case AutopilotFamily::ArduCopterLeash: return "arducopter-leash";
    case AutopilotFamily::PX4: return "px4";
  }
  return "unknown";
}

const std::map<std::string, double>& defaultParameters(AutopilotFamily f) {
  switch (f) {
    case AutopilotFamily::ArduCopterLeash: return kArduCopter3;
    case AutopilotFamily::PX4: return kPx4;
    case AutopilotFamily::ArduCopterSCurve: break;
  }
  return kArduCopter4;
}

double AutopilotConfig::get(const std::string& name) const {
  if (auto it = parameters.find(name); it != parameters.end()) return it->second;
  const auto& d = defaultParameters(family);
  if (auto it = d.find(name); it != d.end()) return it->second;
  throw std::out_of_range("autopilot parameter " + name + " is neither in the vehicle file nor a known " +
                          toString(family) + " default");
}

bool versionAtLeast(const std::string& version, int major, int minor) {
  const auto [ma, mi] = majorMinor(version);
  return ma > major || (ma == major && mi >= minor);
}

AutopilotFamily familyOf(const std::string& firmware, const std::string& version) {
  if (firmware == "PX4") return AutopilotFamily::PX4;
  if (firmware == "ArduCopter") {
    const auto [major, minor] = majorMinor(version);
    if (major == 0) {
      throw std::invalid_argument("autopilot.version '" + version + "' has no version number (e.g. \"4.5.7\")");
    }
    return (major > 4 || (major == 4 && minor >= 1)) ? AutopilotFamily::ArduCopterSCurve
                                                     : AutopilotFamily::ArduCopterLeash;
  }
  throw std::invalid_argument("autopilot.firmware '" + firmware + "' (version '" + version +
                              "'), expected \"ArduCopter\" or \"PX4\" (multicopter firmware)");
}

AutopilotConfig parseAutopilot(const std::string& json_text, const std::string& source) {
  AutopilotConfig c;
  if (json_text.empty()) return c;
  const std::string where = source.empty() ? std::string("autopilot") : source + ": autopilot";
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const std::exception& e) {
    throw std::invalid_argument(where + " is not valid JSON: " + e.what());
  }
  if (!j.is_object()) throw std::invalid_argument(where + " must be an object {\"firmware\", \"version\", \"parameters\"}");
  auto text = [&](const char* key, const std::string& fallback) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_string()) throw std::invalid_argument(where + "." + key + " must be a string");
    return j[key].get<std::string>();
  };
  c.firmware = text("firmware", c.firmware);
  c.version_assumed = !j.contains("version");
  c.version = text("version", c.firmware == "PX4" ? "1.14" : c.version);
  c.family = familyOf(c.firmware, c.version);
  c.from_file = true;
  if (j.contains("parameters")) {
    const auto& p = j["parameters"];
    if (!p.is_object()) throw std::invalid_argument(where + ".parameters must be an object of name: number");
    for (auto it = p.begin(); it != p.end(); ++it) {
      if (!it->is_number() || !std::isfinite(it->get<double>())) {
        throw std::invalid_argument(where + ".parameters." + it.key() + " = " + it->dump() + ", expected a finite number");
      }
      c.parameters[it.key()] = it->get<double>();
    }
  }
  return c;
}

std::string autopilotToJson(const AutopilotConfig& c) {
  nlohmann::json j;
  j["firmware"] = c.firmware;
  j["version"] = c.version;
  j["parameters"] = nlohmann::json::object();
  for (const auto& [k, v] : c.parameters) j["parameters"][k] = v;
  return j.dump(2);
}

}  // namespace wattswath::mission
