// ArduCopter 4.1 and later: every leg is a rest-to-rest S-curve (scurve.hpp); at a waypoint the
// vehicle does not stop when the next navigation item is a waypoint and this one has no hold: the
// next leg's S-curve is started early and added to the end of this one once the predicted middle of
// the overlap is within WPNAV_RADIUS of the waypoint, slower than both legs' speeds and within the
// corner acceleration (AC_WPNav / SCurve::advance_target_along_track, docs/autopilots.md). A
// NAV_SPLINE_WAYPOINT is a Hermite segment (spline_curve.hpp) joined to straight legs at a speed,
// without a corner blend (AC_WPNav::set_spline_destination and its _next variants).
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "circle.hpp"
#include "flight_internal.hpp"
#include "position_follower.hpp"
#include "spline_curve.hpp"
#include "wattswath/mission/scurve.hpp"

namespace wattswath::mission {
namespace {

using detail::kGravity;
using detail::Recorder;

constexpr double kHoldOffset = 0.01;  // [m] a vehicle's altitude off its position target in a hover (RTL climb leg)

struct Params {
  double speed_xy, speed_up, speed_dn, accel_xy, accel_z, jerk, snap, radius, accel_corner;
  double jerk_z, rtl_alt, rtl_alt_final, rtl_climb_min, rtl_speed, rtl_loiter_s, land_speed, land_speed_high,
      land_alt_low, pos_z_p, spool_s, slew_s, rtl_cone_slope;
  double land_wind_down_s;  // [s] from touch-down until the throttle is at its lower limit (throttleWindDown)
  double spline_lateral;  // share of the acceleration limit a spline's curvature may use
  bool rtl_floor_relative;  // before 4.5: the cone's floor is 2.5 m above the vehicle (RTL_ABS_MIN_CLIMB)
  double circle_rate;     // [rad/s] CIRCLE_RATE: a LOITER_TURNS' angular rate, clockwise
  double jerk_xy;         // [m/s^3] the position controller's shaping jerk (PSC_JERK_XY, attitude-limited)
  detail::PositionGains gains;
};

// [-] SplineCurve's LATERAL_ACCEL_SCALER: 1 until ArduPilot PR 19941 (2022-01-31) halved it so
// that the path stays within what the vehicle can follow; 0.5 from 4.2 on.
double splineLateralShare(const std::string& version) { return versionAtLeast(version, 4, 2) ? 0.5 : 1.0; }

Params readParams(const AutopilotConfig& ap) {
  using detail::checkParameter;
  Params p{};
  p.speed_xy = checkParameter("WPNAV_SPEED", ap.get("WPNAV_SPEED"), 20, 5000, "cm/s") / 100.0;
  p.speed_up = checkParameter("WPNAV_SPEED_UP", ap.get("WPNAV_SPEED_UP"), 10, 1000, "cm/s") / 100.0;
  p.speed_dn = checkParameter("WPNAV_SPEED_DN", ap.get("WPNAV_SPEED_DN"), 10, 500, "cm/s") / 100.0;
  p.accel_xy = checkParameter("WPNAV_ACCEL", ap.get("WPNAV_ACCEL"), 50, 500, "cm/s/s") / 100.0;
  p.accel_z = checkParameter("WPNAV_ACCEL_Z", ap.get("WPNAV_ACCEL_Z"), 50, 500, "cm/s/s") / 100.0;
  const double wp_jerk = ap.get("WPNAV_JERK");
  p.jerk = wp_jerk > 0.0 ? checkParameter("WPNAV_JERK", wp_jerk, 0.1, 20, "m/s/s/s") : p.accel_xy;
  const double rate_max = std::min(ap.get("ATC_RATE_R_MAX"), ap.get("ATC_RATE_P_MAX"));  // [deg/s]
  if (rate_max > 0.0) p.jerk = std::min(p.jerk, rate_max * M_PI / 180.0 * kGravity);
  const double input_tc = checkParameter("ATC_INPUT_TC", ap.get("ATC_INPUT_TC"), 0, 1, "s");
  const double tc = std::max(input_tc, 0.1);
  p.snap = p.jerk * M_PI / (2.0 * tc);
  // The attitude target follows the lean asked for through input_shaping_angle's square-root
  // controller, linear with gain 1 / ATC_INPUT_TC (at least 0.01 s): a first-order lag.
  p.gains.attitude_tc = std::max(input_tc, 0.01);
  const double ang_accel = std::min(ap.get("ATC_ACCEL_R_MAX"), ap.get("ATC_ACCEL_P_MAX"));  // [cdeg/s/s]
  if (ang_accel > 0.0) p.snap = std::min(p.snap, ang_accel / 100.0 * M_PI / 180.0 * kGravity);
  p.snap *= 0.5;
  p.radius = checkParameter("WPNAV_RADIUS", ap.get("WPNAV_RADIUS"), 5, 1000, "cm") / 100.0;
  const double accel_c = ap.get("WPNAV_ACCEL_C") / 100.0;
  p.accel_corner = accel_c > 0.0 ? accel_c : 2.0 * p.accel_xy;
  p.jerk_z = checkParameter("PSC_JERK_Z", ap.get("PSC_JERK_Z"), 0.1, 50, "m/s/s/s");
  // ModeRTL::compute_return_target takes at least RTL_ALT_MIN (30 cm) whatever RTL_ALT says, so
  // RTL_ALT 0 (older firmware's "the current altitude") returns at the current altitude.
  p.rtl_alt = checkParameter("RTL_ALT", ap.get("RTL_ALT"), 0, 300000, "cm") / 100.0;
  p.rtl_alt_final = std::max(0.0, ap.get("RTL_ALT_FINAL")) / 100.0;
  p.rtl_climb_min = std::max(0.0, ap.get("RTL_CLIMB_MIN")) / 100.0;
  p.rtl_cone_slope = ap.get("RTL_CONE_SLOPE");
  p.rtl_floor_relative = !versionAtLeast(ap.version, 4, 5);
  const double rtl_speed = ap.get("RTL_SPEED");
  p.rtl_speed = rtl_speed > 0.0 ? rtl_speed / 100.0 : p.speed_xy;
  p.rtl_loiter_s = checkParameter("RTL_LOIT_TIME", ap.get("RTL_LOIT_TIME"), 0, 600000, "ms") / 1000.0;
  p.land_speed = checkParameter("LAND_SPEED", ap.get("LAND_SPEED"), 30, 200, "cm/s") / 100.0;
  p.land_speed_high = std::max(0.0, ap.get("LAND_SPEED_HIGH")) / 100.0;
  p.land_alt_low = std::max(0.0, ap.get("LAND_ALT_LOW")) / 100.0;
  p.pos_z_p = checkParameter("PSC_POSZ_P", ap.get("PSC_POSZ_P"), 0.1, 10, "1/s");
  const double hover = checkParameter("MOT_THST_HOVER", ap.get("MOT_THST_HOVER"), 0.05, 0.95, "(throttle fraction)");
  // On the ground: the spool-up, then (from 4.2; 4.1 rises as the spool-up ends) the auto take-off
  // slews the throttle up at 1 / TKOFF_SLEW_TIME per second until the vehicle rises, at the hover
  // throttle (or TKOFF_THR_MAX, at most 0.9).
  p.spool_s = std::max(0.0, ap.get("MOT_SPOOL_TIME"));
  p.slew_s = versionAtLeast(ap.version, 4, 2) ? checkParameter("TKOFF_SLEW_TIME", ap.get("TKOFF_SLEW_TIME"), 0.25, 5, "s") *
                                                    std::min({hover, std::max(0.0, ap.get("TKOFF_THR_MAX")), 0.9})
                                              : 0.0;
  p.land_wind_down_s = detail::throttleWindDown(hover, p.land_speed, p.pos_z_p,
      checkParameter("PSC_VELZ_P", ap.get("PSC_VELZ_P"), 0.1, 20, "1/s"), checkParameter("PSC_ACCZ_P", ap.get("PSC_ACCZ_P"), 0.01, 5, "-"),
      checkParameter("PSC_ACCZ_I", ap.get("PSC_ACCZ_I"), 0, 10, "1/s"));
  p.gains.pos_p = checkParameter("PSC_POSXY_P", ap.get("PSC_POSXY_P"), 0.1, 10, "1/s");
  p.gains.vel_p = checkParameter("PSC_VELXY_P", ap.get("PSC_VELXY_P"), 0.1, 20, "1/s");
  p.gains.vel_i = checkParameter("PSC_VELXY_I", ap.get("PSC_VELXY_I"), 0, 20, "1/s/s");
  p.gains.vel_imax = checkParameter("PSC_VELXY_IMAX", ap.get("PSC_VELXY_IMAX"), 0, 10000, "cm/s/s") / 100.0;
  p.gains.vel_d = checkParameter("PSC_VELXY_D", ap.get("PSC_VELXY_D"), 0, 10, "s");
  p.gains.filt_e_hz = checkParameter("PSC_VELXY_FLTE", ap.get("PSC_VELXY_FLTE"), 0, 100, "Hz");
  p.gains.filt_d_hz = checkParameter("PSC_VELXY_FLTD", ap.get("PSC_VELXY_FLTD"), 0, 100, "Hz");
  p.gains.accel = p.accel_xy;
  const double psc_angle = ap.get("PSC_ANGLE_MAX");  // [deg], 0: ANGLE_MAX
  const double lean_deg = psc_angle > 0.0 ? psc_angle : checkParameter("ANGLE_MAX", ap.get("ANGLE_MAX"), 1000, 8000, "cdeg") / 100.0;
  p.gains.lean_accel = kGravity * std::tan(std::clamp(lean_deg, 10.0, 80.0) * M_PI / 180.0);
  p.gains.scaler_tc = p.accel_xy / p.jerk;
  p.spline_lateral = splineLateralShare(ap.version);
  p.circle_rate = checkParameter("CIRCLE_RATE", ap.get("CIRCLE_RATE"), -90, 90, "deg/s") * M_PI / 180.0;
  // AC_PosControl::set_max_speed_accel_xy: PSC_JERK_XY, at most what the attitude controller's rate
  // and angular-acceleration limits allow.
  p.jerk_xy = checkParameter("PSC_JERK_XY", ap.get("PSC_JERK_XY"), 0.1, 50, "m/s/s/s");
  if (rate_max > 0.0) p.jerk_xy = std::min(p.jerk_xy, rate_max * M_PI / 180.0 * kGravity);
  if (ang_accel > 0.0) p.jerk_xy = std::min(p.jerk_xy, 0.5 * std::sqrt(p.accel_xy * ang_accel / 100.0 * M_PI / 180.0 * kGravity));
  return p;
}

// One straight leg and its S-curve; positions relative to `origin`.
struct Leg {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), dest = Eigen::Vector3d::Zero(), u = Eigen::Vector3d::Zero();
  SCurveProfile prof;
  double vmax = 0.0, accz = 0.0, t = 0.0;
  bool started = false;
  double remaining() const { return prof.duration() - t; }
  void state(double tt, Eigen::Vector3d& p, Eigen::Vector3d& v, Eigen::Vector3d& a) const {
    const TrackState s = prof.at(tt);
    p = u * s.pos;
    v = u * s.vel;
    a = u * s.acc;
  }
  void advance(double dt) { t = std::min(t + dt, prof.duration()); }
  // A DO_CHANGE_SPEED run while the leg is flown (SCurve::set_speed_max).
  void changeSpeed(double speed_xy, double speed_up, double speed_dn) {
    if (prof.duration() <= 0.0) return;
    prof.setSpeedMax(t, detail::kinematicLimit(u, speed_xy, speed_up, speed_dn));
    vmax = prof.speedMax();
  }
};

// What one leg of a chain asks for.
struct LegSpec {
  Eigen::Vector3d target;
  double speed_xy, speed_up, speed_dn, hold_s;
  int step;
  bool fast;            // the next leg follows without a stop
  bool spline = false;  // a NAV_SPLINE_WAYPOINT: a spline segment, not a straight leg
  // A spline flown through into the approach of the NAV_LAND after it: the point it leaves towards
  std::optional<Eigen::Vector3d> exit_to = std::nullopt;
};

// The straight leg from `from` to `to`, starting at `v0` and ending at `v1` [m/s] (0: at rest;
// more than 0 where it joins a spline).
Leg makeLeg(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const LegSpec& spec, const Params& P, double jerk,
            double v0 = 0.0, double v1 = 0.0) {
  Leg leg;
  leg.origin = from;
  leg.dest = to;
  const Eigen::Vector3d d = to - from;
  const double len = d.norm();
  if (len < 1e-6) return leg;
  leg.u = d / len;
  leg.vmax = detail::kinematicLimit(leg.u, spec.speed_xy, spec.speed_up, spec.speed_dn);
  const double amax = detail::kinematicLimit(leg.u, P.accel_xy, P.accel_z, P.accel_z);
  leg.accz = P.accel_z;
  const double snap = P.snap * jerk / P.jerk;
  leg.prof = SCurveProfile::between(len, v0, v1, {leg.vmax, amax, jerk, snap});
  return leg;
}

// Whether the next leg may start now: the middle of the overlap, predicted, is close enough to
// the waypoint, slow enough and within the corner accelerations.
bool mayStartNext(const Leg& cur, const Leg& next, const Params& P) {
  const double tr = cur.remaining();
  Eigen::Vector3d pc, vc, ac, pn, vn, an;
  cur.state(cur.t + 0.5 * tr, pc, vc, ac);
  next.state(0.5 * tr, pn, vn, an);
  const Eigen::Vector3d p = pc - (cur.dest - cur.origin) + pn, v = vc + vn, a = ac + an;
  return p.norm() < P.radius && v.norm() < std::min(cur.vmax, next.vmax) &&
         std::hypot(a.x(), a.y()) < P.accel_corner && std::abs(a.z()) < std::min(cur.accz, next.accz);
}

// The recorder, the vehicle chasing the target and the S-curve clock scaler, across the flight.
struct Flight {
  Recorder& rec;
  detail::PositionFollower veh;
  double clock = 1.0;  // AC_WPNav's _track_scalar_dt
  double spline_next_stale = 0.0;  // [m/s] arrival limit AC_WPNav's next-leg spline object holds (0 at boot)
  int replanned_faster = 0;  // legs begun at one speed and re-planned faster in flight (DO_CHANGE_SPEED)
  // One tick towards the target (p, v, a), recorded as the vehicle's state.
  void tick(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& a, FlightPhase phase, int step) {
    clock = veh.step(p, v, a, rec.dt());
    rec.tick(veh.position(), veh.velocity(), phase, step);
  }
  // Starts the waypoint controller afresh where the vehicle would stop now, at height `z` [m]
  // (AC_WPNav::wp_and_spline_init, as ModeRTL::init and a wp_start after the controller sat idle
  // run it): the position controller restarts and the S-curve clock runs at full speed again.
  Eigen::Vector3d restartAtStoppingPoint(double z) {
    const Eigen::Vector3d stop = veh.stoppingPoint();
    veh.restartController();
    clock = 1.0;
    return {stop.x(), stop.y(), z};
  }
  // Holds the target at `at` for `seconds` [s] while the vehicle settles on it.
  void hold(const Eigen::Vector3d& at, double seconds, FlightPhase phase, int step) {
    const long n = std::lround(std::max(0.0, seconds) / rec.dt());
    for (long i = 0; i < n; ++i) tick(at, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), phase, step);
  }
};

