// PX4 multicopter missions (FlightTaskAuto + PositionSmoothing): each cycle a desired velocity
// points at the current waypoint, its size limited by the cruise speed and by a braking law that
// arrives at the waypoint with the corner speed sqrt(MPC_XY_TRAJ_P MPC_ACC_HOR r tan(alpha/2))
// (0 at a stop); a jerk-limited tracker (MPC_ACC_HOR, MPC_JERK_AUTO) follows it. A waypoint is
// reached when the vehicle is within its acceptance radius (NAV_ACC_RAD) horizontally and
// NAV_MC_ALT_RAD vertically (docs/autopilots.md, section "PX4").
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flight_internal.hpp"

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

// Jerk-limited tracking of a desired velocity on one axis: acceleration towards the change,
// at most `a_max`, changing at most `jerk` per second and easing in (sqrt law) near the target.
void trackAxis(double v_des, double a_max, double jerk, double dt, double& v, double& a) {
  const double dv = v_des - v;
  const double a_des = std::copysign(std::min(a_max, std::sqrt(2.0 * jerk * std::abs(dv))), dv);
  a += std::clamp(a_des - a, -jerk * dt, jerk * dt);
  v += a * dt;
}

struct Flyer {
  Recorder& rec;
  const Params& P;
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();

  // One time step of the jerk-limited tracking towards `v_des` [m/s], not yet recorded.
  void advance(const Eigen::Vector3d& v_des, double acc_xy, double acc_z_up, double acc_z_dn) {
    const double dt = rec.dt();
    for (int i = 0; i < 2; ++i) trackAxis(v_des[i], acc_xy, P.jerk, dt, v[i], a[i]);
    trackAxis(v_des.z(), v_des.z() > v.z() ? acc_z_up : acc_z_dn, P.jerk, dt, v[2], a[2]);
    p += v * dt;
  }

  void step(const Eigen::Vector3d& v_des, double acc_xy, double acc_z_up, double acc_z_dn, FlightPhase phase, int k) {
    advance(v_des, acc_xy, acc_z_up, acc_z_dn);
    rec.tick(p, v, phase, k);
  }

  // [m/s] The horizontal desired velocity towards `xy` at up to `cruise`, arriving at `v_exit`.
  Eigen::Vector2d towards(const Eigen::Vector2d& xy, double cruise, double v_exit) const {
    const Eigen::Vector2d d = xy - p.head<2>();
    const double dxy = d.norm();
    if (dxy <= 1e-6) return Eigen::Vector2d::Zero();
    return d / dxy * std::min(cruise, brakingSpeed(P.jerk, P.acc, dxy, v_exit));
  }

  // Flies to `to` at `cruise`, leaving it at `v_exit` [m/s]; returns when it is reached.
  void flyTo(const Eigen::Vector3d& to, double cruise, double v_exit, double acc_rad, FlightPhase phase, int k) {
    while (true) {
      const Eigen::Vector3d d = to - p;
      if (d.head<2>().norm() <= acc_rad && std::abs(d.z()) <= P.alt_rad) return;
      Eigen::Vector3d v_des = Eigen::Vector3d::Zero();
      v_des.head<2>() = towards(to.head<2>(), cruise, v_exit);
      v_des.z() = std::clamp(detail::sqrtController(d.z(), 1.0, P.acc_down), -P.down, P.up);
      step(v_des, P.acc, P.acc_up, P.acc_down, phase, k);
    }
  }

  // Holds position at `at` for `seconds` [s], closing on it first if it is not there yet: the
  // setpoint stays on an item that is reached within its acceptance radius while its time runs.
  void holdAt(const Eigen::Vector3d& at, double cruise, double seconds, FlightPhase phase, int k) {
    const long n = std::lround(std::max(0.0, seconds) / rec.dt());
    for (long i = 0; i < n; ++i) {
      Eigen::Vector3d v_des = Eigen::Vector3d::Zero();
      v_des.head<2>() = towards(at.head<2>(), cruise, 0.0);
      v_des.z() = std::clamp(detail::sqrtController(at.z() - p.z(), 1.0, P.acc_down), -P.down, P.up);
      step(v_des, P.acc, P.acc_up, P.acc_down, phase, k);
    }
  }

  // Lands on the land position `xy` (FlightTaskAuto's land setpoints: the position held, or reached,
  // horizontally while the descent follows `law(h)` [m/s] of the height h [m]); returns on touch-down.
  template <class Law>
  void land(const Eigen::Vector2d& xy, double cruise, Law law, int k) {
    while (p.z() > 0.0) {
      Eigen::Vector3d v_des = Eigen::Vector3d::Zero();
      v_des.head<2>() = towards(xy, cruise, 0.0);
      v_des.z() = -law(p.z());
      advance(v_des, P.acc, P.acc_down, P.acc_down);
      if (p.z() <= 0.0) p.z() = 0.0, v.setZero(), a.setZero();
      rec.tick(p, v, FlightPhase::Landing, k);
    }
  }

