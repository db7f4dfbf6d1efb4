#pragma once
/// @file mission_calibration.hpp
/// Logged flights of known missions against their prediction (mission/predict.hpp): time and
/// energy of the whole flight, of the take-off, the mission and the return, and the time of every
/// leg between waypoints, measured the same way on the log and on the predicted trajectory (each
/// waypoint passed, in turn, at the middle of the track's dwell near it: the closest approach for a
/// vehicle flying through, the middle of a stop for one that stops). Calibration fits the autopilot's
/// flight-behaviour parameters to those times (NLopt's Nelder-Mead on the simulated flights) and the energy
/// model's coefficients to the logged power on the logged kinematics (fitModel), and reports the
/// errors before and after.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/calibration/coverage.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/logs/flight_log.hpp"
#include "wattswath/mission/predict.hpp"

namespace wattswath::calibration {

/// A logged flight of a known mission. The log's frame is metres from where the vehicle armed;
/// the mission's home may differ by metres (alignTrack() finds the offset). The comparisons fly
/// the mission from the log's take-off point: the autopilot sets home where it arms and returns
/// there, whatever the file's home row says.
struct MissionFlight {
  std::string name;                ///< label (the log's file name)
  mission::Mission mission;        ///< what the autopilot was told
  logs::FlightLog log;             ///< what it flew, from the take-off command to touch-down
};

/// Times [s] of a flight's parts, measured on a trajectory.
struct FlightTimes {
  double total_s = 0.0;             ///< [s] first to last sample
  double takeoff_s = 0.0;           ///< [s] until the climb reaches 90 % of the first waypoint's height
  double mission_s = 0.0;           ///< [s] first to last waypoint passage
  double return_s = 0.0;            ///< [s] last waypoint passage to the end
  /// [s] when each waypoint is passed: the middle of the time the track spends within 2 m of its
  /// closest approach (entry and exit interpolated between samples; the closest sample when the
  /// track starts or ends inside), NaN when it never comes within the match distance
  std::vector<double> passage_s;
  std::vector<double> leg_s;        ///< [s] between consecutive matched passages (NaN when either is unmatched)
  std::vector<double> leg_energy_j; ///< [J] energy between consecutive passages (NaN when either is unmatched)
  std::vector<double> leg_speed_mps;  ///< [m/s] mean speed along the path between consecutive passages
  /// [m/s] highest horizontal speed between consecutive passages (each speed over a 1 s window, so a
  /// 1 Hz log and a 10 Hz prediction are measured alike; NaN when either passage is unmatched)
  std::vector<double> leg_peak_mps;
  double slow_s = 0.0;              ///< [s] time below 1 m/s horizontally between the first and last passage (NaN: none)
  double energy_j = 0.0;            ///< [J] electrical energy of the whole flight
  double mission_energy_j = 0.0;    ///< [J] energy between the first and last passage
};

/// Measured versus predicted for one flight.
struct FlightComparison {
  std::string name;                  ///< the flight
  FlightTimes measured;              ///< from the log
  FlightTimes predicted;             ///< from the predicted trajectory
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  ///< [m] log frame minus mission frame (east, north)
  /// [m] where the vehicle took off, east and north of the mission's home row: the prediction
  /// takes off and returns there (the autopilot sets home where it arms).
  Eigen::Vector2d launch = Eigen::Vector2d::Zero();
  double time_error_pct = 0.0;       ///< [%] total time, (predicted - measured) / measured
  double energy_error_pct = 0.0;     ///< [%] total energy
  double leg_time_mape_pct = 0.0;    ///< [%] mean absolute percentage error of the matched leg times
  int legs_matched = 0;              ///< legs with both passages matched
  /// [-] median over the matched legs of the measured peak speed over the predicted one
  /// (FlightTimes::leg_peak_mps; NaN without a leg whose predicted peak is 1 m/s or more)
  double leg_peak_ratio = 0.0;
  /// Why the log may not be of this mission (few of its waypoint passages found in the log, or
  /// the track laid onto the waypoints only at the alignment's search limit); empty when it fits.
  std::string match_problem;
};

/// [m] How far alignTrack searches for the logged track's offset from the mission's waypoints.
inline constexpr double kAlignSearchM = 30.0;

/// The translation [m] that best lays the logged track onto the mission's waypoints (least mean
/// distance of each waypoint to the track, coarse grid then refinement within +-`search_m`).
Eigen::Vector2d alignTrack(const std::vector<Eigen::Vector3d>& track, const std::vector<Eigen::Vector3d>& waypoints,
                           double search_m = kAlignSearchM);

/// `f`'s mission flown from where its log took off: the home moved to the log's first sample (placed
/// through the log's geodetic origin when it has one, an autopilot's EKF origin; else the track laid
/// onto the waypoints by alignTrack), the items unchanged. ArduPilot and PX4 set home
/// where the vehicle arms and return there, whatever the file's home row says. `offset` [m]
/// receives the log frame minus the mission frame, `launch` [m] the take-off point east and north
/// of the file's home.
mission::Mission missionFromLaunch(const MissionFlight& f, Eigen::Vector2d* offset = nullptr,
                                   Eigen::Vector2d* launch = nullptr);

/// `m` with its home moved to `launch` [m] east and north of it (FlightComparison::launch), the
/// items unchanged: the mission as the autopilot flies it after arming there.
mission::Mission missionLaunchedAt(const mission::Mission& m, const Eigen::Vector2d& launch);

/// Times of a trajectory (`t` [s], `pos` [m], `power` [W], NaN allowed when unknown) against
/// `waypoints` [m], passages matched within `match_m` [m].
FlightTimes flightTimes(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                        const std::vector<double>& power, const std::vector<Eigen::Vector3d>& waypoints,
                        double match_m = 8.0);

/// The waypoints of a sequenced mission that the vehicle flies to (ENU [m]), in order.
std::vector<Eigen::Vector3d> flownWaypoints(const std::vector<mission::NavStep>& steps);

/// How far a logged vehicle sat off the legs it flew (mission::FlightSettings::tracking_error).
struct TrackingMeasurement {
  static constexpr int kMinSamples = 20;  ///< fewer cruise samples measure nothing
  mission::TrackingError error;           ///< [m] medians; 0 when not measured
  int samples = 0;                        ///< cruise samples used
  bool measured = false;                  ///< true with at least kMinSamples samples
};

/// Appends, for each cruise sample of a track (time `t` [s], `pos` [m], `vel` [m/s]) between
/// `from_s` and `to_s` [s] (the first and last waypoint passage), its horizontal and vertical
/// distance [m] from the nearest leg between consecutive `waypoints`. Cruise: at least 1.5 m/s
/// horizontally and 10 m or more from every waypoint (the model flies the corners itself).
void addCruiseTrackingErrors(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                             const std::vector<Eigen::Vector3d>& vel, const std::vector<Eigen::Vector3d>& waypoints,
                             double from_s, double to_s, std::vector<double>& horizontal, std::vector<double>& vertical);

/// The medians of distances addCruiseTrackingErrors collected (over one flight or several).
TrackingMeasurement trackingFromErrors(const std::vector<double>& horizontal, const std::vector<double>& vertical);

/// One track's tracking error: addCruiseTrackingErrors, then trackingFromErrors.
TrackingMeasurement measureTrackingError(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                                         const std::vector<Eigen::Vector3d>& vel,
                                         const std::vector<Eigen::Vector3d>& waypoints, double from_s, double to_s);

/// Compares `f` with its prediction by `model` flown by `autopilot` (with `settings`).
FlightComparison compareFlight(const MissionFlight& f, const energy::Vehicle& v, const energy::EnergyModel& model,
                               const mission::AutopilotConfig& autopilot, const mission::PredictSettings& settings = {});

/// Settings of a calibration.
struct CalibrationSettings {
  int max_evaluations = 150;     ///< [-] simulated flights per parameter fit (Nelder-Mead); 10..5000
  double sim_dt = 0.02;          ///< [s] simulation step while fitting; 0.005..0.05
  FitSettings fit;               ///< energy coefficient fit
  bool fit_energy = true;        ///< false: keep the model's coefficients
  /// [-] A behaviour parameter whose return to its starting value (the others re-fitted) raises the
  /// time misfit by at most this share keeps its starting value: the flights do not call for a
  /// change (they fit as well, or do not determine it); 0 keeps every fitted value. 0..1
  double keep_share = 0.01;
  /// [-] Significance level of the test that a behaviour parameter's fitted value is called for: it
  /// keeps its starting value unless returning it there (the others re-fitted) raises the time misfit
  /// significantly, by an F-test of the two nested fits with the misfit's terms (each flight's total,
  /// take-off and return time and each matched leg time) as observations and the free parameters and
  /// the take-off delay as fitted; with no more observations than those, every parameter keeps its
  /// start. A return within keep_share keeps the start whatever the test says. 0: keep_share alone
  /// decides. 0..0.5
  double keep_significance = 0.05;
};

/// One flight's own value of the acceleration parameter (WPNAV_ACCEL, MPC_ACC_HOR), the other
/// behaviour parameters kept at their starting values (the take-off delay at the joint fit): whether
/// the flights agree on how the vehicle accelerates.
struct FlightAcceleration {
  std::string flight;            ///< the flight's name (its log)
  double value = 0.0;            ///< the parameter fitted on this flight alone [its unit]
  double misfit_alone = 0.0;     ///< [-] the flight's time misfit with its own value
  double misfit_joint = 0.0;     ///< [-] the flight's time misfit with the joint value (others as above)
  /// true when the flight determines its value: its misfit at the joint value is more than
  /// CalibrationSettings::keep_share above misfit_alone (else it fits the joint value as well)
  bool determined = true;
  MissionKind kind;              ///< what the flight's mission asked for (waypoint kinds, speeds, legs)
};

/// A calibrated autopilot and energy model, with the errors before and after.
struct CalibrationResult {
  mission::AutopilotConfig autopilot;     ///< with the fitted parameters written in
  double takeoff_delay_s = 0.0;           ///< [s] fitted delay from the take-off command to lift-off
  bool stop_at_waypoints = false;         ///< true when stopping at every waypoint fits the logs better
  bool speed_change_late = false;         ///< true when speed changes a waypoint late fit the logs better
  TrackingMeasurement tracking;           ///< measured on the flights' cruise (not fitted), all flights pooled
  MissionKind coverage;                   ///< what the flights' missions asked for (waypoint kinds, speeds)
  /// The fitted behaviour parameters' starting values (autopilot units): the behaviour before.
  std::map<std::string, double> behaviour_before;
  energy::EnergyModel model;              ///< with fitted coefficients
  std::vector<std::string> fitted;        ///< "NAME: before -> after unit" per parameter
  std::vector<FlightComparison> before;   ///< per flight, uncalibrated
  std::vector<FlightComparison> after;    ///< per flight, calibrated on all flights (in-sample)
  std::vector<std::string> notes;         ///< what could not be determined, and why
  std::vector<std::string> kept_at_start;  ///< behaviour parameters the flights do not call to change (keep_share)
  std::string acceleration_parameter;     ///< the acceleration parameter of per_flight (empty: one flight)
  std::vector<FlightAcceleration> per_flight;  ///< each flight's own acceleration (two flights or more)
  bool flights_agree = true;              ///< false when their own accelerations differ by more than 25 %
};

/// Calibrates on `flights`. Throws std::invalid_argument when there is no flight or a log has no
/// measured power.
CalibrationResult calibrateMissions(const std::vector<MissionFlight>& flights, const energy::Vehicle& v,
                                    const energy::EnergyModel& model, const mission::AutopilotConfig& autopilot,
                                    const CalibrationSettings& s = {});

/// The calibration as JSON text for the vehicle file's extensions.calibration (effects, fitted
/// coefficients, take-off delay, what was fitted, notes, the flights it came from).
std::string calibrationToJson(const CalibrationResult& r);

/// An energy model and take-off delay read back from a vehicle file's extensions.calibration.
struct CalibratedModel {
  energy::EnergyModel model;     ///< the calibrated effects and coefficients
  double takeoff_delay_s = -1.0; ///< [s] fitted take-off delay (< 0: none)
  bool stop_at_waypoints = false; ///< the calibrated corner behaviour (FlightSettings::stop_at_waypoints)
  bool speed_change_late = false; ///< the calibrated speed-change timing (FlightSettings::speed_change_late)
  mission::TrackingError tracking_error;  ///< [m] measured (FlightSettings::tracking_error); 0 when absent
  std::optional<MissionKind> coverage;    ///< what the calibration flights flew (none in older files)
  std::map<std::string, double> behaviour_before;  ///< the fitted parameters' values before the calibration
  /// The acceleration parameter the calibration's flights disagreed on (CalibrationResult::
  /// flights_agree false), empty when they agreed or there was one flight.
  std::string disputed_parameter;
  std::vector<double> disputed_values;  ///< each flight's own value of it [the parameter's unit]
  /// Each flight's name and what its mission asked for, in the order of disputed_values (empty in
  /// files before 2026-11-25's last round).
  std::vector<std::string> disputed_flights;
  std::vector<MissionKind> disputed_kinds;  ///< see disputed_flights
};

/// The calibration stored in `v` (extensions.calibration), or nothing when it has none. Throws
/// std::invalid_argument naming the field when it is malformed.
std::optional<CalibratedModel> calibratedModel(const energy::Vehicle& v);

/// `flight` with the calibration's take-off delay (when it fitted one), corner and speed-change
/// behaviour and tracking error: how `predict` flies a mission for the calibrated vehicle.
mission::FlightSettings calibratedFlight(const CalibratedModel& c, mission::FlightSettings flight = {});

/// `v` with the calibration `r` written in: the autopilot with its fitted parameters and
/// extensions.calibration (what `calibrate` writes to its vehicle file).
energy::Vehicle calibratedVehicle(energy::Vehicle v, const CalibrationResult& r);

}  // namespace wattswath::calibration
