// ArduCopter before 4.1 (3.x AC_WPNav): a target point (the "carrot") is dragged along each leg at
// up to WPNAV_SPEED, accelerating at 2 x WPNAV_ACCEL while it stays within a leash of the vehicle,
// braking into a waypoint only when the waypoint has a hold time; a waypoint without one is
// "reached" when the carrot reaches it, and the next leg's carrot starts with the vehicle's
// velocity along the new leg. The vehicle chases the carrot: a square-root position controller
// (POS_XY_P, WPNAV_ACCEL) gives the velocity it asks for, a proportional velocity loop (VEL_XY_P)
// the acceleration, limited by the lean angle and delayed by the attitude response
// (docs/autopilots.md, section "ArduCopter before 4.1").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "circle.hpp"
#include "flight_internal.hpp"
#include "spline_curve.hpp"

namespace wattswath::mission {
namespace {

using detail::kGravity;
using detail::Recorder;
using detail::sqrtController;

constexpr double kAttitudeLag = 0.15;  // [s] attitude response time constant (docs/autopilots.md)

struct Params {
  double speed, speed_up, speed_dn, accel, accel_z, radius, pos_xy_p, pos_z_p, vel_xy_p, vel_xy_i, vel_xy_imax, accel_max;
  double rtl_alt, rtl_alt_final, rtl_climb_min, rtl_loiter_s, land_speed, land_alt_low, spool_s;
  double land_wind_down_s;  // [s] from touch-down until the throttle is at its lower limit (throttleWindDown)
  double circle_rate;       // [rad/s] CIRCLE_RATE: a LOITER_TURNS' angular rate, clockwise
  bool linear_slack;  // before 3.4: the leash slack shrinks linearly with the cross-track error
  // [s] Before 3.4 AC_WPNav::update_wpnav advances the carrot and triggers the horizontal position
  // controller every 0.1 s (WPNAV_WP_UPDATE_TIME), which then runs its four steps (position to
  // velocity to acceleration to lean angles) once on the following loops with dt 0.1 s: lean
  // targets change ten times a second. 0: every simulation step (3.4 and later, full rate).
  double nav_period;
  double leash_up, leash_dn;  // [m] the position controller's vertical leashes (climbing, descending)
  // From 3.3, AC_PosControl::accel_to_lean_angles limits the change of the acceleration target to
  // 17 m/s^3 (POSCONTROL_JERK_LIMIT_CMSSS; from 3.4 _jerk_cmsss, set to it by AC_WPNav) and low-pass
  // filters it (2 Hz: POSCONTROL_ACCEL_FILTER_HZ, from 3.4 PSC_ACC_XY_FILT) before the lean angles;
  // 3.2 converts the target as it is ("To-Do: add 1hz filter"). 0: not applied.
  double lean_jerk;       // [m/s^3]
  double lean_filter_hz;  // [Hz]
  TrackingError tracking;     // [m] the vehicle's typical distance off its line (FlightSettings)
};

// True for ArduCopter versions before 3.4 ("3.2", "3.3.3"), whose advance_wp_target_along_track
// scales the leash slack linearly; 3.4 to 4.0 (and an unspecified "3.x") use the Pythagorean form.
bool linearSlackVersion(const std::string& version) {
  int major = 0, minor = -1;
  if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) < 2) return false;
  return major < 3 || (major == 3 && minor < 4);
}

// True for the versions whose position controller jerk-limits and filters its acceleration
// target: 3.3 and later (an unspecified "3.x" is taken as the later form, as for the slack).
bool shapedLeanVersion(const std::string& version) {
  int major = 0, minor = -1;
  if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) < 2) return true;
  return major > 3 || (major == 3 && minor >= 3);
}

// Leash length of a position controller (AC_PosControl::calc_leash_length) [m].
double leashLength(double speed, double accel, double kp) {
  const double l = speed <= accel / kp ? speed / kp : accel / (2.0 * kp * kp) + speed * speed / (2.0 * accel);
  return std::max(l, 1.0);
}

// A parameter under its 3.3 and later name, else under its 3.2 name when the vehicle file has that
// one, else the default.
double renamed(const AutopilotConfig& ap, const std::string& name, const std::string& name_32) {
  if (ap.parameters.count(name) == 0 && ap.parameters.count(name_32) != 0) return ap.parameters.at(name_32);
  return ap.get(name);
}