// Flies a chain of straight legs from `here`, blending corners into every leg marked fast; returns
// where the vehicle stops (the last leg's target, after its hold). A waypoint without a following
// leg is reached when the S-curve has ended there and the vehicle is within WPNAV_RADIUS of it.
// The first leg starts at `v_start` [m/s]; the last, when fast (a spline follows), ends at `v_end`
// (at most its peak speed), and `end_speed` [m/s] is then the speed it ended at.
Eigen::Vector3d flyChain(Flight& fl, const std::vector<LegSpec>& legs, Eigen::Vector3d here, const Params& P,
                         FlightPhase phase, double jerk, double v_start = 0.0, double v_end = 0.0, double* end_speed = nullptr) {
  Recorder& rec = fl.rec;
  const auto endOf = [&](std::size_t k) { return k + 1 == legs.size() ? v_end : 0.0; };
  Leg prev, cur = makeLeg(here, legs[0].target, legs[0], P, jerk, v_start, endOf(0)), next;
  std::size_t i = 0;
  if (end_speed) *end_speed = 0.0;
  // The next leg is planned when this waypoint starts (ModeAuto::set_next_wp), with the speeds in
  // force then; a DO_CHANGE_SPEED between the two runs when this waypoint is reached and re-plans
  // the next leg in flight (below).
  auto prepareNext = [&] {
    next = Leg();
    if (!legs[i].fast || i + 1 >= legs.size()) return;
    LegSpec planned = legs[i + 1];
    planned.speed_xy = legs[i].speed_xy;
    planned.speed_up = legs[i].speed_up;
    planned.speed_dn = legs[i].speed_dn;
    next = makeLeg(legs[i].target, legs[i + 1].target, planned, P, jerk, 0.0, endOf(i + 1));
  };
  auto arrived = [&] {
    const bool target_done = !next.started && cur.t >= cur.prof.duration() && prev.remaining() <= 0.0;
    return target_done && (legs[i].fast || (fl.veh.position() - legs[i].target).norm() <= P.radius);
  };
  prepareNext();
  while (true) {
    const bool blend = legs[i].fast && next.prof.duration() > 0.0 && cur.prof.duration() > 0.0;
    if (!arrived()) {
      const double dts = rec.dt() * fl.clock;
      prev.advance(dts);
      cur.advance(dts);
      if (blend && !next.started && cur.t >= cur.prof.decelStartTime() && cur.remaining() <= next.prof.accelEndTime() &&
          mayStartNext(cur, next, P)) {
        next.started = true;
      }
      if (next.started) next.advance(dts);
      Eigen::Vector3d p, v, a, pp, vp, ap, pn, vn, an;
      cur.state(cur.t, p, v, a);
      prev.state(prev.t, pp, vp, ap);
      next.state(next.started ? next.t : 0.0, pn, vn, an);
      const Eigen::Vector3d prev_tail = prev.prof.duration() > 0.0 ? Eigen::Vector3d(pp - (prev.dest - prev.origin)) : Eigen::Vector3d::Zero();
      const Eigen::Vector3d z = Eigen::Vector3d::Zero();
      const Eigen::Vector3d pos = cur.origin + p + prev_tail + (next.started ? pn : z);
      fl.tick(pos, v + vp + (next.started ? vn : z), a + ap + (next.started ? an : z), phase, legs[i].step);
    }
    const bool passed = next.started && next.t >= cur.remaining();
    if (passed || arrived()) {
      // A step flown as several legs (RTL: the climb, then the leg home) is reached at the end of
      // its last leg: RTL over home, not where its climb ends.
      if (i + 1 >= legs.size() || legs[i + 1].step != legs[i].step) rec.reached(legs[i].step);
      if (passed) {
        rec.completed(legs[i].step);
        prev = cur;
        cur = next;
        cur.started = true;
        ++i;
        const double peak_before = cur.prof.peakSpeed();
        cur.changeSpeed(legs[i].speed_xy, legs[i].speed_up, legs[i].speed_dn);
        if (cur.prof.peakSpeed() > peak_before + 0.05) ++fl.replanned_faster;  // a second acceleration
        prepareNext();
        continue;
      }
      fl.hold(legs[i].target, legs[i].hold_s, phase, legs[i].step);
      rec.completed(legs[i].step);
      if (i + 1 >= legs.size()) {
        if (end_speed) *end_speed = cur.prof.at(cur.prof.duration()).vel;
        return legs[i].target;
      }
      here = legs[i].target;
      prev = Leg();
      ++i;
      cur = makeLeg(here, legs[i].target, legs[i], P, jerk);
      prepareNext();
    }
  }
}

