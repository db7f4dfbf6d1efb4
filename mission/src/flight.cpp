// Dispatch to the behaviour model of the autopilot's family, and the flown trajectory as pieces.
#include <cmath>
#include <stdexcept>

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
      late[k].speed_up = steps[k - 1].speed_up;
      late[k].speed_down = steps[k - 1].speed_down;
    }
    FlightSettings now = s;
    now.speed_change_late = false;
    FlownMission f = flyMission(late, autopilot, now);
    f.steps = steps;
    f.notes.push_back("DO_CHANGE_SPEED applied one waypoint late (calibrated corner/speed timing)");
    return f;
  }
  switch (autopilot.family) {
    case AutopilotFamily::ArduCopterSCurve: return flyArduCopterSCurve(steps, autopilot, s);
    case AutopilotFamily::ArduCopterLeash: return flyArduCopterLeash(steps, autopilot, s);
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