// The throttle's wind-down after touch-down [s] (detail::throttleWindDown) with the 3.x vertical
// controller: hover throttle MOT_THST_HOVER (3.4 and later) or THR_MID / 1000 (3.2, 3.3), VEL_Z_P,
// ACCEL_Z_P and ACCEL_Z_I (3.2: THR_RATE_P, THR_ACCEL_P, THR_ACCEL_I).
double landWindDown(const AutopilotConfig& ap, double land_speed, double pos_z_p) {
  using detail::checkParameter;
  const double hover = ap.parameters.count("MOT_THST_HOVER") != 0
                           ? checkParameter("MOT_THST_HOVER", ap.parameters.at("MOT_THST_HOVER"), 0.05, 0.95, "(throttle fraction)")
                           : checkParameter("THR_MID", ap.get("THR_MID"), 50, 950, "(throttle x 1000)") / 1000.0;
  return detail::throttleWindDown(hover, land_speed, pos_z_p,
                                  checkParameter("VEL_Z_P", renamed(ap, "VEL_Z_P", "THR_RATE_P"), 0.1, 20, "1/s"),
                                  checkParameter("ACCEL_Z_P", renamed(ap, "ACCEL_Z_P", "THR_ACCEL_P"), 0.01, 5, "-"),
                                  checkParameter("ACCEL_Z_I", renamed(ap, "ACCEL_Z_I", "THR_ACCEL_I"), 0, 10, "1/s"));
}

Params readParams(const AutopilotConfig& ap) {
  using detail::checkParameter;
  Params p{};
  p.speed = checkParameter("WPNAV_SPEED", ap.get("WPNAV_SPEED"), 20, 5000, "cm/s") / 100.0;
  p.speed_up = checkParameter("WPNAV_SPEED_UP", ap.get("WPNAV_SPEED_UP"), 10, 1000, "cm/s") / 100.0;
  p.speed_dn = checkParameter("WPNAV_SPEED_DN", ap.get("WPNAV_SPEED_DN"), 10, 500, "cm/s") / 100.0;
  p.accel = checkParameter("WPNAV_ACCEL", ap.get("WPNAV_ACCEL"), 50, 500, "cm/s/s") / 100.0;
  p.accel_z = checkParameter("WPNAV_ACCEL_Z", ap.get("WPNAV_ACCEL_Z"), 50, 500, "cm/s/s") / 100.0;
  p.radius = checkParameter("WPNAV_RADIUS", ap.get("WPNAV_RADIUS"), 5, 1000, "cm") / 100.0;
  p.pos_xy_p = checkParameter("POS_XY_P", ap.get("POS_XY_P"), 0.1, 10, "1/s");
  p.pos_z_p = checkParameter("POS_Z_P", ap.get("POS_Z_P"), 0.1, 10, "1/s");
  p.vel_xy_p = checkParameter("VEL_XY_P", ap.get("VEL_XY_P"), 0.1, 10, "1/s");
  p.vel_xy_i = checkParameter("VEL_XY_I", ap.get("VEL_XY_I"), 0, 10, "1/s/s");
  p.vel_xy_imax = checkParameter("VEL_XY_IMAX", ap.get("VEL_XY_IMAX"), 0, 4500, "cm/s/s") / 100.0;
  const double angle_max = checkParameter("ANGLE_MAX", ap.get("ANGLE_MAX"), 1000, 8000, "cdeg") / 100.0;
  p.accel_max = std::min(9.8, kGravity * std::tan(angle_max * M_PI / 180.0));
  p.rtl_alt = checkParameter("RTL_ALT", ap.get("RTL_ALT"), 0, 300000, "cm") / 100.0;
  p.rtl_alt_final = std::max(0.0, ap.get("RTL_ALT_FINAL")) / 100.0;
  p.rtl_climb_min = std::max(0.0, ap.get("RTL_CLIMB_MIN")) / 100.0;
  p.rtl_loiter_s = checkParameter("RTL_LOIT_TIME", ap.get("RTL_LOIT_TIME"), 0, 600000, "ms") / 1000.0;
  p.land_speed = checkParameter("LAND_SPEED", ap.get("LAND_SPEED"), 30, 200, "cm/s") / 100.0;
  p.land_alt_low = std::max(0.0, ap.get("LAND_ALT_LOW")) / 100.0;
  p.spool_s = std::max(0.0, ap.get("MOT_SPOOL_TIME"));
  p.land_wind_down_s = landWindDown(ap, p.land_speed, p.pos_z_p);
  p.circle_rate = checkParameter("CIRCLE_RATE", ap.get("CIRCLE_RATE"), -90, 90, "deg/s") * M_PI / 180.0;
  p.linear_slack = linearSlackVersion(ap.version);
  if (shapedLeanVersion(ap.version)) {
    p.lean_jerk = 17.0;
    p.lean_filter_hz = checkParameter("PSC_ACC_XY_FILT", ap.get("PSC_ACC_XY_FILT"), 0.5, 5, "Hz");
  }
  p.nav_period = p.linear_slack ? 0.1 : 0.0;
  p.leash_up = leashLength(p.speed_up, p.accel_z, p.pos_z_p);
  p.leash_dn = leashLength(p.speed_dn, p.accel_z, p.pos_z_p);
  return p;
}


