#include "wattswath/logs/autopilot_log.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/logs/ulog.hpp"
#include "binary_read.hpp"
#include "mav_type.hpp"

namespace wattswath::logs {
namespace {

constexpr double kPi = 3.14159265358979323846;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string num(double x, int precision = 6) {
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

// One battery series.
struct Battery {
  std::string label;
  int instance = 0;
  std::vector<double> t, v, i;
};

// What a format-specific extractor hands to the common assembly.
struct Raw {
  std::string format, firmware, vehicle;
  Battery battery;
  std::vector<std::string> battery_others;  // other instances found, not used
  std::string position_source;
  std::vector<double> pt, yaw;
  std::vector<Eigen::Vector3d> pos, vel, acc;
  bool has_acc = false;
  std::vector<LandedChange> landed;
  std::string landed_source;
  std::vector<LogEvent> events;
  std::map<std::string, std::string> meta;
  std::vector<std::string> warnings;
};

double median(std::vector<double> x) {
  if (x.empty()) return kNaN;
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

double rateHz(const std::vector<double>& t) {
  std::vector<double> dt;
  for (std::size_t k = 1; k < t.size(); ++k) dt.push_back(t[k] - t[k - 1]);
  const double m = median(dt);
  return m > 0 ? 1.0 / m : kNaN;
}

// Compass heading [deg, clockwise from north] to ENU yaw [rad, counter-clockwise from east].
double headingDegToEnuYaw(double deg) { return std::remainder(kPi / 2 - deg * kPi / 180.0, 2 * kPi); }

// Keeps only the rows whose time strictly increases; returns how many were dropped.
template <typename... Cols>
std::size_t keepIncreasing(std::vector<double>& t, Cols&... cols) {
  std::vector<std::size_t> keep;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (std::isfinite(t[k]) && (keep.empty() || t[k] > t[keep.back()])) keep.push_back(k);
  const std::size_t dropped = t.size() - keep.size();
  auto select = [&](auto& v) {
    std::remove_reference_t<decltype(v)> out;
    out.reserve(keep.size());
    for (std::size_t k : keep) out.push_back(v[k]);
    v.swap(out);
  };
  select(t);
  (select(cols), ...);
  return dropped;
}

std::vector<double> unwrap(std::vector<double> a) {
  for (std::size_t k = 1; k < a.size(); ++k) {
    if (!std::isfinite(a[k]) || !std::isfinite(a[k - 1])) continue;
    a[k] = a[k - 1] + std::remainder(a[k] - a[k - 1], 2 * kPi);
  }
  return a;
}

// Acceleration from the position source's velocities at their native rate (log_io's smoothing).
std::vector<Eigen::Vector3d> accelerationFrom(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& v) {
  FlightLog tmp;
  for (std::size_t k = 0; k < t.size(); ++k) {
    LogSample s;
    s.t = t[k];
    s.velocity = v[k];
    tmp.samples.push_back(s);
  }
  deriveKinematics(tmp, false, true);
  std::vector<Eigen::Vector3d> a;
  for (const auto& s : tmp.samples) a.push_back(s.acceleration);
  return a;
}

FlightLog assemble(Raw raw, const std::string& source, const LogReadOptions& opt) {
  const std::string where = source + ": ";
  Battery& b = raw.battery;
  // Drop non-increasing times first: the interpolation below needs two position samples left.
  const std::size_t bd = keepIncreasing(b.t, b.v, b.i);
  const std::size_t pd = keepIncreasing(raw.pt, raw.pos, raw.vel, raw.acc, raw.yaw);
  auto dropped = [](std::size_t d) {
    return d ? ", " + std::to_string(d) + " more with non-increasing or non-finite time not used" : std::string();
  };
  if (b.t.size() < 2) {
    throw std::runtime_error(where + "fewer than two battery samples (" + std::to_string(b.t.size()) + dropped(bd) +
                             "; looked for " + raw.meta["battery_candidates"] + ")");
  }
  if (raw.pt.size() < 2) {
    throw std::runtime_error(where + "fewer than two position samples (" + std::to_string(raw.pt.size()) + dropped(pd) +
                             "; looked for " + raw.meta["position_candidates"] + ")");
  }
  if (bd) raw.warnings.push_back(std::to_string(bd) + " battery samples with non-increasing time not used");
  if (pd) raw.warnings.push_back(std::to_string(pd) + " position samples with non-increasing time not used");
  if (!raw.has_acc) raw.acc = accelerationFrom(raw.pt, raw.vel);
  const std::vector<double> yaw = unwrap(raw.yaw);

  FlightLog log;
  log.source = source;
  log.format = raw.format;
  log.velocity_derived = false;
  log.acceleration_derived = !raw.has_acc;
  std::size_t before = 0, after = 0;
  double max_gap = 0.0;
  std::size_t j = 0;
  for (std::size_t k = 0; k < b.t.size(); ++k) {
    const double t = b.t[k];
    if (t < raw.pt.front()) { ++before; continue; }
    if (t > raw.pt.back()) { ++after; continue; }
    while (j + 2 < raw.pt.size() && raw.pt[j + 1] < t) ++j;
    const double t0 = raw.pt[j], t1 = raw.pt[j + 1];
    const double w = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
    max_gap = std::max(max_gap, t1 - t0);
    LogSample s;
    s.t = t;
    s.position = (1 - w) * raw.pos[j] + w * raw.pos[j + 1];
    s.velocity = (1 - w) * raw.vel[j] + w * raw.vel[j + 1];
    s.acceleration = (1 - w) * raw.acc[j] + w * raw.acc[j + 1];
    s.yaw = std::remainder((1 - w) * yaw[j] + w * yaw[j + 1], 2 * kPi);
    s.voltage = b.v[k];
    s.current = b.i[k];
    s.power = s.voltage * s.current;
    log.samples.push_back(s);
  }
  log.airborne = detectAirborne(b.t, b.i, raw.landed, opt.airborne);
  log.events = std::move(raw.events);

  auto& m = log.metadata;
  m = raw.meta;
  m.erase("battery_candidates");
  m.erase("position_candidates");
  m["source_file"] = source;
  m["source_format"] = raw.format;
  m["firmware"] = raw.firmware;
  m["vehicle"] = raw.vehicle;
  m["battery_source"] = b.label;
  if (!raw.battery_others.empty()) {
    std::string o;
    for (const auto& s : raw.battery_others) o += (o.empty() ? "" : "; ") + s;
    m["battery_sources_not_used"] = o;
  }
  m["position_source"] = raw.position_source;
  m["battery_rate_hz"] = num(rateHz(b.t), 4);
  m["position_rate_hz"] = num(rateHz(raw.pt), 4);
  m["data_start_s"] = num(std::min(b.t.front(), raw.pt.front()), 10);
  m["data_end_s"] = num(std::max(b.t.back(), raw.pt.back()), 10);
  m["battery_samples_outside_position"] = std::to_string(before) + " before, " + std::to_string(after) + " after";
  m["position_max_gap_s"] = num(max_gap, 4);
  m["resampling"] = "battery sample times; position, velocity, acceleration, yaw linearly interpolated";
  m["frame"] = "ENU from the EKF origin (x east, y north, z up)";
  m["airborne_source"] = raw.landed.empty()
                             ? "current > " + num(opt.airborne.current_threshold_a) + " A"
                             : raw.landed_source + " (before the first: current > " +
                                   num(opt.airborne.current_threshold_a) + " A)";
  std::string w;
  for (const auto& s : raw.warnings) w += (w.empty() ? "" : " | ") + s;
  if (!w.empty()) m["warnings"] = w;
  if (log.samples.size() < 2)
    throw std::runtime_error(where + "battery and position data do not overlap in time (battery " +
                             num(b.t.front()) + "-" + num(b.t.back()) + " s, position " + num(raw.pt.front()) + "-" +
                             num(raw.pt.back()) + " s)");
  applyTimeWindow(log, opt);
  return log;
}

// ---------------------------------------------------------------- DataFlash

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
  for (const std::string name : {"BAT", "BAT2", "CURR", "CURR2"}) {
    if (!L.has(name, "Volt") || !L.has(name, "Curr") || !L.hasTime(name)) continue;
    const auto t = L.times(name);
    auto v = L.column(name, "Volt"), i = L.column(name, "Curr");
    std::string unit_note;
    const char vc = L.columnType(name, "Volt");
    if (vc == 'h' || vc == 'H' || vc == 'i' || vc == 'I') {  // ArduCopter <= 3.3: centivolts, centiamps
      for (double& x : v) x /= 100.0;
      for (double& x : i) x /= 100.0;
      unit_note = "; Volt/Curr integer centi-units divided by 100 (ArduPilot <= 3.3)";
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
      found.push_back(bb);
    }
  }
  raw.meta["battery_candidates"] = "BAT, BAT2, CURR, CURR2 with Volt and Curr";
  bool chosen = false;
  for (auto& bb : found) {
    const bool ok = opt.battery_instance >= 0 ? bb.instance == opt.battery_instance : median(bb.v) > 1.0;
    if (ok && !chosen) {
      raw.battery = bb;
      chosen = true;
    } else {
      raw.battery_others.push_back(bb.label + (median(bb.v) > 1.0 ? "" : ", no voltage"));
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
  raw.position_source = name + (L.has(name, "C") ? " core " + num(use_core) : "") +
                        " (PN, PE, PD, VN, VE, VD; NED from the EKF origin; acceleration: quadratic least-squares derivative of VN, VE, VD)";
}

void dataflashEvents(const dataflash::Log& L, Raw& raw, bool copter) {
  if (L.count("EV")) {
    if (L.hasTime("EV") && L.has("EV", "Id")) {
      const auto t = L.times("EV");
      const auto id = L.column("EV", "Id");
      for (std::size_t k = 0; k < t.size(); ++k) {
        const int e = static_cast<int>(id[k]);
        const std::string nm = logEventName(e);
        raw.events.push_back({t[k], "event", "EV " + std::to_string(e) + (nm.empty() ? "" : " " + nm)});
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
  std::stable_sort(raw.events.begin(), raw.events.end(), [](const LogEvent& a, const LogEvent& b) { return a.t < b.t; });
}

}  // namespace

FlightLog readDataFlashBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& opt) {
  const auto L = dataflash::Log::parse(std::move(bytes), source, opt.lenient);
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
  if (params.count("BATT_CAPACITY")) raw.meta["battery_capacity_mah"] = num(params["BATT_CAPACITY"]);
  if (L.has("ORGN", "Lat") && L.has("ORGN", "Lng")) {
    const auto lat = L.column("ORGN", "Lat"), lng = L.column("ORGN", "Lng");
    raw.meta["ekf_origin"] = num(lat.front(), 10) + ", " + num(lng.front(), 10);
  }
  dataflashBattery(L, opt, raw);
  dataflashPosition(L, opt, raw);
  dataflashEvents(L, raw, copter);
  raw.meta["messages"] = std::to_string(L.messageCount());
  return assemble(std::move(raw), source, opt);
}

FlightLog readDataFlashLog(const std::string& path, const LogReadOptions& options) {
  return readDataFlashBytes(binary::readFileBytes(path), path, options);
}

// ---------------------------------------------------------------- ULog

namespace {

std::string px4Version(const std::string& release) {
  if (release.empty()) return "";
  unsigned long v = 0;
  try { v = std::stoul(release); } catch (const std::exception&) { return ""; }
  const unsigned type = v & 0xFF;
  std::string kind = type == 0xFF ? "release" : type >= 192 ? "release candidate" : type >= 128 ? "beta" : type >= 64 ? "alpha" : "development";
  return "v" + std::to_string((v >> 24) & 0xFF) + "." + std::to_string((v >> 16) & 0xFF) + "." +
         std::to_string((v >> 8) & 0xFF) + " (" + kind + ")";
}

std::string navStateName(int s) {
  static const std::map<int, std::string> names = {{0, "MANUAL"}, {1, "ALTCTL"}, {2, "POSCTL"},
      {3, "AUTO_MISSION"}, {4, "AUTO_LOITER"}, {5, "AUTO_RTL"}, {10, "ACRO"}, {12, "DESCEND"},
      {13, "TERMINATION"}, {14, "OFFBOARD"}, {15, "STAB"}, {17, "AUTO_TAKEOFF"}, {18, "AUTO_LAND"},
      {19, "AUTO_FOLLOW_TARGET"}, {20, "AUTO_PRECLAND"}, {21, "ORBIT"}, {22, "AUTO_VTOL_TAKEOFF"}};
  auto it = names.find(s);
  return it == names.end() ? "nav_state" : it->second;
}

// Appends an event each time `field` of `topic` changes value.
void changes(const ulog::Log& L, const std::string& topic, const std::string& field, const std::string& kind,
             const std::function<std::string(int)>& text, Raw& raw) {
  if (L.instances(topic).empty() || !L.hasField(topic, field)) return;
  const auto t = L.times(topic, 0);
  const auto v = L.column(topic, 0, field);
  for (std::size_t k = 0; k < t.size(); ++k)
    if (k == 0 || v[k] != v[k - 1]) raw.events.push_back({t[k], kind, text(static_cast<int>(v[k]))});
}

}  // namespace

FlightLog readUlogBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& opt) {
  const auto L = ulog::Log::parse(std::move(bytes), source, opt.lenient);
  Raw raw;
  raw.format = "ulog";
  raw.warnings = L.warnings();
  const auto& info = L.info();
  auto infoOr = [&](const std::string& k) { auto it = info.find(k); return it == info.end() ? std::string() : it->second; };
  raw.firmware = "PX4 " + px4Version(infoOr("ver_sw_release"));
  if (!infoOr("ver_sw_branch").empty()) raw.firmware += ", branch " + infoOr("ver_sw_branch");
  if (!infoOr("ver_sw").empty()) raw.firmware += ", git " + infoOr("ver_sw").substr(0, 12);
  raw.meta["ulog_version"] = std::to_string(L.version());
  raw.meta["ulog_start_s"] = num(static_cast<double>(L.startTimeUs()) * 1e-6, 10);
  if (L.appendedData()) raw.meta["appended_data"] = "yes";
  if (L.dropouts().first) raw.meta["dropouts"] = std::to_string(L.dropouts().first) + " totalling " + num(L.dropouts().second) + " s";

  // Vehicle: system type from vehicle_status, board from ver_hw.
  raw.vehicle.clear();
  if (!L.instances("vehicle_status").empty() && L.hasField("vehicle_status", "system_type")) {
    const auto st = L.column("vehicle_status", 0, "system_type");
    if (!st.empty()) raw.vehicle = mavTypeName(static_cast<int>(st.back()));
  }
  if (raw.vehicle.empty()) raw.vehicle = "unknown";
  if (!infoOr("ver_hw").empty()) raw.vehicle += ", board " + infoOr("ver_hw");
  if (!infoOr("sys_name").empty()) raw.vehicle += ", " + infoOr("sys_name");

  // Battery.
  raw.meta["battery_candidates"] = "battery_status (voltage_v, current_a)";
  bool chosen = false;
  for (int inst : L.instances("battery_status")) {
    Battery bb;
    bb.instance = inst;
    const auto t = L.times("battery_status", inst);
    const auto v = L.column("battery_status", inst, "voltage_v");
    const auto i = L.column("battery_status", inst, "current_a");
    const bool has_conn = L.hasField("battery_status", "connected");
    const auto conn = has_conn ? L.column("battery_status", inst, "connected") : std::vector<double>(t.size(), 1.0);
    std::size_t skipped = 0, unmeasured = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (conn[k] == 0.0 || !(v[k] > 0.0)) { ++skipped; continue; }
      bb.t.push_back(t[k]);
      bb.v.push_back(v[k]);
      const bool no_current = i[k] == -1.0;
      unmeasured += no_current;
      bb.i.push_back(no_current ? kNaN : i[k]);
    }
    bb.label = "battery_status[" + std::to_string(inst) + "] (" + std::to_string(bb.t.size()) + " samples";
    if (skipped) bb.label += "; " + std::to_string(skipped) + " not connected or without voltage, not used";
    if (unmeasured) bb.label += "; " + std::to_string(unmeasured) + " with current_a = -1 (not measured) read as NaN";
    bb.label += ")";
    const bool ok = opt.battery_instance >= 0 ? inst == opt.battery_instance : (!bb.v.empty() && median(bb.v) > 1.0);
    if (ok && !chosen) {
      raw.battery = bb;
      chosen = true;
    } else {
      raw.battery_others.push_back(bb.label);
    }
  }
  if (!chosen && !raw.battery_others.empty())
    throw std::runtime_error(source + ": no usable battery_status instance (found: " + raw.battery_others.front() + ")");

  // Position: vehicle_local_position instance 0.
  raw.meta["position_candidates"] = "vehicle_local_position (x, y, z, vx, vy, vz)";
  const std::string lp = "vehicle_local_position";
  if (!opt.position_source.empty() && opt.position_source != lp)
    throw std::runtime_error(source + ": position source " + opt.position_source + " not supported for ULog (supported: " + lp + ")");
  if (!L.instances(lp).empty()) {
    const auto t = L.times(lp, 0);
    auto col = [&](const std::string& f) { return L.hasField(lp, f) ? L.column(lp, 0, f) : std::vector<double>(t.size(), kNaN); };
    const auto x = col("x"), y = col("y"), z = col("z"), vx = col("vx"), vy = col("vy"), vz = col("vz");
    const auto ax = col("ax"), ay = col("ay"), az = col("az");
    const auto heading = L.hasField(lp, "heading") ? col("heading") : col("yaw");
    const auto xyv = L.hasField(lp, "xy_valid") ? col("xy_valid") : std::vector<double>(t.size(), 1.0);
    const auto zv = L.hasField(lp, "z_valid") ? col("z_valid") : std::vector<double>(t.size(), 1.0);
    raw.has_acc = L.hasField(lp, "ax") && L.hasField(lp, "ay") && L.hasField(lp, "az");
    std::size_t invalid = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (xyv[k] == 0.0 || zv[k] == 0.0) { ++invalid; continue; }
      raw.pt.push_back(t[k]);
      raw.pos.emplace_back(y[k], x[k], -z[k]);
      raw.vel.emplace_back(vy[k], vx[k], -vz[k]);
      raw.acc.emplace_back(ay[k], ax[k], -az[k]);
      raw.yaw.push_back(std::remainder(kPi / 2 - heading[k], 2 * kPi));
    }
    raw.position_source = lp + "[0] (x, y, z, vx, vy, vz" + std::string(raw.has_acc ? ", ax, ay, az" : "") +
                          "; NED from the EKF reference)";
    if (invalid) {
      raw.warnings.push_back(std::to_string(invalid) + " of " + std::to_string(t.size()) + " " + lp +
                             " samples with xy_valid or z_valid false not used");
      if (raw.pt.size() < 2)
        throw std::runtime_error(source + ": " + lp + " has xy_valid or z_valid false in " + std::to_string(invalid) +
                                 " of " + std::to_string(t.size()) + " samples: no usable local position");
    }
    if (L.hasField(lp, "ref_lat") && L.hasField(lp, "ref_lon")) {
      const auto la = col("ref_lat"), lo = col("ref_lon"), al = col("ref_alt");
      if (!la.empty()) raw.meta["ekf_origin"] = num(la.back(), 10) + ", " + num(lo.back(), 10) + ", " + num(al.back(), 6) + " m";
    }
  }

  // Landed state, modes, arming, mission progress, logged strings.
  const std::string ld = "vehicle_land_detected";
  if (!L.instances(ld).empty() && L.hasField(ld, "landed")) {
    const auto t = L.times(ld, 0);
    const auto landed = L.column(ld, 0, "landed");
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (k > 0 && landed[k] == landed[k - 1]) continue;
      const bool on = landed[k] != 0.0;
      raw.landed.push_back({t[k], on, std::string("vehicle_land_detected.landed = ") + (on ? "true" : "false")});
      raw.events.push_back({t[k], "landed", on ? "landed" : "airborne"});
    }
    raw.landed_source = "vehicle_land_detected.landed";
  }
  changes(L, "vehicle_status", "nav_state", "mode", [](int s) { return navStateName(s) + " (" + std::to_string(s) + ")"; }, raw);
  changes(L, "vehicle_status", "arming_state", "event", [](int s) { return s == 2 ? std::string("armed") : "arming_state " + std::to_string(s); }, raw);
  changes(L, "mission_result", "seq_reached", "mission_item", [](int s) { return "mission item " + std::to_string(s) + " reached"; }, raw);
  if (!L.instances("mission").empty() && L.hasField("mission", "count")) {
    const auto c = L.column("mission", 0, "count");
    if (!c.empty()) raw.meta["mission_items"] = num(c.back());
  }
  for (const auto& s : L.strings()) raw.events.push_back({s.t, "message", s.text});
  std::stable_sort(raw.events.begin(), raw.events.end(), [](const LogEvent& a, const LogEvent& b) { return a.t < b.t; });
  return assemble(std::move(raw), source, opt);
}

FlightLog readUlogLog(const std::string& path, const LogReadOptions& options) {
  return readUlogBytes(binary::readFileBytes(path), path, options);
}

// ---------------------------------------------------------------- common

std::vector<TimeWindow> detectAirborne(const std::vector<double>& t, const std::vector<double>& current,
                                       const std::vector<LandedChange>& changes, const AirborneSettings& s) {
  std::vector<TimeWindow> raw;
  if (t.size() < 2 || current.size() != t.size()) return raw;
  const double t_end = t.back();
  std::vector<LandedChange> ch = changes;
  std::stable_sort(ch.begin(), ch.end(), [](const LandedChange& a, const LandedChange& b) { return a.t < b.t; });
  // Before the first change the current decides, unless that change is a take-off (then the
  // vehicle was on the ground before it).
  const double first_change = ch.empty() ? std::numeric_limits<double>::infinity()
                              : ch.front().landed ? ch.front().t : -std::numeric_limits<double>::infinity();
  // Current-based part, up to the first landed-state change.
  auto flying = [&](std::size_t k) { return std::isfinite(current[k]) && current[k] > s.current_threshold_a; };
  auto crossing = [&](std::size_t k) {  // time between samples k-1 and k where current crosses the threshold
    const double a = current[k - 1], b = current[k];
    if (!std::isfinite(a) || !std::isfinite(b) || a == b) return t[k];
    return t[k - 1] + (s.current_threshold_a - a) / (b - a) * (t[k] - t[k - 1]);
  };
  bool in = false;
  double start = 0.0;
  for (std::size_t k = 0; k < t.size() && t[k] < first_change; ++k) {
    const bool f = flying(k);
    if (f && !in) { in = true; start = k == 0 ? t[0] : crossing(k); }
    if (!f && in) { in = false; raw.push_back({start, crossing(k)}); }
  }
  if (in) raw.push_back({start, std::min(first_change, t_end)});
  // A first change that is a landing says the vehicle flew until then: the current-based window
  // that ended shortly before it (low current in the last metres of a descent) runs up to it.
  if (!ch.empty() && ch.front().landed && !raw.empty() && raw.back().end < first_change &&
      first_change - raw.back().end <= s.landing_extend_s)
    raw.back().end = first_change;
  // Event-based part.
  for (std::size_t k = 0; k < ch.size(); ++k) {
    if (ch[k].landed) continue;
    std::size_t m = k + 1;
    while (m < ch.size() && !ch[m].landed) ++m;
    const double end = m < ch.size() ? ch[m].t : t_end;
    raw.push_back({std::max(ch[k].t, t.front()), std::min(end, t_end)});
    k = m == ch.size() ? m : m - 1;
  }
  // A landing event ends a window the current opened before it.
  std::sort(raw.begin(), raw.end(), [](const TimeWindow& a, const TimeWindow& b) { return a.begin < b.begin; });
  std::vector<TimeWindow> merged;
  for (const auto& w : raw) {
    if (w.end <= w.begin) continue;
    if (!merged.empty() && w.begin - merged.back().end < s.merge_gap_s) merged.back().end = std::max(merged.back().end, w.end);
    else merged.push_back(w);
  }
  std::vector<TimeWindow> out;
  for (const auto& w : merged)
    if (w.end - w.begin >= s.min_duration_s) out.push_back(w);
  return out;
}

void applyTimeWindow(FlightLog& log, const LogReadOptions& opt) {
  double from = opt.from_s, to = opt.to_s;
  if (std::isnan(from) || std::isnan(to) || from > to)
    throw std::invalid_argument(log.source + ": time window from " + num(from) + " s to " + num(to) + " s is empty or invalid");
  if (opt.airborne_only) {
    if (log.airborne.empty()) throw std::runtime_error(log.source + ": --airborne: no airborne window found");
    from = std::max(from, log.airborne.front().begin);
    to = std::min(to, log.airborne.back().end);
  }
  if (std::isinf(from) && std::isinf(to) && !opt.airborne_only) return;
  const double span0 = log.samples.empty() ? kNaN : log.samples.front().t, span1 = log.samples.empty() ? kNaN : log.samples.back().t;
  std::vector<LogSample> kept;
  std::vector<std::vector<std::string>> extra;
  for (std::size_t k = 0; k < log.samples.size(); ++k) {
    if (log.samples[k].t < from || log.samples[k].t > to) continue;
    kept.push_back(log.samples[k]);
    if (k < log.extra_values.size()) extra.push_back(log.extra_values[k]);
  }
  if (kept.size() < 2)
    throw std::runtime_error(log.source + ": " + std::to_string(kept.size()) + " samples in the window " + num(from) + " s to " +
                             num(to) + " s (data span " + num(span0) + " s to " + num(span1) + " s); need at least 2");
  log.samples.swap(kept);
  if (!log.extra_values.empty()) log.extra_values.swap(extra);
  std::vector<TimeWindow> air;
  for (auto w : log.airborne) {
    w.begin = std::max(w.begin, from);
    w.end = std::min(w.end, to);
    if (w.end > w.begin) air.push_back(w);
  }
  log.airborne.swap(air);
  std::vector<LogEvent> ev;
  for (const auto& e : log.events)
    if (e.t >= from && e.t <= to) ev.push_back(e);
  log.events.swap(ev);
  log.metadata["window"] = num(log.samples.front().t, 10) + " s to " + num(log.samples.back().t, 10) + " s" +
                           (opt.airborne_only ? " (airborne part)" : "");
}

LogFormat detectLogFormat(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  char head[7] = {};
  in.read(head, sizeof head);
  const auto n = in.gcount();
  if (n >= 7 && std::string(head, 4) == "ULog" && static_cast<unsigned char>(head[4]) == 0x01 &&
      static_cast<unsigned char>(head[5]) == 0x12 && static_cast<unsigned char>(head[6]) == 0x35)
    return LogFormat::Ulog;
  if (n >= 2 && static_cast<unsigned char>(head[0]) == 0xA3 && static_cast<unsigned char>(head[1]) == 0x95)
    return LogFormat::DataFlash;
  return LogFormat::Csv;
}

FlightLog readFlightLog(const std::string& path, const LogReadOptions& options) {
  switch (detectLogFormat(path)) {
    case LogFormat::Ulog: return readUlogLog(path, options);
    case LogFormat::DataFlash: return readDataFlashLog(path, options);
    case LogFormat::Csv: break;
  }
  FlightLog log = readCsvLog(path);
  if (log.airborne.empty()) {
    std::vector<double> t, i;
    for (const auto& s : log.samples) {
      t.push_back(s.t);
      i.push_back(s.current);
    }
    log.airborne = detectAirborne(t, i, {}, options.airborne);
  }
  applyTimeWindow(log, options);
  return log;
}

}  // namespace wattswath::logs