  void hover(double seconds, FlightPhase phase, int k) {
    const long n = std::lround(seconds / rec.dt());
    for (long i = 0; i < n; ++i) step(Eigen::Vector3d::Zero(), P.acc, P.acc_up, P.acc_down, phase, k);
  }

  // Vertical flight to height `z` [m] at up to `speed` [m/s].
  void vertical(double z, double speed, double acc, FlightPhase phase, int k) {
    vertical(z, [&](double) { return std::make_pair(speed, acc); }, phase, k);
  }
  // Vertical flight to height `z` [m], the speed and acceleration limits [m/s, m/s^2] a function of
  // the height.
  template <class Limits>
  void vertical(double z, Limits limits, FlightPhase phase, int k) {
    while (std::abs(z - p.z()) > P.alt_rad * 0.5 || std::abs(v.z()) > 0.1) {
      const auto [speed, acc] = limits(p.z());
      Eigen::Vector3d v_des = Eigen::Vector3d::Zero();
      v_des.z() = std::clamp(detail::sqrtController(z - p.z(), 1.0, acc), -speed, speed);
      step(v_des, P.acc, acc, acc, phase, k);
    }
  }
};

// Corner speed at waypoint `here` between `from` and `next` (TrajectoryConstraints).
double cornerSpeed(const Eigen::Vector3d& from, const Eigen::Vector3d& here, const Eigen::Vector3d& next, const Params& P,
                   double acc_rad) {
  const Eigen::Vector2d a = (here - from).head<2>(), b = (next - here).head<2>();
  if (a.norm() < 1e-3 || b.norm() < std::max(acc_rad, 1e-3)) return 0.0;
  const double cos_turn = std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0);
  const double alpha = M_PI - std::acos(cos_turn);  // interior angle, pi = straight on
  if (alpha >= M_PI - 1e-6) return 1e9;
  return std::sqrt(P.traj_p * P.acc * acc_rad * std::tan(0.5 * alpha));
}

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
        return h < P.land_alt1 ? std::make_pair(std::min(P.tko_speed, P.up), ramp_acc) : std::make_pair(P.up, P.acc_up);
      };
      f.vertical(std::max(st.target.z(), 0.5), limits, FlightPhase::Takeoff, ki);
    } else if (isFlownTo(st)) {
      const Eigen::Vector3d to = st.has_position ? st.target : f.p;
      const double rad = st.accept_radius_m > 0.0 ? st.accept_radius_m : P.acc_rad;
      double v_exit = 0.0;
      const bool stop = st.hold_s > 0.0 || s.stop_at_waypoints || st.kind == NavStep::Kind::LoiterTime || k + 1 >= steps.size() ||
                        !steps[k + 1].has_position || steps[k + 1].kind == NavStep::Kind::ReturnToLaunch;
      if (!stop) v_exit = std::min(cruise, cornerSpeed(f.p, to, steps[k + 1].target, P, rad));
      f.flyTo(to, cruise, v_exit, rad, FlightPhase::Mission, ki);
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
        if (const double ret = returnAltitude(f.p, P); ret > f.p.z()) f.vertical(ret, P.up, P.acc_up, ph, ki);
        f.flyTo({0.0, 0.0, f.p.z()}, P.cruise, 0.0, P.acc_rad, ph, ki);
        if (f.p.z() > P.rtl_descend) f.flyTo({0.0, 0.0, P.rtl_descend}, P.cruise, 0.0, P.acc_rad, ph, ki);
        f.holdAt({0.0, 0.0, f.p.z()}, P.cruise, P.rtl_delay, ph, ki);
      } else if (st.has_position) {
        land_xy = st.target.head<2>();
        f.flyTo({st.target.x(), st.target.y(), f.p.z()}, cruise, 0.0, P.acc_rad, ph, ki);
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
  rec.note("PX4 " + ap.version + " model: MPC_XY_CRUISE " + detail::num(P.cruise) + " m/s, MPC_ACC_HOR " +
           detail::num(P.acc) + " m/s/s, MPC_JERK_AUTO " + detail::num(P.jerk) + " m/s/s/s, NAV_ACC_RAD " +
           detail::num(P.acc_rad) + " m; take-off at MPC_TKO_SPEED below MPC_LAND_ALT1, MPC_Z_V_AUTO_UP above; RTL returns at MPC_XY_CRUISE, at " +
           std::string(P.rtl_rule == 13 ? "the 1.13+" : P.rtl_rule == 10 ? "the 1.10-1.12" : "the pre-1.10") +
           " return altitude (RTL_RETURN_ALT, RTL_CONE_ANG, RTL_MIN_DIST); landing at " +
           std::string(P.land_step ? "MPC_LAND_SPEED below MPC_LAND_ALT1 (before 1.11)"
                                   : "MPC_LAND_SPEED below MPC_LAND_ALT2, graded up to the descent limit at MPC_LAND_ALT1"));
  return rec.take(steps);
}

}  // namespace wattswath::mission
