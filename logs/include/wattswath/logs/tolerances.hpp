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

}  // namespace wattswath::logs::tol
