// Mission prediction speed (issue 16: `predict` on a 1,000-item mission well under a second): a
// synthetic survey of exactly 1,000 items (NAV_TAKEOFF; a lawnmower of 907 NAV_WAYPOINTs over
// 1 km x 1 km with a DO_CHANGE_SPEED before every 10th leg, 91 of them; NAV_RETURN_TO_LAUNCH)
// predicted end to end by mission::predictMission for each autopilot family, and the stages it
// runs (sequenceMission, flyMission, toPieces, the energy of every piece) timed separately.
// Baselines in the same run: the same predictions at FlightSettings::dt = 0.02 s (half the ticks)
// and sequencing alone. IRIS+ vehicle (data/vehicles/iris.json), model hover + kinetic +
// parasitic drag.
#include <benchmark/benchmark.h>

#include <cmath>

#include <algorithm>
#include <string>
#include <vector>

#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/predict.hpp"

namespace {
using namespace wattswath;

// The IRIS+ of the Marins paper, read once.
const energy::Vehicle& vehicle() {
  static const energy::Vehicle v = energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  return v;
}

// Hover + kinetic + parasitic drag with the vehicle's physics, built once.
const energy::EnergyModel& model() {
  static const energy::EnergyModel m = energy::buildModel(vehicle(), {"hover", "kinetic", "parasitic_drag"});
  return m;
}

// The three families: ArduCopter 4.5 (S-curve, defaults), ArduCopter 3.3 (leash), PX4 1.14.
mission::AutopilotConfig autopilot(int family) {
  switch (family) {
    case 1: return mission::parseAutopilot(R"({"firmware":"ArduCopter","version":"3.3"})", "bench");
    case 2: return mission::parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "bench");
    default: return mission::AutopilotConfig{};  // ArduCopter 4.5 with its documented defaults
  }
}

// Label of a family index for the benchmark output.
const char* familyLabel(int family) {
  static const char* const kLabels[] = {"ArduCopter 4.5", "ArduCopter 3.3", "PX4 1.14"};
  return kLabels[std::clamp(family, 0, 2)];
}

// The survey: home near Pisa; passes 1 km long along x, 35 m apart, a waypoint every 1000/30 m
// along each pass (31 per pass, so every leg is 33.3 m; the pass ends are 90 degree corners),
// 40 m above home; DO_CHANGE_SPEED (horizontal) before every 10th leg, cycling 5, 6, 7, 8, 9 m/s.
mission::Mission survey() {
  const geometry::GeoPoint home{43.7, 10.4, 0.0};
  const geometry::LocalFrame frame(home);
  mission::Mission m;
  m.source = "bench_predict survey";
  m.format = "plan";
  m.home = home;
  m.home_known = true;
  auto add = [&](int command, double x, double y, double alt, double p1, double p2, int frame_no) {
    mission::MissionItem it;
    it.seq = static_cast<int>(m.items.size()) + 1;
    it.command = command;
    it.frame = frame_no;
    it.param[0] = p1;
    it.param[1] = p2;
    if (command == 16) {
      const geometry::GeoPoint g = frame.toGeodetic({x, y});
      it.lat_deg = g.lat_deg;
      it.lon_deg = g.lon_deg;
    }
    it.alt_m = alt;
    it.where = "survey item " + std::to_string(it.seq);
    m.items.push_back(it);
  };
  constexpr int kItems = 1000, kPerPass = 31;
  constexpr double kPass = 1000.0, kSpacing = 35.0, kAlt = 40.0;
  add(22, 0, 0, kAlt, 0, 0, 3);
  int legs = 0, wp = 0;
  while (static_cast<int>(m.items.size()) < kItems - 1) {
    if (legs % 10 == 0 && static_cast<int>(m.items.size()) < kItems - 2) {
      add(178, 0, 0, 0, 1.0, 5.0 + (legs / 10) % 5, 2);  // governs the leg into the next waypoint
    }
    const int pass = wp / kPerPass, along = wp % kPerPass;
    const double t = kPass * along / (kPerPass - 1);
    add(16, pass % 2 == 0 ? t : kPass - t, kSpacing * pass, kAlt, 0, 0, 3);
    ++wp;
    ++legs;
  }
  add(20, 0, 0, 0, 0, 0, 2);
  return m;
}

// The survey, built once.
const mission::Mission& theSurvey() {
  static const mission::Mission m = survey();
  return m;
}

// Default prediction settings with simulation step `dt` [s].
mission::PredictSettings settings(double dt) {
  mission::PredictSettings s;
  s.flight.dt = dt;
  return s;
}

// The prediction's totals as counters, to compare families and steps.
void counters(benchmark::State& state, const mission::MissionPrediction& p) {
  state.counters["items"] = static_cast<double>(theSurvey().items.size());
  state.counters["flight_s"] = p.total.time_s;
  state.counters["energy_kJ"] = p.total.energy_j / 1000.0;
  state.counters["distance_km"] = p.total.distance_m / 1000.0;
  state.counters["pieces"] = static_cast<double>(p.pieces.pieces.size());
}

