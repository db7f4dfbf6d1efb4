// PX4 multicopter missions (FlightTaskAuto + PositionSmoothing): each cycle a desired velocity
// points at the current waypoint, its size limited by the cruise speed and by a braking law that
// arrives at the waypoint with the corner speed sqrt(MPC_XY_TRAJ_P MPC_ACC_HOR r tan(alpha/2))
// (0 at a stop); a jerk-limited tracker (MPC_ACC_HOR, MPC_JERK_AUTO) follows it. A waypoint is
// reached when the vehicle is within its acceptance radius (NAV_ACC_RAD) horizontally and
// NAV_MC_ALT_RAD vertically (docs/autopilots.md, section "PX4").
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "flight_internal.hpp"
#include "velocity_smoothing.hpp"

namespace wattswath::mission {
namespace {

using detail::Recorder;

struct Params {
  double cruise, vel_max, acc, jerk, traj_p, up, down, acc_up, acc_down, vel_max_dn, tko_speed, tko_ramp, land_speed,
      land_alt1, land_alt2, acc_rad, alt_rad, rtl_alt, rtl_descend, rtl_delay, rtl_cone_deg, rtl_min_dist, spool;
  int rtl_rule;  // the return altitude rule: 13 (PX4 1.13 and later), 10 (1.10-1.12), 0 (before the cone)
  bool land_step;  // before 1.11: MPC_LAND_SPEED below MPC_LAND_ALT1, no slow-down between ALT1 and ALT2
};

Params readParams(const AutopilotConfig& ap) {
  using detail::checkParameter;
  Params p{};
  p.cruise = checkParameter("MPC_XY_CRUISE", ap.get("MPC_XY_CRUISE"), 0.5, 30, "m/s");
  p.vel_max = checkParameter("MPC_XY_VEL_MAX", ap.get("MPC_XY_VEL_MAX"), 0.5, 30, "m/s");
  p.acc = checkParameter("MPC_ACC_HOR", ap.get("MPC_ACC_HOR"), 0.5, 20, "m/s/s");
  p.jerk = checkParameter("MPC_JERK_AUTO", ap.get("MPC_JERK_AUTO"), 0.5, 80, "m/s/s/s");
  p.traj_p = checkParameter("MPC_XY_TRAJ_P", ap.get("MPC_XY_TRAJ_P"), 0.1, 1, "-");
  p.up = checkParameter("MPC_Z_V_AUTO_UP", ap.get("MPC_Z_V_AUTO_UP"), 0.5, 8, "m/s");
  p.down = checkParameter("MPC_Z_V_AUTO_DN", ap.get("MPC_Z_V_AUTO_DN"), 0.5, 4, "m/s");
  p.acc_up = checkParameter("MPC_ACC_UP_MAX", ap.get("MPC_ACC_UP_MAX"), 0.5, 15, "m/s/s");
  p.acc_down = checkParameter("MPC_ACC_DOWN_MAX", ap.get("MPC_ACC_DOWN_MAX"), 0.5, 15, "m/s/s");
  p.vel_max_dn = checkParameter("MPC_Z_VEL_MAX_DN", ap.get("MPC_Z_VEL_MAX_DN"), 0.5, 4, "m/s");
  p.tko_speed = checkParameter("MPC_TKO_SPEED", ap.get("MPC_TKO_SPEED"), 0.2, 5, "m/s");
  p.tko_ramp = checkParameter("MPC_TKO_RAMP_T", ap.get("MPC_TKO_RAMP_T"), 0.0, 10, "s");
  p.land_speed = checkParameter("MPC_LAND_SPEED", ap.get("MPC_LAND_SPEED"), 0.2, 2, "m/s");
  p.land_alt1 = ap.get("MPC_LAND_ALT1");
  p.land_alt2 = ap.get("MPC_LAND_ALT2");
  p.acc_rad = checkParameter("NAV_ACC_RAD", ap.get("NAV_ACC_RAD"), 0.05, 200, "m");
  p.alt_rad = checkParameter("NAV_MC_ALT_RAD", ap.get("NAV_MC_ALT_RAD"), 0.05, 200, "m");
  p.rtl_alt = ap.get("RTL_RETURN_ALT");
  p.rtl_descend = ap.get("RTL_DESCEND_ALT");
  p.rtl_delay = std::max(0.0, ap.get("RTL_LAND_DELAY"));
  p.rtl_cone_deg = ap.get("RTL_CONE_ANG");
  p.rtl_min_dist = std::max(0.0, ap.get("RTL_MIN_DIST"));
  // A version without a number (a vehicle file that says only "PX4") takes the current rule.
  p.rtl_rule = versionAtLeast(ap.version, 1, 13) || !versionAtLeast(ap.version, 1, 0) ? 13
               : versionAtLeast(ap.version, 1, 10)                                    ? 10
                                                                                      : 0;
  p.spool = std::max(0.0, ap.get("COM_SPOOLUP_TIME"));
  // FlightTaskAutoMapper2::_prepareLandSetpoints (the 1.9 and 1.10 sources): the descent is at
  // MPC_LAND_SPEED below MPC_LAND_ALT1 and at the descent limit above; later versions
  // (FlightTaskAutoMapper::_getLandSpeed, math::gradual) slow down between MPC_LAND_ALT1 and _ALT2.
  p.land_step = versionAtLeast(ap.version, 1, 0) && !versionAtLeast(ap.version, 1, 11);
  return p;
}

// Largest speed [m/s] from which the vehicle can reach `v_end` within `d` [m] braking at `a`
// after a jerk delay (TrajMath computeMaxSpeedFromDistance): v^2 + (4 a^2 / j) v = 2 a d + v_end^2.
double brakingSpeed(double j, double a, double d, double v_end) {
  const double b = 4.0 * a * a / j;
  return std::max(0.5 * (-b + std::sqrt(b * b + 4.0 * (2.0 * a * d + v_end * v_end))), v_end);
}

// [m/s] Largest horizontal speed at `from` that reaches waypoint `to` at the speed its corner
// towards `next` allows and `next` at rest (TrajectoryConstraints computeXYSpeedFromWaypoints of
// [from, to, next]: the corner speed sqrt(MPC_XY_TRAJ_P MPC_ACC_HOR r tan(alpha / 2)) of the angle
// alpha at `to`, 0 when `next` is `to` or within the acceptance radius `rad` of it).
double xySpeed(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& next, double cruise,
               double rad, const Params& P) {
  const double to_next = (next - to).head<2>().norm();
  double at_to = 0.0;
  if (to_next > 0.001 && to_next >= rad) {
    const Eigen::Vector2d in = (to - from).head<2>(), out = (to - next).head<2>();
    const double c = in.norm() > 0.0 ? in.normalized().dot(out.normalized()) : 0.0;
    const double alpha = std::clamp(std::acos(std::clamp(c, -1.0, 1.0)), 0.0, M_PI - 1.1920929e-07);
    const double turn = std::sqrt(P.traj_p * P.acc * rad * std::tan(0.5 * alpha));
    at_to = std::min({turn, brakingSpeed(P.jerk, P.acc, to_next, 0.0), cruise});
  }
  return std::min(cruise, brakingSpeed(P.jerk, P.acc, (from - to).head<2>().norm(), at_to));
}

// Scales `v` down so that its horizontal (`xy` true) or vertical part is at most `limit`; only that
// part when both are below 0.5 m/s (TrajMath clampToXYNorm / clampToZNorm with PX4's accuracy).
void clampPart(Eigen::Vector3d& v, double limit, bool xy) {
  const double part = xy ? v.head<2>().norm() : std::abs(v.z());
  const double scale = part > 1.1920929e-07 ? limit / part : 1.0;
  if (scale >= 1.0) return;
  if (limit < 0.5 && part < 0.5) {
    if (xy) v.head<2>() *= scale;
    else v.z() *= scale;
  } else {
    v *= scale;
  }
}

// Vertical limits of a trajectory: speed [m/s] and acceleration [m/s^2].
struct ZLimits {
  double speed, acc;
};

// The vehicle's setpoint as PX4's position task generates it (PositionSmoothing): each tick a
// desired velocity from the waypoints, then three jerk-limited axes (JerkLimitedAxis) planning
// the quickest change to it, time-synchronised, flying one tick of the plan. The model flies the
// setpoint exactly (no tracking error, so no time stretch).
struct Flyer {
  Recorder& rec;
  const Params& P;
  std::array<detail::JerkLimitedAxis, 3> axes{};
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_wp = Eigen::Vector3d::Zero();  // the waypoint before the target (L1 line start)
  double speed_before_turn = 0.0;                     // [m/s] the speed limit kept while turning

