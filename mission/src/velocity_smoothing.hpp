#pragma once
// Private to mission/src: PX4's jerk-limited velocity trajectory of one axis
// (src/lib/motion_planning/VelocitySmoothing, read as in docs/autopilots-source-notes.md), written
// in our own words. Each cycle the multicopter position task asks each axis for a velocity; the axis
// plans the quickest change to it with a jerk phase (T1), a constant-acceleration phase (T2) and a
// jerk phase back to zero acceleration (T3), and flies the first tick of that plan. The three axes
// are then stretched to end together (time synchronisation), so a change of velocity is a straight
// line in velocity space.
#include <array>

namespace wattswath::mission::detail {

/// One axis of PX4's VelocitySmoothing: state, limits and the current three-phase plan.
class JerkLimitedAxis {
 public:
  /// Sets the limits: jerk [m/s^3], acceleration [m/s^2] and speed [m/s] (all > 0).
  void setLimits(double max_jerk, double max_accel, double max_vel) {
    max_jerk_ = max_jerk;
    max_accel_ = max_accel;
    max_vel_ = max_vel;
  }
  /// Plans the quickest change to velocity `v_sp` [m/s] (clamped to the speed limit) from the
  /// current state (updateDurations).
  void plan(double v_sp);
  /// Re-plans the change to the same velocity to last `total_s` [s] (updateDurationsGivenTotalTime).
  void planInTime(double total_s);
  /// Flies the plan for `dt` [s] from where it was made (updateTraj).
  void advance(double dt);
  /// [s] Length of the current plan (T1 + T2 + T3).
  double totalTime() const { return t1_ + t2_ + t3_; }
  double acceleration() const { return a_; }  ///< [m/s^2] current acceleration
  double velocity() const { return v_; }      ///< [m/s] current velocity
  double position() const { return x_; }      ///< [m] current position
  /// Sets the state to position `x` [m] and velocity `v` [m/s] with no acceleration.
  void reset(double x, double v) {
    x_ = x;
    v_ = v;
    a_ = 0.0;
    x0_ = x, v0_ = v, a0_ = 0.0;
    t1_ = t2_ = t3_ = local_ = 0.0;
  }

 private:
  int direction() const;
  double max_jerk_ = 1.0, max_accel_ = 1.0, max_vel_ = 1.0;
  double x_ = 0.0, v_ = 0.0, a_ = 0.0;     // current state
  double x0_ = 0.0, v0_ = 0.0, a0_ = 0.0;  // state the plan starts from
  double v_sp_ = 0.0;                      // velocity planned to
  int dir_ = 0;                            // sign of the jerk of the first phase
  double t1_ = 0.0, t2_ = 0.0, t3_ = 0.0, local_ = 0.0;
};

/// Stretches the shorter plans of `axes` to end with the longest (timeSynchronization).
void synchronise(std::array<JerkLimitedAxis, 3>& axes);

}  // namespace wattswath::mission::detail
