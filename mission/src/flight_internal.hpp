#pragma once
// Private to mission/src: what the behaviour models share (recording the trajectory, limits in SI,
// the landing descent, hovering in place).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/mission/flight.hpp"

namespace wattswath::mission::detail {

inline constexpr double kGravity = 9.80665;  // [m/s^2] as the autopilots use it

/// Records the simulated state every tick and keeps a sample every sample_dt.
class Recorder {
 public:
  Recorder(const FlightSettings& s, std::size_t step_count) : s_(s), every_(std::max(1L, std::lround(s.sample_dt / s.dt))) {
    out_.events.resize(step_count);
    for (std::size_t i = 0; i < step_count; ++i) {
      out_.events[i].step = static_cast<int>(i);
      out_.events[i].reached_s = out_.events[i].completed_s = std::nan("");
    }
  }
  /// Advances one tick to state (p, v) and records it when a sample is due.
  void tick(const Eigen::Vector3d& p, const Eigen::Vector3d& v, FlightPhase phase, int step, bool airborne = true) {
    t_ += s_.dt;
    ++ticks_;
    pos_ = p;
    vel_ = v;
    if (t_ > s_.max_time_s) {
      throw std::runtime_error("the predicted flight exceeds " + std::to_string(s_.max_time_s / 3600.0) +
                               " h; expected a mission a battery-powered multicopter can fly");
    }
    if (ticks_ % every_ == 0) out_.samples.push_back({t_, p, v, phase, step, airborne});
  }
  /// Stays at the current position for `seconds` [s].
  void hold(double seconds, FlightPhase phase, int step, bool airborne = true) {
    const long n = std::lround(std::max(0.0, seconds) / s_.dt);
    for (long i = 0; i < n; ++i) tick(pos_, Eigen::Vector3d::Zero(), phase, step, airborne);
  }
  /// Marks step `k` reached now.
  void reached(int k) {
    if (k >= 0 && k < static_cast<int>(out_.events.size()) && std::isnan(out_.events[k].reached_s)) out_.events[k].reached_s = t_;
  }
  /// Marks step `k` complete now.
  void completed(int k) {
    if (k >= 0 && k < static_cast<int>(out_.events.size())) out_.events[k].completed_s = t_;
  }
  /// Adds a note on what the model assumed (once: a note already given is not repeated).
  void note(const std::string& n) {
    if (std::find(out_.notes.begin(), out_.notes.end(), n) == out_.notes.end()) out_.notes.push_back(n);
  }
  /// Sets the line saying which model flew and with which parameters (FlownMission::model).
  void model(const std::string& m) { out_.model = m; }
  /// Starts the record at home on the ground and waits the take-off delay (FlightSettings, or the
  /// autopilot's documented spool-up time `spool_s` [s] when the settings give none).
  void startOnGround(double spool_s) {
    start(Eigen::Vector3d::Zero());
    hold(s_.takeoff_delay_s >= 0.0 ? s_.takeoff_delay_s : spool_s, FlightPhase::Takeoff, 0, false);
  }
  /// Starts the record at `p` (the first sample, t = 0).
  void start(const Eigen::Vector3d& p) {
    pos_ = p;
    out_.samples.push_back({0.0, p, Eigen::Vector3d::Zero(), FlightPhase::Takeoff, 0, false});
  }
  double time() const { return t_; }
  double dt() const { return s_.dt; }
  const Eigen::Vector3d& position() const { return pos_; }
  const Eigen::Vector3d& velocity() const { return vel_; }
  const FlightSettings& settings() const { return s_; }
  FlownMission take(std::vector<NavStep> steps) {
    out_.steps = std::move(steps);
    return std::move(out_);
  }

