#pragma once
// What the flight-behaviour tests share: missions written in local metres and speed look-ups.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/flight.hpp"
#include "wattswath/mission/mission.hpp"

namespace wattswath::mission::testing {

/// Notes (or warnings) one per line, to search in with find().
inline std::string joined(const std::vector<std::string>& notes) {
  std::string all;
  for (const auto& n : notes) all += n + "\n";
  return all;
}

/// A mission in local metres: home at the origin of a frame, a take-off to the first waypoint's
/// height, an optional DO_CHANGE_SPEED (`speed` [m/s]), the waypoints as ENU offsets [m] with
/// MAVLink `command` (16 NAV_WAYPOINT, 82 NAV_SPLINE_WAYPOINT) and hold `hold_s` [s], and an RTL.
inline Mission localMission(const std::vector<Eigen::Vector3d>& wps, double hold_s = 0.0, double speed = 0.0, bool rtl = true,
                            int command = 16) {
  const wattswath::geometry::GeoPoint home{43.7, 10.4, 0.0};
  const wattswath::geometry::LocalFrame frame(home);
  Mission m;
  m.source = "test";
  m.home = home;
  m.home_known = true;
  int seq = 1;
  auto add = [&](int cmd, const Eigen::Vector3d& p, double p1 = 0.0, double p2 = 0.0, int frame_no = 3) {
    MissionItem it;
    it.seq = seq++;
    it.command = cmd;
    it.frame = frame_no;
    it.param[0] = p1;
    it.param[1] = p2;
    if (p.head<2>().norm() > 0.0 || cmd == 16 || cmd == 82) {
      const auto g = frame.toGeodetic({p.x(), p.y()});
      it.lat_deg = g.lat_deg;
      it.lon_deg = g.lon_deg;
    }
    it.alt_m = p.z();
    it.where = "test item " + std::to_string(it.seq);
    m.items.push_back(it);
  };
  add(22, {0, 0, wps.front().z()});
  if (speed > 0.0) add(178, {0, 0, 0}, 1.0, speed, 2);
  for (const auto& w : wps) add(command, w, hold_s);
  if (rtl) add(20, {0, 0, 0}, 0, 0, 2);
  return m;
}

/// [s] When `f` lifts off: its first airborne sample (after the spool-up and any throttle slew).
inline double liftoffTime(const FlownMission& f) {
  const auto up = std::find_if(f.samples.begin(), f.samples.end(), [](const FlightSample& s) { return s.airborne; });
  return up == f.samples.end() ? NAN : up->t;
}

/// [m/s] The lowest speed of `f` between `t0` and `t1` [s].
inline double minSpeedBetween(const FlownMission& f, double t0, double t1) {
  double v = 1e9;
  for (const auto& s : f.samples)
    if (s.t >= t0 && s.t <= t1) v = std::min(v, s.velocity.norm());
  return v;
}

/// [m/s] The highest horizontal speed of `f` between `t0` and `t1` [s].
inline double maxSpeedBetween(const FlownMission& f, double t0, double t1) {
  double v = 0.0;
  for (const auto& s : f.samples)
    if (s.t >= t0 && s.t <= t1) v = std::max(v, s.velocity.head<2>().norm());
  return v;
}

}  // namespace wattswath::mission::testing
