#include "wattswath/logs/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/ulog.hpp"
#include "binary_read.hpp"
#include "mav_type.hpp"

namespace wattswath::logs {
namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string number(double x) {
  const double r = std::round(x);
  return r == x && std::fabs(x) < 1e15 ? std::to_string(static_cast<long long>(r)) : std::to_string(x);
}

// ---------------------------------------------------------------- DataFlash

// ArduPilot's EV ids that mark the start of a flight, by preference.
constexpr int kEvNotLanded = 28;
constexpr int kEvArmed = 10;
constexpr int kEvLandMaybe = 17;
constexpr int kEvLanded = 18;

// One PARM record.
struct ParmRecord {
  std::string name;
  double value = 0.0;
  double default_value = std::nan("");
  std::size_t offset = 0;  // [B] position in the file
};

std::vector<ParmRecord> parmRecords(const dataflash::Log& L) {
  std::vector<ParmRecord> out;
  if (!L.count("PARM") || !L.has("PARM", "Name") || !L.has("PARM", "Value"))
    throw std::runtime_error(L.source() + ": no parameters in the log (no PARM messages); a log of the vehicle written "
                                          "with its parameters is needed (ArduPilot logs them when logging starts)");
  const auto names = L.textColumn("PARM", "Name");
  const auto values = L.column("PARM", "Value");
  const bool has_default = L.has("PARM", "Default");
  const auto defaults = has_default ? L.column("PARM", "Default") : std::vector<double>();
  for (std::size_t k = 0; k < names.size(); ++k)
    out.push_back({names[k], values[k], has_default ? defaults[k] : std::nan(""), L.offsetOf("PARM", k)});
  return out;
}

// [B] Offset of the first EV `id`, or 0 when there is none (PARM records never start at 0).
std::size_t firstEvent(const dataflash::Log& L, int id) {
  if (!L.count("EV") || !L.has("EV", "Id")) return 0;
  const auto ids = L.column("EV", "Id");
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (static_cast<int>(ids[k]) == id) return L.offsetOf("EV", k);
  return 0;
}

// The smaller of two offsets where 0 means "none".
std::size_t earliest(std::size_t a, std::size_t b) { return a == 0 ? b : b == 0 ? a : std::min(a, b); }

// Keeps, per name, the last value before `takeoff` (a byte offset; 0: none known), else the first
// after it; a later record with another value lists the name in changed_after_takeoff.
void selectValues(const std::vector<ParmRecord>& records, std::size_t takeoff, AutopilotParameters& out) {
  std::map<std::string, bool> before;  // name -> kept value is from before take-off
  for (const auto& r : records) {
    if (!std::isfinite(r.value)) {
      out.warnings.push_back("parameter " + r.name + " has a non-finite value; record not used");
      continue;
    }
    const bool is_before = takeoff == 0 || r.offset < takeoff;
    auto it = out.parameters.find(r.name);
    if (it == out.parameters.end() || (is_before && before[r.name])) {
      out.parameters[r.name] = r.value;
      before[r.name] = is_before;
    } else if (it->second != r.value && !is_before) {
      out.changed_after_takeoff.push_back(r.name);
    }
    if (std::isfinite(r.default_value)) out.defaults[r.name] = r.default_value;
  }
  std::sort(out.changed_after_takeoff.begin(), out.changed_after_takeoff.end());
  out.changed_after_takeoff.erase(std::unique(out.changed_after_takeoff.begin(), out.changed_after_takeoff.end()),
                                  out.changed_after_takeoff.end());
}

std::size_t takeoffOffset(const dataflash::Log& L, std::string& selection) {
  if (const std::size_t t = firstEvent(L, kEvNotLanded)) {
    selection = "last value before take-off (the first EV NOT_LANDED, byte " + std::to_string(t) + ")";
    return t;
  }
  const std::size_t armed = firstEvent(L, kEvArmed);
  const std::size_t landed = earliest(firstEvent(L, kEvLandMaybe), firstEvent(L, kEvLanded));
  if (armed && !(landed && landed < armed)) {
    selection = "last value before arming (the first EV ARMED, byte " + std::to_string(armed) + "; no take-off event logged)";
    return armed;
  }
  selection = landed ? "last value in the log (the log starts in the air: its first flight event is a landing)"
                     : "last value in the log (no take-off or arming event logged)";
  return 0;
}

std::vector<std::string> messages(const dataflash::Log& L) {
  return L.count("MSG") && L.has("MSG", "Message") ? L.textColumn("MSG", "Message") : std::vector<std::string>();
}

// Firmware from VER (FWS text, else Maj/Min/Pat), else the first MSG text naming a firmware.
void dataflashVersion(const dataflash::Log& L, AutopilotParameters& out) {
  if (L.count("VER") && L.has("VER", "FWS")) {
    const auto fws = L.textColumn("VER", "FWS");
    if (!fws.empty() && parseArduPilotVersion(fws.front()).family != "unknown") out.firmware_text = fws.front();
  }
  for (const auto& m : messages(L))
    if (out.firmware_text.empty() && parseArduPilotVersion(m).family != "unknown") out.firmware_text = m;
  out.firmware = parseArduPilotVersion(out.firmware_text);
  if (out.firmware.version.empty() && L.count("VER") && L.has("VER", "Maj") && L.has("VER", "Min") && L.has("VER", "Pat")) {
    out.firmware.major = static_cast<int>(L.column("VER", "Maj").front());
    out.firmware.minor = static_cast<int>(L.column("VER", "Min").front());
    out.firmware.patch = static_cast<int>(L.column("VER", "Pat").front());
    out.firmware.version = std::to_string(out.firmware.major) + "." + std::to_string(out.firmware.minor) + "." +
                           std::to_string(out.firmware.patch);
  }
}

// Family without a version text: SYSID_SW_TYPE (ArduPilot 3.x), else parameters only one vehicle has.
std::string familyFromParameters(const std::map<std::string, double>& p) {
  auto it = p.find("SYSID_SW_TYPE");
  if (it != p.end()) {
    const int t = static_cast<int>(it->second);
    if (t == 0) return "ArduPlane";
    if (t == 10) return "ArduCopter";
    if (t == 20) return "ArduRover";
  }
  if (p.count("WPNAV_SPEED")) return "ArduCopter";
  if (p.count("TECS_CLMB_MAX")) return "ArduPlane";
  if (p.count("CRUISE_SPEED")) return "ArduRover";
  return "unknown";
}

std::string dataflashVehicle(const dataflash::Log& L, const std::map<std::string, double>& p) {
  for (const auto& m : messages(L))
    if (startsWith(m, "Frame: ")) return m.substr(7);
  std::string frame;
  for (const char* name : {"FRAME_CLASS", "FRAME_TYPE", "FRAME"}) {
    auto it = p.find(name);
    if (it != p.end()) frame += (frame.empty() ? "" : ", ") + std::string(name) + "=" + number(it->second);
  }
  return frame;
}

AutopilotParameters readDataFlash(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient) {
  const auto L = dataflash::Log::parseAcceptingCutEnd(std::move(bytes), source, lenient);
  AutopilotParameters out;
  out.source = source;
  out.format = "dataflash";
  out.warnings = L.warnings();
  const auto records = parmRecords(L);
  selectValues(records, takeoffOffset(L, out.selection), out);
  dataflashVersion(L, out);
  if (out.firmware.family == "unknown") out.firmware.family = familyFromParameters(out.parameters);
  out.vehicle_type = dataflashVehicle(L, out.parameters);
  return out;
}

// ---------------------------------------------------------------- ULog

std::string infoOr(const ulog::Log& L, const std::string& key) {
  auto it = L.info().find(key);
  return it == L.info().end() ? std::string() : it->second;
}

std::string ulogVehicle(const ulog::Log& L) {
  if (!L.instances("vehicle_status").empty() && L.hasField("vehicle_status", "system_type")) {
    const auto st = L.column("vehicle_status", 0, "system_type");
    if (!st.empty()) return mavTypeName(static_cast<int>(st.back()));
  }
  auto it = L.parameters().find("MAV_TYPE");
  return it == L.parameters().end() || it->second == 0 ? std::string() : mavTypeName(static_cast<int>(it->second));
}

void ulogVersion(const ulog::Log& L, AutopilotParameters& out) {
  const std::string release = infoOr(L, "ver_sw_release");
  std::uint32_t v = 0;
  try {
    v = release.empty() ? 0 : static_cast<std::uint32_t>(std::stoll(release));
  } catch (const std::exception&) {
    out.warnings.push_back("info ver_sw_release '" + release + "' is not a number; version unknown");
  }
  out.firmware = parsePx4Release(v);
  const std::string sys = infoOr(L, "sys_name");
  out.firmware_text = (sys.empty() ? std::string("PX4") : sys) + (out.firmware.version.empty() ? "" : " v" + out.firmware.version);
  if (!infoOr(L, "ver_sw_branch").empty()) out.firmware_text += ", branch " + infoOr(L, "ver_sw_branch");
}

AutopilotParameters readUlog(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient) {
  const auto L = ulog::Log::parse(std::move(bytes), source, lenient);
  AutopilotParameters out;
  out.source = source;
  out.format = "ulog";
  out.warnings = L.warnings();
  if (L.parameters().empty())
    throw std::runtime_error(source + ": no parameters in the log (no ULog 'P' messages); a log of the vehicle "
                                      "written with its parameters is needed");
  for (const auto& [name, value] : L.parameters()) {
    if (std::isfinite(value)) out.parameters[name] = value;
    else out.warnings.push_back("parameter " + name + " has a non-finite value; not used");
  }
  out.defaults = L.defaultParameters();
  out.selection = "last value in the log (ULog parameter changes are not matched against take-off)";
  ulogVersion(L, out);
  out.vehicle_type = ulogVehicle(L);
  return out;
}

bool isUlog(const std::vector<std::uint8_t>& b) {
  return b.size() >= 7 && b[0] == 'U' && b[1] == 'L' && b[2] == 'o' && b[3] == 'g' && b[4] == 0x01 && b[5] == 0x12 &&
         b[6] == 0x35;
}

bool isDataFlash(const std::vector<std::uint8_t>& b) { return b.size() >= 2 && b[0] == 0xA3 && b[1] == 0x95; }

// ---------------------------------------------------------------- flight-behaviour selection

bool matchesAny(const std::string& name, const std::vector<std::string>& prefixes, const std::vector<std::string>& exact) {
  for (const auto& p : prefixes)
    if (startsWith(name, p)) return true;
  for (const auto& e : exact)
    if (name == e) return true;
  return false;
}

bool isArduPilotFlightParameter(const std::string& n) {
  static const std::vector<std::string> prefixes = {"WPNAV_", "PSC_JERK_", "PSC_POSXY_", "PSC_VELXY_", "PSC_POSZ_",
      "PSC_VELZ_", "PSC_ACCZ_", "RTL_", "LAND_", "TKOFF_", "LOIT_", "POS_XY_", "POS_Z_", "VEL_XY_", "VEL_Z_", "ACCEL_Z_",
      "CIRCLE_"};
  static const std::vector<std::string> exact = {"PSC_ANGLE_MAX", "ANGLE_MAX", "ATC_INPUT_TC", "ATC_SLEW_YAW",
      "WP_YAW_BEHAVIOR", "PILOT_SPEED_UP", "PILOT_SPEED_DN", "PILOT_TKOFF_ALT", "WP_NAVALT_MIN", "RC_FEEL_RP",
      "PILOT_VELZ_MAX", "PILOT_ACCEL_Z", "MOT_THST_HOVER", "MOT_SPOOL_TIME", "THR_MID", "THR_ALT_P", "THR_RATE_P",
      "THR_ACCEL_P", "THR_ACCEL_I", "PSC_ACC_XY_FILT"};
  const bool limit = (startsWith(n, "ATC_ACCEL_") || startsWith(n, "ATC_RATE_")) && endsWith(n, "_MAX");
  return limit || matchesAny(n, prefixes, exact);
}

bool isPx4FlightParameter(const std::string& n) {
  return matchesAny(n, {"MPC_", "RTL_", "MIS_"}, {"NAV_ACC_RAD", "NAV_MC_ALT_RAD", "COM_SPOOLUP_TIME"});
}

}  // namespace

