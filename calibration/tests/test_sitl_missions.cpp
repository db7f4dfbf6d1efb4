// Missions flown by ArduCopter 4.7-dev's own code in SITL (../shared/data/sitl): the S-curve model,
// with the parameters read from each log's PARM messages, against the times at which each item was
// reached. The figures are in docs/validation.md ("Missions flown by the autopilot's own code").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "wattswath/logs/airframe.hpp"
#include "wattswath/logs/parameters.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/flight.hpp"

namespace ms = wattswath::mission;

namespace {

std::string sitl(const std::string& name) { return std::string(WATTSWATH_SHARED_DATA_DIR) + "/sitl/" + name; }

// Item number -> reached time after lift-off [s] (items.csv), NAV_WAYPOINT rows only.
std::map<int, double> reachedTimes(const std::string& name) {
  std::ifstream in(sitl(name + ".items.csv"));
  std::string line;
  std::getline(in, line);
  std::map<int, double> out;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    if (f.size() >= 7 && f[1] == "NAV_WAYPOINT" && !f[6].empty()) out[std::stoi(f[0])] = std::stod(f[6]);
  }
  return out;
}

struct SitlRun {
  double predicted_flight_s = 0.0, measured_flight_s = 0.0, worst_leg_error_s = 0.0, worst_item_error_s = 0.0;
  double worst_item_error_fraction = 0.0;
  int legs = 0;
};

SitlRun run(const std::string& name) {
  const auto params = wattswath::logs::readAutopilotParameters(sitl(name + ".BIN"));
  ms::AutopilotConfig ap;
  ap.firmware = "ArduCopter";
  ap.version = params.firmware.version;
  ap.family = ms::familyOf(ap.firmware, ap.version);
  ap.parameters = wattswath::logs::flightBehaviourParameters(params);
  const ms::Mission m = ms::readMission(sitl(name + ".waypoints"));
  const auto steps = ms::sequenceMission(m);
  // The airframe identified from the same log, as `vehicle params` writes it: its drag (lean angle
  // against speed) and its response (achieved against target acceleration).
  const auto airframe = wattswath::logs::estimateAirframe(sitl(name + ".BIN"));
  const auto& drag = airframe.drag;
  EXPECT_TRUE(drag.determined) << drag.reason;
  EXPECT_TRUE(airframe.response.determined) << airframe.response.reason;
  std::printf("%s: airframe drag %.3f 1/s x v + %.4f 1/m x v^2 (R^2 %.3f, %zu samples from %s), response %.3f s (R^2 %.4f)\n",
              name.c_str(), drag.drag_linear_per_s, drag.drag_quadratic_per_m, drag.r2, drag.samples, drag.velocity_source.c_str(),
              airframe.response.response_s, airframe.response.r2);
  ms::FlightSettings fs;
  fs.airframe.drag_linear_per_s = drag.drag_linear_per_s;
  fs.airframe.drag_quadratic_per_m = drag.drag_quadratic_per_m;
  fs.airframe.response_s = airframe.response.response_s;
  const ms::FlownMission f = ms::flyMission(steps, ap, fs);
  // The SITL times count from lift-off; ours from the take-off command (MOT_SPOOL_TIME earlier).
  const double liftoff = ap.get("MOT_SPOOL_TIME");
  const auto reached = reachedTimes(name);
  nlohmann::json times;
  std::ifstream(sitl(name + ".times.json")) >> times;
  SitlRun r;
  r.measured_flight_s = times["flight_time_s"].get<double>();
  r.predicted_flight_s = f.samples.back().t - liftoff;
  double prev_m = NAN, prev_p = NAN;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (steps[k].item < 0) continue;
    const auto it = reached.find(m.items[steps[k].item].seq);
    if (it == reached.end()) continue;
    // ArduCopter reports an item reached when it completes (after its hold).
    const double p = f.events[k].completed_s - liftoff;
    r.worst_item_error_s = std::max(r.worst_item_error_s, std::abs(p - it->second));
    r.worst_item_error_fraction = std::max(r.worst_item_error_fraction, std::abs(p - it->second) / it->second);
    std::printf("  item %d reached %.2f s predicted, %.2f s in SITL (%+.2f s)\n", m.items[steps[k].item].seq, p, it->second, p - it->second);
    if (std::isfinite(prev_m)) {
      r.worst_leg_error_s = std::max(r.worst_leg_error_s, std::abs((p - prev_p) - (it->second - prev_m)));
      ++r.legs;
    }
    prev_m = it->second;
    prev_p = p;
  }
  std::printf("%s: flight %.1f s predicted vs %.1f s (%+.1f %%), worst leg %.2f s, worst item %.2f s over %d legs\n",
              name.c_str(), r.predicted_flight_s, r.measured_flight_s, 100.0 * (r.predicted_flight_s / r.measured_flight_s - 1.0),
              r.worst_leg_error_s, r.worst_item_error_s, r.legs);
  return r;
}

}  // namespace

// The targets: take-off to landing within 3 %, each item reached within 3 % of its time,
// each leg's duration within 2 s. Before the vehicle's tracking of its target was modelled
// (position controller, airframe drag, the S-curve clock scaler, RTL from the stopping point) the
// flights came out 3.6-6.2 % short (docs/validation.md 5.1).
void expectTargets(const SitlRun& r) {
  EXPECT_LT(r.worst_leg_error_s, 2.0);
  EXPECT_LT(r.worst_item_error_fraction, 0.03);
  EXPECT_NEAR(r.predicted_flight_s / r.measured_flight_s, 1.0, 0.03);
}

TEST(SitlMissions, SquareAt5mpsWithin3Percent) {
  const SitlRun r = run("square_5mps");
  EXPECT_EQ(r.legs, 3);
  expectTargets(r);
}

TEST(SitlMissions, SquareAt10mpsWithin3Percent) {
  const SitlRun r = run("square_10mps");
  EXPECT_EQ(r.legs, 3);
  expectTargets(r);
}

TEST(SitlMissions, PlannedMissionWithHoldsWithin3Percent) {
  const SitlRun r = run("plan_sharp_hold1s");
  EXPECT_GE(r.legs, 20);
  expectTargets(r);
}