LegSpec specOf(const NavStep& s, const Params& P, int k) {
  // A DO_CHANGE_SPEED above WPNAV_SPEED is flown (AC_WPNav::set_speed_xy does not cap it; the
  // airframe's lean limit and drag may).
  return {s.target, s.speed_xy > 0 ? s.speed_xy : P.speed_xy, s.speed_up > 0 ? s.speed_up : P.speed_up,
          s.speed_down > 0 ? s.speed_down : P.speed_dn, s.hold_s, k, false, s.kind == NavStep::Kind::SplineWaypoint};
}

// The spline segment of legs[k] from `origin`, entered along tangent `in` (zero from a stop), and
// left along the next leg (AC_WPNav::set_spline_destination): towards the waypoint after next when
// that is a spline too, else along the next straight leg; not at all (a stop) when legs[k] is not
// fast. `stale` [m/s] is the arrival limit the autopilot's curve object still holds (it sets only
// the origin speed limit). With
// `limit_by_next`, the arrival speed is also kept to what the next leg can start at; a next spline
// is built as AC_WPNav builds it in its next-leg object (_spline_next_leg), from the arrival limit
// that object holds, `*next_stale` [m/s] (the last spline built there, unlimited; 0 at boot),
// which is then updated.
detail::SplineCurve splineOf(const std::vector<LegSpec>& legs, std::size_t k, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& in, const Params& P, double jerk, double stale, double* next_stale,
                             bool limit_by_next = true) {
  const LegSpec& s = legs[k];
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const bool next = s.fast && k + 1 < legs.size();
  if (next) out = legs[k + 1].target - (legs[k + 1].spline ? origin : s.target);
  else if (s.fast && s.exit_to) out = *s.exit_to - s.target;
  const detail::SplineLimits lim{s.speed_xy, s.speed_up, s.speed_dn, P.accel_xy, P.accel_z, P.spline_lateral};
  detail::SplineCurve c(origin, s.target, in, out, lim, stale);
  if (next && limit_by_next && !out.isZero()) {
    if (legs[k + 1].spline) {
      const detail::SplineCurve n = splineOf(legs, k + 1, s.target, out, P, jerk, *next_stale, nullptr, false);
      *next_stale = n.destinationSpeedMax();
      c.limitDestinationSpeed(n.originSpeedMax());
    } else {
      c.limitDestinationSpeed(makeLeg(s.target, legs[k + 1].target, legs[k + 1], P, jerk).prof.peakSpeed());
    }
  }
  return c;
}