  // One tick towards `v_des` [m/s]: horizontal limits MPC_JERK_AUTO, MPC_ACC_HOR, MPC_XY_VEL_MAX;
  // vertical `z` (speed and acceleration of the current direction), not recorded.
  void advance(const Eigen::Vector3d& v_des, ZLimits z) {
    for (int i = 0; i < 2; ++i) axes[i].setLimits(P.jerk, P.acc, P.vel_max);
    axes[2].setLimits(P.jerk, z.acc, std::max(z.speed, std::abs(v_des.z())));
    for (int i = 0; i < 3; ++i) axes[i].plan(v_des[i]);
    detail::synchronise(axes);
    for (int i = 0; i < 3; ++i) {
      axes[i].advance(rec.dt());
      p[i] = axes[i].position();
      v[i] = axes[i].velocity();
    }
  }

  void step(const Eigen::Vector3d& v_des, ZLimits z, FlightPhase phase, int k) {
    advance(v_des, z);
    rec.tick(p, v, phase, k);
  }

  // The mission's vertical limits towards height `z` [m]: MPC_Z_V_AUTO_UP / MPC_ACC_UP_MAX up,
  // MPC_Z_V_AUTO_DN / MPC_ACC_DOWN_MAX down.
  ZLimits zLimits(double z) const { return z > p.z() ? ZLimits{P.up, P.acc_up} : ZLimits{P.down, P.acc_down}; }

