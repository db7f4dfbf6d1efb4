#pragma once
/// @file tolerances.hpp
/// Named bounds of the flight-log readers, in one place (README: "Precision").

namespace wattswath::logs::tol {

/// [SI unit of the column] largest magnitude a flight-log value may have (positions, velocities,
/// accelerations, voltage, current, power, mass, wind; not time): beyond it squares and cubes in
/// the model overflow to infinity instead of giving an error.
inline constexpr double kLogMaxMagnitude = 1e9;
/// [m] largest altitude magnitude of a geodetic flight-log sample and of the origin metadata (the
/// same bound, so that a log read with one reads back after writeCsvLog).
inline constexpr double kLogMaxAltitude = 1e5;
/// [s] smallest time step between flight-log samples (1 MHz): closer samples make the derived
/// velocities meaningless.
inline constexpr double kLogMinTimeStep = 1e-6;

/// [A] most negative battery current a flight-log sample may have: a current sensor's offset at
/// idle reads a few tenths of an ampere below zero, a multirotor never charges its battery in
/// flight; below this the sensor's sign or offset is wrong and the energy would come out negative.
inline constexpr double kLogMinCurrent = -1.0;
/// [s] default longest time between two consecutive flight-log samples (LogReadOptions::max_gap_s):
/// a longer gap is the logger stopping or two flights in one log, whose energy must not be
/// counted as if measured.
inline constexpr double kLogMaxSampleGap = 60.0;
/// [s] longest time between two position samples of a .bin/.ulg log read without a warning: the
/// kinematics across a longer gap are a straight-line interpolation (EKF outputs run at 10-50 Hz).
inline constexpr double kLogPositionGapWarn = 2.0;
/// [B] default largest flight-log file read (LogReadOptions::max_file_bytes, `--max-log-size`):
/// logs are read whole, and reading takes about 2x the file in memory for DataFlash and ULog and
/// 3x for CSV, so 512 MiB stays under 2 GB. Hours of logging at default rates are well below it.
inline constexpr long long kLogMaxFileBytes = 512LL * 1024 * 1024;

}  // namespace wattswath::logs::tol
