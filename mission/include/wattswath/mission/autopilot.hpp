#pragma once
/// @file autopilot.hpp
/// Which autopilot flies the mission and with which parameters: the vehicle file's `autopilot`
/// object ({"firmware", "version", "parameters"}), parameters in the autopilot's own units (as in
/// its parameter list: cm, cm/s, ms for ArduPilot; m, m/s for PX4), and each firmware's
/// documented defaults for what the file does not give (docs/autopilots.md).

#include <map>
#include <string>
#include <vector>

namespace wattswath::mission {

/// Flight-behaviour model families.
enum class AutopilotFamily {
  ArduCopterSCurve,  ///< ArduCopter 4.1 and later: S-curve legs blended at corners
  ArduCopterLeash,   ///< ArduCopter before 4.1: a target point dragged along each leg (leash)
  PX4,               ///< PX4 multicopter: jerk-limited velocity tracking, corner speed from NAV_ACC_RAD
};

/// Lower-case name of a family ("arducopter-scurve", "arducopter-leash", "px4").
const char* toString(AutopilotFamily f);

/// An autopilot and its parameters.
struct AutopilotConfig {
  AutopilotFamily family = AutopilotFamily::ArduCopterSCurve;  ///< behaviour model
  std::string firmware = "ArduCopter";                         ///< "ArduCopter" or "PX4"
  std::string version = "4.5";                                 ///< firmware version, e.g. "3.3.3"
  std::map<std::string, double> parameters;                    ///< as given (autopilot units)
  bool from_file = false;  ///< true when the vehicle file had an `autopilot` object
  bool version_assumed = false;  ///< true when that object gave no version (`version` is then the default)

  /// Parameter `name` as given, else the family's documented default; throws
  /// std::out_of_range naming the parameter when neither exists.
  double get(const std::string& name) const;
  /// True when `name` was given in the file (not a default).
  bool given(const std::string& name) const { return parameters.count(name) > 0; }
};

/// The family's documented defaults (autopilot units), by parameter name.
const std::map<std::string, double>& defaultParameters(AutopilotFamily f);

/// True when firmware version `version` ("4.5.7", "V3.3.3") is at least `major`.`minor`.
bool versionAtLeast(const std::string& version, int major, int minor);

/// Family of a firmware name and version: ArduCopter < 4.1 is the leash model, 4.1 and later the
/// S-curve model, PX4 the PX4 model; throws std::invalid_argument naming both for anything else.
AutopilotFamily familyOf(const std::string& firmware, const std::string& version);

/// Parses a vehicle file's `autopilot` object (JSON text); `source` names it in errors. An empty
/// text gives the default (ArduCopter 4.5 with its defaults). Throws std::invalid_argument naming
/// the source and field for a wrong type, an unknown firmware or a non-finite parameter.
AutopilotConfig parseAutopilot(const std::string& json_text, const std::string& source);

/// Serialises `c` as the `autopilot` JSON object parseAutopilot reads.
std::string autopilotToJson(const AutopilotConfig& c);

}  // namespace wattswath::mission
