#include "wattswath/planner/mission_from_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "wattswath/geometry/clearance.hpp"
#include "wattswath/planner/camera.hpp"
#include "wattswath/planner/margin.hpp"

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
         " m/s, the least speed the written missions command whatever the autopilot (ArduCopter ignores "
         "DO_CHANGE_SPEED below 1 m/s in 3.x, 0.2 m/s in 4.x), so the speed flown there differs from the speed scored";
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

/// Throws std::invalid_argument naming the field of `o` out of range.
void validate(const MissionOptions& o) {
  auto bad = [](const std::string& field, double v, const std::string& range) {
    throw std::invalid_argument("MissionOptions." + field + " = " + std::to_string(v) + " is outside " + range);
  };
  if (!(o.trigger_distance_m >= 0.0 && std::isfinite(o.trigger_distance_m))) bad("trigger_distance_m", o.trigger_distance_m, "[0, inf)");
  if (!(o.stop_hold_s >= 0.0 && o.stop_hold_s <= 3600.0)) bad("stop_hold_s", o.stop_hold_s, "[0, 3600]");
  if (!(o.fence_margin_m >= 0.0 && o.fence_margin_m <= 1000.0)) bad("fence_margin_m", o.fence_margin_m, "[0, 1000]");
  if (!(o.no_fly_margin_m >= 0.0 && o.no_fly_margin_m <= 1000.0)) bad("no_fly_margin_m", o.no_fly_margin_m, "[0, 1000]");
}

/// The waypoints as they are written, with the speed in force and the legs planned too slow.
struct Builder {
  MissionWaypoints out;
  std::vector<int> slow_legs;
  double slowest = kMinCommandedSpeed;
  double in_force = -1.0;  // [m/s] speed commanded so far (-1: none yet)

  /// A waypoint at `at` [m] ending leg `leg`, planned at `planned` [m/s]: commanded at least at
  /// kMinCommandedSpeed, at the speed in force when within kSpeedChangeTolerance of it.
  void add(const geo::Point& at, double planned, int leg) {
    if (planned < kMinCommandedSpeed && leg >= 0) {
      slow_legs.push_back(leg);
      slowest = std::min(slowest, planned);
    }
    double speed = std::max(planned, kMinCommandedSpeed);
    if (in_force > 0.0 && std::abs(speed - in_force) <= kSpeedChangeTolerance) speed = in_force;
    in_force = speed;
    MissionWaypoint w;
    w.position = at;
    w.speed_mps = speed;
    w.planned_speed_mps = planned;
    w.leg = leg;
    out.waypoints.push_back(w);
  }
};

/// The points strictly inside arc `leg` at which it is cut into chords that each stay within
/// kArcChordSagitta of the arc (none when the whole chord does).
std::vector<geo::Point> arcWaypoints(const geo::PathLeg& leg) {
  const double r = leg.radius, turn = std::abs(leg.turn_angle);
  if (!(r > kArcChordSagitta) || !(turn > 0.0)) return {};
  const double max_step = 2.0 * std::acos(1.0 - kArcChordSagitta / r);  // [rad] chord angle at the sagitta
  const int n = static_cast<int>(std::ceil(turn / max_step - 1e-9));
  std::vector<geo::Point> out;
  const geo::Point v0 = leg.start - leg.center;
  for (int k = 1; k < n; ++k) {
    const double a = leg.turn_angle * k / n;
    out.push_back(leg.center + geo::Point(std::cos(a) * v0.x() - std::sin(a) * v0.y(), std::sin(a) * v0.x() + std::cos(a) * v0.y()));
  }
  return out;
}

/// Camera runs, their length and photos as the written commands make them: from a waypoint that
/// switches the camera on to the next that switches it off, along the flown legs between them.
void countPhotos(const FlownPath& flown, double trigger_m, MissionWaypoints& out) {
  bool on = false;
  int from = -1;
  for (const auto& w : out.waypoints) {
    if (!w.camera_trigger_m) continue;
    if (*w.camera_trigger_m > 0.0 && !on) {
      on = true;
      from = w.leg;
    } else if (*w.camera_trigger_m == 0.0 && on) {
      on = false;
      double length = 0.0;
      for (int i = from + 1; i <= w.leg; ++i) {
        length += flown.path.legs[static_cast<size_t>(i)].length();
        out.camera_legs.push_back(i);
      }
      ++out.camera_runs;
      out.photos += photosAlong(length, trigger_m);
      out.camera_length_m += length;
    }
  }
}

