#pragma once
/// @file replay.hpp
/// Model versus measurement on one or more flight logs: phase segmentation, legs, replay of any
/// EnergyModel on the measured kinematics, energies per leg / phase / flight, residuals binned
/// by speed, climb rate, acceleration, heading and time, and the error metrics fits report.

#include <array>
#include <string>
#include <vector>

#include "wattswath/logs/flight_log.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::calibration {

// The types of the libraries calibration builds on, used unqualified in its interface.
using energy::EnergyModel;
using energy::kPhaseCount;
using energy::MotionState;
using energy::Phase;
using energy::Piece;
using energy::Vehicle;
using logs::FlightLog;
using logs::LogSample;
using logs::TimeWindow;

/// Thresholds of the phase segmentation and leg splitting.
struct SegmentSettings {
  double stop_speed = 0.7;          ///< [m/s] horizontal speed below which the vehicle is at rest; 0.1..3
  double vertical_speed = 0.6;      ///< [m/s] |v_z| above which a sample is climb or descent; 0.1..3
  double acceleration = 0.35;       ///< [m/s^2] along-track acceleration above which accelerate/brake; 0.05..3
  double turn_rate = 0.3;           ///< [rad/s] yaw or track rate above which a sample is a turn; 0.05..3
  double ground_height = 0.5;       ///< [m] height above the lowest sample that still counts as ground; 0..5
  double ground_power_fraction = 0.5;  ///< [-] idle if power is below this share of the median; 0..1
  double leg_slowdown = 0.6;        ///< [-] a leg ends at a speed minimum below this share of both
                                    ///< neighbouring peaks (or below stop_speed); 0.1..1
  double yaw_rate_window = 2;       ///< [samples] half window of the yaw-rate derivative; 1..50
};

/// Throws std::invalid_argument naming the field, its value and the range when out of range.
void validate(const SegmentSettings& s);

/// One leg: a contiguous run of samples between two stops or slow-downs (or waypoints).
struct LegSpan {
  int first = 0;            ///< index of the first sample
  int last = 0;             ///< index of the last sample (inclusive)
  double t_start = 0.0;     ///< [s] time of the first sample
  double t_end = 0.0;       ///< [s] time of the last sample
  double distance = 0.0;    ///< [m] distance flown (3-D, sum of chords)
  bool moving = false;      ///< true when its peak horizontal speed exceeds stop_speed
};

/// A log made ready for replay: motion states, phase per sample, legs and integration weights.
struct PreparedLog {
  std::string source;                  ///< file the log came from
  std::vector<MotionState> states;     ///< motion state of each sample (t relative to the log's time)
  std::vector<double> measured;        ///< [W] measured electrical power per sample
  std::vector<double> weight;          ///< [s] trapezoid weight of each sample (energy = sum w p)
  std::vector<Phase> phase;            ///< phase of each sample
  std::vector<int> leg;                ///< leg index of each sample
  std::vector<LegSpan> legs;           ///< legs in time order, covering every sample
  std::vector<Eigen::Vector3d> position;  ///< [m] ENU position per sample
  std::vector<double> voltage;         ///< [V] battery voltage per sample (NaN when not logged)
  std::vector<double> current;         ///< [A] battery current per sample (NaN when not logged)
};

/// Motion states, phases and legs of `log`. With `waypoints` (ENU [m], in flight order) the legs
/// end where the track passes closest to each waypoint in turn; otherwise at stops and slow-downs.
PreparedLog prepareLog(const FlightLog& log, const SegmentSettings& s = {},
                       const std::vector<Eigen::Vector3d>& waypoints = {});

/// Measured versus modelled energy of a set of samples.
struct EnergyCompare {
  double measured_j = 0.0;  ///< [J] measured energy
  double modelled_j = 0.0;  ///< [J] modelled energy
  double time_s = 0.0;      ///< [s] duration
  /// Signed error (modelled - measured) / measured [%] (0 when nothing was measured).
  double errorPct() const { return measured_j != 0.0 ? 100.0 * (modelled_j - measured_j) / measured_j : 0.0; }
};

