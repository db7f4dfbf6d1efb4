// ArduCopter spline segments and the 4.x target along them (spline_curve.hpp).
#include "spline_curve.hpp"

#include <algorithm>
#include <cmath>

#include "flight_internal.hpp"

namespace wattswath::mission::detail {
namespace {

constexpr double kSplineFactor = 4.0;   // tangents longer than this x the chord are scaled down
constexpr double kTangential = 0.5;     // share of the acceleration limit along the curve

}  // namespace

HermiteSegment::HermiteSegment(const Eigen::Vector3d& origin, const Eigen::Vector3d& destination, Eigen::Vector3d v0,
                               Eigen::Vector3d v1) {
  const Eigen::Vector3d chord = destination - origin;
  if (chord.squaredNorm() < 1e-12) {
    for (auto& h : h_) h.setZero();
    h_[0] = destination;
    return;
  }
  const double vel_len = v0.norm() + v1.norm(), pos_len = kSplineFactor * chord.norm();
  if (vel_len > pos_len) {
    v0 *= pos_len / vel_len;
    v1 *= pos_len / vel_len;
  }
  h_[0] = origin;
  h_[1] = v0;
  h_[2] = -3.0 * origin - 2.0 * v0 + 3.0 * destination - v1;
  h_[3] = 2.0 * origin + v0 - 2.0 * destination + v1;
}

SplineCurve::SplineCurve(const Eigen::Vector3d& origin, const Eigen::Vector3d& destination, const Eigen::Vector3d& origin_tangent,
                         const Eigen::Vector3d& destination_tangent, const SplineLimits& limits, double previous_arrival_max)
    : destination_(destination),
      destination_tangent_(destination_tangent),
      curve_(origin, destination, origin_tangent, destination_tangent),
      lim_(limits) {
  zero_length_ = (destination - origin).squaredNorm() < 1e-12;
  if (zero_length_) {
    time_ = 1.0;
    reached_ = true;
    return;
  }
  // SplineCurve::set_origin_and_destination: the origin limit is computed with the arrival limit
  // the object still holds; the arrival limit is computed into that same variable (an alias), so
  // its stopping-distance clause reads the curvature limit just found and leaves it unchanged.
  origin_speed_max_ = step(0.0, 0.0, previous_arrival_max).speed_max;
  destination_speed_max_ = destination_tangent.isZero() ? 0.0 : step(1.0, 0.0, 1e300).speed_max;
}

void SplineCurve::limitDestinationSpeed(double speed) { destination_speed_max_ = std::min(destination_speed_max_, speed); }

SplineCurve::Step SplineCurve::step(double t, double distance, double arrival_max) const {
  Step s;
  s.pos = curve_.at(t);
  const Eigen::Vector3d d1 = curve_.d1(t), d2 = curve_.d2(t), d3 = curve_.d3();
  const double d1n = d1.norm();
  if (d1n > 0.0) {
    s.unit = d1 / d1n;
    s.dt_param = distance / d1n;
  } else if (d2.squaredNorm() > 0.0) {  // at rest on the curve: the direction is the acceleration's
    s.unit = d2.normalized();
    s.dt_param = std::sqrt(2.0 * distance / d2.norm());
  } else {
    s.unit = d3.normalized();
    s.dt_param = std::cbrt(6.0 * distance / d3.norm());
  }
  // The speed whose normal acceleration is the lateral share of the limit in its direction.
  const Eigen::Vector3d a_norm = d2 - d2.dot(s.unit) * s.unit;
  const double a_norm_len = a_norm.norm();
  const double v_tan_max = kinematicLimit(s.unit, lim_.speed_xy, lim_.speed_up, lim_.speed_dn);
  const double a_norm_max =
      a_norm_len > 0.0 ? lim_.lateral * kinematicLimit(a_norm / a_norm_len, lim_.accel_xy, lim_.accel_z, lim_.accel_z) : 0.0;
  s.speed_max = v_tan_max;
  if (a_norm_max > 0.0 && a_norm_len > 0.0 && d1n > 0.0 && a_norm_len / a_norm_max > (d1n / v_tan_max) * (d1n / v_tan_max))
    s.speed_max = d1n / std::sqrt(a_norm_len / a_norm_max);
  s.accel_max = kTangential * kinematicLimit(s.unit, lim_.accel_xy, lim_.accel_z, lim_.accel_z);
  // Slow enough to stop (or reach the arrival speed) in the straight-line distance left.
  const double dist = (destination_ - s.pos).norm();
  if (arrival_max < 1e299) s.speed_max = std::min(s.speed_max, std::sqrt(2.0 * s.accel_max * dist + arrival_max * arrival_max));
  return s;
}

void SplineCurve::advance(double dt, double& speed, Eigen::Vector3d& pos, Eigen::Vector3d& vel) {
  if (zero_length_) {
    pos = destination_;
    vel.setZero();
    speed = 0.0;
    return;
  }
  const Step s = step(time_, speed * dt, destination_speed_max_);
  speed = std::clamp(s.speed_max, speed - s.accel_max * dt, speed + s.accel_max * dt);
  speed = std::max(speed, 0.0);
  pos = s.pos;
  vel = s.unit * speed;
  time_ += s.dt_param;
  if (time_ >= 1.0) {
    time_ = 1.0;
    reached_ = true;
  }
}

}  // namespace wattswath::mission::detail
