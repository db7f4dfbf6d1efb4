// Dispatch to the behaviour model of the autopilot's family, and the flown trajectory as pieces.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "flight_internal.hpp"

namespace wattswath::mission {

FlownMission flyArduCopterSCurve(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s);
FlownMission flyArduCopterLeash(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s);
FlownMission flyPx4(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s);

namespace {

void validate(const FlightSettings& s) {
  if (!(s.dt >= 0.001 && s.dt <= 0.05)) throw std::invalid_argument("FlightSettings.dt = " + std::to_string(s.dt) + " s, expected 0.001..0.05");
  if (!(s.sample_dt >= s.dt && s.sample_dt <= 1.0)) {
    throw std::invalid_argument("FlightSettings.sample_dt = " + std::to_string(s.sample_dt) + " s, expected dt..1");
  }
  if (!(s.max_time_s > 0.0)) throw std::invalid_argument("FlightSettings.max_time_s must be > 0");
  if (!(s.landed_detect_s >= 0.0 && s.landed_detect_s <= 60.0)) {
    throw std::invalid_argument("FlightSettings.landed_detect_s = " + std::to_string(s.landed_detect_s) + " s, expected 0..60");
  }
  const Airframe& a = s.airframe;
  if (!(a.drag_linear_per_s >= 0.0 && a.drag_linear_per_s <= 10.0) || !(a.drag_quadratic_per_m >= 0.0 && a.drag_quadratic_per_m <= 1.0) ||
      (a.response_s && !(*a.response_s >= 0.0 && *a.response_s <= 2.0))) {
    throw std::invalid_argument("FlightSettings.airframe: drag " + std::to_string(a.drag_linear_per_s) + " 1/s, " +
                                std::to_string(a.drag_quadratic_per_m) + " 1/m, response " +
                                (a.response_s ? std::to_string(*a.response_s) : std::string("unset")) +
                                " s; expected 0..10 1/s, 0..1 1/m, 0..2 s");
  }
  if (!(a.wind.allFinite() && a.wind.norm() <= 40.0)) {
    throw std::invalid_argument("FlightSettings.airframe.wind: (" + std::to_string(a.wind.x()) + ", " + std::to_string(a.wind.y()) +
                                ") m/s east, north; expected a speed of 0..40 m/s");
  }
  const TrackingError& e = s.tracking_error;
  if (!(e.horizontal_m >= 0.0 && e.horizontal_m <= 20.0) || !(e.vertical_m >= 0.0 && e.vertical_m <= 20.0)) {
    throw std::invalid_argument("FlightSettings.tracking_error: " + std::to_string(e.horizontal_m) + " m horizontal, " +
                                std::to_string(e.vertical_m) + " m vertical; expected 0..20 m each");
  }
  if (!(s.takeoff_delay_s <= 60.0)) {
    throw std::invalid_argument("FlightSettings.takeoff_delay_s = " + std::to_string(s.takeoff_delay_s) + " s, expected <= 60");
  }
}

double wrapPi(double a) {
  while (a > M_PI) a -= 2.0 * M_PI;
  while (a < -M_PI) a += 2.0 * M_PI;
  return a;
}

// Phase of the energy model for a piece from its speeds, climb and turn.
energy::Phase energyPhase(const FlightSample& a, const FlightSample& b, double length, double climb, double yaw) {
  if (!a.airborne && !b.airborne) return energy::Phase::Ground;
  const double dt = b.t - a.t;
  if (length < 1e-3 * dt) return energy::Phase::Hover;
  if (std::abs(climb) > 0.7 * length) return climb > 0 ? energy::Phase::Climb : energy::Phase::Descent;
  if (std::abs(yaw) > 0.05 * dt) return energy::Phase::Turn;  // faster than about 3 deg/s
  const double dv = b.velocity.norm() - a.velocity.norm();
  if (dv > 0.05 * dt) return energy::Phase::Accelerate;
  if (dv < -0.05 * dt) return energy::Phase::Brake;
  return energy::Phase::Cruise;
}

// The item's "FILE:LINE" for notes, else "step K (mission item index I)".
std::string stepName(const NavStep& st, std::size_t k) {
  if (!st.where.empty()) return st.where;
  return "step " + std::to_string(k) + " (mission item index " + std::to_string(st.item) + ")";
}

// The steps as ArduPilot stores and reads them, for its two models:
// - AP_Mission (mavlink_int_to_mission_cmd) keeps a waypoint's, spline's or LOITER_TIME's hold in
//   whole seconds (uint16 p1): 2.7 s holds 2 s, 0.5 s none, so that waypoint is flown through;
// - ModeAuto::loc_from_cmd (3.x: pv_location_to_vector_with_default) takes latitude and longitude
//   0 as the previous target's, keeping the item's altitude, and an altitude of 0 as the previous
//   target's altitude.
// Each change is noted. After a circle the previous target is where the circle ends, which only the
// flight knows, so such items are left to the model ("here").
std::vector<NavStep> asArduPilotReadsThem(const std::vector<NavStep>& steps, std::vector<std::string>& notes) {
  std::vector<NavStep> out = steps;
  bool known = true;
  Eigen::Vector3d prev = Eigen::Vector3d::Zero();  // home, on the ground
  for (std::size_t k = 0; k < out.size(); ++k) {
    NavStep& st = out[k];
    if (isFlownTo(st) && st.hold_s != std::floor(st.hold_s)) {
      notes.push_back(stepName(st, k) + ": hold " + detail::num(st.hold_s) + " s is kept by ArduPilot in whole seconds (" +
                      detail::num(std::floor(st.hold_s)) + " s" + (st.hold_s < 1.0 ? ": no stop, flown through" : "") + ")");
      st.hold_s = std::floor(st.hold_s);
    }
    if (st.kind == NavStep::Kind::Takeoff) {
      prev = {0.0, 0.0, st.target.z()};
      known = true;
    } else if (st.kind == NavStep::Kind::LoiterTurns) {
      if (known && !st.alt_given) st.target.z() = prev.z();
      if (!st.has_position) {
        notes.push_back(stepName(st, k) + ": latitude and longitude 0: ArduPilot circles round where the vehicle is" +
                        (st.alt_given ? std::string() : ", at the previous target's altitude"));
      }
      known = false;
    } else if (isFlownTo(st) && known) {
      Eigen::Vector3d t = st.has_position ? st.target : Eigen::Vector3d(prev.x(), prev.y(), st.target.z());
      if (!st.alt_given) t.z() = prev.z();
      if (!st.has_position && (t - prev).norm() > 0.01) {
        st.has_position = true;
        notes.push_back(stepName(st, k) + ": latitude and longitude 0 are the previous target's for ArduPilot, flown to at the item's altitude " +
                        detail::num(t.z()) + " m");
      }
      if (!st.alt_given && st.has_position) {
        notes.push_back(stepName(st, k) + ": altitude 0 is the previous target's for ArduPilot (" + detail::num(t.z()) + " m)");
      }
      if (!st.has_position && (t - prev).norm() <= 0.01) {
        notes.push_back(stepName(st, k) +
                        (st.alt_given ? ": latitude and longitude 0 are the previous target's for ArduPilot, and its altitude, " +
                                            detail::num(t.z()) + " m, is the vehicle's"
                                      : std::string(": latitude, longitude and altitude 0 are the previous target's for "
                                                    "ArduPilot, where the vehicle already is")) +
                        ": a leg of no length" + (st.hold_s > 0.0 ? ", then the hold" : ""));
      }
      st.target = t;
      if (st.has_position) prev = t;
    }
  }
  return out;
}

// The speeds in force as ArduCopter 4.1-4.4 has them (NavStep::speed_xy_41 ...: the first waypoint
// after a take-off or a circle restarts the waypoint controller at the default speeds, dropping the
// DO_CHANGE_SPEED run just before it; ArduPilot issue 21080, fixed in 4.5), noted where they differ
// from what the mission asks.
std::vector<NavStep> withSpeedsBefore45(std::vector<NavStep> steps, const std::string& version, std::vector<std::string>& notes) {
  int differ = 0;
  std::string first;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    NavStep& st = steps[k];
    const bool flies = isFlownTo(st) || st.kind == NavStep::Kind::Land || st.kind == NavStep::Kind::LoiterTurns;
    if (flies && (st.speed_xy != st.speed_xy_41 || st.speed_up != st.speed_up_41 || st.speed_down != st.speed_down_41)) {
      if (differ++ == 0) first = stepName(st, k);
    }
    st.speed_xy = st.speed_xy_41;
    st.speed_up = st.speed_up_41;
    st.speed_down = st.speed_down_41;
  }
  if (differ > 0) {
    notes.push_back("ArduCopter " + version + " drops a DO_CHANGE_SPEED run just before the first waypoint after a take-off "
                    "or a circle: that waypoint restarts the waypoint controller at WPNAV_SPEED (ArduPilot issue 21080, "
                    "fixed in 4.5; written twice, the repeat runs after the restart and is kept); " + std::to_string(differ) +
                    " item(s) fly at the default speeds where the mission asks others, the first " + first);
  }
  return steps;
}

}  // namespace

