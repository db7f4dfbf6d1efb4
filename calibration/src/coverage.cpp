// What kind of flying a calibration saw, and whether a mission asks for the same kind.
#include "wattswath/calibration/coverage.hpp"

#include <algorithm>

#include "number_text.hpp"

namespace wattswath::calibration {
namespace {

using detail::num;

// [m/s] The horizontal speed the autopilot flies without a DO_CHANGE_SPEED.
double defaultSpeed(const mission::AutopilotConfig& ap) {
  if (ap.family == mission::AutopilotFamily::PX4) return ap.get("MPC_XY_CRUISE");
  return ap.get("WPNAV_SPEED") / 100.0;
}

}  // namespace

MissionKind missionKind(const std::vector<mission::NavStep>& steps, const mission::AutopilotConfig& autopilot) {
  MissionKind k;
  const double fallback = defaultSpeed(autopilot);
  const mission::NavStep* prev = nullptr;
  for (const auto& s : steps) {
    if (!mission::isFlownTo(s) || !s.has_position) {
      if (s.kind == mission::NavStep::Kind::Takeoff) prev = &s;
      continue;
    }
    (s.hold_s > 0.0 || s.kind == mission::NavStep::Kind::LoiterTime ? k.stop_waypoints : k.fast_waypoints) += 1;
    const bool moves = prev == nullptr || (s.target - prev->target).head<2>().norm() > 1.0;
    if (moves) {
      const double v = s.speed_xy > 0.0 ? s.speed_xy : fallback;
      k.speed_lo_mps = k.speed_lo_mps > 0.0 ? std::min(k.speed_lo_mps, v) : v;
      k.speed_hi_mps = std::max(k.speed_hi_mps, v);
    }
    prev = &s;
  }
  return k;
}

MissionKind combine(const MissionKind& a, const MissionKind& b) {
  MissionKind k;
  k.stop_waypoints = a.stop_waypoints + b.stop_waypoints;
  k.fast_waypoints = a.fast_waypoints + b.fast_waypoints;
  k.speed_hi_mps = std::max(a.speed_hi_mps, b.speed_hi_mps);
  k.speed_lo_mps = a.speed_lo_mps <= 0.0 ? b.speed_lo_mps : b.speed_lo_mps <= 0.0 ? a.speed_lo_mps : std::min(a.speed_lo_mps, b.speed_lo_mps);
  return k;
}

std::vector<std::string> outsideCalibration(const MissionKind& m, const MissionKind& c) {
  std::vector<std::string> why;
  if (m.stop_waypoints > 0 && c.stop_waypoints == 0) {
    why.push_back("this mission stops at " + std::to_string(m.stop_waypoints) +
                  " waypoint(s) with a hold time; the calibration flights had no such waypoint");
  }
  if (m.fast_waypoints > 0 && c.fast_waypoints == 0) {
    why.push_back("this mission flies through " + std::to_string(m.fast_waypoints) +
                  " waypoint(s) without a hold time; the calibration flights stopped at all of theirs");
  }
  if (c.speed_hi_mps > 0.0 && m.speed_hi_mps > 0.0 &&
      (m.speed_hi_mps > 1.1 * c.speed_hi_mps || m.speed_lo_mps < c.speed_lo_mps / 1.1)) {
    why.push_back("this mission commands " + num(m.speed_lo_mps) + " to " + num(m.speed_hi_mps) +
                  " m/s; the calibration flights " + num(c.speed_lo_mps) + " to " + num(c.speed_hi_mps) + " m/s");
  }
  return why;
}

}  // namespace wattswath::calibration