 private:
  FlightSettings s_;
  long every_;
  long ticks_ = 0;
  double t_ = 0.0;
  Eigen::Vector3d pos_ = Eigen::Vector3d::Zero(), vel_ = Eigen::Vector3d::Zero();
  FlownMission out_;
};

/// sqrt_controller of the autopilots: speed [m/s] that brings an error `e` [m] to 0 with gain
/// `p` [1/s] and deceleration `a` [m/s^2] (linear near zero, square root far away); signed as e.
inline double sqrtController(double e, double p, double a) {
  const double lin = a / (p * p);
  const double mag = std::abs(e) <= lin ? p * std::abs(e) : std::sqrt(2.0 * a * (std::abs(e) - 0.5 * lin));
  return std::copysign(mag, e);
}

/// The autopilots' stopping distance [m] from speed `v` [m/s] (AP_Math stopping_distance, the
/// inverse of sqrtController with gain `p` [1/s] and deceleration `a` [m/s^2]; AC_PosControl's
/// get_stopping_point_xy): v / p below a / p, a / 2p^2 + v^2 / 2a above.
inline double stoppingDistance(double v, double p, double a) {
  return v < a / p ? v / p : a / (2.0 * p * p) + v * v / (2.0 * a);
}

/// [m/s^2] Drag deceleration of airframe `a` at horizontal ground velocity `vh` [m/s]: c1 v + c2 v^2
/// against the velocity through the air (`vh` minus the wind).
inline Eigen::Vector2d airDrag(const Airframe& a, const Eigen::Vector2d& vh) {
  const Eigen::Vector2d air = vh - a.wind;
  const double speed = air.norm();
  if (speed <= 1e-9) return Eigen::Vector2d::Zero();
  return -air / speed * (a.drag_linear_per_s * speed + a.drag_quadratic_per_m * speed * speed);
}

/// Direction-scaled limit of a 3-D leg (ArduPilot kinematic_limit): the largest speed (or
/// acceleration) along unit direction `u` such that its horizontal part stays within `xy` and its
/// vertical part within `up` (climbing) or `down` (descending).
inline double kinematicLimit(const Eigen::Vector3d& u, double xy, double up, double down) {
  const double uxy = std::hypot(u.x(), u.y()), uz = u.z();
  double lim = 1e300;
  if (uxy > 1e-9) lim = std::min(lim, xy / uxy);
  if (std::abs(uz) > 1e-9) lim = std::min(lim, (uz > 0 ? up : down) / std::abs(uz));
  return lim;
}

/// [m] Altitude above home of positional item `it` of `m` in its frame: absolute (0, 5) less the
/// home's, relative (3, 6) as written, above terrain (10, 11) as written (flat terrain at home's
/// height); throws std::invalid_argument naming the item for another frame.
double altitudeAboveHome(const MissionItem& it, const Mission& m);

/// `x` with up to 4 significant digits, for notes ("2.5", "10", "5.236").
inline std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

/// Throws std::invalid_argument naming the autopilot parameter unless lo <= value <= hi.
inline double checkParameter(const std::string& name, double value, double lo, double hi, const char* unit) {
  if (!(value >= lo && value <= hi)) {
    throw std::invalid_argument("autopilot parameter " + name + " = " + std::to_string(value) + " " + unit +
                                ", expected " + std::to_string(lo) + ".." + std::to_string(hi));
  }
  return value;
}

/// ArduCopter's vertical controller after touch-down, until the throttle reaches its lower limit [s]
/// (the land detector's LAND_DETECTOR_TRIGGER_SEC counts from then; Copter::update_land_detector).
/// On the ground the position target keeps descending at `land_speed` [m/s] (land_at_climb_rate with
/// the descent limit ignored), so the velocity target grows by `pos_p` x land_speed per second; the
/// velocity loop (`vel_p` [1/s]) asks for a downward acceleration that the acceleration loop
/// (`acc_p`, `acc_i` [1/s]; throttle 0.001 per cm/s/s) takes off the hover throttle `hover` [0..1].
/// Throttle removed after t seconds: k (acc_p (1 + pos_p t) + acc_i (t + pos_p t^2 / 2)) with
/// k = 0.1 vel_p land_speed; the root of that equal to `hover` (0 when the first step already
/// removes it, at most 30 s). ArduCopter 4.7 SITL, hover 0.39 and the 4.x defaults: 0.59 s; its logs
/// show 0.6-0.7 s from touch-down to LAND_COMPLETE_MAYBE less its 0.2 s.
inline double throttleWindDown(double hover, double land_speed, double pos_p, double vel_p, double acc_p, double acc_i) {
  const double k = 0.1 * vel_p * land_speed;
  const double a = 0.5 * k * acc_i * pos_p, b = k * (acc_p * pos_p + acc_i), c = k * acc_p - hover;
  if (c >= 0.0) return 0.0;
  double t = 30.0;
  if (a > 1e-12) {
    t = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  } else if (b > 1e-12) {
    t = -c / b;
  }
  return std::min(t, 30.0);
}

/// Descends vertically to the ground with a speed law `speed(h)` [m/s, > 0] of the height above
/// home `h` [m], then waits `detect_s` on the ground (the landing detector).
template <class SpeedLaw>
void descendAndLand(Recorder& rec, SpeedLaw speed, double accel, int step, double detect_s) {
  Eigen::Vector3d p = rec.position();
  double vz = std::min(0.0, rec.velocity().z());
  while (p.z() > 0.0) {
    const double target = -speed(p.z());
    const double dv = std::clamp(target - vz, -accel * rec.dt(), accel * rec.dt());
    vz += dv;
    p.z() = std::max(0.0, p.z() + vz * rec.dt());
    rec.tick(p, Eigen::Vector3d(0, 0, p.z() > 0.0 ? vz : 0.0), FlightPhase::Landing, step);
  }
  rec.hold(detect_s, FlightPhase::Landing, step, false);
}

}  // namespace wattswath::mission::detail
