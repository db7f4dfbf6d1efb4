#pragma once
/// @file scurve.hpp
/// Jerk-limited straight-line speed profiles of the kind ArduCopter 4.1 and later flies between
/// waypoints (its `SCurve`, libraries/AP_Math/SCurve.cpp): jerk rises and falls as a raised cosine
/// over a time tj = pi J / (2 S) set by the snap limit S, is held at J, and the acceleration is held
/// at A; 7 segments accelerate from rest to the leg speed within the first half of the leg, a
/// constant-speed segment follows, and 7 mirrored segments stop at the end. Our own implementation
/// of the same kinematics (docs/autopilots.md): the segment times are solved numerically
/// (bisection) where the autopilot uses closed-form roots.

#include <array>

namespace wattswath::mission {

/// Limits of one S-curve leg, in SI units.
struct SCurveLimits {
  double speed = 10.0;  ///< [m/s] speed along the track, > 0
  double accel = 2.5;   ///< [m/s^2] largest acceleration along the track, > 0
  double jerk = 1.0;    ///< [m/s^3] largest jerk, > 0
  double snap = 5.2;    ///< [m/s^4] largest snap (rate of change of jerk), > 0
};

/// Position, speed and acceleration along a track at one time.
struct TrackState {
  double pos = 0.0;  ///< [m] distance from the leg's origin
  double vel = 0.0;  ///< [m/s] speed along the track
  double acc = 0.0;  ///< [m/s^2] acceleration along the track
};

/// A rest-to-rest S-curve profile along a straight leg: 7 accelerating segments, 7 speed-change
/// segments (used when the speed limit changes in flight), a constant-speed segment and 7
/// decelerating segments (unused segments have zero duration), as ArduCopter's SCurve lays them out.
class SCurveProfile {
 public:
  /// A zero-length profile (duration 0).
  SCurveProfile() = default;
  /// The profile of a leg of `length` [m] from rest to rest under `limits`; throws
  /// std::invalid_argument when a limit is not positive and finite or the length is negative.
  static SCurveProfile restToRest(double length, const SCurveLimits& limits);
  /// The profile of a leg of `length` [m] that starts at `origin_speed` and ends at
  /// `destination_speed` [m/s] (each at most the rest-to-rest peak speed), as ArduCopter joins a
  /// straight leg to a spline (SCurve::set_origin_speed_max / set_destination_speed_max): the
  /// rest-to-rest peak is kept and each end's speed change starts (or ends) at its own speed.
  static SCurveProfile between(double length, double origin_speed, double destination_speed, const SCurveLimits& limits);

  /// Re-plans the leg for the speed limit `speed` [m/s] at `time` [s] after its start, as
  /// ArduCopter's SCurve::set_speed_max does when a DO_CHANGE_SPEED runs while the leg is flown:
  /// before the start the whole leg is planned anew; during the acceleration a faster speed is
  /// reached by a second speed change after the first (the first is not re-planned) and a slower
  /// one by cutting the constant-acceleration segment short; in the cruise the speed changes from
  /// the current speed; once braking has begun nothing changes. A speed change is planned only when
  /// the cruise lasts more than 12 jerk times (the autopilot's rule) and reaches at most the cruise
  /// length / (12 jerk times). A speed that is not positive and finite is ignored, as ArduCopter does.
  void setSpeedMax(double time, double speed);
  /// The speed limit the leg is planned for [m/s] (the last setSpeedMax, else the limits' speed).
  double speedMax() const { return limits_.speed; }

  /// State at time `t` [s] after the start (clamped to [0, duration()]).
  TrackState at(double t) const;
  /// Total time from start to end [s].
  double duration() const { return end_time_[kSegments - 1]; }
  /// Time at which the acceleration phase ends and constant speed begins [s].
  double accelEndTime() const { return end_time_[kAccelEnd]; }
  /// Time at which the deceleration phase begins [s].
  double decelStartTime() const { return end_time_[kConst]; }
  /// Length of the leg [m].
  double length() const { return length_; }
  /// Speed of the cruise (after the acceleration and any speed change) [m/s].
  double peakSpeed() const { return end_vel_[kSpeedChangeEnd]; }

  /// Number of segments (the initial rest state counts as segment 0).
  static constexpr int kSegments = 23;

 private:
  static constexpr int kAccelMax = 4;         // constant-acceleration segment of the acceleration phase
  static constexpr int kAccelEnd = 7;         // last segment of the acceleration phase
  static constexpr int kSpeedChangeEnd = 14;  // last segment of the in-flight speed change
  static constexpr int kConst = 15;           // the constant-speed segment
  static constexpr int kDecelEnd = 22;        // last segment
  enum class Kind { ConstJerk, IncrJerk, DecrJerk };
  void push(int& i, Kind kind, double duration, double jerk);
  void pushJerkRamp(int& i, double tj, double jerk, double t_const);
  void pushPhase(int& i, double tj, double jerk, double t2, double t4);
  void set(int k, Kind kind, double jerk, double time, double acc, double vel, double pos);
  void hold(int first, int last, int ref);
  void stretchCruise();
  void restartAfterSpeedChange();
  void restartInCruise(double time);
  void shortenAcceleration(double time);
  void planSpeedChangeSegments();
  void planDeceleration(double end_speed);

  double length_ = 0.0;
  SCurveLimits limits_{};
  std::array<Kind, kSegments> kind_{};
  std::array<double, kSegments> jerk_{};      // [m/s^3] peak (or constant) jerk of the segment
  std::array<double, kSegments> end_time_{};  // [s]
  std::array<double, kSegments> end_acc_{};   // [m/s^2]
  std::array<double, kSegments> end_vel_{};   // [m/s]
  std::array<double, kSegments> end_pos_{};   // [m]
};

/// Segment times of one speed change from `v0` to at most `vmax` [m/s] within `distance` [m].
struct SpeedChange {
  double jerk = 0.0;  ///< [m/s^3] jerk amplitude used
  double tj = 0.0;    ///< [s] duration of each raised-cosine jerk ramp
  double t2 = 0.0;    ///< [s] constant-jerk time of the rise (and of the fall)
  double t4 = 0.0;    ///< [s] constant-acceleration time
};

/// Plans the fastest jerk-limited speed-up from `v0` towards `vmax` [m/s] that ends at zero
/// acceleration within `distance` [m], under `limits` (ArduCopter's case analysis: the jerk ramp
/// is shortened when the acceleration limit cannot be reached, the constant-acceleration time
/// when the speed or the distance is the binding limit).
SpeedChange planSpeedChange(double v0, double vmax, double distance, const SCurveLimits& limits);

/// Distance [m] and speed gain [m/s] of a speed change `c` started at `v0` [m/s].
struct SpeedChangeExtent {
  double distance = 0.0;    ///< [m]
  double speed_gain = 0.0;  ///< [m/s]
  double duration = 0.0;    ///< [s]
};

/// The extent of speed change `c` started at speed `v0` [m/s].
SpeedChangeExtent extentOf(const SpeedChange& c, double v0);

}  // namespace wattswath::mission