// Flies spline segment `c` of leg `s` from target speed `speed` [m/s]; returns the target speed at
// its end. It is reached when its curve ends there, and, at a stop, when the vehicle is also within
// WPNAV_RADIUS (AC_WPNav::advance_wp_target_along_track); then its hold.
double flySpline(Flight& fl, detail::SplineCurve& c, const LegSpec& s, const Params& P, FlightPhase phase, double speed) {
  while (true) {
    Eigen::Vector3d pos, vel;
    c.advance(fl.rec.dt() * fl.clock, speed, pos, vel);
    fl.tick(pos, vel, Eigen::Vector3d::Zero(), phase, s.step);
    if (c.reached() && (s.fast || (fl.veh.position() - s.target).norm() <= P.radius)) break;
  }
  fl.rec.reached(s.step);
  fl.hold(s.target, s.hold_s, phase, s.step);
  fl.rec.completed(s.step);
  return s.fast ? speed : 0.0;
}

// Flies a chain (chainFrom) from `here`: runs of straight legs as S-curve chains (flyChain), spline
// legs as spline segments, joined at the speed both allow (AC_WPNav::set_spline_destination_next,
// set_wp_destination_next); returns where the vehicle stops.
Eigen::Vector3d flyRoute(Flight& fl, const std::vector<LegSpec>& legs, const Eigen::Vector3d& here, const Params& P,
                         FlightPhase phase, double jerk, double* end_speed) {
  *end_speed = 0.0;
  if (std::none_of(legs.begin(), legs.end(), [](const LegSpec& l) { return l.spline; }))
    return flyChain(fl, legs, here, P, phase, jerk);
  Eigen::Vector3d origin = here, in = Eigen::Vector3d::Zero();
  double speed = 0.0;
  for (std::size_t a = 0; a < legs.size();) {
    if (legs[a].spline) {
      // The spline flown: only its origin speed limit would depend on the arrival limit its curve
      // object holds, and the speed it starts at is the one the leg before hands over, so 0 does.
      detail::SplineCurve c = splineOf(legs, a, origin, in, P, jerk, 0.0, &fl.spline_next_stale);
      speed = flySpline(fl, c, legs[a], P, phase, speed);
      in = legs[a].fast ? c.destinationTangent() : Eigen::Vector3d::Zero();
      origin = legs[a].target;
      ++a;
      continue;
    }
    std::size_t b = a;
    while (b + 1 < legs.size() && !legs[b + 1].spline) ++b;
    const Eigen::Vector3d leg_origin = b > a ? legs[b - 1].target : origin;
    double v_end = 0.0;
    if (b + 1 < legs.size()) {  // a straight leg into a spline: the spline is built as the next leg
      const detail::SplineCurve n =
          splineOf(legs, b + 1, legs[b].target, legs[b].target - leg_origin, P, jerk, fl.spline_next_stale, nullptr, false);
      fl.spline_next_stale = n.destinationSpeedMax();
      v_end = n.originSpeedMax();
    }
    flyChain(fl, {legs.begin() + static_cast<std::ptrdiff_t>(a), legs.begin() + static_cast<std::ptrdiff_t>(b) + 1}, origin, P, phase,
             jerk, speed, v_end, &speed);
    in = legs[b].fast ? Eigen::Vector3d(legs[b].target - leg_origin) : Eigen::Vector3d::Zero();
    origin = legs[b].target;
    a = b + 1;
  }
  if (legs.back().fast) *end_speed = speed;  // a spline flown through into a landing's approach
  return origin;
}