// The vehicle and the carrot it chases.
struct Vehicle {
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
  Eigen::Vector2d v_cmd_prev = Eigen::Vector2d::Zero();  // the previous step's velocity command (feed-forward)
  Eigen::Vector2d integ = Eigen::Vector2d::Zero();       // [m/s^2] the velocity loop's integrator (VEL_XY_I)
  Eigen::Vector2d a_cmd = Eigen::Vector2d::Zero();       // [m/s^2] the acceleration (lean) target in force
  Eigen::Vector2d ff = Eigen::Vector2d::Zero();          // [m/s^2] the velocity loop's feed-forward last computed
  Eigen::Vector2d a_jerk = Eigen::Vector2d::Zero();      // [m/s^2] the jerk-limited acceleration target (3.3+)
  Eigen::Vector2d a_filt = Eigen::Vector2d::Zero();      // [m/s^2] the same after the low-pass filter (3.3+)
  bool freeze_ff = false;  // a new leg: the next controller run keeps the feed-forward (AC_PosControl::freeze_ff_xy)
  double since_nav = 1e9;  // [s] since the carrot and the horizontal controller last ran (1e9: never)
};

// Advances the navigation clock by `dt` [s]; returns the time [s] the carrot and the horizontal
// position controller run over on this step, 0 when they do not run. Before 3.4 one clock drives
// both (AC_WPNav::update_wpnav: every WPNAV_WP_UPDATE_TIME = 0.1 s it moves the carrot and triggers
// the controller, whose steps run on the next loops with the same dt), across legs and holds: a
// new leg's carrot first moves at the next tick. From 3.4 on (nav_period 0) both run every step.
double navStep(Vehicle& veh, const Params& P, double dt) {
  if (P.nav_period <= 0.0) return dt;
  if (veh.since_nav > 1e8) {  // the first call: run at once, over one period
    veh.since_nav = 0.0;
    return P.nav_period;
  }
  veh.since_nav += dt;
  if (veh.since_nav < P.nav_period - 1e-9) return 0.0;
  const double ran = veh.since_nav;  // a step that does not divide 0.1 s makes it a little longer
  veh.since_nav = 0.0;
  return ran;
}

struct Leg {
  Eigen::Vector3d origin, dest, u;
  double length = 0.0, desired = 0.0, lim = 0.0, track_speed = 0.0, track_accel = 0.0, leash = 0.0, slow_down = 0.0;
  double pos_leash = 1.0;  // [m] the position controller's horizontal leash at the leg's speed
  bool fast = false, slowing = false;
  Eigen::Vector3d carrot() const { return origin + u * desired; }
};

// `leash_speed` [m/s]: the speed of the position controller's horizontal leash when the leg starts
// (see Flyer::leash_speed).
Leg startLeg(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double speed, double leash_speed, bool fast,
             const Vehicle& veh, const Params& P) {
  Leg g;
  g.origin = from;
  g.dest = to;
  const Eigen::Vector3d d = to - from;
  g.length = d.norm();
  g.u = g.length > 1e-9 ? Eigen::Vector3d(d / g.length) : Eigen::Vector3d::Zero();
  g.fast = fast;
  if (g.length <= 1e-9) return g;
  g.track_speed = detail::kinematicLimit(g.u, speed, P.speed_up, P.speed_dn);
  g.track_accel = detail::kinematicLimit(g.u, P.accel, P.accel_z, P.accel_z);
  g.leash = std::min(detail::kinematicLimit(g.u, leashLength(leash_speed, P.accel, P.pos_xy_p), 1e300, 1e300),
                     detail::kinematicLimit(g.u, 1e300, P.leash_up, P.leash_dn));
  g.pos_leash = leashLength(speed, P.accel, P.pos_xy_p);
  g.slow_down = g.track_speed * g.track_speed / (4.0 * g.track_accel);
  g.lim = std::clamp(veh.v.dot(g.u), 0.0, g.track_speed);
  return g;
}

