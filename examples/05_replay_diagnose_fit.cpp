// Example 5: model versus measurement. Simulate a flight log with a wind the model does not know,
// replay the model on it, let the diagnosis find the missing effect, and fit it.
// Usage (from the repository root): example_05_replay_diagnose_fit [VEHICLE.json] [PATH.txt]
// With your own log, start at logs::readCsvLog (or the DataFlash / ULog readers) instead.
// Links wattswath::calibration; docs/examples.md shows the output.
#include <cstdio>
#include <string>
#include <vector>

#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/replay.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/logs/log_io.hpp"

namespace cal = wattswath::calibration;
namespace en = wattswath::energy;
namespace lg = wattswath::logs;

int main(int argc, char** argv) {
  const std::string vehicle_path = argc > 1 ? argv[1] : "data/vehicles/iris.json";
  const std::string path_file = argc > 2 ? argv[2] : "tests/data/good/path_lawnmower.txt";
  const en::Vehicle v = en::loadVehicle(vehicle_path);
  const en::EnergyModel model = en::buildModel(v, {"hover", "kinetic", "parasitic_drag"});

  // The "real" vehicle flies in a 3 m/s east, 2 m/s south wind (drag at air speed).
  en::EnergyModel truth = en::buildModel(v, {"hover", "kinetic", "wind"});
  truth.effect("wind").setCoefficientValues({v.drag_area_m2, 3.0, -2.0});  // drag_area, wind_east, wind_north
  cal::SimulationSettings sim;
  sim.rate_hz = 5.0;
  const lg::FlightLog log = cal::simulateFlight(lg::readWaypointPath(path_file), truth, sim);
  std::printf("log: %zu samples over %.0f s\n", log.samples.size(), log.samples.back().t - log.samples.front().t);

  // Replay: the model's power on the logged kinematics, against the logged power.
  const cal::PreparedLog prepared = cal::prepareLog(log);
  const cal::LogReplay r = cal::replay(model, prepared);
  const cal::ErrorMetrics before = cal::errorMetrics({r});
  std::printf("replay: measured %.0f J, modelled %.0f J (%+.1f %%), RMSE %.1f W, %zu legs\n", r.flight.measured_j,
              r.flight.modelled_j, r.flight.errorPct(), before.rmse_w, prepared.legs.size());

  // Diagnose: try candidate effects, each fitted with the model's own coefficients, ranked by
  // held-out error (contiguous time blocks of this one log).
  cal::DiagnoseSettings ds;
  ds.candidates = {"wind", "translational_lift", "climb", "payload_mass"};
  const cal::Diagnosis d = cal::diagnose(model, v, {prepared}, ds);
  std::printf("diagnosis (%s): %s\n  %s\n", d.validation.c_str(), d.verdict.c_str(), d.conclusion.c_str());
  for (const auto& c : d.candidates)
    std::printf("  %-18s held-out RMSE %5.1f W, %5.1f %% better: %s\n", c.effect.c_str(), c.rmse_w, c.improvement_pct,
                c.summary.c_str());

  // Fit: the model with the best candidate added, every coefficient fitted (Ceres, bounded).
  const en::EnergyModel start = en::withCandidate(model, d.candidates.front().effect, v);
  const cal::FitReport fit = cal::fitAndCompare(start, {prepared}, {});
  std::printf("fit: RMSE %.1f W -> %.1f W\n", fit.train_before.rmse_w, fit.train_after.rmse_w);
  for (const auto& c : fit.fit.coefficients)
    std::printf("  %s.%s = %.4g +- %.2g %s\n", c.effect.c_str(), c.name.c_str(), c.value, c.sigma, c.unit.c_str());
  return 0;
}
