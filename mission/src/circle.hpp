#pragma once
// Private to mission/src: ArduCopter's NAV_LOITER_TURNS (ModeAuto::do_circle, AC_Circle): the
// closest point of the circle that the vehicle first flies to, the target point that then runs
// round the circle, and ArduCopter 4.x's input shaper that the position controller passes it
// through (AC_PosControl::input_pos_vel_accel_xy with no velocity or acceleration given).
// docs/autopilots.md, "NAV_LOITER_TURNS".
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "flight_internal.hpp"

namespace wattswath::mission::detail {

/// [rad/s^2] AC_CIRCLE_ANGULAR_ACCEL_MIN: the slowest angular acceleration of the target (2 deg/s^2).
inline constexpr double kCircleAngularAccelMin = 2.0 * M_PI / 180.0;
/// [m] ModeAuto::circle_movetoedge_start (4.x): nearer the edge than this, circling starts at once.
inline constexpr double kCircleEdgeDistance = 3.0;

/// The point of the circle round `center` [m, ENU] of `radius` [m] closest to `from` (horizontally),
/// at the centre's height (AC_Circle::get_closest_point_on_circle); from the centre itself, the
/// point behind `heading` (a horizontal direction; north when zero).
inline Eigen::Vector3d circleEdge(const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& from,
                                  const Eigen::Vector2d& heading) {
  Eigen::Vector2d d = (from - center).head<2>();
  if (d.norm() < 1e-9) d = heading.norm() > 1e-9 ? Eigen::Vector2d(-heading.normalized()) : Eigen::Vector2d(0.0, -1.0);
  const Eigen::Vector2d p = center.head<2>() + d.normalized() * radius;
  return {p.x(), p.y(), center.z()};
}

/// The centre of a LOITER_TURNS step: its position, or where the vehicle is (`here`, lat = lon = 0 in
/// the item) at the item's height.
inline Eigen::Vector3d circleCenter(const NavStep& st, const Eigen::Vector3d& here) {
  return st.has_position ? st.target : Eigen::Vector3d(here.x(), here.y(), st.target.z());
}

/// AC_Circle's target: an angle that speeds up at max(accel / radius, 2 deg/s^2) to the rate asked
/// (CIRCLE_RATE, negative counter-clockwise), capped at min(speed, sqrt(0.5 accel radius)) / radius,
/// and the point of the circle at that angle (a bearing: 0 north, clockwise positive).
class CircleTarget {
 public:
  /// The circle of LOITER_TURNS step `st` round `center` [m]: CIRCLE_RATE `rate_param` [rad/s] in
  /// the step's sense (ModeAuto::circle_movetoedge_start: |CIRCLE_RATE|, negative counter-clockwise),
  /// `speed` [m/s] and `accel` [m/s^2] the position controller's limits; the angle starts at the
  /// bearing of `start` from the centre (AC_Circle::init_start_angle).
  CircleTarget(const NavStep& st, const Eigen::Vector3d& center, double rate_param, double speed, double accel,
               const Eigen::Vector3d& start)
      : c_(center), r_(st.loiter_radius_m), goal_(2.0 * M_PI * st.loiter_turns), ccw_(st.loiter_ccw), where_(st.where) {
    const double rate = ccw_ ? -std::abs(rate_param) : std::abs(rate_param);
    const double edge_speed = std::sqrt(0.5 * accel * r_);  // [m/s] within half the acceleration limit
    const double w_cap = std::min(speed, edge_speed) / r_;
    w_max_ = std::clamp(rate, -w_cap, w_cap);
    cap_ = std::abs(rate) <= w_cap ? "CIRCLE_RATE" : speed <= edge_speed ? "the speed in force" : "half the acceleration limit";
    if (st.loiter_turns > 0.0 && std::abs(w_max_) < 1e-6) {
      throw std::invalid_argument("autopilot parameter CIRCLE_RATE = 0 deg/s: a NAV_LOITER_TURNS would never end "
                                  "(AC_Circle's target does not turn); expected a rate other than 0");
    }
    alpha_ = std::max(accel / r_, kCircleAngularAccelMin);
    const Eigen::Vector2d d = (start - center).head<2>();
    angle_ = d.norm() > 1e-9 ? std::atan2(d.x(), d.y()) : 0.0;
  }
  /// Advances the angle by `dt` [s] (AC_Circle::update); returns the target point [m, ENU].
  Eigen::Vector3d step(double dt) {
    if (w_ < w_max_) w_ = std::min(w_ + alpha_ * dt, w_max_);
    if (w_ > w_max_) w_ = std::max(w_ - alpha_ * dt, w_max_);
    angle_ += w_ * dt;
    total_ += w_ * dt;
    return {c_.x() + r_ * std::sin(angle_), c_.y() + r_ * std::cos(angle_), c_.z()};
  }
  /// True once the turns are flown (ModeAuto::verify_circle: |total angle| / 2 pi >= turns).
  bool done() const { return std::abs(total_) >= goal_; }
  /// [s] How long the target takes: the ramp, then the rest at the rate kept (or all in the ramp).
  double duration() const {
    const double w = std::abs(w_max_), ramp = w * w / (2.0 * alpha_);
    if (goal_ <= 0.0) return 0.0;
    return goal_ <= ramp ? std::sqrt(2.0 * goal_ / alpha_) : w / alpha_ + (goal_ - ramp) / w;
  }
  /// A note for the prediction, after the item's FILE:LINE when known: turns, radius and sense, the
  /// rate kept and what caps it, the time.
  std::string note() const {
    return (where_.empty() ? std::string() : where_ + ": ") + "NAV_LOITER_TURNS: " + num(goal_ / (2.0 * M_PI)) + " turn(s) of " + num(r_) + " m " +
           (ccw_ ? "counter-clockwise" : "clockwise") + " at " + num(std::abs(w_max_) * 180.0 / M_PI) + " deg/s (" +
           num(std::abs(w_max_) * r_) + " m/s on the circle; capped by " + cap_ + "), " + num(duration()) +
           " s after reaching the circle; the vehicle flies a little inside it (it chases a target it lags)";
  }