// Moves the carrot one step (AC_WPNav::advance_wp_target_along_track of 3.x).
void advanceCarrot(Leg& g, const Vehicle& veh, const Params& P, double dt) {
  if (g.length <= 1e-9) return;
  const Eigen::Vector3d rel = veh.p - g.origin;
  const double covered = rel.dot(g.u);
  // How far ahead of the vehicle's along-track position the carrot may run: the cross-track error
  // as a fraction of the position controller's own leashes (horizontal, and up or down) scales
  // the track leash; before 3.4 the slack is the track leash minus that scaled error, from 3.4 on
  // the other side of the right triangle whose hypotenuse is the track leash. 0 beyond the leash.
  // The vehicle's typical distance off its line (FlightSettings::tracking_error, noise the
  // simulation does not fly) is added in quadrature to the simulated error; a vertical error is
  // above the line (the climb leash) as often as below it (the descent leash).
  const Eigen::Vector3d err = rel - g.u * covered;
  const double leash_z = err.z() >= 0.0 ? P.leash_up : P.leash_dn;
  const double noise_z = P.tracking.vertical_m * 0.5 * (1.0 / P.leash_up + 1.0 / P.leash_dn);
  const double err_xy = std::hypot(err.head<2>().norm(), P.tracking.horizontal_m);
  const double scaled_err =
      g.leash * std::max(err_xy / g.pos_leash, std::hypot(std::abs(err.z()) / leash_z, noise_z));
  const double slack = scaled_err >= g.leash ? 0.0
                       : P.linear_slack ? g.leash - scaled_err
                                        : std::sqrt(g.leash * g.leash - scaled_err * scaled_err);
  const double max_desired = covered + slack;
  const bool at_leash = g.desired > max_desired;
  const double v_along = veh.v.dot(g.u), v_lin = g.track_accel / P.pos_xy_p;
  if (v_along < -v_lin) {
    g.lim = 0.0;
  } else {
    if (!at_leash) g.lim += 2.0 * g.track_accel * dt;
    g.lim = std::clamp(g.lim, 0.0, g.track_speed);
    if (!g.fast) {
      if (g.length - g.desired <= g.slow_down) g.slowing = true;
      if (g.slowing) g.lim = std::min(g.lim, std::max(std::sqrt(4.0 * g.track_accel * std::max(0.0, g.length - g.desired)), 0.5));
    }
    if (std::abs(v_along) < v_lin) g.lim = std::clamp(g.lim, v_along - v_lin, v_along + v_lin);
  }
  if (!at_leash) {
    g.desired += g.lim * dt;
    if (g.desired > max_desired) {
      g.desired = max_desired;
      g.lim = std::max(0.0, g.lim - 2.0 * g.track_accel * dt);
    }
  }
  g.desired = std::clamp(g.desired, 0.0, g.length + (g.fast ? 2.0 : 0.0));
}

void xyController(Vehicle& veh, const Eigen::Vector3d& carrot, double speed, const Params& P, double dt);

// The vehicle chases `carrot` one step of `dt` [s]: square-root position controller, PI velocity
// loop (AC_PosControl::rate_to_accel_xy of 3.x: the integrator holds at the lean limit), lean limit,
// attitude lag, the airframe's drag; vertical: square-root controller to a climb or descent speed.
// `nav_dt` [s]: when > 0 the horizontal controller runs over it on this step (navStep).
void chase(Vehicle& veh, const Eigen::Vector3d& carrot, double speed, const Params& P, const Airframe& af, double dt,
           double nav_dt) {
  if (nav_dt > 0.0) xyController(veh, carrot, speed, P, nav_dt);
  veh.a.head<2>() += (veh.a_cmd - veh.a.head<2>()) * std::min(1.0, dt / kAttitudeLag);
  const double vz_cmd = std::clamp(sqrtController(carrot.z() - veh.p.z(), P.pos_z_p, P.accel_z), -P.speed_dn, P.speed_up);
  veh.a.z() = std::clamp((vz_cmd - veh.v.z()) / std::max(dt, 0.2), -P.accel_z, P.accel_z);
  veh.v.head<2>() += (veh.a.head<2>() + detail::airDrag(af, veh.v.head<2>())) * dt;
  veh.v.z() += veh.a.z() * dt;
  veh.p += veh.v * dt;
}

