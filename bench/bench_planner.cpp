// Planner speed (issue 22 adds the 2 ha rectangle and the L at 10 m, sharp and default corners):
// the full energy search (all sweep angles coarse 10 deg then 1 deg, all start
// corners, corner choices, cell order, transits, baselines) against a length-objective greedy plan
// measured in the same run. Areas: the E-Spiral rectangle, 1 km^2 with 3 holes, 100 ha with 10
// holes, and the IRIS+ real-flight area with its no-fly zone (data/areas/iris_area.geojson).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/planner/coverage.hpp"
#include "random_gtsp.hpp"  // planner/tests
#include "wattswath/planner/order.hpp"

namespace {
using namespace wattswath;
using geometry::Ring;

energy::Vehicle vehicle() { return energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json"); }

Ring square(double cx, double cy, double h) { return {{cx - h, cy - h}, {cx - h, cy + h}, {cx + h, cy + h}, {cx + h, cy - h}}; }

// A square field of side `side` m with `holes` square holes on a seeded jittered grid.
planner::SurveyProblem field(double side, int holes, unsigned seed) {
  planner::SurveyProblem p;
  p.area.outer = {{0, 0}, {side, 0.1 * side}, {side * 1.05, side}, {-0.05 * side, side * 0.95}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> j(-0.1, 0.1);
  const int per_row = static_cast<int>(std::ceil(std::sqrt(holes)));
  for (int i = 0; i < holes; ++i) {
    const double cx = side * ((i % per_row) + 0.5 + j(rng)) / per_row;
    const double cy = side * 0.1 + side * 0.8 * ((i / per_row) + 0.5 + j(rng)) / per_row;
    p.area.holes.push_back(square(cx, cy, 0.03 * side));
  }
  p.spacing = 30.0;
  p.footprint = 33.0;
  p.home = {-20, -20};
  return p;
}

planner::SurveyProblem rectangle() {
  planner::SurveyProblem p;
  p.area.outer = {{0, 0}, {252, 0}, {252, 118}, {0, 118}};
  p.spacing = 21.45;
  p.footprint = 23.8;
  p.home = {-5, -5};
  return p;
}

// The IRIS+ real-flight area (about 150 m x 170 m, 11 vertices) with its no-fly zone as a hole and
// its home point, read from the bundled data/areas/iris_area.geojson (converted from the shared
// .waypoints files), planned at 15 m between passes as in scripts/example.sh.
planner::SurveyProblem irisArea() {
  static const geometry::SurveyArea a =
      geometry::readSurveyArea(std::string(WATTSWATH_SOURCE_DIR) + "/data/areas/iris_area.geojson");
  planner::SurveyProblem p;
  p.area = a.polygon();
  p.home = a.home.value_or(p.area.outer.front());
  p.spacing = p.footprint = 15.0;
  return p;
}

// Issue 22's small hole-free fields at 10 m between lines, home at the first vertex: the 2 ha
// rectangle (200 x 100 m) and the L (200 x 60 m and 80 x 160 m).
planner::SurveyProblem small(bool l_shape) {
  planner::SurveyProblem p;
  p.area.outer = l_shape ? Ring{{0, 0}, {200, 0}, {200, 60}, {80, 60}, {80, 160}, {0, 160}}
                         : Ring{{0, 0}, {200, 0}, {200, 100}, {0, 100}};
  p.spacing = p.footprint = 10.0;
  p.home = {0, 0};
  return p;
}

void run(benchmark::State& state, const planner::SurveyProblem& p, bool energy_search, bool per_cell = true,
         planner::CornerStrategy corners = planner::CornerStrategy::Auto) {
  const auto v = vehicle();
  const auto model = energy::marinsModel(v);
  planner::PlannerSettings ps;
  ps.per_cell = per_cell;
  ps.corners = corners;
  if (!energy_search) {  // baseline: one angle (longest edge), greedy order, length objective only
    ps.coarse_step_deg = 90.0;
    ps.fine_step_deg = 90.0;
    ps.threads = 1;
    ps.exact_max_cells = 0;
  }
  for (auto _ : state) {
    const auto r = planner::planCoverage(p, v, model, ps);
    benchmark::DoNotOptimize(r.plan.flown.energy);
  }
}

// A field of about 500 m x 500 m whose outline has `vertices` vertices (a wavy circle: a
// non-convex outline whose sweep lines meet it in several intervals), no holes.
planner::SurveyProblem wavy(int vertices) {
  planner::SurveyProblem p;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * M_PI * i / vertices;
    const double r = 250.0 * (1.0 + 0.08 * std::sin(5.0 * a));
    p.area.outer.push_back({250.0 + r * std::cos(a), 250.0 + r * std::sin(a)});
  }
  p.spacing = 30.0;
  p.footprint = 33.0;
  p.home = {-20, -20};
  return p;
}

// Scaling: the full energy search, with the number of cells of the plan as a counter.
void scaling(benchmark::State& state, const planner::SurveyProblem& p) {
  const auto v = vehicle();
  const auto model = energy::marinsModel(v);
  int cells = 0;
  for (auto _ : state) {
    const auto r = planner::planCoverage(p, v, model);
    cells = r.plan.cells;
    benchmark::DoNotOptimize(r.plan.flown.energy);
  }
  state.counters["cells"] = cells;
  state.counters["vertices"] = static_cast<double>(p.area.outer.size());
  state.counters["holes"] = static_cast<double>(p.area.holes.size());
}
void BM_Scaling_Holes(benchmark::State& s) { scaling(s, field(1000, static_cast<int>(s.range(0)), 3)); }
void BM_Scaling_Vertices(benchmark::State& s) { scaling(s, wavy(static_cast<int>(s.range(0)))); }

void BM_Rect2ha_EnergySearch(benchmark::State& s) { run(s, small(false), true); }
void BM_Rect2ha_EnergySearchSharp(benchmark::State& s) { run(s, small(false), true, true, planner::CornerStrategy::Sharp); }
void BM_Rect2ha_Baseline(benchmark::State& s) { run(s, small(false), false); }
void BM_LShape_EnergySearch(benchmark::State& s) { run(s, small(true), true); }
void BM_LShape_EnergySearchSharp(benchmark::State& s) { run(s, small(true), true, true, planner::CornerStrategy::Sharp); }
void BM_LShape_Baseline(benchmark::State& s) { run(s, small(true), false); }
void BM_Rectangle_EnergySearch(benchmark::State& s) { run(s, rectangle(), true); }
void BM_Rectangle_Baseline(benchmark::State& s) { run(s, rectangle(), false); }
void BM_IrisArea_EnergySearch(benchmark::State& s) { run(s, irisArea(), true); }
void BM_IrisArea_Baseline(benchmark::State& s) { run(s, irisArea(), false); }
void BM_Field1km2_3holes_EnergySearch(benchmark::State& s) { run(s, field(1000, 3, 1), true); }
void BM_Field1km2_3holes_Baseline(benchmark::State& s) { run(s, field(1000, 3, 1), false); }
void BM_Field100ha_10holes_EnergySearch(benchmark::State& s) { run(s, field(1000, 10, 2), true); }
void BM_Field100ha_10holes_Baseline(benchmark::State& s) { run(s, field(1000, 10, 2), false); }
// The energy search without the per-cell stage (one sweep angle for the whole area): what the
// per-cell search (each cell its own angle or a spiral) costs on top.
void BM_IrisArea_OneAngleSearch(benchmark::State& s) { run(s, irisArea(), true, false); }
void BM_Field1km2_3holes_OneAngleSearch(benchmark::State& s) { run(s, field(1000, 3, 1), true, false); }
void BM_Field100ha_10holes_OneAngleSearch(benchmark::State& s) { run(s, field(1000, 10, 2), true, false); }

// The cell order of a field cut into many cells (a wiggly 2,000-vertex boundary makes hundreds): a
// random asymmetric GTSP of N clusters of 3 candidates, the local search alone. Scaling in N in
// one run; the 2,000-vertex field's plan went 244 -> 26 s when moves got O(1) estimates (order.cpp).
void BM_GtspHeuristic_Clusters(benchmark::State& st) {
  const planner::GtspInstance g = planner::randomGtspInstance(static_cast<int>(st.range(0)), 3, 5, 1000.0, 1.0);
  for (auto _ : st) benchmark::DoNotOptimize(planner::solveGtspHeuristic(g));
}

}  // namespace

BENCHMARK(BM_Rect2ha_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Rect2ha_EnergySearchSharp)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Rect2ha_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_LShape_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_LShape_EnergySearchSharp)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_LShape_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Rectangle_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Rectangle_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_IrisArea_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_IrisArea_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field1km2_3holes_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field1km2_3holes_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field100ha_10holes_EnergySearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field100ha_10holes_Baseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_IrisArea_OneAngleSearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field1km2_3holes_OneAngleSearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Field100ha_10holes_OneAngleSearch)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Scaling_Holes)->Arg(0)->Arg(1)->Arg(3)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_GtspHeuristic_Clusters)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Scaling_Vertices)->Arg(8)->Arg(32)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_MAIN();
