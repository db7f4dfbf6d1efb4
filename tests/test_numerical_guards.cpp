// Numerical guards (issue 8): property tests with fixed seeds that the energy model's power, the
// leg energies, the replay metrics and the Ceres coefficient fit never return NaN or infinity for
// valid inputs drawn across their documented ranges (vehicle fields within validate()'s ranges,
// SimulationSettings within their documented ranges, coefficients anywhere within their bounds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/energy/forward_flight.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/optimal_speed.hpp"

using namespace wattswath::energy;
using namespace wattswath::logs;
using namespace wattswath::calibration;

namespace {

/// A random physically valid vehicle: every field inside the range validate() documents, drawn
/// log-uniformly so small and large vehicles are both exercised.
Vehicle randomVehicle(std::mt19937& rng) {
  auto logU = [&](double lo, double hi) {
    return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
  };
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Vehicle v;
  v.name = "random";
  v.mass_kg = logU(0.05, 100.0);
  v.rotor_count = std::uniform_int_distribution<int>(1, 12)(rng);
  v.rotor_diameter_m = logU(0.03, 3.0);
  v.disk_area_m2 = v.rotor_count * M_PI * 0.25 * v.rotor_diameter_m * v.rotor_diameter_m;
  v.motor_efficiency = u(0.05, 1.0);
  v.propeller_efficiency = u(0.05, 1.0);
  v.drag_area_m2 = u(0.0, 1.0);
  v.max_acceleration_mps2 = logU(0.1, 20.0);
  v.max_yaw_rate_radps = logU(0.1, 10.0);
  v.max_speed_mps = logU(1.0, 60.0);
  v.air_density_kgpm3 = u(0.5, 1.5);
  v.gravity_mps2 = u(1.0, 25.0);
  validate(v, "randomVehicle");
  return v;
}

MotionState randomState(std::mt19937& rng) {
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  MotionState s;
  s.t = u(0.0, 3600.0);
  s.velocity = {u(-40, 40), u(-40, 40), u(-10, 10)};
  s.acceleration = {u(-10, 10), u(-10, 10), u(-5, 5)};
  s.yaw_rate = u(-5, 5);
  s.heading = u(-M_PI, M_PI);
  s.airborne = u(0, 1) > 0.1;
  return s;
}

// Every known effect, with vehicle-physics coefficients and with each coefficient set to its lower
// bound, its upper bound (capped at 1e6) and a random value between: power is finite everywhere.
TEST(NumericalGuards, EffectPowerFiniteAcrossVehiclesStatesAndCoefficientBounds) {
  std::mt19937 rng(20261122);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Vehicle v = randomVehicle(rng);
    for (const auto& name : knownEffectNames()) {
      auto e = makeEffect(name, v);
      const auto base = e->coefficients();
      for (int variant = 0; variant < 4; ++variant) {
        std::vector<double> vals;
        for (const auto& c : base) {
          const double hi = std::min(c.upper, 1e6);
          const double pick = variant == 0   ? c.value
                              : variant == 1 ? c.lower
                              : variant == 2 ? hi
                                             : std::uniform_real_distribution<double>(c.lower, hi)(rng);
          vals.push_back(pick);
        }
        e->setCoefficientValues(vals);
        for (int k = 0; k < 25; ++k) {
          const MotionState s = randomState(rng);
          const double p = e->power(s);
          ASSERT_TRUE(std::isfinite(p)) << name << " variant " << variant << " trial " << trial << ": power " << p
                                        << " at v = " << s.velocity.transpose() << ", a = " << s.acceleration.transpose();
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 10000);
}

// Leg profiles of any length and speed within the ranges give finite energies with the paper model.
TEST(NumericalGuards, LegEnergyFiniteFromMillimetresToKilometres) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Vehicle v = randomVehicle(rng);
    const EnergyModel m = buildModel(v, {"hover", "kinetic", "parasitic_drag"});
    const double len = std::exp(std::uniform_real_distribution<double>(std::log(1e-3), std::log(1e4))(rng));
    const double speed = std::uniform_real_distribution<double>(0.1, v.max_speed_mps)(rng);
    const double dz = std::uniform_real_distribution<double>(-0.5, 0.5)(rng) * len;
    ProfileLimits lim;
    lim.acceleration = lim.deceleration = v.max_acceleration_mps2;
    const double e = m.energy(buildLegProfile(len, 0.0, speed, 0.0, lim, 0.0, dz));
    ASSERT_TRUE(std::isfinite(e) && e >= 0.0) << "trial " << trial << ": leg " << len << " m at " << speed
                                              << " m/s -> " << e << " J";
  }
}

// The induced-velocity solver (Hwang Eq. 5) across its documented range: thrust from 0 to 1e5 N,
// forward speed 0 (and subnormal) to 100 m/s, tilt in [0, pi/2), density 0.3 to 1.5 kg/m^3, disk area 1 cm^2 to
// 100 m^2. The root is finite, inside the documented bracket and satisfies Eq. 5; the Hwang
// model's level-flight power (both parts) of random vehicles is finite from hover to 60 m/s.
TEST(NumericalGuards, InducedVelocityFiniteAcrossItsDocumentedRange) {
  std::mt19937 rng(5);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto logU = [&](double lo, double hi) { return std::exp(u(std::log(lo), std::log(hi))); };
  for (int trial = 0; trial < 20000; ++trial) {
    const double T = trial % 50 == 0 ? 0.0 : logU(1e-6, 1e5);
    const double U = trial % 7 == 0 ? 0.0 : trial % 13 == 0 ? 1e-310 : (trial % 2 ? logU(1e-12, 100.0) : u(0.0, 100.0));
    const double th = trial % 11 == 0 ? 0.0 : u(0.0, 0.5 * M_PI * (1.0 - 1e-9));
    const double rho = u(0.3, 1.5), A = logU(1e-4, 100.0);
    double ui = 0.0;
    ASSERT_NO_THROW(ui = inducedVelocity(T, U, th, rho, A)) << "T " << T << " U " << U << " th " << th;
    const double k = T / (2.0 * rho * A);
    ASSERT_TRUE(std::isfinite(ui) && ui >= 0.0) << "T " << T << " U " << U << " th " << th << ": " << ui;
    const double bracket = U > 0.0 ? std::min(std::sqrt(k), k / U) : std::sqrt(k);
    EXPECT_LE(ui, bracket * (1.0 + 1e-9) + 1e-300) << "T " << T << " U " << U << " th " << th;
    if (T > 0.0) {
      const double rhs = k / std::hypot(U * std::cos(th), U * std::sin(th) + ui);
      EXPECT_NEAR(ui, rhs, 1e-6 * std::max(ui, 1e-12)) << "T " << T << " U " << U << " th " << th;
    }
  }
  for (int trial = 0; trial < 100; ++trial) {
    const Vehicle v = randomVehicle(rng);
    const EnergyModel m = hwangModel(v);
    for (double speed : {0.0, 0.1, 1.0, 5.0, 15.0, 30.0, 60.0}) {
      MotionState s;
      s.velocity = {speed, 0.0, 0.0};
      s.airborne = true;
      const double p = m.power(s);
      ASSERT_TRUE(std::isfinite(p) && p > 0.0) << "trial " << trial << " speed " << speed << ": " << p << " W";
    }
  }
}

// The optimal cruise speed (energy/optimal_speed.hpp) of random vehicles, leg lengths from 1 cm to
// 10 km, and models with a random extra effect: a finite speed inside [min_speed, v_max] with
// finite energy and time. The paper's Eq. 10 closed form likewise for any drag area > 0.
TEST(NumericalGuards, OptimalCruiseSpeedFiniteAcrossVehiclesAndLegs) {
  std::mt19937 rng(1234);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const std::vector<std::string> paper = {"hover", "kinetic", "parasitic_drag"};
  std::vector<std::string> extras;
  for (const auto& n : knownEffectNames())
    if (std::find(paper.begin(), paper.end(), n) == paper.end()) extras.push_back(n);
  for (int trial = 0; trial < 150; ++trial) {
    Vehicle v = randomVehicle(rng);
    EnergyModel m = buildModel(v, paper);
    if (trial % 3 == 1) m = withCandidate(m, extras[trial % extras.size()], v);
    const double d = std::exp(u(std::log(1e-2), std::log(1e4)));
    ProfileLimits lim;
    lim.acceleration = lim.deceleration = v.max_acceleration_mps2;
    const double v_max = v.max_speed_mps;
    const double v_in = trial % 4 == 0 ? u(0.0, std::min(v_max, std::sqrt(v.max_acceleration_mps2 * d))) : 0.0;
    const std::string what = "trial " + std::to_string(trial) + " d " + std::to_string(d) + " v_in " +
                             std::to_string(v_in) + " model " + (m.effects().size() > 3 ? m.effects().back()->name() : "paper");
    CruiseSpeedOptimum o;
    ASSERT_NO_THROW(o = optimalCruiseSpeed(m, d, v_in, 0.0, lim, v_max)) << what;
    EXPECT_TRUE(std::isfinite(o.speed) && std::isfinite(o.energy) && std::isfinite(o.time)) << what;
    // The searched range is [min(min_speed, upper_bound / 2), upper_bound] (optimal_speed.cpp):
    // legs too short to reach min_speed search below it.
    EXPECT_GE(o.speed, std::min(CruiseSpeedSettings{}.min_speed, 0.5 * o.upper_bound) * (1 - 1e-9)) << what;
    EXPECT_LE(o.speed, o.upper_bound * (1 + 1e-9)) << what;
    EXPECT_LE(o.upper_bound, v_max * (1 + 1e-9)) << what;
    if (v.drag_area_m2 > 1e-4) {
      const double eq10 = MarinsClosedForm::fromVehicle(v).eq10OptimalSpeed(d);
      EXPECT_TRUE(std::isfinite(eq10) && eq10 > 0.0) << what << ": Eq. 10 speed " << eq10;
    }
  }
}

// Simulated flights with random vehicles, settings and hidden effects, read back through CSV,
// replayed and fitted: metrics and fitted coefficients are finite (sigma may be NaN only when the
// fit says the covariance is singular).
TEST(NumericalGuards, ReplayAndFitFiniteOnRandomSimulatedFlights) {
  std::mt19937 rng(42);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const std::vector<std::vector<Eigen::Vector3d>> paths = {
      {{0, 0, 0}, {0, 0, 10}, {60, 0, 10}, {60, 20, 10}, {0, 20, 10}, {0, 0, 0}},  // survey
      {{0, 0, 0}, {0, 0, 20}, {0, 0, 0}},                                         // vertical only
      {{0, 0, 5}, {0.5, 0, 5}},                                                   // half a metre
  };
  for (int trial = 0; trial < 6; ++trial) {
    const Vehicle v = randomVehicle(rng);
    std::vector<std::string> names = {"hover", "kinetic", "parasitic_drag"};
    std::vector<std::string> cands;
    for (const auto& n : knownEffectNames())
      if (std::find(names.begin(), names.end(), n) == names.end()) cands.push_back(n);
    const std::string hidden = cands[std::uniform_int_distribution<size_t>(0, cands.size() - 1)(rng)];
    EnergyModel truth = withCandidate(buildModel(v, names), hidden, v);
    SimulationSettings s;
    s.rate_hz = u(2.0, 20.0);
    s.cruise_speed = u(0.5, std::min(40.0, v.max_speed_mps));
    s.acceleration = u(0.1, 10.0);
    s.power_noise_w = trial % 3 == 0 ? 0.0 : u(0.0, 50.0);
    s.velocity_noise_mps = u(0.0, 0.5);
    s.seed = 100 + trial;
    const auto& path = paths[trial % paths.size()];
    const FlightLog log = parseCsvLog(writeCsvLog(simulateFlight(path, truth, s)), "sim.csv");
    const PreparedLog prepared = prepareLog(log);
    const EnergyModel start = buildModel(v, names);
    const LogReplay r = replay(start, prepared);
    const ErrorMetrics m = errorMetrics({r});
    const std::string what = "trial " + std::to_string(trial) + " hidden " + hidden;
    EXPECT_TRUE(std::isfinite(m.rmse_w)) << what;
    EXPECT_TRUE(std::isfinite(m.energy_error_pct)) << what;
    EXPECT_TRUE(std::isfinite(r.flight.measured_j) && std::isfinite(r.flight.modelled_j)) << what;
    FitSettings fs;
    fs.max_samples = 600;
    fs.max_iterations = 30;
    const FitResult fit = fitModel(start, {SampleSet{&prepared, {}}}, fs);
    EXPECT_TRUE(std::isfinite(fit.train_rmse_w)) << what;
    for (const auto& c : fit.coefficients) {
      EXPECT_TRUE(std::isfinite(c.value)) << what << ": " << c.effect << "." << c.name << " = " << c.value;
    }
    for (const auto& e : fit.model.effects()) {
      for (const auto& c : e->coefficients()) {
        EXPECT_GE(c.value, c.lower) << what << ": " << e->name() << "." << c.name;
        EXPECT_LE(c.value, c.upper) << what << ": " << e->name() << "." << c.name;
      }
    }
  }
}

}  // namespace
