#pragma once
/// @file measurement_check.hpp
/// Is a log a measurement of a flying multirotor? Checked before any replay, diagnosis or fit
/// (issue 19): the measured power against the vehicle's hover power from physics (a sensor stuck
/// at 0 A, a constant reading, a power far below hover while airborne), and the position estimate
/// (an EKF that diverged to impossible speeds or altitudes is cut off, or refused).

#include <string>
#include <vector>

#include "wattswath/energy/vehicle.hpp"
#include "wattswath/logs/flight_log.hpp"

namespace wattswath::calibration {

/// What a flying multirotor's log can show; beyond these limits the measurement is refused.
///
/// Power band: the median power of the airborne samples must lie in [min_hover_fraction,
/// max_hover_multiple] x energy::marinsHoverPowerW(vehicle). The lower edge, a quarter of the
/// physics hover power, is below what a perfect rotor (momentum theory, 100 % efficient motors
/// and propellers) needs to lift the vehicle's mass: marinsHoverPowerW = 2 P_ideal / eta_tot, so
/// 0.25 of it is P_ideal / (2 eta_tot), about 0.85 P_ideal for eta_tot = 0.585. A real log below it
/// is a sensor that is not measuring (or a vehicle 2.5 times lighter than the file says). The
/// upper edge, 8 times hover, is full thrust of a thrust-to-weight ratio of 4 (power grows with
/// thrust^1.5): no multirotor draws that as its median.
struct MeasurementLimits {
  double min_hover_fraction = 0.25;     ///< [-] lower edge of the power band (share of physics hover power); 0..1
  double max_hover_multiple = 8.0;      ///< [-] upper edge of the power band (multiple of physics hover power); >= 1
  double stuck_current_a = 0.1;         ///< [A] current within +-this in every airborne sample: stuck at 0; >= 0
  double constant_relative = 1e-4;      ///< [-] (max - min) / max|x| at most this: a constant reading; >= 0
  double max_vertical_speed = 15.0;     ///< [m/s] faster up or down is a diverged estimate (free fall reaches it after 11 m); > 0
  double max_horizontal_speed = 40.0;   ///< [m/s] faster is diverged (or twice the vehicle's max speed when higher); > 0
  double max_altitude_change = 2000.0;  ///< [m] farther up or down from the first sample is diverged; > 0
  double airborne_height = 1.0;         ///< [m] above the lowest sample counts as airborne when the log has no windows; >= 0
  double min_kept_s = 10.0;             ///< [s] a cut leaving less than this refuses the log instead; >= 0
  /// [-] airborne median voltage below this x the vehicle battery's full voltage is another battery (a note); 0..1
  double min_voltage_fraction = 0.5;
  /// [-] airborne median voltage above this x the vehicle battery's full voltage is another battery (a note); >= 1
  double max_voltage_multiple = 1.6;
  /// [-] airborne median voltage beyond this factor of the full voltage either way is a wrong unit
  /// (the log is refused, unless --trust-power); within it, a note only; >= 1
  double unit_factor = 5.0;
};

/// What checkMeasurement() found in one log.
struct MeasurementCheck {
  std::string power_problem;      ///< why the measured power is not a flying multirotor's; empty: plausible
  std::string position_problem;   ///< why the position estimate is unusable as a whole; empty: usable
  std::vector<std::string> notes; ///< what was cut, and checks that could not be made
  int airborne_samples = 0;       ///< [-] samples the power was checked on
  double median_power_w = 0.0;    ///< [W] median measured power of those samples
  double median_current_a = 0.0;  ///< [A] median battery current of those samples (NaN when not logged)
  double hover_power_w = 0.0;     ///< [W] the vehicle's hover power from physics (marinsHoverPowerW)
  bool cut = false;               ///< true when a diverged end of the position estimate was cut off
  double cut_at_s = 0.0;          ///< [s] log time of the first sample cut off (when `cut`)
};

/// Throws std::invalid_argument naming the field, its value and the range when out of range.
void validate(const MeasurementLimits& limits);

/// Checks `log` against `vehicle`: first the position estimate (a diverged end is cut off
/// `log.samples`, airborne windows clipped, the cut stated in `notes` and in metadata `warnings`;
/// a log diverged from the start, or with less than min_kept_s left, gets `position_problem`),
/// then the measured power of the airborne samples (log.airborne windows, else samples higher
/// than airborne_height above the lowest, else all). Never throws for what it finds.
MeasurementCheck checkMeasurement(logs::FlightLog& log, const energy::Vehicle& vehicle,
                                  const MeasurementLimits& limits = {});

}  // namespace wattswath::calibration
