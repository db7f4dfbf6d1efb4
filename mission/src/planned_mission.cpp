#include "wattswath/mission/planned_mission.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wattswath::mission {
namespace {

using nlohmann::json;

// MAVLink numbers used in the mission (common.xml).
constexpr int kCmdWaypoint = 16;        // MAV_CMD_NAV_WAYPOINT
constexpr int kCmdReturnToLaunch = 20;  // MAV_CMD_NAV_RETURN_TO_LAUNCH
constexpr int kCmdTakeoff = 22;         // MAV_CMD_NAV_TAKEOFF
constexpr int kCmdChangeSpeed = 178;    // MAV_CMD_DO_CHANGE_SPEED
constexpr int kFrameGlobal = 0;         // MAV_FRAME_GLOBAL (home row of WPL files)
constexpr int kFrameMission = 2;        // MAV_FRAME_MISSION (commands without a position)
constexpr int kFrameRelativeAlt = 3;    // MAV_FRAME_GLOBAL_RELATIVE_ALT

/// One mission item before formatting.
struct Item {
  int command = 0;
  int frame = kFrameRelativeAlt;
  std::array<double, 7> params{};
};

void checkGeo(const GeoPoint& g, const std::string& what) {
  if (!std::isfinite(g.lat_deg) || g.lat_deg < -90.0 || g.lat_deg > 90.0)
    throw std::invalid_argument("mission: " + what + " latitude " + std::to_string(g.lat_deg) +
                                " deg is outside [-90, 90]");
  if (!std::isfinite(g.lon_deg) || g.lon_deg < -180.0 || g.lon_deg > 180.0)
    throw std::invalid_argument("mission: " + what + " longitude " + std::to_string(g.lon_deg) +
                                " deg is outside [-180, 180]");
}

void checkPositive(double v, const std::string& what) {
  if (!std::isfinite(v) || v <= 0.0)
    throw std::invalid_argument("mission: " + what + " = " + std::to_string(v) + " must be positive");
}

// The flight as MAVLink items: take-off, then per waypoint a speed change when its speed differs
// from the one in force (the caller decides what counts as a change: planner::missionWaypoints),
// then the waypoint; finally return to launch.
std::vector<Item> items(const PlannedMission& m) {
  validate(m);
  std::vector<Item> out;
  Item takeoff;
  takeoff.command = kCmdTakeoff;
  takeoff.params = {0, 0, 0, NAN, m.home.lat_deg, m.home.lon_deg, m.takeoff_altitude_m};
  out.push_back(takeoff);
  double current = -1.0;
  for (const auto& w : m.waypoints) {
    if (w.speed_mps != current) {
      Item s;
      s.command = kCmdChangeSpeed;
      s.frame = kFrameMission;
      s.params = {1 /* ground speed */, w.speed_mps, -1 /* throttle unchanged */, 0, 0, 0, 0};
      out.push_back(s);
      current = w.speed_mps;
    }
    Item wp;
    wp.command = kCmdWaypoint;
    wp.params = {0 /* hold */, 0, 0, NAN /* yaw unchanged */, w.position.lat_deg, w.position.lon_deg, w.altitude_m};
    out.push_back(wp);
  }
  Item rtl;
  rtl.command = kCmdReturnToLaunch;
  rtl.frame = kFrameMission;
  out.push_back(rtl);
  return out;
}

json jsonNumber(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string num(double v, int precision) {
  if (std::isnan(v)) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", precision, v);
  return buf;
}

std::string csvEscape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

}  // namespace

void validate(const PlannedMission& m) {
  checkGeo(m.home, "home");
  if (!std::isfinite(m.home_altitude_amsl_m))
    throw std::invalid_argument("mission: home_altitude_amsl_m is not finite");
  checkPositive(m.takeoff_altitude_m, "takeoff_altitude_m");
  checkPositive(m.cruise_speed_mps, "cruise_speed_mps");
  checkPositive(m.hover_speed_mps, "hover_speed_mps");
  if (m.waypoints.empty()) throw std::invalid_argument("mission: no waypoints (a mission needs at least one)");
  for (size_t i = 0; i < m.waypoints.size(); ++i) {
    const auto& w = m.waypoints[i];
    const std::string what = "waypoint " + std::to_string(i);
    checkGeo(w.position, what);
    checkPositive(w.speed_mps, what + " speed_mps");
    if (!std::isfinite(w.altitude_m) || w.altitude_m <= 0.0)
      throw std::invalid_argument("mission: " + what + " altitude_m = " + std::to_string(w.altitude_m) +
                                  " must be above home (> 0)");
  }
  for (size_t i = 0; i < m.no_fly.size(); ++i) {
    if (m.no_fly[i].size() < 3)
      throw std::invalid_argument("mission: no-fly polygon " + std::to_string(i) + " has " +
                                  std::to_string(m.no_fly[i].size()) + " vertices (at least 3 expected)");
    for (size_t k = 0; k < m.no_fly[i].size(); ++k)
      checkGeo(m.no_fly[i][k], "no-fly polygon " + std::to_string(i) + " vertex " + std::to_string(k));
  }
}

std::string toQgcPlan(const PlannedMission& m) {
  const auto list = items(m);
  json jitems = json::array();
  int jump_id = 1;
  for (const auto& it : list) {
    json params = json::array();
    for (double p : it.params) params.push_back(jsonNumber(p));
    json j = {{"autoContinue", true}, {"command", it.command}, {"doJumpId", jump_id++},
              {"frame", it.frame},     {"params", params},      {"type", "SimpleItem"}};
    if (it.command == kCmdWaypoint || it.command == kCmdTakeoff) {
      j["AMSLAltAboveTerrain"] = nullptr;
      j["Altitude"] = it.params[6];
      j["AltitudeMode"] = 1;  // relative to launch
    }
    jitems.push_back(j);
  }
  json polygons = json::array();
  for (const auto& poly : m.no_fly) {
    json ring = json::array();
    for (const auto& g : poly) ring.push_back({g.lat_deg, g.lon_deg});
    polygons.push_back({{"inclusion", false}, {"polygon", ring}, {"version", 1}});
  }
  json plan = {
      {"fileType", "Plan"},
      {"version", 1},
      {"groundStation", "QGroundControl"},
      {"mission",
       {{"version", 2},
        {"firmwareType", static_cast<int>(m.firmware)},
        {"vehicleType", 2},  // MAV_TYPE_QUADROTOR
        {"globalPlanAltitudeMode", 1},
        {"cruiseSpeed", m.cruise_speed_mps},
        {"hoverSpeed", m.hover_speed_mps},
        {"plannedHomePosition", {m.home.lat_deg, m.home.lon_deg, m.home_altitude_amsl_m}},
        {"items", jitems}}},
      {"geoFence", {{"version", 2}, {"circles", json::array()}, {"polygons", polygons}}},
      {"rallyPoints", {{"version", 2}, {"points", json::array()}}}};
  return plan.dump(4) + "\n";
}

std::string toQgcWpl(const PlannedMission& m) {
  const auto list = items(m);
  std::ostringstream o;
  o << "QGC WPL 110\n";
  // Row 0 is home, as QGroundControl and Mission Planner write it.
  o << "0\t1\t" << kFrameGlobal << "\t" << kCmdWaypoint << "\t0\t0\t0\t0\t" << num(m.home.lat_deg, 8) << "\t"
    << num(m.home.lon_deg, 8) << "\t" << num(m.home_altitude_amsl_m, 3) << "\t1\n";
  int index = 1;
  for (const auto& it : list) {
    o << index++ << "\t0\t" << it.frame << "\t" << it.command;
    for (int k = 0; k < 7; ++k) o << "\t" << num(it.params[k], k >= 4 && k <= 5 ? 8 : 3);
    o << "\t1\n";
  }
  return o.str();
}

std::vector<std::string> checkQgcPlan(const std::string& json_text) {
  std::vector<std::string> problems;
  json j;
  try {
    j = json::parse(json_text);
  } catch (const std::exception& e) {
    return {std::string("not JSON: ") + e.what()};
  }
  auto need = [&](const json& obj, const std::string& where, const std::string& key, json::value_t type) -> bool {
    if (!obj.is_object() || !obj.contains(key)) {
      problems.push_back(where + ": missing key '" + key + "'");
      return false;
    }
    const auto t = obj.at(key).type();
    const bool number_ok = (type == json::value_t::number_float) &&
                           (t == json::value_t::number_integer || t == json::value_t::number_unsigned ||
                            t == json::value_t::number_float);
    const bool int_ok = (type == json::value_t::number_integer) &&
                        (t == json::value_t::number_integer || t == json::value_t::number_unsigned);
    if (!(t == type || number_ok || int_ok)) {
      problems.push_back(where + ": key '" + key + "' has the wrong type");
      return false;
    }
    return true;
  };
  using vt = json::value_t;
  if (need(j, "plan", "fileType", vt::string) && j["fileType"] != "Plan") problems.push_back("plan: fileType must be \"Plan\"");
  if (need(j, "plan", "version", vt::number_integer) && j["version"] != 1) problems.push_back("plan: version must be 1");
  need(j, "plan", "groundStation", vt::string);
  if (need(j, "plan", "mission", vt::object)) {
    const auto& mi = j["mission"];
    if (need(mi, "mission", "version", vt::number_integer) && mi["version"] != 2)
      problems.push_back("mission: version must be 2");
    if (need(mi, "mission", "firmwareType", vt::number_integer)) {
      const int f = mi["firmwareType"];
      if (f != 0 && f != 3 && f != 12) problems.push_back("mission: firmwareType " + std::to_string(f) + " unknown");
    }
    // Optional in QGC's loader (MissionController::_loadJsonMissionFileV2), numbers when present.
    for (const char* k : {"vehicleType", "cruiseSpeed", "hoverSpeed"})
      if (mi.contains(k)) need(mi, "mission", k, std::string(k) == "vehicleType" ? vt::number_integer : vt::number_float);
    if (need(mi, "mission", "plannedHomePosition", vt::array) && mi["plannedHomePosition"].size() != 3)
      problems.push_back("mission: plannedHomePosition must be [lat, lon, alt]");
    if (need(mi, "mission", "items", vt::array)) {
      if (mi["items"].empty()) problems.push_back("mission: items must contain at least one item");
      int expected_id = 1;
      for (size_t i = 0; i < mi["items"].size(); ++i) {
        const auto& it = mi["items"][i];
        const std::string w = "mission item " + std::to_string(i);
        if (need(it, w, "type", vt::string) && it["type"] != "SimpleItem")
          problems.push_back(w + ": type must be \"SimpleItem\"");
        need(it, w, "frame", vt::number_integer);
        need(it, w, "command", vt::number_integer);
        need(it, w, "autoContinue", vt::boolean);
        if (need(it, w, "doJumpId", vt::number_integer) && it["doJumpId"] != expected_id)
          problems.push_back(w + ": doJumpId " + it["doJumpId"].dump() + ", expected " + std::to_string(expected_id));
        ++expected_id;
        if (need(it, w, "params", vt::array)) {
          if (it["params"].size() != 7) problems.push_back(w + ": params must hold 7 values");
          for (const auto& p : it["params"])
            if (!p.is_number() && !p.is_null()) problems.push_back(w + ": params must be numbers or null");
          if (it["params"].size() == 7 && (it["command"] == kCmdWaypoint || it["command"] == kCmdTakeoff)) {
            const auto& lat = it["params"][4];
            const auto& lon = it["params"][5];
            if (!lat.is_number() || !lon.is_number() || std::abs(lat.get<double>()) > 90.0 ||
                std::abs(lon.get<double>()) > 180.0)
              problems.push_back(w + ": latitude/longitude out of range");
          }
        }
      }
    }
  }
  if (j.contains("geoFence")) {
    const auto& g = j["geoFence"];
    if (need(g, "geoFence", "version", vt::number_integer) && g["version"] != 2)
      problems.push_back("geoFence: version must be 2");
    need(g, "geoFence", "circles", vt::array);
    if (need(g, "geoFence", "polygons", vt::array)) {
      for (size_t i = 0; i < g["polygons"].size(); ++i) {
        const auto& p = g["polygons"][i];
        const std::string w = "geoFence polygon " + std::to_string(i);
        need(p, w, "inclusion", vt::boolean);
        need(p, w, "version", vt::number_integer);
        if (need(p, w, "polygon", vt::array)) {
          if (p["polygon"].size() < 3) problems.push_back(w + ": fewer than 3 vertices");
          for (const auto& v : p["polygon"])
            if (!v.is_array() || v.size() != 2) problems.push_back(w + ": vertices must be [lat, lon]");
        }
      }
    }
  }
  if (j.contains("rallyPoints")) {
    const auto& r = j["rallyPoints"];
    if (need(r, "rallyPoints", "version", vt::number_integer) && r["version"] != 2)
      problems.push_back("rallyPoints: version must be 2");
    need(r, "rallyPoints", "points", vt::array);
  }
  return problems;
}

std::string toLegCsv(const std::vector<LegRecord>& legs) {
  std::ostringstream o;
  o << "leg,kind,role,start_lat_deg,start_lon_deg,end_lat_deg,end_lon_deg,length_m,speed_start_mps,"
       "speed_cruise_mps,speed_end_mps,time_s,energy_j\n";
  for (size_t i = 0; i < legs.size(); ++i) {
    const auto& l = legs[i];
    o << i << "," << csvEscape(l.kind) << "," << csvEscape(l.role) << "," << num(l.start.lat_deg, 8) << ","
      << num(l.start.lon_deg, 8) << "," << num(l.end.lat_deg, 8) << "," << num(l.end.lon_deg, 8) << ","
      << num(l.length_m, 3) << "," << num(l.speed_start_mps, 3) << "," << num(l.speed_cruise_mps, 3) << ","
      << num(l.speed_end_mps, 3) << "," << num(l.time_s, 3) << "," << num(l.energy_j, 2) << "\n";
  }
  return o.str();
}

}  // namespace wattswath::mission