FirmwareVersion parseArduPilotVersion(const std::string& text) {
  static const std::vector<std::pair<std::string, std::string>> families = {
      {"ArduCopter", "ArduCopter"}, {"APM:Copter", "ArduCopter"}, {"ArduPlane", "ArduPlane"},
      {"APM:Plane", "ArduPlane"},   {"ArduRover", "ArduRover"},   {"APM:Rover", "ArduRover"},
      {"APMrover2", "ArduRover"}};
  FirmwareVersion v;
  for (const auto& [prefix, family] : families)
    if (startsWith(text, prefix)) v.family = family;
  if (v.family == "unknown") return v;
  static const std::regex number(R"([Vv](\d+)\.(\d+)(?:\.(\d+))?([-+~A-Za-z0-9.]*))");
  std::smatch m;
  if (!std::regex_search(text, m, number)) return v;
  v.version = m.str(0).substr(1);
  v.major = std::stoi(m.str(1));
  v.minor = std::stoi(m.str(2));
  v.patch = m[3].matched ? std::stoi(m.str(3)) : 0;
  return v;
}

FirmwareVersion parsePx4Release(std::uint32_t r) {
  FirmwareVersion v;
  v.family = "PX4";
  if (r == 0) return v;
  v.major = static_cast<int>((r >> 24) & 0xFF);
  v.minor = static_cast<int>((r >> 16) & 0xFF);
  v.patch = static_cast<int>((r >> 8) & 0xFF);
  const unsigned type = r & 0xFF;
  const std::string kind = type == 0xFF ? "" : type >= 192 ? "-rc" : type >= 128 ? "-beta" : type >= 64 ? "-alpha" : "-dev";
  v.version = std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.patch) + kind;
  return v;
}

bool isFlightBehaviourParameter(const std::string& family, const std::string& name) {
  return family == "PX4" ? isPx4FlightParameter(name) : isArduPilotFlightParameter(name);
}

std::map<std::string, double> flightBehaviourParameters(const AutopilotParameters& p) {
  std::map<std::string, double> out;
  for (const auto& [name, value] : p.parameters)
    if (isFlightBehaviourParameter(p.firmware.family, name)) out[name] = value;
  return out;
}

AutopilotParameters readAutopilotParametersBytes(std::vector<std::uint8_t> bytes, const std::string& source,
                                                 const LogReadOptions& options) {
  if (isUlog(bytes)) return readUlog(std::move(bytes), source, options.lenient);
  if (isDataFlash(bytes)) return readDataFlash(std::move(bytes), source, options.lenient);
  throw std::runtime_error(source + ": not an ArduPilot DataFlash (.bin) or PX4 ULog (.ulg) log; parameters are "
                                    "read from those only");
}

AutopilotParameters readAutopilotParameters(const std::string& path, const LogReadOptions& options) {
  return readAutopilotParametersBytes(binary::readFileBytes(path, options.max_file_bytes), path, options);
}

}  // namespace wattswath::logs