// The waypoints from step k on that the vehicle flies without stopping, up to the first stop.
std::vector<LegSpec> chainFrom(const std::vector<NavStep>& steps, std::size_t k, const Eigen::Vector3d& here,
                               const Params& P, bool stop_all) {
  std::vector<LegSpec> legs;
  for (std::size_t j = k; j < steps.size() && isFlownTo(steps[j]); ++j) {
    LegSpec spec = specOf(steps[j], P, static_cast<int>(j));
    if (!steps[j].has_position) spec.target = legs.empty() ? here : legs.back().target;
    const bool next_flown = j + 1 < steps.size() && isFlownTo(steps[j + 1]) && steps[j + 1].has_position;
    spec.fast = steps[j].kind != NavStep::Kind::LoiterTime && steps[j].hold_s <= 0.0 && next_flown && !stop_all;
    // A spline with no hold flies through into a NAV_LAND with a position after it
    // (ModeAuto::get_spline_from_cmd takes any next navigation item's location as its exit, and
    // set_next_wp plans no next leg), whose approach then starts at the spline's end speed.
    if (spec.spline && steps[j].hold_s <= 0.0 && !stop_all && j + 1 < steps.size() && steps[j + 1].kind == NavStep::Kind::Land &&
        steps[j + 1].has_position) {
      const Eigen::Vector3d land{steps[j + 1].target.x(), steps[j + 1].target.y(), spec.target.z()};
      if ((land - spec.target).norm() > 0.01) spec.fast = true, spec.exit_to = land;
    }
    legs.push_back(spec);
    if (!spec.fast) break;
  }
  return legs;
}