 private:
  Eigen::Vector3d c_;
  double r_, goal_;
  bool ccw_;
  double w_max_ = 0.0, alpha_ = 0.0, w_ = 0.0, angle_ = 0.0, total_ = 0.0;
  const char* cap_ = "CIRCLE_RATE";
  std::string where_;  // the item's FILE:LINE, or empty
};

/// ArduCopter 4.x's kinematic input shaper for a position given without velocity
/// (AC_PosControl::input_pos_vel_accel_xy: update_pos_vel_accel_xy, then shape_pos_vel_accel_xy of
/// AP_Math/control.cpp as of 2025: a square-root controller with gain 0.5 jerk / accel and
/// deceleration 0.5 accel on the position error, capped at the speed limit, then a square-root
/// controller with gain jerk / accel on the velocity error, the acceleration within `accel`
/// [m/s^2] and changed at most at `jerk` [m/s^3]). Its desired state chases the target: a point
/// moving round a circle is followed on a smaller one.
class InputShaper {
 public:
  InputShaper(double speed, double accel, double jerk) : vmax_(speed), amax_(accel), jmax_(jerk) {}
  /// Starts at `p` [m] at rest (AC_PosControl::init_xy_controller_stopping_point).
  void reset(const Eigen::Vector2d& p) {
    p_ = p;
    v_.setZero();
    a_.setZero();
  }
  /// One step of `dt` [s] towards `target` [m].
  void step(const Eigen::Vector2d& target, double dt) {
    p_ += v_ * dt + 0.5 * a_ * dt * dt;
    v_ += a_ * dt;
    Eigen::Vector2d vel_t = scaled(target - p_, 0.5 * jmax_ / amax_, 0.5 * amax_, dt);
    if (vel_t.norm() > vmax_) vel_t *= vmax_ / vel_t.norm();
    Eigen::Vector2d acc_t = scaled(vel_t - v_, jmax_ / amax_, jmax_, dt);
    if (acc_t.norm() > amax_) acc_t *= amax_ / acc_t.norm();
    Eigen::Vector2d da = acc_t - a_;
    if (da.norm() > jmax_ * dt) da *= jmax_ * dt / da.norm();
    a_ += da;
  }
  const Eigen::Vector2d& position() const { return p_; }      ///< [m] the desired position
  const Eigen::Vector2d& velocity() const { return v_; }      ///< [m/s] the desired velocity
  const Eigen::Vector2d& acceleration() const { return a_; }  ///< [m/s^2] the desired acceleration

 private:
  // AP_Math's vector sqrt_controller: along the error, at most |error| / dt.
  static Eigen::Vector2d scaled(const Eigen::Vector2d& e, double p, double lim, double dt) {
    const double n = e.norm();
    if (n <= 1e-12) return Eigen::Vector2d::Zero();
    const double c = std::min(std::abs(sqrtController(n, p, lim)), n / dt);
    return e * (c / n);
  }
  double vmax_, amax_, jmax_;
  Eigen::Vector2d p_ = Eigen::Vector2d::Zero(), v_ = Eigen::Vector2d::Zero(), a_ = Eigen::Vector2d::Zero();
};

}  // namespace wattswath::mission::detail
