#pragma once
/// @file parameters.hpp
/// The autopilot's firmware and parameters as a flight log records them: ArduPilot DataFlash
/// (.bin: MSG/VER text, PARM messages) and PX4 ULog (.ulg: info 'ver_sw_release'/'sys_name',
/// parameters 'P' and default parameters 'Q'). Values are in the autopilot's own units, as in its
/// parameter list (e.g. ArduCopter WPNAV_SPEED in cm/s, PX4 MPC_XY_CRUISE in m/s).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::logs {

/// A firmware family and version as read from a version text or number.
struct FirmwareVersion {
  std::string family = "unknown";  ///< "ArduCopter", "ArduPlane", "ArduRover", "PX4" or "unknown"
  std::string version;             ///< e.g. "4.7.0-dev", "3.3-dev", "1.15.0-beta"; empty when not known
  int major = -1;                  ///< [-] major version number; -1 when not known
  int minor = -1;                  ///< [-] minor version number; -1 when not known
  int patch = -1;                  ///< [-] patch number (0 when the text gives only major.minor); -1 when not known
};

/// The autopilot's firmware and parameters read from one flight log.
struct AutopilotParameters {
  std::string source;               ///< the file (or name) the log was read from
  std::string format;               ///< "dataflash" or "ulog"
  FirmwareVersion firmware;         ///< family and version
  std::string firmware_text;        ///< the text the version came from, e.g. "ArduCopter V4.7.0-dev (90700977)"
  std::string vehicle_type;         ///< e.g. "QUAD/PLUS" (ArduPilot "Frame:" text) or "quadrotor" (PX4 MAV_TYPE); empty when not known
  std::map<std::string, double> parameters;  ///< every parameter, name -> value in the autopilot's own units
  std::map<std::string, double> defaults;    ///< firmware defaults where the log records them (ArduPilot PARM.Default, PX4 'Q' system-wide)
  std::vector<std::string> changed_after_takeoff;  ///< parameters logged again after take-off with another value (the value before take-off is kept)
  std::string selection;            ///< which value is kept when a parameter is logged several times, in words
  std::vector<std::string> warnings;  ///< parameters dropped for a non-finite value, and reader skips in lenient mode
};

/// Reads the firmware and parameters of the ArduPilot DataFlash (.bin) or PX4 ULog (.ulg) log at
/// `path` (format picked by content). A parameter logged several times keeps its last value
/// before take-off (ArduPilot: the first EV NOT_LANDED, else ARMED, by file order), else its first
/// value after it; without a take-off event, and for ULog, the last value. Only options.lenient is
/// used. Throws std::runtime_error naming the file when it is neither format or has no parameters.
AutopilotParameters readAutopilotParameters(const std::string& path, const LogReadOptions& options = {});

/// As readAutopilotParameters() for bytes already in memory; `source` names them in messages.
AutopilotParameters readAutopilotParametersBytes(std::vector<std::uint8_t> bytes, const std::string& source,
                                                 const LogReadOptions& options = {});

/// Family and version from an ArduPilot version text such as "ArduCopter V4.7.0-dev (90700977)",
/// "APM:Copter V3.1.5" or "ArduPlane V4.5.7"; family "unknown" and no version when not recognised.
FirmwareVersion parseArduPilotVersion(const std::string& text);

/// Family "PX4" and version from a ULog `ver_sw_release` number 0xAABBCCTT (AA.BB.CC, TT the
/// release type: 0 development, 64 alpha, 128 beta, 192 release candidate, 255 release).
FirmwareVersion parsePx4Release(std::uint32_t ver_sw_release);

/// True when parameter `name` shapes how a vehicle of firmware `family` flies a mission (speeds,
/// accelerations, jerks, corner radius, yaw, take-off, return and landing): for ArduPilot
/// families WPNAV_*, PSC_JERK_*, PSC_ANGLE_MAX, ANGLE_MAX, ATC_INPUT_TC, ATC_ACCEL_*_MAX,
/// ATC_RATE_*_MAX, ATC_SLEW_YAW, WP_YAW_BEHAVIOR, RTL_*, LAND_*, PILOT_SPEED_UP/DN,
/// PILOT_TKOFF_ALT, TKOFF_*, WP_NAVALT_MIN, LOIT_* and the 3.x names RC_FEEL_RP, PILOT_VELZ_MAX,
/// PILOT_ACCEL_Z; for PX4 MPC_*, NAV_ACC_RAD, NAV_MC_ALT_RAD, COM_SPOOLUP_TIME, RTL_*, MIS_*. Family "unknown" uses
/// the ArduPilot list.
bool isFlightBehaviourParameter(const std::string& family, const std::string& name);

/// The parameters of `p` for which isFlightBehaviourParameter() holds.
std::map<std::string, double> flightBehaviourParameters(const AutopilotParameters& p);

}  // namespace wattswath::logs
