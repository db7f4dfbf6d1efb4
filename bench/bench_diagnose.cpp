// Diagnosis time for a one-hour 10 Hz simulated log (issue 6 target: under 2 s; since issue 18 the
// greedy search with 5 contiguous folds and a residual-signature test takes 6.8 s of CPU on the
// shared 2-core machine, docs/validation.md), against the baseline of replaying the model once on
// the same log (measured in the same run).
#include <benchmark/benchmark.h>

#include "wattswath/calibration/diagnose.hpp"

using namespace wattswath::energy;
using namespace wattswath::calibration;

namespace {

/// The paper's IRIS, from the bundled vehicle file (data/vehicles/iris.json).
Vehicle iris() { return loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json"); }

// A lawnmower repeated until the flight lasts about an hour, with a hidden translational lift.
const PreparedLog& hourLog() {
  static const PreparedLog log = [] {
    const Vehicle v = iris();
    EnergyModel truth = buildModel(v, {"hover", "kinetic", "parasitic_drag"});
    truth.add(TranslationalLiftEffect(80.0, 5.0));
    std::vector<Eigen::Vector3d> w = {{0, 0, 0}, {0, 0, 20}};
    for (int lap = 0; w.size() < 400; ++lap) {
      for (int k = 0; k < 8; ++k) {
        const double y = 25.0 * k;
        w.push_back({k % 2 ? 300.0 : 0.0, y, 20.0});
        w.push_back({k % 2 ? 0.0 : 300.0, y, 20.0});
      }
      w.push_back({0, 0, 20});
    }
    w.push_back({0, 0, 0});
    SimulationSettings s;
    s.rate_hz = 10.0;
    FlightLog log = simulateFlight(w, truth, s);
    while (log.duration() > 3600.0) log.samples.pop_back();
    return prepareLog(log);
  }();
  return log;
}

void BM_ReplayOneHour(benchmark::State& st) {
  const EnergyModel m = buildModel(iris(), {"hover", "kinetic", "parasitic_drag"});
  for (auto _ : st) benchmark::DoNotOptimize(replay(m, hourLog()));
  st.counters["samples"] = static_cast<double>(hourLog().states.size());
}
BENCHMARK(BM_ReplayOneHour)->Unit(benchmark::kMillisecond);

void BM_DiagnoseOneHour(benchmark::State& st) {
  const Vehicle v = iris();
  const EnergyModel m = buildModel(v, {"hover", "kinetic", "parasitic_drag"});
  const std::vector<PreparedLog> logs{hourLog()};
  for (auto _ : st) benchmark::DoNotOptimize(diagnose(m, v, logs));
  st.counters["samples"] = static_cast<double>(hourLog().states.size());
}
BENCHMARK(BM_DiagnoseOneHour)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
