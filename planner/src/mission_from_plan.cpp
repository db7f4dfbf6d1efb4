#include "wattswath/planner/mission_from_plan.hpp"

#include <algorithm>
#include <cmath>

namespace wattswath::planner {
namespace {

namespace geo = wattswath::geometry;

/// Default cruise speed of a mission without waypoints [m/s] (validate() rejects it anyway).
constexpr double kDefaultCruise = 5.0;

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

PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geo::LocalFrame& frame,
                            double home_altitude_amsl_m) {
  PlanMission pm;
  auto& m = pm.mission;
  m.home = frame.toGeodetic(problem.home);
  m.home_altitude_amsl_m = home_altitude_amsl_m;
  m.takeoff_altitude_m = problem.altitude;
  double fastest = 0.0;
  for (size_t i = 0; i < flown.path.legs.size(); ++i) {
    const auto& leg = flown.path.legs[i];
    if (leg.kind == geo::PrimitiveKind::TurnInPlace) continue;
    const double v = std::max(flown.speeds.cruise[i], 0.1);
    fastest = std::max(fastest, v);
    m.waypoints.push_back({frame.toGeodetic(leg.end), problem.altitude, v});
  }
  m.cruise_speed_mps = fastest > 0.0 ? fastest : kDefaultCruise;
  m.hover_speed_mps = m.cruise_speed_mps;
  for (const auto& z : fenceOf(problem)) {
    std::vector<mission::GeoPoint> ring;
    for (const auto& p : z) ring.push_back(frame.toGeodetic(p));
    m.no_fly.push_back(ring);
  }
  return pm;
}

}  // namespace wattswath::planner
