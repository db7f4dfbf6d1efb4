#include "wattswath/planner/mission_from_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wattswath::planner {
namespace {

namespace geo = wattswath::geometry;

/// Default cruise speed of a mission without waypoints [m/s] (validate() rejects it anyway).
constexpr double kDefaultCruise = 5.0;
/// Legs named one by one in the note on raised speeds, the rest counted.
constexpr size_t kLegsNamed = 8;

std::string fixed(double v, int precision) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", precision, v);
  return buf;
}

/// The note on legs planned below kMinCommandedSpeed (empty when there are none).
std::string slowLegsNote(const std::vector<int>& legs, double slowest) {
  if (legs.empty()) return {};
  std::string names;
  for (size_t k = 0; k < legs.size() && k < kLegsNamed; ++k) names += (k ? ", " : "") + std::to_string(legs[k]);
  if (legs.size() > kLegsNamed) names += " and " + std::to_string(legs.size() - kLegsNamed) + " more";
  return "mission: " + std::to_string(legs.size()) + " leg(s) planned slower than " + fixed(kMinCommandedSpeed, 1) +
         " m/s (leg " + names + "; slowest " + fixed(slowest, 2) + " m/s) are commanded at " +
         fixed(kMinCommandedSpeed, 1) +
         " m/s: ArduCopter ignores DO_CHANGE_SPEED below 1 m/s (3.x) or 0.2 m/s (4.x), so the speed flown "
         "there differs from the speed scored";
}

/// True when rings `a` and `b` have the same vertices within 1 mm (in any order).
bool sameRing(const geo::Ring& a, const geo::Ring& b) {
  if (a.size() != b.size()) return false;
  for (const auto& p : a)
    if (std::none_of(b.begin(), b.end(), [&](const geo::Point& q) { return (p - q).norm() < 1e-3; })) return false;
  return true;
}

/// The geofence [m]: every hole of the area (holes are no-fly zones) and each extra no-fly zone that
/// did not become a hole (one clipped by the boundary, or outside the area).
std::vector<geo::Ring> fenceOf(const SurveyProblem& problem) {
  std::vector<geo::Ring> fence = problem.area.holes;
  for (const auto& z : problem.no_fly)
    if (std::none_of(problem.area.holes.begin(), problem.area.holes.end(),
                     [&](const geo::Ring& h) { return sameRing(h, z); }))
      fence.push_back(z);
  return fence;
}

}  // namespace

MissionWaypoints missionWaypoints(const FlownPath& flown) {
  MissionWaypoints out;
  std::vector<int> slow_legs;
  double slowest = kMinCommandedSpeed, in_force = -1.0;
  const auto& legs = flown.path.legs;
  for (size_t i = 0; i < legs.size() && i < flown.speeds.cruise.size(); ++i) {
    const auto& leg = legs[i];
    if (leg.kind == geo::PrimitiveKind::TurnInPlace) continue;
    if (!out.waypoints.empty() && (leg.end - out.waypoints.back().position).norm() < kMinWaypointSpacing) continue;
    const double planned = flown.speeds.cruise[i];
    if (planned < kMinCommandedSpeed) {
      slow_legs.push_back(static_cast<int>(i));
      slowest = std::min(slowest, planned);
    }
    double speed = std::max(planned, kMinCommandedSpeed);
    if (in_force > 0.0 && std::abs(speed - in_force) <= kSpeedChangeTolerance) speed = in_force;
    in_force = speed;
    out.waypoints.push_back({leg.end, speed, planned, static_cast<int>(i)});
  }
  if (auto note = slowLegsNote(slow_legs, slowest); !note.empty()) out.notes.push_back(note);
  return out;
}

PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geo::LocalFrame& frame,
                            double home_altitude_amsl_m) {
  PlanMission pm;
  auto& m = pm.mission;
  m.home = frame.toGeodetic(problem.home);
  m.home_altitude_amsl_m = home_altitude_amsl_m;
  m.takeoff_altitude_m = problem.altitude;
  auto wps = missionWaypoints(flown);
  double fastest = 0.0;
  for (const auto& w : wps.waypoints) {
    m.waypoints.push_back({frame.toGeodetic(w.position), problem.altitude, w.speed_mps});
    fastest = std::max(fastest, std::max(w.planned_speed_mps, kMinCommandedSpeed));
  }
  m.cruise_speed_mps = fastest > 0.0 ? fastest : kDefaultCruise;
  m.hover_speed_mps = m.cruise_speed_mps;
  for (const auto& z : fenceOf(problem)) {
    std::vector<mission::GeoPoint> ring;
    for (const auto& p : z) ring.push_back(frame.toGeodetic(p));
    m.no_fly.push_back(ring);
  }
  pm.notes = std::move(wps.notes);
  return pm;
}

}  // namespace wattswath::planner
