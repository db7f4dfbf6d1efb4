#pragma once
// Private to mission/src: the path ArduCopter flies to a NAV_SPLINE_WAYPOINT (HermiteSegment), and
// how 4.1 and later move the target along it, our own implementation of its SplineCurve (libraries/AP_Math/SplineCurve.cpp, docs/autopilots.md): a
// cubic Hermite curve from origin to destination whose end tangents come from the neighbouring
// waypoints, and a target that moves along it at the speed the curvature, the speed limits and the
// distance left to stop allow, changing speed by at most half the acceleration limit.
#include <Eigen/Core>

namespace wattswath::mission::detail {

/// The cubic Hermite segment ArduCopter flies to a spline waypoint (3.x AC_WPNav and 4.x
/// SplineCurve alike): from `origin` to `destination` [m] with end tangents [m per unit of the
/// curve parameter], both scaled down together when their lengths add to more than 4 x the chord.
class HermiteSegment {
 public:
  /// The segment; a zero chord is a point (every derivative zero).
  HermiteSegment(const Eigen::Vector3d& origin, const Eigen::Vector3d& destination, Eigen::Vector3d origin_tangent,
                 Eigen::Vector3d destination_tangent);
  /// [m] The point at parameter `t` in [0, 1].
  Eigen::Vector3d at(double t) const { return h_[0] + t * (h_[1] + t * (h_[2] + t * h_[3])); }
  /// [m] dP/dt at `t`.
  Eigen::Vector3d d1(double t) const { return h_[1] + 2.0 * t * h_[2] + 3.0 * t * t * h_[3]; }
  /// [m] d2P/dt2 at `t`.
  Eigen::Vector3d d2(double t) const { return 2.0 * h_[2] + 6.0 * t * h_[3]; }
  /// [m] d3P/dt3.
  Eigen::Vector3d d3() const { return 6.0 * h_[3]; }

 private:
  Eigen::Vector3d h_[4];  // P(t) = h0 + h1 t + h2 t^2 + h3 t^3
};

/// Limits of one spline segment, SI units.
struct SplineLimits {
  double speed_xy = 10.0;  ///< [m/s] horizontal speed (WPNAV_SPEED or the DO_CHANGE_SPEED in force)
  double speed_up = 2.5;   ///< [m/s] climb speed
  double speed_dn = 1.5;   ///< [m/s] descent speed
  double accel_xy = 2.5;   ///< [m/s^2] WPNAV_ACCEL
  double accel_z = 1.0;    ///< [m/s^2] WPNAV_ACCEL_Z
  double lateral = 0.5;    ///< [-] share of the acceleration limit for the normal acceleration
};

/// One spline segment and the target moving along it.
class SplineCurve {
 public:
  /// The segment from `origin` to `destination` [m] with Hermite tangents `origin_tangent` and
  /// `destination_tangent` [m per unit of the curve parameter]; a zero destination tangent stops
  /// there. Both are scaled down together when their lengths add to more than 4 x the chord.
  /// `previous_arrival_max` [m/s] is the arrival limit the autopilot's SplineCurve object still
  /// holds from its last segment (0 for its first): it reads it when it limits the origin speed.
  SplineCurve(const Eigen::Vector3d& origin, const Eigen::Vector3d& destination, const Eigen::Vector3d& origin_tangent,
              const Eigen::Vector3d& destination_tangent, const SplineLimits& limits, double previous_arrival_max = 0.0);
  /// [m/s] The highest speed the curve allows at its origin.
  double originSpeedMax() const { return origin_speed_max_; }
  /// [m/s] The speed the target may have on arriving (0 when it stops there).
  double destinationSpeedMax() const { return destination_speed_max_; }
  /// Lowers the arrival speed to at most `speed` [m/s] (what the next segment can start at).
  void limitDestinationSpeed(double speed);
  /// The destination tangent as given (unscaled): the next spline's origin tangent.
  const Eigen::Vector3d& destinationTangent() const { return destination_tangent_; }
  /// Advances the target by `dt` [s] from speed `speed` [m/s] (updated): `pos` [m] is the
  /// position at the parameter before the step, `vel` [m/s] the new velocity along the curve.
  void advance(double dt, double& speed, Eigen::Vector3d& pos, Eigen::Vector3d& vel);
  /// True once the target is at the destination (the curve parameter has reached 1).
  bool reached() const { return reached_; }
  /// The point of the curve at parameter `t` in [0, 1] [m].
  Eigen::Vector3d at(double t) const;

 private:
  struct Step {
    double dt_param = 0.0, speed_max = 0.0, accel_max = 0.0;
    Eigen::Vector3d pos = Eigen::Vector3d::Zero(), unit = Eigen::Vector3d::Zero();
  };
  Step step(double t, double distance, double arrival_max) const;
  Eigen::Vector3d destination_, destination_tangent_;
  HermiteSegment curve_;
  SplineLimits lim_;
  double time_ = 0.0, origin_speed_max_ = 0.0, destination_speed_max_ = 0.0;
  bool reached_ = false, zero_length_ = false;
};

}  // namespace wattswath::mission::detail
