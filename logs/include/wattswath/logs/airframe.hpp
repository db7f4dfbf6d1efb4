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

/// What a log says about how fast the airframe's acceleration follows the position controller's.
struct ResponseEstimate {
  bool determined = false;  ///< false: the log does not determine the response (see reason)
  std::string reason;       ///< why not, when not determined
  double response_s = 0.0;  ///< [s] first-order lag of the achieved acceleration behind the target
  double r2 = 0.0;          ///< [-] share of the achieved acceleration's variance the lag explains
  std::size_t samples = 0;  ///< samples compared (north and east together)
};

/// The airframe one log identifies: its drag and its response.
struct AirframeEstimate {
  AirframeDragEstimate drag;    ///< the horizontal drag (estimateAirframeDrag)
  ResponseEstimate response;    ///< the acceleration's lag (ArduCopter 4.x PSCN/PSCE messages)
};

/// Identifies the drag from the ATT and EKF velocity messages of an ArduPilot DataFlash log.
/// Determined when at least 100 samples above 1 m/s reach 3 m/s and the fit explains at least
/// 80 % of the drag's variance. Throws std::runtime_error for an unreadable file or a log that is
/// not DataFlash (PX4 ULog: not supported yet, said in the message).
AirframeDragEstimate estimateAirframeDrag(const std::string& path, const LogReadOptions& options = {});

/// Identifies the drag (as estimateAirframeDrag) and the response from one reading of the log.
/// The response: the first-order lag that best turns the position controller's target
/// acceleration (PSCN.TAN, PSCE.TAE) into the acceleration the lean angles give (AN, AE, as
/// AC_PosControl logs them), the 10 Hz target interpolated in time and the lag simulated in 5 ms
/// steps, restarted after each gap over 0.5 s. Determined with at least 300 samples and at least
/// 80 % of the achieved acceleration's variance explained; ArduCopter logs PSCN/PSCE from 4.5 on.
/// Throws as estimateAirframeDrag.
AirframeEstimate estimateAirframe(const std::string& path, const LogReadOptions& options = {});

}  // namespace wattswath::logs