/// Notes on the straight legs home -> waypoints -> home that come within `margin` [m] of a zone of
/// `problem` (the path keeps the margin; a chord of an arc may not); returns how many do.
int checkWaypointLegs(const MissionWaypoints& wps, const SurveyProblem& problem, double margin,
                      std::vector<std::string>& notes) {
  geo::CoveragePath legs;
  geo::Point from = problem.home;
  for (const auto& w : wps.waypoints) {
    geo::PathLeg l;
    l.start = from;
    l.end = from = w.position;
    legs.legs.push_back(l);
  }
  const auto close = geo::marginViolations(legs, noFlyZones(problem), margin);
  for (size_t k = 0; k < close.size() && k < kLegsNamed; ++k)
    notes.push_back("mission: the straight leg into waypoint " + std::to_string(close[k].leg + 1) + " (of " +
                    std::to_string(wps.waypoints.size()) + ") passes " +
                    fixed(close[k].distance_m, 2) + " m from no-fly zone " + std::to_string(close[k].zone) + ", within the " +
                    fixed(margin, 1) + " m margin the planned path keeps (an arc written as its chord)");
  return static_cast<int>(close.size());
}

}  // namespace

MissionWaypoints missionWaypoints(const FlownPath& flown, const MissionOptions& options) {
  validate(options);
  Builder b;
  const bool camera = options.trigger_distance_m > 0.0;
  bool camera_on = false;
  size_t on_at = 0;                    // the waypoint where the camera was last turned on
  std::optional<double> before_on;     // its command before that (an "off" of the run before)
  const auto& legs = flown.path.legs;
  const auto& junction = flown.speeds.junction;
  for (size_t i = 0; i < legs.size() && i < flown.speeds.cruise.size(); ++i) {
    const auto& leg = legs[i];
    const double planned = flown.speeds.cruise[i];
    if (camera && leg.kind != geo::PrimitiveKind::TurnInPlace) {  // a turn in place takes no photo, ends no run
      const bool sweep = leg.role == geo::LegRole::Sweep;
      if (sweep && !camera_on) {
        if (b.out.waypoints.empty()) b.add(leg.start, planned, -1);  // a sweep from home: camera on at its start
        on_at = b.out.waypoints.size() - 1;
        before_on = b.out.waypoints.back().camera_trigger_m;
        b.out.waypoints.back().camera_trigger_m = options.trigger_distance_m;
      } else if (!sweep && camera_on) {
        // A run whose sweep was merged into the waypoint that turned the camera on (a stub under
        // kMinWaypointSpacing) flies nowhere: that waypoint gets back the command it had (an "off"
        // ending the run before, or none), not "on" overwritten by "off", which left a stray "off"
        // and an uncounted photo.
        if (on_at == b.out.waypoints.size() - 1) b.out.waypoints.back().camera_trigger_m = before_on;
        else b.out.waypoints.back().camera_trigger_m = 0.0;
      }
      camera_on = sweep;
    }
    if (options.arc_waypoints && leg.kind == geo::PrimitiveKind::Arc) {  // densified: every chord within kArcChordSagitta of the arc
      for (const auto& p : arcWaypoints(leg))
        if (b.out.waypoints.empty() || (p - b.out.waypoints.back().position).norm() >= kMinWaypointSpacing) b.add(p, planned, -1);
    }
    const bool merged = !b.out.waypoints.empty() && (leg.end - b.out.waypoints.back().position).norm() < kMinWaypointSpacing;
    if (leg.kind != geo::PrimitiveKind::TurnInPlace && !merged) b.add(leg.end, planned, static_cast<int>(i));
    const bool stops = i + 1 < junction.size() && junction[i + 1] < kStopSpeed;
    if (stops && options.stop_hold_s > 0.0 && !b.out.waypoints.empty()) b.out.waypoints.back().hold_s = options.stop_hold_s;
  }
  auto& out = b.out;
  if (options.speeds_a_waypoint_early) {  // in order: waypoint i + 1 still holds its own planned command
    // The command with waypoint i is flown on leg i (an autopilot that changes speed at once) or on
    // leg i + 1 (ArduCopter 3.x, a waypoint late): where only one of the two takes photos it is held
    // at that leg's own speed, so the camera leg is never flown faster than planned either way (a
    // sortie's last sweep was flown at its transit home's 10.5 m/s where the trigger interval capped
    // the sweeps at 5.25: a photo every 21 m for 10.5 m).
    bool photos = false;  // the camera is on along the leg into waypoint i
    for (size_t i = 0; i + 1 < out.waypoints.size(); ++i) {
      const bool into_photos = photos;
      if (out.waypoints[i].camera_trigger_m) photos = *out.waypoints[i].camera_trigger_m > 0.0;
      const double own = out.waypoints[i].speed_mps, next = out.waypoints[i + 1].speed_mps;
      double early = std::max(own, next);
      if (into_photos && !photos) early = std::min(early, own);
      if (!into_photos && photos) early = std::min(early, next);
      out.waypoints[i].speed_mps = early;
    }
  }
  if (camera_on) out.waypoints.back().camera_trigger_m = 0.0;
  if (!out.waypoints.empty()) out.waypoints.back().hold_s = 0.0;  // the return to launch stops there anyway
  for (const auto& w : out.waypoints) out.holds += w.hold_s > 0.0;
  if (camera) countPhotos(flown, options.trigger_distance_m, out);
  if (auto note = slowLegsNote(b.slow_legs, b.slowest); !note.empty()) out.notes.push_back(note);
  return out;
}

PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geo::LocalFrame& frame,
                            double home_altitude_amsl_m, const MissionOptions& options) {
  PlanMission pm;
  auto& m = pm.mission;
  m.home = frame.toGeodetic(problem.home);
  m.home_altitude_amsl_m = home_altitude_amsl_m;
  m.takeoff_altitude_m = problem.altitude;
  m.firmware = options.firmware;
  m.repeat_first_speed_change = options.repeat_first_speed_change;
  auto wps = missionWaypoints(flown, options);
  double fastest = 0.0;
  const double acceptance = options.firmware == mission::Firmware::PX4 ? kPx4AcceptanceRadius : 0.0;
  for (const auto& w : wps.waypoints) {
    m.waypoints.push_back({frame.toGeodetic(w.position), problem.altitude, w.speed_mps, w.hold_s, w.camera_trigger_m, acceptance});
    fastest = std::max(fastest, std::max(w.planned_speed_mps, kMinCommandedSpeed));
  }
  m.cruise_speed_mps = fastest > 0.0 ? fastest : kDefaultCruise;
  m.hover_speed_mps = m.cruise_speed_mps;
  if (const auto type = mission::mavTypeOfRotors(options.rotor_count)) {
    m.vehicle_type = *type;
  } else {
    wps.notes.push_back("mission: no MAVLink vehicle type for " + std::to_string(options.rotor_count) +
                        " rotors (3, 4, 6 and 8 have one): vehicleType written as a quadrotor (2)");
  }
  for (const auto& z : fenceOf(problem)) {
    std::vector<mission::GeoPoint> ring;
    for (const auto& p : z) ring.push_back(frame.toGeodetic(p));
    m.no_fly.push_back(ring);
  }
  if (options.fence_margin_m > 0.0) {
    const auto fence = inclusionFence(problem, flown.path, options.fence_margin_m);
    for (const auto& p : fence.ring) m.fence_inclusion.push_back(frame.toGeodetic(p));
    pm.fence_distance_m = fence.distance_m;
  }
  if (options.no_fly_margin_m > 0.0) pm.legs_within_margin = checkWaypointLegs(wps, problem, options.no_fly_margin_m, wps.notes);
  pm.notes = std::move(wps.notes);
  pm.holds = wps.holds;
  pm.camera_runs = wps.camera_runs;
  pm.photos = wps.photos;
  pm.camera_length_m = wps.camera_length_m;
  pm.camera_legs = std::move(wps.camera_legs);
  return pm;
}

}  // namespace wattswath::planner