// One run of the horizontal position controller over `dt` [s]: the acceleration target it sets.
void xyController(Vehicle& veh, const Eigen::Vector3d& carrot, double speed, const Params& P, double dt) {
  Eigen::Vector2d err = (carrot - veh.p).head<2>();
  const double leash = leashLength(speed, P.accel, P.pos_xy_p);
  if (err.norm() > leash) err *= leash / err.norm();
  Eigen::Vector2d v_cmd = Eigen::Vector2d::Zero();
  if (err.norm() > 1e-9) v_cmd = err / err.norm() * sqrtController(err.norm(), P.pos_xy_p, P.accel);
  if (v_cmd.norm() > speed) v_cmd *= speed / v_cmd.norm();
  // Acceleration: the change of the velocity command (feed-forward, AC_PosControl::rate_to_accel_xy,
  // bounded by the lean limit so a jump at a new leg is not followed at once) plus the velocity loop.
  // At a new leg the feed-forward is frozen for one run ("stop the feed forward being calculated
  // during a known discontinuity").
  Eigen::Vector2d ff = veh.ff;
  if (!veh.freeze_ff) {
    ff = (v_cmd - veh.v_cmd_prev) / dt;
    if (ff.norm() > P.accel_max) ff *= P.accel_max / ff.norm();
  }
  veh.freeze_ff = false;
  veh.ff = ff;
  veh.v_cmd_prev = v_cmd;
  const Eigen::Vector2d verr = v_cmd - veh.v.head<2>();
  Eigen::Vector2d a_cmd = ff + P.vel_xy_p * verr + veh.integ;
  if (a_cmd.norm() > P.accel_max) {
    a_cmd *= P.accel_max / a_cmd.norm();
  } else {
    veh.integ += P.vel_xy_i * verr * dt;
    if (veh.integ.norm() > P.vel_xy_imax) veh.integ *= P.vel_xy_imax / veh.integ.norm();
  }
  if (P.lean_jerk > 0.0) {  // accel_to_lean_angles from 3.3: jerk limit, then the low-pass filter
    Eigen::Vector2d change = a_cmd - veh.a_jerk;
    if (change.norm() > P.lean_jerk * dt) change *= P.lean_jerk * dt / change.norm();
    veh.a_jerk += change;
    veh.a_filt += (veh.a_jerk - veh.a_filt) * (dt / (dt + 1.0 / (2.0 * M_PI * P.lean_filter_hz)));
    a_cmd = veh.a_filt;
  }
  veh.a_cmd = a_cmd;
}

// What a 3.x spline segment hands to the next (AC_WPNav keeps them across segments).
struct SplineCarry {
  bool active = false;  // the last segment was a spline flown through (SEGMENT_SPLINE, not stopped)
  Eigen::Vector3d out = Eigen::Vector3d::Zero();  // its destination tangent, unscaled [m]
  double time = 0.0;    // [-] its curve parameter at the end (may pass 1 by a step)
  double scaler = 0.0;  // [m/s] _spline_vel_scaler: the target's speed
};

struct Flyer {
  Recorder& rec;
  const Params& P;
  const Airframe& af;
  Vehicle veh;
  // [m/s] The speed the position controller's leash was last computed with. A DO_CHANGE_SPEED runs
  // in AP_Mission's advance loop just before the next waypoint starts: AC_PosControl::set_speed_xy
  // only flags its leash for recalculation at its next update, while AC_WPNav's
  // set_wp_origin_and_destination computes the track leash at once from that stale leash and
  // clears its own recalculation flag. The leg is therefore flown with the previous speed's leash:
  // an increase takes effect one waypoint late (the carrot cannot run further ahead than the old
  // leash, and the square-root controller turns that distance into the old speed); a decrease at
  // once (AC_PosControl caps the velocity at the new speed).
  double leash_speed;
  int late_increases = 0;  // legs commanded faster than the leash they start with (flown at the old speed)