Airframe airframeOf(double drag_area_m2, double mass_kg, double air_density_kgpm3) {
  Airframe a;
  if (mass_kg > 0.0 && drag_area_m2 > 0.0 && air_density_kgpm3 > 0.0) a.drag_quadratic_per_m = 0.5 * air_density_kgpm3 * drag_area_m2 / mass_kg;
  return a;
}

FlownMission flyMission(const std::vector<NavStep>& steps, const AutopilotConfig& autopilot, const FlightSettings& s) {
  validate(s);
  if (steps.empty()) throw std::invalid_argument("flyMission: no navigation steps");
  if (s.speed_change_late) {
    std::vector<NavStep> late = steps;
    for (std::size_t k = late.size(); k-- > 1;) {
      late[k].speed_xy = steps[k - 1].speed_xy;
      late[k].speed_xy_3x = steps[k - 1].speed_xy_3x;
      late[k].speed_up = steps[k - 1].speed_up;
      late[k].speed_down = steps[k - 1].speed_down;
      late[k].speed_xy_41 = steps[k - 1].speed_xy_41;
      late[k].speed_up_41 = steps[k - 1].speed_up_41;
      late[k].speed_down_41 = steps[k - 1].speed_down_41;
    }
    FlightSettings now = s;
    now.speed_change_late = false;
    FlownMission f = flyMission(late, autopilot, now);
    f.steps = steps;
    f.notes.push_back("DO_CHANGE_SPEED applied one waypoint late (calibrated corner/speed timing)");
    return f;
  }
  switch (autopilot.family) {
    case AutopilotFamily::ArduCopterSCurve:
    case AutopilotFamily::ArduCopterLeash: {
      std::vector<std::string> notes;
      std::vector<NavStep> read = asArduPilotReadsThem(steps, notes);
      if (autopilot.family == AutopilotFamily::ArduCopterSCurve && !versionAtLeast(autopilot.version, 4, 5)) {
        read = withSpeedsBefore45(std::move(read), autopilot.version, notes);
      }
      FlownMission f = autopilot.family == AutopilotFamily::ArduCopterSCurve ? flyArduCopterSCurve(read, autopilot, s)
                                                                           : flyArduCopterLeash(read, autopilot, s);
      f.notes.insert(f.notes.begin(), notes.begin(), notes.end());
      return f;
    }
    case AutopilotFamily::PX4: return flyPx4(steps, autopilot, s);
  }
  throw std::invalid_argument("flyMission: unknown autopilot family");
}

