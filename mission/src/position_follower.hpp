#pragma once
// Private to mission/src: the vehicle under ArduCopter 4.x's horizontal position controller
// (AC_PosControl::update_xy_controller: a square-root position loop on the target's position
// error plus the target velocity, a PID velocity loop on the filtered error plus the target acceleration, the lean-angle
// limit) flying an airframe with drag and a lagging attitude response (FlightSettings::Airframe),
// and the S-curve clock scaler AC_WPNav derives from how far the vehicle lags its target
// (AC_WPNav::advance_wp_target_along_track, `_track_scalar_dt`). Vertically the vehicle is taken
// to be on its target. docs/autopilots.md, "Tracking error".
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "flight_internal.hpp"

namespace wattswath::mission::detail {

/// Gains and limits of the horizontal position controller, in SI units.
struct PositionGains {
  double pos_p = 1.0;      ///< [1/s] PSC_POSXY_P
  double vel_p = 2.0;      ///< [1/s] PSC_VELXY_P
  double vel_i = 1.0;      ///< [1/s^2] PSC_VELXY_I
  double vel_imax = 10.0;  ///< [m/s^2] PSC_VELXY_IMAX
  double vel_d = 0.25;     ///< [-] PSC_VELXY_D: on the rate of change of the filtered velocity error
  double filt_e_hz = 5.0;  ///< [Hz] PSC_VELXY_FLTE: low-pass filter on the velocity error (0: none)
  double filt_d_hz = 5.0;  ///< [Hz] PSC_VELXY_FLTD: low-pass filter on its derivative (0: none)
  double accel = 2.5;      ///< [m/s^2] WPNAV_ACCEL: the square-root controller's deceleration
  double lean_accel = 5.66;  ///< [m/s^2] g tan(lean limit): the largest horizontal acceleration
  double scaler_tc = 2.5;  ///< [s] time constant of the S-curve clock scaler (WPNAV_ACCEL / WPNAV_JERK)
  double attitude_tc = 0.15;  ///< [s] ATC_INPUT_TC: the lean's lag when the airframe gives no response
};

/// The vehicle chasing the autopilot's target, one tick at a time.
class PositionFollower {
 public:
  PositionFollower(const PositionGains& g, const Airframe& a)
      : g_(g), a_(a), response_s_(std::max(a.response_s.value_or(g.attitude_tc), 0.0)) {}

  /// Places the vehicle at `p` at rest.
  void reset(const Eigen::Vector3d& p) {
    p_ = p;
    v_.setZero();
    lean_.setZero();
    integ_.setZero();
    reset_filter_ = true;
  }

  /// Advances `dt` [s] towards the target (position `tp` [m], velocity `tv` [m/s], acceleration
  /// `ta` [m/s^2]); returns the factor by which AC_WPNav advances its S-curve clock next tick.
  double step(const Eigen::Vector3d& tp, const Eigen::Vector3d& tv, const Eigen::Vector3d& ta, double dt) {
    if (!a_.track) {
      p_ = tp;
      v_ = tv;
      return 1.0;
    }
    updateScaler(tp, tv, dt);
    const Eigen::Vector2d e = (tp - p_).head<2>();
    Eigen::Vector2d vel_target = tv.head<2>();
    if (e.norm() > 1e-12) vel_target += e / e.norm() * sqrtController(e.norm(), g_.pos_p, g_.accel);
    const Eigen::Vector2d verr = filteredError(vel_target - v_.head<2>(), dt);
    Eigen::Vector2d cmd = ta.head<2>() + g_.vel_p * verr + integ_ + g_.vel_d * deriv_;
    if (cmd.norm() > g_.lean_accel) {
      cmd *= g_.lean_accel / cmd.norm();  // at the lean limit: the integrator holds (anti-windup)
    } else {
      integ_ += g_.vel_i * verr * dt;
      if (integ_.norm() > g_.vel_imax) integ_ *= g_.vel_imax / integ_.norm();
    }
    lean_ += (cmd - lean_) * std::min(1.0, dt / std::max(response_s_, dt));
    v_.head<2>() += (lean_ + drag(v_.head<2>())) * dt;
    p_.head<2>() += v_.head<2>() * dt;
    p_.z() = tp.z();
    v_.z() = tv.z();
    return scaler_;
  }

