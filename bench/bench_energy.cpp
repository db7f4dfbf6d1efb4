// Leg energy evaluations per second: the generic effect-by-effect path (EnergyModel over the pieces of
// buildLegProfile) against the inlined Marins closed form, on the same seeded legs, plus the optimisers.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/optimal_speed.hpp"

namespace en = wattswath::energy;

namespace {

en::Vehicle iris() { return en::loadVehicle(WATTSWATH_SOURCE_DIR "/data/vehicles/iris.json"); }

struct Leg {
  double d, ve, vc, vx;
};

/// 4096 seeded stop-to-stop and flying legs (some triangular), all feasible.
const std::vector<Leg>& legs() {
  static const std::vector<Leg> l = [] {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> len(5.0, 800.0), spd(1.0, 16.0), frac(0.0, 1.0);
    std::vector<Leg> out;
    while (out.size() < 4096) {
      const double d = len(rng), vc = spd(rng);
      const bool flying = frac(rng) < 0.5;
      const double ve = flying ? vc * frac(rng) : 0.0, vx = flying ? vc * frac(rng) : 0.0;
      try {
        en::buildLegProfile(d, ve, vc, vx, {1.0, 1.0});
        out.push_back({d, ve, vc, vx});
      } catch (const std::invalid_argument&) {
      }
    }
    return out;
  }();
  return l;
}

void BM_LegEnergyGenericModel(benchmark::State& state) {
  const auto model = en::marinsModel(iris());
  const auto& l = legs();
  size_t i = 0;
  for (auto _ : state) {
    const Leg& g = l[i++ & 4095];
    benchmark::DoNotOptimize(model.energy(en::buildLegProfile(g.d, g.ve, g.vc, g.vx, {1.0, 1.0})));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LegEnergyGenericModel);

void BM_LegEnergyClosedFormFastPath(benchmark::State& state) {
  const auto m = en::MarinsClosedForm::fromVehicle(iris());
  const auto& l = legs();
  size_t i = 0;
  for (auto _ : state) {
    const Leg& g = l[i++ & 4095];
    benchmark::DoNotOptimize(m.legEnergy(g.d, g.ve, g.vc, g.vx));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LegEnergyClosedFormFastPath);

void BM_Eq10CubicRoot(benchmark::State& state) {
  const auto m = en::MarinsClosedForm::fromVehicle(iris(), en::DragIntegration::PaperCruiseSpeed);
  const auto& l = legs();
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(m.eq10OptimalSpeed(l[i++ & 4095].d));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Eq10CubicRoot);

void BM_OptimalCruiseSpeedGeneric(benchmark::State& state) {
  const auto model = en::marinsModel(iris());
  const auto& l = legs();
  size_t i = 0;
  for (auto _ : state) {
    const Leg& g = l[i++ & 4095];
    benchmark::DoNotOptimize(en::optimalCruiseSpeed(model, g.d, g.ve, g.vx, {1.0, 1.0}, 16.0).speed);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OptimalCruiseSpeedGeneric);

}  // namespace

BENCHMARK_MAIN();