FlightPieces toPieces(const FlownMission& f) {
  FlightPieces out;
  out.pieces.reserve(f.samples.size());
  double heading = 0.0;
  for (std::size_t i = 1; i < f.samples.size(); ++i) {
    const FlightSample& a = f.samples[i - 1];
    const FlightSample& b = f.samples[i];
    const double dt = b.t - a.t;
    if (!(dt > 0.0)) continue;
    const double va = a.velocity.norm(), vb = b.velocity.norm();
    energy::Piece p;
    p.duration = dt;
    p.v_start = va;
    p.v_end = vb;
    p.length = 0.5 * (va + vb) * dt;
    p.climb = std::clamp(b.position.z() - a.position.z(), -p.length, p.length);
    const double ha = std::hypot(a.velocity.x(), a.velocity.y()) > 0.05 ? std::atan2(a.velocity.y(), a.velocity.x()) : heading;
    const double hb = std::hypot(b.velocity.x(), b.velocity.y()) > 0.05 ? std::atan2(b.velocity.y(), b.velocity.x()) : ha;
    p.heading = ha;
    p.yaw_angle = p.length > 0.0 ? wrapPi(hb - ha) : 0.0;
    heading = hb;
    p.v_cruise = std::max(va, vb);
    p.phase = energyPhase(a, b, p.length, p.climb, p.yaw_angle);
    if (p.phase == energy::Phase::Hover || p.phase == energy::Phase::Ground) {
      p.length = 0.0;
      p.v_start = p.v_end = 0.0;
      p.climb = 0.0;
      p.yaw_angle = 0.0;
    }
    out.pieces.push_back(p);
    out.phase.push_back(b.phase);
    out.step.push_back(b.step);
  }
  return out;
}

}  // namespace wattswath::mission
