// Surveys larger than one battery (issue 23): the energy-aware split into sorties (dynamic
// programming over 50 m sweep pieces, each sortie forward or reversed: the fewest sorties, then
// the least total energy) against the naive split
// (each sortie as long as the budget allows, in flight order, with its own return) measured in the
// same run, on the 1 km^2 and 100 ha benchmark fields (bench/data/) at 20 m spacing with the IRIS+
// 3S 5.1 Ah pack (80 % usable), 25 % reserve. The plan is made once (not timed); the split's
// closed-form energies (transits around the zones, the plan's own leg energies, a 20 s hover as
// the take-off and landing of every sortie) are counters: sorties and total kJ.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/planner/battery_use.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/sorties.hpp"

namespace {
using namespace wattswath;

// One field planned once: the problem, the vehicle, its model and the plan.
struct Planned {
  planner::SurveyProblem problem;
  energy::Vehicle vehicle;
  std::unique_ptr<energy::EnergyModel> model;
  planner::PlanResult plan;
};

const Planned& planned(const std::string& file) {
  static std::map<std::string, std::unique_ptr<Planned>> cache;
  auto& p = cache[file];
  if (p) return *p;
  p = std::make_unique<Planned>();
  const auto area = geometry::readSurveyArea(std::string(WATTSWATH_SOURCE_DIR) + "/bench/data/" + file);
  p->problem.area = area.polygon();
  p->problem.home = area.home.value_or(p->problem.area.outer.front());
  p->problem.spacing = p->problem.footprint = 20.0;
  p->vehicle = energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  p->model = std::make_unique<energy::EnergyModel>(energy::marinsModel(p->vehicle));
  p->plan = planner::planCoverage(p->problem, p->vehicle, *p->model);
  return *p;
}

void split(benchmark::State& state, const std::string& file, bool naive, int count = 0) {
  const Planned& p = planned(file);
  planner::RouteScorer scorer(*p.model, planner::SpeedSettings::fromVehicle(p.vehicle));
  planner::SortieSettings s;
  s.budget_j = 0.75 * planner::predictBatteryUse(p.plan.plan.flown, *p.vehicle.battery).usable_energy_j;
  s.overhead_j = 20.0 * energy::marinsHoverPowerW(p.vehicle);
  s.naive = naive;
  s.count = count;
  planner::SortieSplit out;
  for (auto _ : state) {
    out = planner::splitIntoSorties(p.plan.plan.flown, p.problem, scorer, s);
    benchmark::DoNotOptimize(out.estimate_j);
  }
  state.counters["sorties"] = static_cast<double>(out.sorties.size());
  state.counters["total_kJ"] = out.estimate_j / 1000.0;
  state.counters["one_flight_kJ"] = (p.plan.plan.flown.energy + s.overhead_j) / 1000.0;
}

void BM_Sorties_Field1km2_EnergyAware(benchmark::State& s) { split(s, "field_1km2.geojson", false); }
void BM_Sorties_Field1km2_Naive(benchmark::State& s) { split(s, "field_1km2.geojson", true); }
void BM_Sorties_Field100ha_EnergyAware(benchmark::State& s) { split(s, "field_100ha.geojson", false); }
void BM_Sorties_Field100ha_Naive(benchmark::State& s) { split(s, "field_100ha.geojson", true); }

}  // namespace

BENCHMARK(BM_Sorties_Field1km2_EnergyAware)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sorties_Field1km2_Naive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sorties_Field100ha_EnergyAware)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sorties_Field100ha_Naive)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
