#pragma once
// Simulated logs for the diagnosis tests (issue 18): the lawnmower of test_diagnose.cpp flown by a
// truth model (energy effects the diagnosis knows), plus effects it does not know applied to the
// noise-free power - battery I^2 R, motor heating, air density with altitude, a current-sensor
// lag, ground effect - then Gaussian power noise with a fixed seed.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "test_util.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/logs/log_io.hpp"

namespace wattswath::test {

/// The IRIS+ vehicle of data/vehicles/iris.json.
inline energy::Vehicle iris() { return energy::loadVehicle(sourcePath("data/vehicles/iris.json")); }

/// A lawnmower with a take-off, a climb, a diagonal transit and a landing (about 4 min at 8 m/s);
/// `top` [m] lifts the second half (air density needs altitude to show).
inline std::vector<Eigen::Vector3d> surveyPath(double low = 15.0, double top = 25.0) {
  return {{0, 0, 0},       {0, 0, low},     {160, 0, low}, {160, 25, low}, {0, 25, low}, {0, 50, low},
          {160, 50, low},  {160, 50, top},  {80, 90, top}, {0, 0, top},    {160, 0, top}, {0, 0, 0}};
}

/// An effect outside the candidate list, applied to the noise-free power.
struct OutsideEffect {
  std::string kind;       ///< "", "battery_resistance", "motor_heating", "air_density", "sensor_lag", "ground_effect"
  double strength = 0.0;  ///< [Ohm], [-] share at saturation, [-] multiple of the real lapse rate, [s], [-] share at z = 0
};

/// Power after `e` (noise-free) at each sample of `log`; voltage as in the log.
inline void applyOutside(logs::FlightLog& log, const OutsideEffect& e) {
  double lagged = log.samples.front().power;
  for (size_t i = 0; i < log.samples.size(); ++i) {
    auto& x = log.samples[i];
    const double p = x.power, z = x.position.z();
    if (e.kind == "battery_resistance") {
      const double amps = p / x.voltage;  // loss R I^2 drawn on top (first order)
      x.power = p + e.strength * amps * amps;
    } else if (e.kind == "motor_heating") {
      x.power = p * (1.0 + e.strength * (1.0 - std::exp(-x.t / 60.0)));  // efficiency falls as windings heat
    } else if (e.kind == "air_density") {
      x.power = p * (1.0 + e.strength * z / (2.0 * 8500.0));  // P ~ rho^-1/2, rho ~ exp(-z / 8500 m)
    } else if (e.kind == "sensor_lag") {
      const double dt = i > 0 ? x.t - log.samples[i - 1].t : 0.0;
      lagged += (p - lagged) * (dt / (e.strength + dt));  // first-order low-pass, time constant strength
      x.power = lagged;
    } else if (e.kind == "ground_effect") {
      x.power = p * (1.0 - e.strength * std::exp(-z / 0.5));  // rotors near the ground need less power
    }
  }
}

/// A canonical log of `truth` through `path` at 5 Hz with `outside` applied, power noise
/// `noise_w` [W] and velocity noise 0.05 m/s (seed `seed`), through the CSV writer and reader.
inline calibration::PreparedLog simulateLog(const energy::EnergyModel& truth, unsigned seed,
                                            const OutsideEffect& outside = {},
                                            const std::vector<Eigen::Vector3d>& path = surveyPath(),
                                            double noise_w = 5.0, double hover_s = 10.0) {
  calibration::SimulationSettings s;
  s.rate_hz = 5.0;
  s.seed = seed;
  s.power_noise_w = 0.0;
  s.hover_s = hover_s;
  logs::FlightLog log = calibration::simulateFlight(path, truth, s);
  applyOutside(log, outside);
  std::mt19937 rng(seed + 1000);
  std::normal_distribution<double> noise(0.0, noise_w);
  for (auto& x : log.samples) {
    x.power += noise(rng);
    x.current = x.power / x.voltage;
  }
  return calibration::prepareLog(logs::parseCsvLog(logs::writeCsvLog(log), "simulated.csv"));
}

}  // namespace wattswath::test
