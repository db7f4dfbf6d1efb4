#pragma once
/// @file airframe.hpp
/// The airframe's horizontal drag identified from an ArduPilot log: in flight the lean angle
/// tilts the thrust, and what that horizontal thrust does not spend on changing the velocity it
/// spends against drag, a_drag = (a_thrust - dv/dt) . v / |v|, with a_thrust = g tan(lean) in
/// the lean's direction (the thrust taken to hold the height). The drag deceleration is fitted
/// as c1 v + c2 v^2 (rotor momentum drag and body drag) by non-negative least squares over the
/// samples above 1 m/s. Ground speed is taken for airspeed: wind biases the result (docs/autopilots.md).

#include <cstddef>
#include <string>

#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::logs {

/// What a log says about its airframe's drag.
struct AirframeDragEstimate {
  bool determined = false;            ///< false: the log does not determine the drag (see reason)
  std::string reason;                 ///< why not, when not determined
  double drag_linear_per_s = 0.0;     ///< [1/s] c1
  double drag_quadratic_per_m = 0.0;  ///< [1/m] c2
  double r2 = 0.0;                    ///< [-] share of the drag's variance the fit explains
  double rms_mps2 = 0.0;              ///< [m/s^2] rms residual
  std::size_t samples = 0;            ///< samples above 1 m/s used
  double speed_max_mps = 0.0;         ///< [m/s] fastest sample used
  std::string velocity_source;        ///< message the velocity came from (XKF1, NKF1, EKF1, PSCN)
};

/// Identifies the drag from the ATT and EKF velocity messages of an ArduPilot DataFlash log.
/// Determined when at least 100 samples above 1 m/s reach 3 m/s and the fit explains at least
/// 80 % of the drag's variance. Throws std::runtime_error for an unreadable file or a log that is
/// not DataFlash (PX4 ULog: not supported yet, said in the message).
AirframeDragEstimate estimateAirframeDrag(const std::string& path, const LogReadOptions& options = {});

}  // namespace wattswath::logs