// predictMission of the survey by `family` with settings `s`, timed, with its totals as counters.
void predictLoop(benchmark::State& state, int family, const mission::PredictSettings& s) {
  const mission::AutopilotConfig ap = autopilot(family);
  mission::MissionPrediction p;
  for (auto _ : state) {
    p = mission::predictMission(theSurvey(), vehicle(), model(), ap, s);
    // Not DoNotOptimize(p.total.energy_j): with GCC its asm constraint can clobber a double that
    // is read afterwards (google/benchmark#903); the counters below read it.
    benchmark::DoNotOptimize(p.pieces.pieces.data());
  }
  state.SetLabel(familyLabel(family));
  counters(state, p);
}

// predictMission end to end; range(0) family, range(1) dt in ms.
void BM_Predict(benchmark::State& state) {
  predictLoop(state, static_cast<int>(state.range(0)), settings(state.range(1) / 1000.0));
}

// predictMission at dt 0.01 s in a 6 m/s wind from the north-east (range(0) family) against the
// same in still air (BM_Predict with dt_ms 10): the drag at air speed has no closed form over a
// piece, so the energy stage takes quadrature, and the flight models chase the drag at air speed.
void BM_PredictInWind(benchmark::State& state) {
  mission::PredictSettings s = settings(0.01);
  s.wind = {-6.0 * std::sqrt(0.5), -6.0 * std::sqrt(0.5)};  // from 45 deg: the air moves south-west
  predictLoop(state, static_cast<int>(state.range(0)), s);
}

// Stage 1: the mission items sequenced into navigation steps (DO commands, local metres).
void BM_Stage_Sequence(benchmark::State& state) {
  std::size_t n = 0;
  for (auto _ : state) {
    std::vector<std::string> warnings;
    const auto steps = mission::sequenceMission(theSurvey(), &warnings);
    n = steps.size();
    benchmark::DoNotOptimize(steps.data());
  }
  state.counters["steps"] = static_cast<double>(n);
}

// Stage 2: the steps flown by the family's behaviour model (dt 0.01 s, samples every 0.1 s).
// Flight settings with the vehicle's airframe response (its lean lag), as predictMission flies it.
mission::FlightSettings vehicleFlight() {
  mission::FlightSettings fs;
  fs.airframe = mission::airframeOfVehicle(vehicle(), "iris.json");
  return fs;
}

void BM_Stage_Fly(benchmark::State& state) {
  const int family = static_cast<int>(state.range(0));
  const mission::AutopilotConfig ap = autopilot(family);
  const auto steps = mission::sequenceMission(theSurvey());
  const mission::FlightSettings fs = vehicleFlight();
  std::size_t samples = 0;
  for (auto _ : state) {
    const mission::FlownMission f = mission::flyMission(steps, ap, fs);
    samples = f.samples.size();
    benchmark::DoNotOptimize(f.samples.data());
  }
  state.SetLabel(familyLabel(family));
  state.counters["samples"] = static_cast<double>(samples);
}

// Stage 3: the flown trajectory as energy pieces.
void BM_Stage_ToPieces(benchmark::State& state) {
  const int family = static_cast<int>(state.range(0));
  const mission::FlownMission f = mission::flyMission(mission::sequenceMission(theSurvey()), autopilot(family), vehicleFlight());
  for (auto _ : state) {
    const mission::FlightPieces p = mission::toPieces(f);
    benchmark::DoNotOptimize(p.pieces.data());
  }
  state.SetLabel(familyLabel(family));
}

// Stage 4: the energy of every piece and the breakdown, as predictMission evaluates them (each
// piece on its own, so that it can be added to its phase and its mission item).
void BM_Stage_Energy(benchmark::State& state) {
  const int family = static_cast<int>(state.range(0));
  const mission::FlightPieces fp = mission::toPieces(mission::flyMission(mission::sequenceMission(theSurvey()), autopilot(family), vehicleFlight()));
  for (auto _ : state) {
    energy::Breakdown b = model().emptyBreakdown();
    double total = 0.0;
    for (const energy::Piece& pc : fp.pieces) {
      const std::vector<energy::Piece> one{pc};
      model().accumulate(one, b);
      total += model().energy(one);
    }
    benchmark::DoNotOptimize(total);
  }
  state.SetLabel(familyLabel(family));
  state.counters["pieces"] = static_cast<double>(fp.pieces.size());
}

}  // namespace

BENCHMARK(BM_Predict)->ArgsProduct({{0, 1, 2}, {10, 20}})->ArgNames({"family", "dt_ms"})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_PredictInWind)->Arg(0)->Arg(1)->Arg(2)->ArgName("family")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Stage_Sequence)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Stage_Fly)->Arg(0)->Arg(1)->Arg(2)->ArgName("family")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Stage_ToPieces)->Arg(0)->Arg(1)->Arg(2)->ArgName("family")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_Stage_Energy)->Arg(0)->Arg(1)->Arg(2)->ArgName("family")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_MAIN();
