// What kind of flying a calibration saw, and whether a mission asks for the same kind.
#include "wattswath/calibration/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "number_text.hpp"

namespace wattswath::calibration {
namespace {

using detail::num;

// [m/s] The horizontal speed the autopilot flies without a DO_CHANGE_SPEED.
double defaultSpeed(const mission::AutopilotConfig& ap) {
  if (ap.family == mission::AutopilotFamily::PX4) return ap.get("MPC_XY_CRUISE");
  return ap.get("WPNAV_SPEED") / 100.0;
}

// A length [m] as a pilot reads it: whole metres from 10 m up, else to a decimetre.
std::string metres(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, m >= 10.0 ? "%.0f" : "%.1f", m);
  return buf;
}

// The lower of two positive values, 0 meaning "none".
double lowest(double a, double b) { return a <= 0.0 ? b : b <= 0.0 ? a : std::min(a, b); }

}  // namespace

MissionKind missionKind(const std::vector<mission::NavStep>& steps, const mission::AutopilotConfig& autopilot) {
  MissionKind k;
  const double fallback = defaultSpeed(autopilot);
  const mission::NavStep* prev = nullptr;
  std::vector<const mission::NavStep*> corners;  // the flown-to waypoints after a horizontal leg, in order
  std::vector<Eigen::Vector2d> headings;         // the horizontal direction of the leg into each
  std::vector<const mission::NavStep*> froms;    // where that leg starts
  std::vector<double> legs;                      // [m] the horizontal legs' lengths
  k.circles = static_cast<int>(std::count_if(steps.begin(), steps.end(), [](const mission::NavStep& s) {
    return s.kind == mission::NavStep::Kind::LoiterTurns;
  }));
  for (const auto& s : steps) {
    if (!mission::isFlownTo(s) || !s.has_position) {
      if (s.kind == mission::NavStep::Kind::Takeoff) prev = &s;
      continue;
    }
    (s.hold_s > 0.0 || s.kind == mission::NavStep::Kind::LoiterTime ? k.stop_waypoints : k.fast_waypoints) += 1;
    const Eigen::Vector2d d = prev ? Eigen::Vector2d((s.target - prev->target).head<2>()) : Eigen::Vector2d::Zero();
    const bool moves = prev == nullptr || d.norm() > 1.0;
    if (moves) {
      const double v = s.speed_xy > 0.0 ? s.speed_xy : fallback;
      k.speed_lo_mps = k.speed_lo_mps > 0.0 ? std::min(k.speed_lo_mps, v) : v;
      k.speed_hi_mps = std::max(k.speed_hi_mps, v);
    }
    if (prev != nullptr && d.norm() > 1.0) {
      legs.push_back(d.norm());
      corners.push_back(&s);
      headings.push_back(d.normalized());
      froms.push_back(prev);
    }
    if (prev != nullptr && prev->kind != mission::NavStep::Kind::Takeoff)
      k.climb_hi_m = std::max(k.climb_hi_m, std::abs(s.target.z() - prev->target.z()));
    prev = &s;
  }
  if (!legs.empty()) {
    std::nth_element(legs.begin(), legs.begin() + static_cast<long>(legs.size() / 2), legs.end());
    k.leg_lo_m = k.leg_hi_m = legs[legs.size() / 2];
  }
  // A turn is taken at a waypoint without a hold time between two horizontal legs.
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const mission::NavStep& c = *corners[i];
    if (c.hold_s > 0.0 || c.kind == mission::NavStep::Kind::LoiterTime) continue;
    if (froms[i + 1] != &c) continue;  // something was flown to in between (a climb on the spot)
    const double cosine = std::clamp(headings[i].dot(headings[i + 1]), -1.0, 1.0);
    k.turn_hi_deg = std::max(k.turn_hi_deg, std::acos(cosine) * 180.0 / M_PI);
  }
  return k;
}

MissionKind combine(const MissionKind& a, const MissionKind& b) {
  MissionKind k;
  k.stop_waypoints = a.stop_waypoints + b.stop_waypoints;
  k.fast_waypoints = a.fast_waypoints + b.fast_waypoints;
  k.speed_hi_mps = std::max(a.speed_hi_mps, b.speed_hi_mps);
  k.speed_lo_mps = lowest(a.speed_lo_mps, b.speed_lo_mps);
  k.leg_lo_m = lowest(a.leg_lo_m, b.leg_lo_m);
  k.leg_hi_m = std::max(a.leg_hi_m, b.leg_hi_m);
  k.turn_hi_deg = std::max(a.turn_hi_deg, b.turn_hi_deg);
  k.climb_hi_m = std::max(a.climb_hi_m, b.climb_hi_m);
  k.circles = a.circles < 0 || b.circles < 0 ? std::max(a.circles, b.circles) : a.circles + b.circles;
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
  if (m.leg_lo_m > 0.0 && c.leg_lo_m > 0.0 && m.leg_lo_m < 0.5 * c.leg_lo_m) {
    why.push_back("this mission's median leg is " + metres(m.leg_lo_m) + " m; the calibration flights' " + metres(c.leg_lo_m) +
                  " m or more (a short leg is flown accelerating and braking)");
  }
  if (m.turn_hi_deg >= 0.0 && c.turn_hi_deg >= 0.0 && m.turn_hi_deg > c.turn_hi_deg + 20.0) {
    why.push_back("this mission turns by up to " + metres(std::round(m.turn_hi_deg)) +
                  " deg at waypoints without a hold time; the calibration flights by up to " + metres(std::round(c.turn_hi_deg)) +
                  " deg");
  }
  if (m.climb_hi_m >= 0.0 && c.climb_hi_m >= 0.0 && m.climb_hi_m > std::max(2.0 * c.climb_hi_m, c.climb_hi_m + 5.0)) {
    why.push_back("this mission's legs change height by up to " + metres(m.climb_hi_m) + " m; the calibration flights' by up to " +
                  metres(c.climb_hi_m) + " m");
  }
  if (m.circles > 0 && c.circles == 0) {
    why.push_back("this mission circles " + std::to_string(m.circles) +
                  " time(s) (NAV_LOITER_TURNS); the calibration flights did not circle");
  }
  return why;
}

}  // namespace wattswath::calibration
