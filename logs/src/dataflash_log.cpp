// ArduPilot DataFlash logs in: battery, EKF position and events extracted from the parsed log
// (dataflash.cpp) and assembled into a FlightLog (autopilot_log.cpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "autopilot_log_internal.hpp"
#include "binary_read.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/dataflash.hpp"

namespace wattswath::logs {

using namespace detail;

namespace {

// Compass heading [deg, clockwise from north] to ENU yaw [rad, counter-clockwise from east].
double headingDegToEnuYaw(double deg) { return std::remainder(kPi / 2 - deg * kPi / 180.0, 2 * kPi); }

std::string copterModeName(int mode) {
  static const std::map<int, std::string> names = {
      {0, "STABILIZE"}, {1, "ACRO"},     {2, "ALT_HOLD"},  {3, "AUTO"},       {4, "GUIDED"},   {5, "LOITER"},
      {6, "RTL"},       {7, "CIRCLE"},   {9, "LAND"},      {11, "DRIFT"},     {13, "SPORT"},   {14, "FLIP"},
      {15, "AUTOTUNE"}, {16, "POSHOLD"}, {17, "BRAKE"},    {18, "THROW"},     {19, "AVOID_ADSB"},
      {20, "GUIDED_NOGPS"}, {21, "SMART_RTL"}, {22, "FLOWHOLD"}, {23, "FOLLOW"}, {24, "ZIGZAG"},
      {25, "SYSTEMID"}, {26, "AUTOROTATE"}, {27, "AUTO_RTL"}};
  auto it = names.find(mode);
  return it == names.end() ? "mode" : it->second;
}

// AP_Logger LogEvent ids (the same numbering in Copter 3.x and the shared 4.x enum).
std::string logEventName(int id) {
  static const std::map<int, std::string> names = {
      {10, "ARMED"}, {11, "DISARMED"}, {15, "AUTO_ARMED"}, {17, "LAND_COMPLETE_MAYBE"}, {18, "LAND_COMPLETE"},
      {25, "SET_HOME"}, {28, "NOT_LANDED"}};
  auto it = names.find(id);
  return it == names.end() ? "" : it->second;
}

void dataflashBattery(const dataflash::Log& L, const LogReadOptions& opt, Raw& raw) {
  std::vector<Battery> found;
  std::string untimed;
  // CUR2: the second battery of ArduCopter 3.4-3.6 (LogStructure.h LOG_CURRENT2_MSG).
  for (const std::string name : {"BAT", "BAT2", "CURR", "CURR2", "CUR2"}) {
    if (L.has(name, "Volt") && L.has(name, "Curr") && !L.hasTime(name)) untimed += (untimed.empty() ? "" : ", ") + name;
    if (!L.has(name, "Volt") || !L.has(name, "Curr") || !L.hasTime(name)) continue;
    const auto t = L.times(name);
    auto v = L.column(name, "Volt"), i = L.column(name, "Curr");
    std::string unit_note;
    const char vc = L.columnType(name, "Volt");
    // Integer columns are centivolts and centiamps: the format of ArduCopter 3.3 and older and of
    // early 3.4 development builds (the type, not a version, decides: a 3.4-dev log carries it too).
    if (vc == 'h' || vc == 'H' || vc == 'i' || vc == 'I') {
      for (double& x : v) x /= 100.0;
      for (double& x : i) x /= 100.0;
      unit_note = "; Volt/Curr logged as integers: centi-units, divided by 100 (the format of ArduPilot up to early 3.4 "
                  "development builds)";
    }
    std::vector<double> inst(t.size(), (name.back() == '2') ? 1.0 : 0.0);
    for (const char* col : {"Inst", "I", "Instance"})
      if (L.has(name, col)) { inst = L.column(name, col); break; }
    std::map<int, Battery> by;
    for (std::size_t k = 0; k < t.size(); ++k) {
      Battery& bb = by[static_cast<int>(inst[k])];
      bb.t.push_back(t[k]);
      bb.v.push_back(v[k]);
      bb.i.push_back(i[k]);
    }
    for (auto& [n, bb] : by) {
      bb.instance = n;
      bb.label = name + " instance " + std::to_string(n) + " (" + std::to_string(bb.t.size()) + " samples" + unit_note + ")";
      bb.voltage_field = name + "[" + std::to_string(n) + "].Volt";
      bb.current_field = name + "[" + std::to_string(n) + "].Curr";
      found.push_back(bb);
    }
  }
  raw.meta["battery_candidates"] = "BAT, BAT2, CURR, CURR2, CUR2 with Volt and Curr";
  if (!untimed.empty()) {
    raw.meta["battery_candidates"] += " and a timestamp; " + untimed + " here without one (ArduCopter <= 3.1), which cannot be placed in time";
  }
  // By default the first with a voltage, preferring one whose current is measured (a monitor without
  // a current sensor logs NaN): the power of a voltage-only monitor is unknown.
  const auto measuresCurrent = [](const Battery& bb) {
    return std::count_if(bb.i.begin(), bb.i.end(), [](double x) { return std::isfinite(x); }) * 2 > static_cast<long>(bb.i.size());
  };
  const bool any_current = std::any_of(found.begin(), found.end(), [&](const Battery& bb) { return median(bb.v) > 1.0 && measuresCurrent(bb); });
  bool chosen = false;
  for (auto& bb : found) {
    const bool ok = opt.battery_instance >= 0 ? bb.instance == opt.battery_instance
                                              : median(bb.v) > 1.0 && (!any_current || measuresCurrent(bb));
    if (ok && !chosen) {
      raw.battery = bb;
      chosen = true;
    } else {
      raw.battery_others.push_back(bb.label + (median(bb.v) > 1.0 ? (measuresCurrent(bb) ? "" : ", current not measured") : ", no voltage"));
    }
  }
  if (!chosen && !found.empty())
    throw std::runtime_error(L.source() + ": no battery instance " +
                             (opt.battery_instance >= 0 ? std::to_string(opt.battery_instance) + " " : "with a voltage above 1 V ") +
                             "(found: " + [&] { std::string s; for (auto& bb : found) s += bb.label + "; "; return s; }() + ")");
}

void dataflashPosition(const dataflash::Log& L, const LogReadOptions& opt, Raw& raw) {
  const std::vector<std::string> candidates = {"XKF1", "NKF1", "EKF1", "NKF6"};
  raw.meta["position_candidates"] = "XKF1, NKF1, EKF1 (PN, PE, PD, VN, VE, VD)";
  std::string name;
  for (const auto& c : candidates) {
    if (!opt.position_source.empty() && c != opt.position_source) continue;
    if (L.has(c, "PN") && L.has(c, "PE") && L.has(c, "PD") && L.has(c, "VN") && L.hasTime(c)) { name = c; break; }
  }
  if (name.empty()) {
    if (!opt.position_source.empty())
      throw std::runtime_error(L.source() + ": position source " + opt.position_source +
                               " not found or not supported (supported: XKF1, NKF1, NKF6, EKF1)");
    return;
  }
  const auto t = L.times(name);
  const auto pn = L.column(name, "PN"), pe = L.column(name, "PE"), pd = L.column(name, "PD");
  const auto vn = L.column(name, "VN"), ve = L.column(name, "VE"), vd = L.column(name, "VD");
  const std::vector<double> yaw = L.has(name, "Yaw") ? L.column(name, "Yaw") : std::vector<double>(t.size(), kNaN);
  std::vector<double> core(t.size(), 0.0);
  if (L.has(name, "C")) core = L.column(name, "C");
  const double use_core = core.empty() ? 0.0 : *std::min_element(core.begin(), core.end());
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (core[k] != use_core) continue;
    raw.pt.push_back(t[k]);
    raw.pos.emplace_back(pe[k], pn[k], -pd[k]);
    raw.vel.emplace_back(ve[k], vn[k], -vd[k]);
    raw.yaw.push_back(headingDegToEnuYaw(yaw[k]));
  }
  raw.acc.assign(raw.pt.size(), Eigen::Vector3d::Zero());
  raw.position_message = name + (L.has(name, "C") ? "[core " + num(use_core) + "]" : "");
  raw.pos_fields = {"PE", "PN", "PD"};
  raw.vel_fields = {"VE", "VN", "VD"};
  raw.acc_fields = {"VE", "VN", "VD"};  // never logged: derived from the velocities
  raw.position_source = name + (L.has(name, "C") ? " core " + num(use_core) : "") +
                        " (PN, PE, PD, VN, VE, VD; NED from the EKF origin; acceleration: quadratic least-squares derivative of VN, VE, VD)";
}

void dataflashEvents(const dataflash::Log& L, Raw& raw, bool copter) {
  if (L.count("EV")) {
    if (L.hasTime("EV") && L.has("EV", "Id")) {
      const auto t = L.times("EV");
      const auto id = L.column("EV", "Id");
      // EV 17 LAND_COMPLETE_MAYBE is logged each time the flag sets and nothing when it clears
      // (ArduCopter land_detector.cpp, set_land_complete_maybe): one followed by another 17 (or by a
      // NOT_LANDED before any LAND_COMPLETE) was a moment of low throttle in flight, not a landing.
      auto maybeThatCleared = [&](std::size_t k) {
        for (std::size_t n = k + 1; n < t.size(); ++n) {
          const int next = static_cast<int>(id[n]);
          if (next == 17 || next == 28) return true;
          if (next == 11 || next == 18) return false;
        }
        return false;  // the log ends: taken as the touch-down
      };
      for (std::size_t k = 0; k < t.size(); ++k) {
        const int e = static_cast<int>(id[k]);
        const std::string nm = logEventName(e);
        raw.events.push_back({t[k], "event", "EV " + std::to_string(e) + (nm.empty() ? "" : " " + nm)});
        if (e == 17 && maybeThatCleared(k)) continue;
        if (e == 11 || e == 17 || e == 18) raw.landed.push_back({t[k], true, "EV " + std::to_string(e) + " " + nm});
        if (e == 28) raw.landed.push_back({t[k], false, "EV 28 NOT_LANDED"});
      }
      if (!raw.landed.empty()) raw.landed_source = "EV landed/not-landed/disarmed events";
    } else {
      raw.meta["events_note"] = "EV messages carry no timestamp in this firmware; airborne windows come from the current";
    }
  }
  if (L.count("MODE") && L.hasTime("MODE")) {
    const auto t = L.times("MODE");
    const std::string col = L.has("MODE", "ModeNum") ? "ModeNum" : "Mode";
    const auto mode = L.column("MODE", col);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const int md = static_cast<int>(mode[k]);
      raw.events.push_back({t[k], "mode", copter ? copterModeName(md) + " (" + std::to_string(md) + ")" : "mode " + std::to_string(md)});
    }
  }
  if (L.count("CMD") && L.hasTime("CMD") && L.has("CMD", "CId")) {
    const auto t = L.times("CMD");
    const auto cid = L.column("CMD", "CId");
    const auto cnum = L.has("CMD", "CNum") ? L.column("CMD", "CNum") : std::vector<double>(t.size(), kNaN);
    const auto lat = L.has("CMD", "Lat") ? L.column("CMD", "Lat") : std::vector<double>(t.size(), kNaN);
    const auto lng = L.has("CMD", "Lng") ? L.column("CMD", "Lng") : std::vector<double>(t.size(), kNaN);
    const auto alt = L.has("CMD", "Alt") ? L.column("CMD", "Alt") : std::vector<double>(t.size(), kNaN);
    for (std::size_t k = 0; k < t.size(); ++k)
      raw.events.push_back({t[k], "mission_item",
                            "item " + num(cnum[k]) + ": MAV_CMD " + num(cid[k]) + " at " + num(lat[k], 9) + ", " +
                                num(lng[k], 9) + ", " + num(alt[k]) + " m"});
    raw.meta["mission_items"] = std::to_string(t.size());
  }
  if (L.count("MSG") && L.hasTime("MSG") && L.has("MSG", "Message")) {
    const auto t = L.times("MSG");
    const auto msg = L.textColumn("MSG", "Message");
    for (std::size_t k = 0; k < t.size(); ++k) raw.events.push_back({t[k], "message", msg[k]});
  }
}

}  // namespace