  // True while the horizontal velocity is more than about 11 degrees off the direction to `to`,
  // above 0.2 m/s and outside `rad` of it (PositionSmoothing::_isTurning).
  bool turning(const Eigen::Vector3d& to, double rad) const {
    const Eigen::Vector2d vel = v.head<2>(), d = (to - p).head<2>();
    if (vel.norm() <= 0.2 || d.norm() <= rad) return false;
    return vel.normalized().dot(d.normalized()) < 0.98;
  }

  // The point on the line prev_wp -> `to` at max(rad, 5 m) from the vehicle, or the foot of the
  // perpendicular when the line is farther (PositionSmoothing::_getL1Point).
  Eigen::Vector2d l1Point(const Eigen::Vector3d& to, double rad) const {
    const Eigen::Vector2d a = prev_wp.head<2>(), line = to.head<2>() - a;
    const Eigen::Vector2d u = line.norm() > 0.0 ? Eigen::Vector2d(line.normalized()) : Eigen::Vector2d::Zero();
    const Eigen::Vector2d closest = a + u * u.dot(p.head<2>() - a);
    const double cross = (closest - p.head<2>()).norm(), l1 = std::max(rad, 5.0);
    return closest + u * (l1 > cross ? std::sqrt(l1 * l1 - cross * cross) : 0.0);
  }