  // Flies one leg from `from` (where the carrot is) to `to`; returns when the autopilot declares it
  // reached, with where the carrot then is (past `to` by up to a step's advance on a fast waypoint).
  Eigen::Vector3d leg(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double speed, bool fast, FlightPhase phase,
                      int step) {
    Leg g = startLeg(from, to, speed, leash_speed, fast, veh, P);
    if (speed > leash_speed + 0.05 && g.length > 1e-9 && std::abs(g.u.z()) < 0.5) ++late_increases;
    leash_speed = speed;  // recalculated at the position controller's first update on this leg
    veh.freeze_ff = true;  // AC_WPNav::update_wpnav: new_wp_destination freezes the feed-forward once
    while (true) {
      const double nav_dt = navStep(veh, P, rec.dt());
      if (nav_dt > 0.0) advanceCarrot(g, veh, P, nav_dt);
      chase(veh, g.length > 1e-9 ? g.carrot() : to, speed, P, af, rec.dt(), nav_dt);
      rec.tick(veh.p, veh.v, phase, step);
      const bool carrot_there = g.length <= 1e-9 || g.desired >= g.length;  // a degenerate leg has no carrot to move
      if (carrot_there && (fast || (veh.p - to).norm() <= P.radius)) return g.length > 1e-9 ? g.carrot() : to;
    }
  }
  // A spline segment (AC_WPNav::set_spline_origin_and_destination, advance_spline_target_along_track
  // of 3.x) from where the target is to `to`, entered along `in` and left along `out` (zero
  // vectors: a stop there, for which ArduPilot takes the chord x 0.02: "0.02 * distance vector");
  // `carry` continues the last spline's parameter and speed when `in` comes from it. The target
  // speeds up at WPNAV_ACCEL while the leash has slack, up to WPNAV_SPEED; a stop brakes on
  // sqrt(2 WPNAV_ACCEL d) within track speed^2 / 4 track accel; the curve parameter moves by
  // speed / |P'| x dt. Reached when the parameter reaches 1; returns where the target then is.
  Eigen::Vector3d spline(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& in,
                         const Eigen::Vector3d& out, double speed, FlightPhase phase, int step, SplineCarry& carry) {
    const bool stop = out.isZero();
    const Eigen::Vector3d at_rest = (to - from) * 0.02;
    const detail::HermiteSegment c(from, to, in.isZero() ? at_rest : in, stop ? at_rest : out);
    double t = 0.0, scaler = 0.0;
    if (carry.active) {  // from a spline flown through: its leftover parameter and speed
      t = carry.time > 1.0 && carry.time < 1.1 ? carry.time - 1.0 : 0.0;
      scaler = carry.scaler;
    } else if (!in.isZero()) {  // from a straight leg flown through: the position controller's speed
      scaler = veh.v_cmd_prev.norm();
    }
    Eigen::Vector3d target = from;
    leash_speed = speed;
    veh.freeze_ff = true;  // new_wp_destination: the feed-forward is frozen once
    while (true) {
      const double nav_dt = navStep(veh, P, rec.dt());
      if (nav_dt > 0.0 && t < 1.0) {
        const Eigen::Vector3d pos = c.at(t), vel = c.d1(t);
        const double vel_len = vel.norm();
        if (vel_len < 1e-12) {
          t = 1.0;  // 3.6 and later: a curve with no direction is reached
        } else {
          const Eigen::Vector3d u = vel / vel_len;
          const double track_speed = detail::kinematicLimit(u, speed, P.speed_up, P.speed_dn);
          const double track_accel = detail::kinematicLimit(u, P.accel, P.accel_z, P.accel_z);
          const double leash = std::min(detail::kinematicLimit(u, leashLength(speed, P.accel, P.pos_xy_p), 1e300, 1e300),
                                        detail::kinematicLimit(u, 1e300, P.leash_up, P.leash_dn));
          const Eigen::Vector3d err = veh.p - pos;
          const double leash_xy = leashLength(speed, P.accel, P.pos_xy_p), leash_z = err.z() >= 0.0 ? P.leash_up : P.leash_dn;
          const double slack = std::max(0.0, std::min(leash * (leash_z - std::abs(err.z())) / leash_z,
                                                       leash * (leash_xy - err.head<2>().norm()) / leash_xy));
          const double vel_limit = std::min(speed, slack / nav_dt);
          const double dist = (to - pos).norm();
          if (stop && dist < track_speed * track_speed / (4.0 * track_accel)) {
            scaler = std::sqrt(2.0 * P.accel * dist);
          } else if (scaler < vel_limit) {
            scaler += P.accel * nav_dt;
          }
          scaler = std::clamp(scaler, 0.0, vel_limit);
          target = pos;
          t += scaler / vel_len * nav_dt;
        }
      }
      chase(veh, target, speed, P, af, rec.dt(), nav_dt);
      rec.tick(veh.p, veh.v, phase, step);
      if (t >= 1.0) break;
    }
    carry = {!stop, out, t, scaler};
    return target;
  }
  // Where the position controller would bring the vehicle to rest (AC_PosControl::get_stopping_point_xy
  // of 3.x: linear below WPNAV_ACCEL / POS_XY_P, then v^2 / 2 WPNAV_ACCEL, within the leash at `speed`).
  Eigen::Vector3d stoppingPoint(double speed) const {
    const Eigen::Vector2d vh = veh.v.head<2>();
    const double v = vh.norm();
    if (v < 1e-9) return veh.p;
    const double d = std::min(detail::stoppingDistance(v, P.pos_xy_p, P.accel), leashLength(speed, P.accel, P.pos_xy_p));
    Eigen::Vector3d out = veh.p;
    out.head<2>() += vh / v * d;
    return out;
  }
  // NAV_LOITER_TURNS of 3.x (do_circle, auto_circle_movetoedge_start, AC_Circle): a stop leg from
  // where the carrot is to the closest point of the circle, then the circle's target point, moved
  // with the horizontal controller's period, chased like a carrot (position only, no feed-forward)
  // until it has turned the turns; returns where the next leg starts (the stopping point:
  // set_wp_destination with the waypoint controller idle for more than a second).
  Eigen::Vector3d circle(const NavStep& st, const Eigen::Vector3d& from, double speed, int step) {
    const Eigen::Vector3d center = detail::circleCenter(st, from);
    const Eigen::Vector3d edge = detail::circleEdge(center, st.loiter_radius_m, stoppingPoint(speed), veh.v.head<2>());
    leg(from, edge, speed, false, FlightPhase::Mission, step);
    rec.reached(step);
    detail::CircleTarget c(st, center, P.circle_rate, speed, P.accel, veh.p);
    rec.note(c.note());
    Eigen::Vector3d target = stoppingPoint(speed);  // AC_Circle::init: the target at the stopping point
    while (!c.done()) {
      const double nav_dt = navStep(veh, P, rec.dt());
      if (nav_dt > 0.0) target = c.step(nav_dt);
      chase(veh, target, speed, P, af, rec.dt(), nav_dt);
      rec.tick(veh.p, veh.v, FlightPhase::Mission, step);
    }
    return stoppingPoint(speed);
  }
  // Hovers at `at` for `seconds`, the vehicle still converging on it.
  void hold(const Eigen::Vector3d& at, double seconds, double speed, FlightPhase phase, int step) {
    const long n = std::lround(seconds / rec.dt());
    for (long i = 0; i < n; ++i) {
      chase(veh, at, speed, P, af, rec.dt(), navStep(veh, P, rec.dt()));
      rec.tick(veh.p, veh.v, phase, step);
    }
  }
};