  /// Starts the waypoint controller afresh, as a mode such as RTL does (AC_WPNav::wp_and_spline_init):
  /// the S-curve clock at full speed (`_track_scalar_dt = 1`), and AC_PosControl::init_xy_controller's
  /// velocity loop: its filters reset and its integrator set to the lean acceleration minus the
  /// acceleration achieved, i.e. what holds the airframe's drag now.
  void restartController() {
    scaler_ = 1.0;
    reset_filter_ = true;
    integ_ = -drag(v_.head<2>());
  }

  /// Where the autopilot would bring the vehicle to rest from its state now
  /// (AC_PosControl::get_stopping_point_xy: linear near zero speed, v^2 / 2a beyond).
  Eigen::Vector3d stoppingPoint() const {
    const Eigen::Vector2d vh = v_.head<2>();
    const double v = vh.norm();
    if (v < 1e-9) return p_;
    const double d = stoppingDistance(v, g_.pos_p, g_.accel);
    Eigen::Vector3d out = p_;
    out.head<2>() += vh / v * d;
    return out;
  }

  const Eigen::Vector3d& position() const { return p_; }
  const Eigen::Vector3d& velocity() const { return v_; }

 private:
  // [m/s^2] The airframe's drag deceleration at horizontal ground velocity `vh` (in the wind).
  Eigen::Vector2d drag(const Eigen::Vector2d& vh) const { return airDrag(a_, vh); }

  // The velocity error as AC_PID_2D::update_all keeps it: low-passed (PSC_VELXY_FLTE), its rate of
  // change low-passed too (PSC_VELXY_FLTD) into deriv_; at the first call taken as it is.
  Eigen::Vector2d filteredError(const Eigen::Vector2d& raw, double dt) {
    auto alpha = [dt](double hz) { return hz > 0.0 ? dt / (dt + 1.0 / (2.0 * M_PI * hz)) : 1.0; };
    if (reset_filter_) {
      reset_filter_ = false;
      err_ = raw;
      deriv_.setZero();
      return err_;
    }
    const Eigen::Vector2d last = err_;
    err_ += (raw - err_) * alpha(g_.filt_e_hz);
    deriv_ += ((err_ - last) / dt - deriv_) * alpha(g_.filt_d_hz);
    return err_;
  }

  // _track_scalar_dt: slows the S-curve clock when the vehicle cannot keep up with its target.
  void updateScaler(const Eigen::Vector3d& tp, const Eigen::Vector3d& tv, double dt) {
    double raw = 1.0;
    const double tvn = tv.norm();
    if (tvn > 1e-9) {
      const Eigen::Vector3d dir = tv / tvn;
      Eigen::Vector3d err = tp - p_;
      err.z() = 0.0;
      raw = std::clamp(0.05 + (v_.dot(dir) - g_.pos_p * err.dot(dir)) / tvn, 0.0, 1.0);
    }
    scaler_ += (raw - scaler_) * std::min(1.0, dt / g_.scaler_tc);
  }

  PositionGains g_;
  Airframe a_;
  double response_s_;  // [s] the achieved lean's first-order lag behind the command
  Eigen::Vector3d p_ = Eigen::Vector3d::Zero(), v_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d lean_ = Eigen::Vector2d::Zero(), integ_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d err_ = Eigen::Vector2d::Zero(), deriv_ = Eigen::Vector2d::Zero();  // filtered velocity error, its rate
  bool reset_filter_ = true;
  double scaler_ = 1.0;
};

}  // namespace wattswath::mission::detail