// NAV_LOITER_TURNS (ModeAuto::do_circle): from `here`, where the leg before it stopped, fly to the
// closest point of the circle (a stop leg, only when more than 3 m from it:
// circle_movetoedge_start), then circle: AC_Circle's target point runs round at CIRCLE_RATE (or
// what the speed and half the acceleration limit allow) and reaches it at WPNAV_ACCEL / radius; the
// position controller takes it through its input shaper (no velocity given), whose desired state
// the vehicle chases. Done when the target has turned the turns (verify_circle); the next leg then
// starts afresh from the vehicle's stopping point (wp_start: the waypoint controller was idle).
Eigen::Vector3d flyLoiterTurns(Flight& fl, const NavStep& st, const Params& P, FlightPhase phase, int k, Eigen::Vector3d here) {
  const double speed = st.speed_xy > 0.0 ? st.speed_xy : P.speed_xy;
  const Eigen::Vector3d center = detail::circleCenter(st, here);
  const Eigen::Vector2d heading = fl.veh.velocity().head<2>();
  const Eigen::Vector3d edge = detail::circleEdge(center, st.loiter_radius_m, fl.veh.stoppingPoint(), heading);
  if ((fl.veh.position() - edge).norm() > detail::kCircleEdgeDistance) {
    LegSpec to_edge = specOf(st, P, k);
    to_edge.target = edge;
    to_edge.hold_s = 0.0;
    here = flyChain(fl, {to_edge}, here, P, phase, P.jerk);
  }
  fl.rec.reached(k);
  // circle_start: AC_Circle::init restarts the position controller at its stopping point.
  const Eigen::Vector3d start = fl.veh.stoppingPoint();
  detail::CircleTarget circle(st, center, P.circle_rate, speed, P.accel_xy, start);
  fl.rec.note(circle.note());
  detail::InputShaper shaper(speed, P.accel_xy, P.jerk_xy);
  shaper.reset(start.head<2>());
  const double z = here.z();
  while (!circle.done()) {
    const Eigen::Vector3d t = circle.step(fl.rec.dt());
    shaper.step(t.head<2>(), fl.rec.dt());
    const Eigen::Vector2d& p = shaper.position();
    const Eigen::Vector2d& v = shaper.velocity();
    const Eigen::Vector2d& a = shaper.acceleration();
    fl.tick({p.x(), p.y(), z}, {v.x(), v.y(), 0.0}, {a.x(), a.y(), 0.0}, phase, k);
  }
  fl.rec.completed(k);
  // wp_start: the waypoint controller, idle while circling, starts at the stopping point.
  return fl.restartAtStoppingPoint(z);
}

