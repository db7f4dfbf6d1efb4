#include "wattswath/mission/planned_mission.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "wattswath/mission/files.hpp"

namespace wattswath::mission {
namespace {

using nlohmann::json;

// MAVLink numbers used in the mission (common.xml).
constexpr int kCmdWaypoint = 16;        // MAV_CMD_NAV_WAYPOINT
constexpr int kCmdReturnToLaunch = 20;  // MAV_CMD_NAV_RETURN_TO_LAUNCH
constexpr int kCmdTakeoff = 22;         // MAV_CMD_NAV_TAKEOFF
constexpr int kCmdChangeSpeed = 178;    // MAV_CMD_DO_CHANGE_SPEED
constexpr int kCmdCamTriggDist = 206;   // MAV_CMD_DO_SET_CAM_TRIGG_DIST
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

void checkNonNegative(double v, const std::string& what) {
  if (!std::isfinite(v) || v < 0.0)
    throw std::invalid_argument("mission: " + what + " = " + std::to_string(v) + " must be finite and >= 0");
}

void checkPolygon(const std::vector<GeoPoint>& poly, const std::string& what) {
  if (poly.size() < 3)
    throw std::invalid_argument("mission: " + what + " has " + std::to_string(poly.size()) +
                                " vertices (at least 3 expected)");
  for (size_t k = 0; k < poly.size(); ++k) checkGeo(poly[k], what + " vertex " + std::to_string(k));
}

json ringJson(const std::vector<GeoPoint>& poly, bool inclusion) {
  json ring = json::array();
  for (const auto& g : poly) ring.push_back({g.lat_deg, g.lon_deg});
  return {{"inclusion", inclusion}, {"polygon", ring}, {"version", 1}};
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
      // ArduCopter 4.1-4.4 drops the first DO item after the take-off when it changes the speed: the
      // first waypoint restarts the waypoint controller at WPNAV_SPEED (issue 21080); the repeat
      // runs after that restart.
      if (current < 0.0 && m.repeat_first_speed_change) out.push_back(s);
      current = w.speed_mps;
    }
    Item wp;
    wp.command = kCmdWaypoint;
    wp.params = {w.hold_s, w.acceptance_radius_m, 0, NAN /* yaw unchanged */, w.position.lat_deg, w.position.lon_deg, w.altitude_m};
    out.push_back(wp);
    if (w.camera_trigger_m) {
      // As QGC's survey (TransectStyleComplexItem::_appendCameraTriggerDistance): param3 1 takes one
      // photo at once, so each sweep's first and last footprints are photographed.
      Item cam;
      cam.command = kCmdCamTriggDist;
      cam.frame = kFrameMission;
      cam.params = {*w.camera_trigger_m, 0 /* shutter integration: ignore */, 1 /* trigger once now */, 0, 0, 0, 0};
      out.push_back(cam);
    }
  }
  Item rtl;
  rtl.command = kCmdReturnToLaunch;
  rtl.frame = kFrameMission;
  out.push_back(rtl);
  checkMissionItemCount(out.size());  // before either writer produces any text
  return out;
}

json jsonNumber(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// NaN as Mission Planner writes it (a yaw of NaN is "unchanged"; 0 would turn a PX4 vehicle north).
std::string num(double v, int precision) {
  if (std::isnan(v)) return "NaN";
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

std::optional<int> mavTypeOfRotors(int rotor_count) {
  switch (rotor_count) {
    case 3: return 15;  // MAV_TYPE_TRICOPTER
    case 4: return 2;   // MAV_TYPE_QUADROTOR
    case 6: return 13;  // MAV_TYPE_HEXAROTOR
    case 8: return 14;  // MAV_TYPE_OCTOROTOR
    default: return std::nullopt;
  }
}

int planSpeedField(double speed_mps) {
  if (!std::isfinite(speed_mps) || speed_mps <= 1.0) return 1;
  return static_cast<int>(std::min(std::lround(speed_mps), 1000L));
}

void validate(const PlannedMission& m) {
  checkGeo(m.home, "home");
  if (!std::isfinite(m.home_altitude_amsl_m))
    throw std::invalid_argument("mission: home_altitude_amsl_m is not finite");
  checkPositive(m.takeoff_altitude_m, "takeoff_altitude_m");
  checkPositive(m.cruise_speed_mps, "cruise_speed_mps");
  checkPositive(m.hover_speed_mps, "hover_speed_mps");
  if (m.vehicle_type != 2 && m.vehicle_type != 13 && m.vehicle_type != 14 && m.vehicle_type != 15)
    throw std::invalid_argument("mission: vehicle_type = " + std::to_string(m.vehicle_type) +
                                " is not a multirotor MAV_TYPE (2, 13, 14 or 15 expected)");
  if (m.waypoints.empty()) throw std::invalid_argument("mission: no waypoints (a mission needs at least one)");
  for (size_t i = 0; i < m.waypoints.size(); ++i) {
    const auto& w = m.waypoints[i];
    const std::string what = "waypoint " + std::to_string(i);
    checkGeo(w.position, what);
    checkPositive(w.speed_mps, what + " speed_mps");
    if (!std::isfinite(w.altitude_m) || w.altitude_m <= 0.0)
      throw std::invalid_argument("mission: " + what + " altitude_m = " + std::to_string(w.altitude_m) +
                                  " must be above home (> 0)");
    checkNonNegative(w.hold_s, what + " hold_s");
    checkNonNegative(w.acceptance_radius_m, what + " acceptance_radius_m");
    if (w.camera_trigger_m) checkNonNegative(*w.camera_trigger_m, what + " camera_trigger_m");
  }
  for (size_t i = 0; i < m.no_fly.size(); ++i) checkPolygon(m.no_fly[i], "no-fly polygon " + std::to_string(i));
  if (!m.fence_inclusion.empty()) checkPolygon(m.fence_inclusion, "inclusion fence");
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
  if (!m.fence_inclusion.empty()) polygons.push_back(ringJson(m.fence_inclusion, true));
  for (const auto& poly : m.no_fly) polygons.push_back(ringJson(poly, false));
  json plan = {
      {"fileType", "Plan"},
      {"version", 1},
      {"groundStation", "QGroundControl"},
      {"mission",
       {{"version", 2},
        {"firmwareType", static_cast<int>(m.firmware)},
        {"vehicleType", m.vehicle_type},
        {"globalPlanAltitudeMode", 1},
        {"cruiseSpeed", planSpeedField(m.cruise_speed_mps)},
        {"hoverSpeed", planSpeedField(m.hover_speed_mps)},
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

std::string toLegCsv(const std::vector<LegRecord>& legs) {
  std::ostringstream o;
  o << "leg,kind,role,start_lat_deg,start_lon_deg,end_lat_deg,end_lon_deg,length_m,speed_start_mps,"
       "speed_cruise_mps,speed_end_mps,time_s,energy_j\n";
  for (size_t i = 0; i < legs.size(); ++i) {
    const auto& l = legs[i];
    o << i + 1 << "," << csvEscape(l.kind) << "," << csvEscape(l.role) << "," << num(l.start.lat_deg, 8) << ","
      << num(l.start.lon_deg, 8) << "," << num(l.end.lat_deg, 8) << "," << num(l.end.lon_deg, 8) << ","
      << num(l.length_m, 3) << "," << num(l.speed_start_mps, 3) << "," << num(l.speed_cruise_mps, 3) << ","
      << num(l.speed_end_mps, 3) << "," << num(l.time_s, 3) << "," << num(l.energy_j, 2) << "\n";
  }
  return o.str();
}

}  // namespace wattswath::mission