  // [m/s] The desired velocity towards waypoint `to` on the way to `next` (`to` itself: a stop),
  // PositionSmoothing::_generateVelocitySetpoint: aimed at `to`, or while turning at the L1 point
  // with the speed limit of before the turn; a straight line in 3-D scaled to the horizontal and
  // vertical limits.
  Eigen::Vector3d desired(const Eigen::Vector3d& to, const Eigen::Vector3d& next, double cruise, double rad, ZLimits z) {
    Eigen::Vector3d aim = to;
    double xy = xySpeed(p, to, next, cruise, rad, P);
    if (turning(to, rad)) {
      aim.head<2>() = l1Point(to, rad);
      xy = std::min(speed_before_turn, xy);
    } else {
      speed_before_turn = xy;
    }
    const double zs = std::min(z.speed, brakingSpeed(P.jerk, z.acc, std::abs(to.z() - p.z()), 0.0));
    const Eigen::Vector3d d = aim - p;
    Eigen::Vector3d vs = d.norm() > 0.0 ? Eigen::Vector3d(d.normalized() * std::hypot(xy, zs)) : Eigen::Vector3d::Zero();
    clampPart(vs, xy, true);
    clampPart(vs, zs, false);
    return vs;
  }

  // Flies to `to` leaving towards `next` (`to`: a stop) at up to `cruise`; returns when it is
  // within `acc_rad` horizontally and NAV_MC_ALT_RAD vertically; `to` becomes the previous waypoint.
  void flyTo(const Eigen::Vector3d& to, const Eigen::Vector3d& next, double cruise, double acc_rad, FlightPhase phase, int k) {
    while (true) {
      const Eigen::Vector3d d = to - p;
      if (d.head<2>().norm() <= acc_rad && std::abs(d.z()) <= P.alt_rad) break;
      const ZLimits z = zLimits(to.z());
      step(desired(to, next, cruise, acc_rad, z), z, phase, k);
    }
    prev_wp = to;
  }

  // Holds position at `at` for `seconds` [s], closing on it first if it is not there yet: the
  // setpoint stays on an item that is reached within its acceptance radius while its time runs.
  void holdAt(const Eigen::Vector3d& at, double cruise, double seconds, FlightPhase phase, int k) {
    const long n = std::lround(std::max(0.0, seconds) / rec.dt());
    for (long i = 0; i < n; ++i) {
      const ZLimits z = zLimits(at.z());
      step(desired(at, at, cruise, P.acc_rad, z), z, phase, k);
    }
  }

  // Lands on the land position `xy` (FlightTaskAuto's land setpoints: the position held, or reached,
  // horizontally while the descent follows `law(h)` [m/s] of the height h [m]); returns on touch-down.
  template <class Law>
  void land(const Eigen::Vector2d& xy, double cruise, Law law, int k) {
    while (p.z() > 0.0) {
      const Eigen::Vector3d at{xy.x(), xy.y(), p.z()};
      Eigen::Vector3d v_des = Eigen::Vector3d::Zero();
      v_des.head<2>() = desired(at, at, cruise, P.acc_rad, {0.0, P.acc_down}).head<2>();
      v_des.z() = -law(p.z());
      advance(v_des, {P.vel_max_dn, P.acc_down});
      if (p.z() <= 0.0) {
        p.z() = 0.0, v.setZero();
        for (int i = 0; i < 3; ++i) axes[i].reset(p[i], 0.0);
      }
      rec.tick(p, v, FlightPhase::Landing, k);
    }
  }

  void hover(double seconds, FlightPhase phase, int k) {
    const long n = std::lround(seconds / rec.dt());
    for (long i = 0; i < n; ++i) step(Eigen::Vector3d::Zero(), zLimits(p.z()), phase, k);
  }