/// One sample of a replay: what reports plot (measured and modelled power over time).
struct ReplaySample {
  double t = 0.0;            ///< [s] log time
  Phase phase = Phase::Hover;  ///< phase of the sample
  int leg = 0;               ///< leg index
  double measured_w = 0.0;   ///< [W] measured power
  double modelled_w = 0.0;   ///< [W] modelled power
  double speed = 0.0;        ///< [m/s] horizontal ground speed
  double climb_rate = 0.0;   ///< [m/s] vertical speed (up positive)
  double acceleration = 0.0; ///< [m/s^2] along-track acceleration (braking negative)
  double heading = 0.0;      ///< [rad] ENU track heading (0 east, counter-clockwise)
};

/// A model replayed on one log.
struct LogReplay {
  std::string source;                          ///< the log's file
  std::vector<ReplaySample> samples;           ///< per sample
  std::vector<EnergyCompare> legs;             ///< per leg (PreparedLog::legs order)
  std::array<EnergyCompare, kPhaseCount> phases{};  ///< per phase
  EnergyCompare flight;                        ///< the whole log
};

/// Model power at every sample of `log` [W].
std::vector<double> modelPower(const EnergyModel& m, const PreparedLog& log);

/// Assembles a replay from per-sample modelled power (any source: one model, cross-validation folds).
LogReplay assembleReplay(const PreparedLog& log, const std::vector<double>& modelled);

/// Replays `m` on `log`.
LogReplay replay(const EnergyModel& m, const PreparedLog& log);

/// Sample and energy errors over one or more replays.
struct PhaseError {
  int samples = 0;             ///< number of samples in the phase
  double rmse_w = 0.0;         ///< [W] sample RMSE
  double measured_mean_w = 0.0;  ///< [W] mean measured power
  double modelled_mean_w = 0.0;  ///< [W] mean modelled power
  double energy_error_pct = 0.0; ///< [%] signed energy error of the phase, summed over logs
};

/// Error metrics of replays: the numbers fit and diagnose report.
struct ErrorMetrics {
  int samples = 0;                  ///< samples compared
  double rmse_w = 0.0;              ///< [W] sample RMSE
  double energy_error_pct = 0.0;    ///< [%] mean over logs of |whole-flight energy error|
  double leg_energy_mape_pct = 0.0; ///< [%] mean absolute % error of leg energies (moving legs >= 3 s)
  std::array<PhaseError, kPhaseCount> phases{};  ///< per phase
};

/// Error metrics of `replays`.
ErrorMetrics errorMetrics(const std::vector<LogReplay>& replays);

/// One bin of a residual table.
struct ResidualBin {
  double lo = 0.0;               ///< lower edge, in the table's unit
  double hi = 0.0;               ///< upper edge, in the table's unit
  int count = 0;                 ///< samples in the bin
  double measured_mean_w = 0.0;  ///< [W] mean measured power
  double modelled_mean_w = 0.0;  ///< [W] mean modelled power
  /// Mean residual modelled - measured [W].
  double residualW() const { return modelled_mean_w - measured_mean_w; }
};

/// Residuals binned by one quantity.
struct ResidualTable {
  std::string quantity;          ///< "speed", "climb_rate", "acceleration", "heading", "time"
  std::string unit;              ///< unit of the bin edges ("m/s", "m/s^2", "deg", "s")
  std::vector<ResidualBin> bins; ///< in increasing order; empty bins omitted
};

/// Residual tables by speed (1 m/s bins), climb rate (0.5 m/s), along-track acceleration
/// (0.25 m/s^2), track heading of moving samples (45 deg, compass bearing) and time (60 s).
std::vector<ResidualTable> residualTables(const std::vector<LogReplay>& replays);

}  // namespace wattswath::calibration