// [m] How far a hovering vehicle's measured altitude is off its position target: a leg from the
// target to the measured altitude is never of zero length, and AC_WPNav flies even a leg of
// millimetres as a whole S-curve (0.6-1.1 s for 1 mm-1 cm). The measured vertical tracking error,
// else kHoldOffset (the ArduCopter 4.7 SITL logs: 0.2-1.4 cm, a 0.75-1.1 s pause before the return).
double hoverOffset(const FlightSettings& s) { return std::max(s.tracking_error.vertical_m, kHoldOffset); }

// [m] The RTL's return altitude from `here` [m, home at the origin] (ModeRTL::compute_return_target):
// RTL_ALT, at least RTL_CLIMB_MIN above the vehicle (and 0.3 m, RTL_ALT_MIN); with RTL_CONE_SLOPE
// >= 0.5 no higher than the cone's slope x the distance home, yet not below a floor: from 4.5 (PR
// 25660) max(0.3 m, here + RTL_CLIMB_MIN), before it 2.5 m above the vehicle (RTL_ABS_MIN_CLIMB,
// so near home the vehicle always climbs 2.5 m); never a descent.
double returnAltitude(const Params& P, const Eigen::Vector3d& here) {
  const double curr = here.z();
  double alt = std::max({P.rtl_alt, curr + P.rtl_climb_min, 0.3});
  if (P.rtl_cone_slope >= 0.5) {
    const double floor = P.rtl_floor_relative ? curr + 2.5 : std::max(0.3, curr + P.rtl_climb_min);
    alt = std::min(alt, std::max(std::hypot(here.x(), here.y()) * P.rtl_cone_slope, floor));
  }
  return std::max(alt, curr);
}

void land(Recorder& rec, const Params& P, double speed_dn, int step, const FlightSettings& s) {
  const double v_hi = std::max(P.land_speed_high > 0.0 ? P.land_speed_high : speed_dn, P.land_speed);
  const double alt_low = std::max(P.land_alt_low, 1.0);
  auto law = [&](double h) {
    if (h <= alt_low) return P.land_speed;
    return std::clamp(std::abs(detail::sqrtController(alt_low - h, P.pos_z_p, P.accel_z)), P.land_speed, v_hi);
  };
  detail::descendAndLand(rec, law, P.accel_z, step, P.land_wind_down_s + s.landed_detect_s);
}

}  // namespace