  // Vertical flight to height `z` [m] at up to `speed` [m/s], done within NAV_MC_ALT_RAD of it.
  void vertical(double z, double speed, double acc, FlightPhase phase, int k) {
    vertical(z, P.alt_rad, [&](double) { return ZLimits{speed, acc}; }, phase, k);
  }
  // Vertical flight to height `z` [m] over the current position, the limits a function of the
  // height (PositionSmoothing with a target straight above or below where it started, so it comes
  // back to that point if it was still moving); done, as the navigator's item is reached, within
  // `accept` [m] of the height (MissionBlock: NAV_MC_ALT_RAD; a take-off only needs to be above
  // z - accept). The climb goes on into the next item.
  template <class Limits>
  void vertical(double z, double accept, Limits limits, FlightPhase phase, int k) {
    const Eigen::Vector3d to{p.x(), p.y(), z};
    while (z > p.z() ? z - p.z() >= accept : p.z() - z > accept) {
      const ZLimits lim = limits(p.z());
      step(desired(to, to, P.cruise, P.acc_rad, lim), lim, phase, k);
    }
  }
};

// [m] The altitude above home at which RTL returns (PX4 navigator, RTL_TYPE 0, home as the
// destination) from `here` [m, home at the origin], never below the current altitude.
// 1.13 and later (`RTL::computeReturnAltitude`, before 1.15 `calculate_return_alt_from_cone_half_angle`),
// with RTL_CONE_ANG > 0: RTL_RETURN_ALT; within RTL_MIN_DIST of home the cone's height there if
// lower, yet at least 2 NAV_ACC_RAD; within NAV_ACC_RAD twice the distance; RTL_CONE_ANG 0:
// RTL_RETURN_ALT. 1.10-1.12: within RTL_MIN_DIST RTL_DESCEND_ALT; else the cone's height capped at
// RTL_RETURN_ALT (RTL_RETURN_ALT without a cone); never below RTL_DESCEND_ALT. Before 1.10 (no
// RTL_CONE_ANG; the 1.9 log has none): RTL_RETURN_ALT.
double returnAltitude(const Eigen::Vector3d& here, const Params& P) {
  const double d = here.head<2>().norm();
  const auto coneHeight = [&] { return d / std::tan(std::clamp(P.rtl_cone_deg, 1.0, 89.0) * M_PI / 180.0); };
  if (P.rtl_rule == 0 || (P.rtl_rule == 13 && P.rtl_cone_deg <= 0.0)) return std::max(P.rtl_alt, here.z());
  if (P.rtl_rule == 13) {
    double alt = P.rtl_alt;
    if (d <= P.acc_rad) {
      alt = 2.0 * d;
    } else {
      if (d <= P.rtl_min_dist) alt = std::min(coneHeight(), alt);
      alt = std::max(alt, 2.0 * P.acc_rad);
    }
    return std::max(alt, here.z());
  }
  double alt = here.z();
  if (d <= P.rtl_min_dist) alt = P.rtl_descend;
  else if (here.z() > P.rtl_alt || P.rtl_cone_deg >= 90.0) alt = here.z();
  else if (P.rtl_cone_deg <= 0.0) alt = P.rtl_alt;
  else alt = std::max(here.z(), std::min(coneHeight(), P.rtl_alt));
  return std::max(alt, P.rtl_descend);
}

}  // namespace

FlownMission flyPx4(const std::vector<NavStep>& steps, const AutopilotConfig& ap, const FlightSettings& s) {
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (steps[k].kind == NavStep::Kind::LoiterTurns) {
      throw std::invalid_argument("step " + std::to_string(k) + " (mission item index " + std::to_string(steps[k].item) +
                                  "): NAV_LOITER_TURNS is not modelled for PX4 (the mission feasibility check of some "
                                  "PX4 versions rejects it as not yet supported, and how the others fly it was not "
                                  "read); the ArduCopter models fly it");
    }
  }
  const Params P = readParams(ap);
  Recorder rec(s, steps.size());
  rec.startOnGround(P.spool);
  Flyer f{rec, P};
  double cruise = P.cruise;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const NavStep& st = steps[k];
    const int ki = static_cast<int>(k);
    // The cruise speed in force: a DO_CHANGE_SPEED's, capped at MPC_XY_VEL_MAX, or MPC_XY_CRUISE
    // (the mission starts at it, and -1 returns to it).
    cruise = st.speed_xy_px4 > 0.0 ? std::min(st.speed_xy_px4, P.vel_max) : P.cruise;
    if (st.kind == NavStep::Kind::Takeoff) {
      // FlightTaskAuto::_updateTrajConstraints: below MPC_LAND_ALT1 the take-off climbs at
      // MPC_TKO_SPEED with the ramp's acceleration, above it at MPC_Z_V_AUTO_UP and MPC_ACC_UP_MAX.
      const double ramp_acc = P.tko_ramp > 0.0 ? std::min(P.acc_up, P.tko_speed / P.tko_ramp) : P.acc_up;
      const auto limits = [&](double h) {
        return h < P.land_alt1 ? ZLimits{std::min(P.tko_speed, P.up), ramp_acc} : ZLimits{P.up, P.acc_up};
      };
      // Reached once above the take-off height less NAV_MC_ALT_RAD, or half the height when that
      // is smaller (MissionBlock::position_achieved, NAV_CMD_TAKEOFF for a rotary wing).
      const double tko_alt = std::max(st.target.z(), 0.5);
      f.vertical(tko_alt, std::min(P.alt_rad, 0.5 * tko_alt), limits, FlightPhase::Takeoff, ki);
      f.prev_wp = f.p;
      // Mission::set_mission_items: after the climb the take-off item becomes a waypoint ("navigate
      // to the actual waypoint now") at its latitude and longitude, reached within NAV_ACC_RAD; a
      // mission leg, as a landing's approach is.
      if (st.takeoff_xy.allFinite() && (st.takeoff_xy - f.p.head<2>()).norm() > P.acc_rad) {
        const Eigen::Vector3d to(st.takeoff_xy.x(), st.takeoff_xy.y(), tko_alt);
        const bool stop = k + 1 >= steps.size() || !steps[k + 1].has_position || !isFlownTo(steps[k + 1]);
        f.flyTo(to, stop ? to : steps[k + 1].target, cruise, P.acc_rad, FlightPhase::Mission, ki);
      }
    } else if (isFlownTo(st)) {
      const Eigen::Vector3d to = st.has_position ? st.target : f.p;
      const double rad = st.accept_radius_m > 0.0 ? st.accept_radius_m : P.acc_rad;
      // The navigator's next item (a stop when there is none to fly on to).
      const bool stop = st.hold_s > 0.0 || s.stop_at_waypoints || st.kind == NavStep::Kind::LoiterTime || k + 1 >= steps.size() ||
                        !steps[k + 1].has_position || steps[k + 1].kind == NavStep::Kind::ReturnToLaunch;
      f.flyTo(to, stop ? to : steps[k + 1].target, cruise, rad, FlightPhase::Mission, ki);
      rec.reached(ki);
      if (st.hold_s > 0.0) f.holdAt(to, cruise, st.hold_s, FlightPhase::Mission, ki);
    } else if (st.kind == NavStep::Kind::Delay) {
      rec.reached(ki);
      f.hover(st.hold_s, FlightPhase::Mission, ki);
    } else {
      const bool rtl = st.kind == NavStep::Kind::ReturnToLaunch;
      const FlightPhase ph = rtl ? FlightPhase::Return : FlightPhase::Landing;
      // The navigator's items of RTL and of a mission LAND's approach are reached within NAV_ACC_RAD
      // (MissionBlock::setMoveToPositionMissionItem); the landing then holds the land position
      // horizontally, so the vehicle closes the rest of the way while it descends.
      Eigen::Vector2d land_xy = f.p.head<2>();
      double land_cruise = cruise;
      if (rtl) {
        land_xy.setZero();
        land_cruise = P.cruise;  // RTL starts at the default cruise speed (RTL/RtlDirect::on_activation)
        // A return altitude below the vehicle (before 1.13, near home) is reached in the descent below.
        // The return item flies at the return altitude, the climb item having ended within
        // NAV_MC_ALT_RAD of it (RTL_STATE_CLIMB, then RTL_STATE_RETURN at the same altitude).
        const double ret = std::max(returnAltitude(f.p, P), f.p.z());
        if (ret > f.p.z()) f.vertical(ret, P.up, P.acc_up, ph, ki);
        f.prev_wp = f.p;
        const Eigen::Vector3d over_home{0.0, 0.0, ret};
        f.flyTo(over_home, over_home, P.cruise, P.acc_rad, ph, ki);
        rec.reached(ki);  // over home (within NAV_ACC_RAD), before the descent to RTL_DESCEND_ALT and RTL_LAND_DELAY
        const Eigen::Vector3d descended{0.0, 0.0, P.rtl_descend};
        if (f.p.z() > P.rtl_descend) f.flyTo(descended, descended, P.cruise, P.acc_rad, ph, ki);
        f.holdAt({0.0, 0.0, f.p.z()}, P.cruise, P.rtl_delay, ph, ki);
      } else if (st.has_position) {
        land_xy = st.target.head<2>();
        const Eigen::Vector3d over{st.target.x(), st.target.y(), f.p.z()};
        // The approach at altitude is a mission leg; the landing phase is the descent.
        f.flyTo(over, over, cruise, P.acc_rad, FlightPhase::Mission, ki);
      }
      rec.reached(ki);
      auto law = [&](double h) {
        if (h >= P.land_alt1) return P.vel_max_dn;
        if (h <= P.land_alt2 || P.land_step) return P.land_speed;
        return P.land_speed + (P.vel_max_dn - P.land_speed) * (h - P.land_alt2) / (P.land_alt1 - P.land_alt2);
      };
      f.land(land_xy, land_cruise, law, ki);
      rec.hold(s.landed_detect_s, FlightPhase::Landing, ki, false);
    }
    if (st.kind == NavStep::Kind::Takeoff) rec.reached(ki);
    rec.completed(ki);
    if (st.kind == NavStep::Kind::ReturnToLaunch) {
      // The RTL's descend item asks for the heading the vehicle armed with, and the navigator lands
      // once the heading is within MIS_YAW_ERR (the real 1.9 return: 2.5 s; docs/validation.md 5.1).
      const double yaw_rate = ap.get("MPC_YAWRAUTO_MAX"), yaw_err = ap.get("MIS_YAW_ERR");
      if (yaw_rate > 0.0 && yaw_err >= 0.0 && yaw_err < 180.0) {
        rec.note("PX4's RTL turns to the heading the vehicle armed with before it lands, as the real 1.9 return does, until "
                 "within MIS_YAW_ERR " + detail::num(yaw_err) + " deg at up to MPC_YAWRAUTO_MAX " + detail::num(yaw_rate) +
                 " deg/s: up to " + detail::num((180.0 - yaw_err) / yaw_rate) +
                 " s of hover that the prediction leaves out, as it does not know that heading");
      }
    }
  }
  rec.model("PX4 " + ap.version + " model: MPC_XY_CRUISE " + detail::num(P.cruise) + " m/s, MPC_ACC_HOR " +
           detail::num(P.acc) + " m/s/s, MPC_JERK_AUTO " + detail::num(P.jerk) + " m/s/s/s, NAV_ACC_RAD " +
           detail::num(P.acc_rad) + " m; take-off at MPC_TKO_SPEED below MPC_LAND_ALT1, MPC_Z_V_AUTO_UP above; RTL returns at MPC_XY_CRUISE, at " +
           std::string(P.rtl_rule == 13 ? "the 1.13+" : P.rtl_rule == 10 ? "the 1.10-1.12" : "the pre-1.10") +
           " return altitude (RTL_RETURN_ALT, RTL_CONE_ANG, RTL_MIN_DIST); landing at " +
           std::string(P.land_step ? "MPC_LAND_SPEED below MPC_LAND_ALT1 (before 1.11)"
                                   : "MPC_LAND_SPEED below MPC_LAND_ALT2, graded up to the descent limit at MPC_LAND_ALT1"));
  return rec.take(steps);
}

}  // namespace wattswath::mission
