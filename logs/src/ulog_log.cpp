// PX4 ULog logs in: battery, local position and events extracted from the parsed log (ulog.cpp)
// and assembled into a FlightLog (autopilot_log.cpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "autopilot_log_internal.hpp"
#include "binary_read.hpp"
#include "mav_type.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/ulog.hpp"

namespace wattswath::logs {

using namespace detail;

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

// The value of the ULog info key `k`, empty when the log has none.
std::string infoValue(const ulog::Log& L, const std::string& k) {
  const auto it = L.info().find(k);
  return it == L.info().end() ? std::string() : it->second;
}

// Firmware (ver_sw_release, branch, git hash) and the file's facts: ULog version, start time,
// appended data, skipped gaps and dropouts.
void readFirmwareAndFacts(const ulog::Log& L, Raw& raw) {
  raw.firmware = "PX4 " + px4Version(infoValue(L, "ver_sw_release"));
  if (!infoValue(L, "ver_sw_branch").empty()) raw.firmware += ", branch " + infoValue(L, "ver_sw_branch");
  if (!infoValue(L, "ver_sw").empty()) raw.firmware += ", git " + infoValue(L, "ver_sw").substr(0, 12);
  raw.meta["ulog_version"] = std::to_string(L.version());
  raw.meta["ulog_start_s"] = num(static_cast<double>(L.startTimeUs()) * 1e-6, 10);
  if (L.appendedData()) raw.meta["appended_data"] = "yes";
  if (!L.gaps().empty()) {
    std::string g;
    for (const auto& x : L.gaps())
      g += (g.empty() ? "" : "; ") + std::string("byte offset ") + std::to_string(x.offset) + ", " + std::to_string(x.length) +
           " bytes" + (x.to_end ? " to the end of the file" : "") + " (" + x.reason + ")";
    raw.meta["gaps"] = std::to_string(L.gaps().size()) + " skipped: " + g;
  }
  if (L.dropouts().first) raw.meta["dropouts"] = std::to_string(L.dropouts().first) + " totalling " + num(L.dropouts().second) + " s";
}

// The vehicle: system type from vehicle_status, board from ver_hw, the system name.
void readVehicle(const ulog::Log& L, Raw& raw) {
  raw.vehicle.clear();
  if (!L.instances("vehicle_status").empty() && L.hasField("vehicle_status", "system_type")) {
    const auto st = L.column("vehicle_status", 0, "system_type");
    if (!st.empty()) raw.vehicle = mavTypeName(static_cast<int>(st.back()));
  }
  if (raw.vehicle.empty()) raw.vehicle = "unknown";
  if (!infoValue(L, "ver_hw").empty()) raw.vehicle += ", board " + infoValue(L, "ver_hw");
  if (!infoValue(L, "sys_name").empty()) raw.vehicle += ", " + infoValue(L, "sys_name");
}

// The battery: the first battery_status instance with a voltage (or the one asked for); samples not
// connected or without voltage are left out, a current of -1 (not measured) is read as NaN.
void readBattery(const ulog::Log& L, const std::string& source, const LogReadOptions& opt, Raw& raw) {
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
    bb.voltage_field = "battery_status[" + std::to_string(inst) + "].voltage_v";
    bb.current_field = "battery_status[" + std::to_string(inst) + "].current_a";
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
}

// The position: vehicle_local_position instance 0, NED turned to ENU; samples with xy_valid or
// z_valid false are left out.
void readPosition(const ulog::Log& L, const std::string& source, const LogReadOptions& opt, Raw& raw) {
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
    raw.position_message = lp + "[0]";
    raw.pos_fields = {"y", "x", "z"};  // ENU from NED
    raw.vel_fields = {"vy", "vx", "vz"};
    raw.acc_fields = {"ay", "ax", "az"};
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
      if (!la.empty()) setOrigin(raw, la.back(), lo.back(), al.back());
    }
  }
}

// Landed state, modes, arming, mission progress and logged strings, as events in time order.
void readEvents(const ulog::Log& L, Raw& raw) {
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
}

// The capacity of the battery used: BAT<n>_CAPACITY for battery_status instance n - 1 (PX4 1.12
// and later), else BAT_CAPACITY (earlier); -1, PX4's default, is "not set".
void readBatteryCapacity(const ulog::Log& L, Raw& raw) {
  const auto& p = L.parameters();
  for (const std::string& name : {"BAT" + std::to_string(raw.battery.instance + 1) + "_CAPACITY", std::string("BAT_CAPACITY")}) {
    const auto it = p.find(name);
    if (it == p.end()) continue;
    if (it->second > 0.0) {
      raw.meta["battery_capacity_mah"] = num(it->second);
      raw.meta["battery_capacity_source"] = name + " parameter";
    }
    return;
  }
}

}  // namespace

FlightLog readUlogBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& opt) {
  const auto L = ulog::Log::parse(std::move(bytes), source, opt.lenient);
  Raw raw;
  raw.format = "ulog";
  raw.warnings = L.warnings();
  readFirmwareAndFacts(L, raw);
  readVehicle(L, raw);
  readBattery(L, source, opt, raw);
  readBatteryCapacity(L, raw);
  readPosition(L, source, opt, raw);
  readEvents(L, raw);
  return assemble(std::move(raw), source, opt);
}

FlightLog readUlogLog(const std::string& path, const LogReadOptions& options) {
  return readUlogBytes(binary::readFileBytes(path, options.max_file_bytes), path, options);
}

}  // namespace wattswath::logs