FlownMission flyArduCopterSCurve(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s) {
  const Params P = readParams(ap);
  Recorder rec(s, steps.size());
  rec.startOnGround(P.spool_s + P.slew_s);
  Flight fl{rec, detail::PositionFollower(P.gains, s.airframe)};
  Eigen::Vector3d here = Eigen::Vector3d::Zero();
  FlightPhase phase = FlightPhase::Mission;
  double carried = 0.0;  // [m/s] target speed a spline hands to the landing approach after it
  for (std::size_t k = 0; k < steps.size();) {
    const NavStep& st = steps[k];
    const int ki = static_cast<int>(k);
    if (st.kind == NavStep::Kind::Takeoff) {
      // ModeAuto::takeoff_start: at least 1 m above the vehicle when it is on the ground, at least
      // where it is when it is in the air (a take-off below it is complete at once).
      const bool landed = here.z() < 0.5;
      const double top = std::max(st.target.z(), here.z() + (landed ? 1.0 : 0.0));
      if (top - here.z() < 0.01) {
        rec.reached(ki);
        rec.completed(ki);
      } else {
        LegSpec up = specOf(st, P, ki);
        up.target = {here.x(), here.y(), top};
        here = flyChain(fl, {up}, here, P, FlightPhase::Takeoff, P.jerk_z);
      }
      ++k;
    } else if (isFlownTo(st)) {
      const std::vector<LegSpec> legs = chainFrom(steps, k, here, P, s.stop_at_waypoints);
      here = flyRoute(fl, legs, here, P, phase, P.jerk, &carried);
      k += legs.size();
    } else if (st.kind == NavStep::Kind::Delay) {
      rec.reached(ki);
      fl.hold(here, st.hold_s, phase, ki);
      rec.completed(ki);
      ++k;
    } else if (st.kind == NavStep::Kind::LoiterTurns) {
      here = flyLoiterTurns(fl, st, P, phase, ki, here);
      ++k;
    } else if (st.kind == NavStep::Kind::ReturnToLaunch) {
      // RTL starts from where the vehicle would stop now (it may still be moving or lagging), the
      // controller afresh (ModeRTL::init runs AC_WPNav::wp_and_spline_init).
      here = fl.restartAtStoppingPoint(here.z());
      double alt = returnAltitude(P, here);
      // The climb leg runs from the position target to the measured altitude at least.
      alt = std::max(alt, here.z() + hoverOffset(s));
      LegSpec climb{{here.x(), here.y(), alt}, P.rtl_speed, P.speed_up, P.speed_dn, 0.0, ki, true};
      LegSpec home{{0.0, 0.0, alt}, P.rtl_speed, P.speed_up, P.speed_dn, P.rtl_loiter_s, ki, false};
      here = flyChain(fl, {climb, home}, here, P, FlightPhase::Return, P.jerk);
      if (P.rtl_alt_final > 0.0) {
        here = flyChain(fl, {{{0.0, 0.0, P.rtl_alt_final}, P.rtl_speed, P.speed_up, P.speed_dn, 0.0, ki, false}}, here, P,
                        FlightPhase::Return, P.jerk_z);
        rec.note("RTL_ALT_FINAL > 0: the vehicle hovers at " + std::to_string(P.rtl_alt_final) + " m; the prediction ends there");
      } else {
        land(rec, P, P.speed_dn, ki, s);
      }
      rec.completed(ki);
      ++k;
    } else {  // Land
      if (st.has_position) {
        // ModeAuto::do_land flies to the point at the vehicle's measured altitude
        // (shift_alt_to_current_alt): a leg from the last target that is never of zero length, even
        // over the waypoint the vehicle stopped at, flown as a whole S-curve (as RTL's climb leg).
        LegSpec over = specOf(st, P, ki);
        over.target.z() = here.z() + hoverOffset(s);
        // The approach at altitude is a mission leg; the landing phase is the descent.
        here = flyChain(fl, {over}, here, P, FlightPhase::Mission, P.jerk, std::exchange(carried, 0.0));
      }
      // ModeAuto::land_start sets the descent limit back to WPNAV_SPEED_DN (get_default_speed_down:
      // the parameter, not a DO_CHANGE_SPEED of type 3), which land_run_vertical_control caps at.
      land(rec, P, P.speed_dn, ki, s);
      rec.reached(ki);
      rec.completed(ki);
      ++k;
    }
  }
  if (fl.replanned_faster > 0) {
    rec.note(std::to_string(fl.replanned_faster) + " leg(s) after a waypoint flown through are commanded faster than the leg "
             "before: ArduCopter " + ap.version + " plans such a leg when the waypoint before it starts, at the speed then in "
             "force, and re-plans it when its DO_CHANGE_SPEED runs as that waypoint is reached; the prediction flies them so, "
             "with a second acceleration after the first (a speed command written a waypoint earlier avoids it)");
  }
  rec.model("ArduCopter " + ap.version + " S-curve model: WPNAV_SPEED " + detail::num(P.speed_xy) + " m/s, WPNAV_ACCEL " +
           detail::num(P.accel_xy) + " m/s/s, jerk " + detail::num(P.jerk) + " m/s/s/s, snap " +
           detail::num(P.snap) + " m/s^4, WPNAV_RADIUS " + detail::num(P.radius) + " m, RTL speed " +
           detail::num(P.rtl_speed) + " m/s (RTL_SPEED, else WPNAV_SPEED); lift-off " + detail::num(P.spool_s + P.slew_s) +
           " s after the take-off command (MOT_SPOOL_TIME, then the take-off throttle slew TKOFF_SLEW_TIME x MOT_THST_HOVER; "
           "ARMING_DELAY_SEC's 2 s from arming is not counted)");
  return rec.take(steps);
}

}  // namespace wattswath::mission