FlightLog readDataFlashBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& opt) {
  const auto L = dataflash::Log::parseAcceptingCutEnd(std::move(bytes), source, opt.lenient);
  Raw raw;
  raw.format = "dataflash";
  raw.warnings = L.warnings();
  // Firmware and frame: MSG/VER text, else parameters.
  std::vector<std::string> texts;
  if (L.has("MSG", "Message")) texts = L.textColumn("MSG", "Message");
  for (const auto& s : texts) {
    if (raw.firmware.empty() && (s.rfind("Ardu", 0) == 0 || s.rfind("APM:", 0) == 0)) raw.firmware = s;
    if (raw.vehicle.empty() && s.rfind("Frame: ", 0) == 0) raw.vehicle = s.substr(7);
  }
  if (L.has("VER", "FWS")) {
    const auto fws = L.textColumn("VER", "FWS");
    if (!fws.empty() && !fws.front().empty()) raw.firmware = fws.front();
  }
  std::map<std::string, double> params;
  if (L.has("PARM", "Name") && L.has("PARM", "Value")) {
    const auto names = L.textColumn("PARM", "Name");
    const auto values = L.column("PARM", "Value");
    for (std::size_t k = 0; k < names.size(); ++k) params[names[k]] = values[k];
  }
  const bool copter = raw.firmware.find("Copter") != std::string::npos ||
                      (raw.firmware.empty() && (params.count("FRAME_CLASS") || params.count("FRAME")) &&
                       !params.count("SERVO_AUTO_TRIM"));
  if (raw.firmware.empty()) {
    raw.firmware = std::string("ArduPilot") + (copter ? " Copter" : "") + ", version not logged (" +
                   (L.has("CURR", "TimeUS") || L.has("BAT", "TimeUS") ? "TimeUS timestamps: 3.4 or later" : "TimeMS timestamps: 3.3 or earlier") + ")";
  }
  std::string frame;
  if (params.count("FRAME_CLASS")) frame += "FRAME_CLASS=" + num(params["FRAME_CLASS"]);
  if (params.count("FRAME_TYPE")) frame += (frame.empty() ? "" : ", ") + std::string("FRAME_TYPE=") + num(params["FRAME_TYPE"]);
  if (params.count("FRAME")) frame += (frame.empty() ? "" : ", ") + std::string("FRAME=") + num(params["FRAME"]);
  if (raw.vehicle.empty()) raw.vehicle = copter ? "multicopter" : "unknown";
  if (!frame.empty()) raw.vehicle += " (" + frame + ")";
  if (L.has("ORGN", "Lat") && L.has("ORGN", "Lng")) {
    // ORGN Type 0 is the EKF origin the positions are measured from (Type 1: home).
    const auto lat = L.column("ORGN", "Lat"), lng = L.column("ORGN", "Lng");
    const auto type = L.has("ORGN", "Type") ? L.column("ORGN", "Type") : std::vector<double>(lat.size(), 0.0);
    const auto alt = L.has("ORGN", "Alt") ? L.column("ORGN", "Alt") : std::vector<double>(lat.size(), 0.0);
    for (std::size_t k = 0; k < lat.size(); ++k) {
      if (type[k] != 0.0 || !setOrigin(raw, lat[k], lng[k], alt[k])) continue;
      raw.meta["ekf_origin"] = num(lat[k], 10) + ", " + num(lng[k], 10);
      break;
    }
  }
  dataflashBattery(L, opt, raw);
  // The capacity of the battery used: BATT_CAPACITY for instance 0, BATT2_ ... BATT9_ for 1 ... 8.
  const int bi = raw.battery.instance;
  const std::string cap = bi == 0 ? "BATT_CAPACITY" : "BATT" + std::to_string(bi + 1) + "_CAPACITY";
  if (bi >= 0 && bi <= 8 && params.count(cap) && params[cap] > 0.0) {
    raw.meta["battery_capacity_mah"] = num(params[cap]);
    raw.meta["battery_capacity_source"] = cap + " parameter";
  }
  dataflashPosition(L, opt, raw);
  dataflashEvents(L, raw, copter);
  raw.meta["messages"] = std::to_string(L.messageCount());
  return assemble(std::move(raw), source, opt);
}

FlightLog readDataFlashLog(const std::string& path, const LogReadOptions& options) {
  return readDataFlashBytes(binary::readFileBytes(path, options.max_file_bytes), path, options);
}

}  // namespace wattswath::logs