// The exit tangent of the spline to steps[k] flown from `origin` (Copter::do_spline_wp's segment
// end type): along the next leg when a waypoint follows without a hold, towards the next point
// from the origin when a spline follows, else zero (a stop).
Eigen::Vector3d splineExit(const std::vector<NavStep>& steps, std::size_t k, const Eigen::Vector3d& origin, bool stop_all) {
  if (stop_all || steps[k].hold_s > 0.0 || k + 1 >= steps.size() || !steps[k + 1].has_position) return Eigen::Vector3d::Zero();
  const NavStep& next = steps[k + 1];
  if (next.kind == NavStep::Kind::Waypoint) return next.target - steps[k].target;
  if (next.kind == NavStep::Kind::SplineWaypoint) return next.target - origin;
  return Eigen::Vector3d::Zero();
}

void land(Recorder& rec, const Params& P, int step, const FlightSettings& s) {
  const double alt_low = std::max(P.land_alt_low, 1.0);
  auto law = [&](double h) { return h > alt_low ? std::max(P.speed_dn, P.land_speed) : P.land_speed; };
  detail::descendAndLand(rec, law, P.accel_z, step, P.land_wind_down_s + s.landed_detect_s);
}

}  // namespace

FlownMission flyArduCopterLeash(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s) {
  Params P = readParams(ap);
  P.tracking = s.tracking_error;
  Recorder rec(s, steps.size());
  rec.startOnGround(P.spool_s);
  Flyer f{rec, P, s.airframe, {}, P.speed};  // wp_and_spline_init sets the leash from WPNAV_SPEED
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // where the carrot is
  double speed = P.speed;  // DO_CHANGE_SPEED overwrites WPNAV_SPEED in memory (RTL inherits it)
  SplineCarry carry;
  Eigen::Vector3d straight_in = Eigen::Vector3d::Zero();  // the last straight leg, when flown through
  // Copter::do_change_speed of 3.2-3.6 sets the horizontal speed from any DO_CHANGE_SPEED, whatever
  // its type; 4.0's ModeAuto::do_change_speed sends types 2 and 3 to the climb and descent speeds.
  const bool any_type = !versionAtLeast(ap.version, 4, 0);
  bool vertical_asked = false;  // 4.0: a climb or descent speed was asked for (not modelled)
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const NavStep& st = steps[k];
    const int ki = static_cast<int>(k);
    const double asked = any_type ? st.speed_xy_3x : st.speed_xy;
    if (asked >= 1.0) speed = asked;  // AC_WPNav::set_speed_xy ignores requests below 1 m/s
    vertical_asked = vertical_asked || st.speed_up > 0.0 || st.speed_down > 0.0;
    if (st.kind == NavStep::Kind::Takeoff) {
      const Eigen::Vector3d top(target.x(), target.y(), std::max(st.target.z(), 1.0));
      f.leg(target, top, speed, false, FlightPhase::Takeoff, ki);
      target = top;
    } else if (st.kind == NavStep::Kind::SplineWaypoint && st.has_position) {
      const Eigen::Vector3d out = splineExit(steps, k, target, s.stop_at_waypoints);
      const Eigen::Vector3d in = carry.active ? carry.out : straight_in;
      const Eigen::Vector3d end = f.spline(target, st.target, in, out, speed, FlightPhase::Mission, ki, carry);
      rec.reached(ki);
      f.hold(st.target, st.hold_s, speed, FlightPhase::Mission, ki);
      target = out.isZero() ? st.target : end;
      straight_in.setZero();
    } else if (isFlownTo(st)) {
      const Eigen::Vector3d to = st.has_position ? st.target : target;
      const bool fast = st.kind != NavStep::Kind::LoiterTime && st.hold_s <= 0.0 && !s.stop_at_waypoints;
      const Eigen::Vector3d carrot = f.leg(target, to, speed, fast, FlightPhase::Mission, ki);
      rec.reached(ki);
      f.hold(to, st.hold_s, speed, FlightPhase::Mission, ki);
      // A spline next enters along this leg when it was flown through (Copter::do_spline_wp: the
      // previous command a waypoint without a hold).
      straight_in = fast && st.kind == NavStep::Kind::Waypoint ? Eigen::Vector3d(to - target) : Eigen::Vector3d::Zero();
      carry = {};
      target = fast ? carrot : to;  // AC_WPNav::set_wp_destination starts the next leg where the carrot is
    } else if (st.kind == NavStep::Kind::Delay) {
      rec.reached(ki);
      f.hold(target, st.hold_s, speed, FlightPhase::Mission, ki);
    } else if (st.kind == NavStep::Kind::LoiterTurns) {
      target = f.circle(st, target, speed, ki);
    } else if (st.kind == NavStep::Kind::ReturnToLaunch) {
      const double alt = std::max({P.rtl_alt, f.veh.p.z() + P.rtl_climb_min, f.veh.p.z()});
      const Eigen::Vector3d climb(target.x(), target.y(), alt), home(0.0, 0.0, alt);
      f.leg(target, climb, speed, true, FlightPhase::Return, ki);
      f.leg(climb, home, speed, false, FlightPhase::Return, ki);
      rec.reached(ki);
      f.hold(home, P.rtl_loiter_s, speed, FlightPhase::Return, ki);
      target = home;
      if (P.rtl_alt_final > 0.0) {
        f.leg(home, {0.0, 0.0, P.rtl_alt_final}, speed, false, FlightPhase::Return, ki);
        rec.note("RTL_ALT_FINAL > 0: the prediction ends hovering at " + std::to_string(P.rtl_alt_final) + " m");
      } else {
        land(rec, P, ki, s);
      }
    } else {  // Land
      if (st.has_position) {
        const Eigen::Vector3d over(st.target.x(), st.target.y(), target.z());
        f.leg(target, over, speed, false, FlightPhase::Mission, ki);  // the approach; the landing is the descent
      }
      rec.reached(ki);
      land(rec, P, ki, s);
    }
    if (st.kind == NavStep::Kind::Takeoff) rec.reached(ki);
    if (!isFlownTo(st)) {  // a spline after these starts from a stop
      carry = {};
      straight_in.setZero();
    }
    rec.completed(ki);
  }
  if (vertical_asked && !any_type) {
    rec.note("a DO_CHANGE_SPEED of type 2 or 3 (climb or descent): ArduCopter " + ap.version + " sets WPNAV's climb or "
             "descent speed from it (ModeAuto::do_change_speed), which the leash model does not follow: it climbs and "
             "descends at WPNAV_SPEED_UP and WPNAV_SPEED_DN");
  }
  if (f.late_increases > 0) {
    rec.note(std::to_string(f.late_increases) + " leg(s) are commanded faster than the leg before: ArduCopter " + ap.version +
             " applies a speed increase only from the next waypoint on (the leg's leash is computed before the new speed "
             "takes effect), and the prediction flies them so: near the previous leg's speed");
  }
  if (P.tracking.horizontal_m > 0.0 || P.tracking.vertical_m > 0.0) {
    rec.note("the vehicle is taken to sit " + detail::num(P.tracking.horizontal_m) + " m off its line horizontally and " +
             detail::num(P.tracking.vertical_m) + " m vertically (measured on logs): ArduCopter " + ap.version + " shortens " +
             "the carrot's lead by it" + (P.linear_slack ? ", which slows the cruise" : ", a small effect from 3.4 on"));
  }
  rec.model("ArduCopter " + ap.version + " leash model: WPNAV_ACCEL " + detail::num(P.accel) + " m/s/s, lean-limited acceleration " +
           detail::num(P.accel_max) + " m/s/s, attitude lag " + detail::num(kAttitudeLag) + " s" +
           (P.nav_period > 0.0 ? ", navigation and position control every " + detail::num(P.nav_period) + " s" : std::string()) +
           "; RTL flies at the last DO_CHANGE_SPEED (3.x overwrites WPNAV_SPEED in memory)");
  return rec.take(steps);
}

}  // namespace wattswath::mission
