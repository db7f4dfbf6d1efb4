// Missions flown by ArduCopter 4.7-dev's own code in SITL (../shared/data/sitl): the S-curve model,
// with the parameters read from each log's PARM messages, against the times at which each item was
// reached. The figures are in docs/validation.md ("Missions flown by the autopilot's own code").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "wattswath/logs/airframe.hpp"
#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/parameters.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/flight.hpp"
#include "wattswath/mission/scurve.hpp"

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
  // The SITL times count from lift-off; ours from the take-off command (MOT_SPOOL_TIME and the
  // take-off throttle slew earlier).
  double liftoff = 0.0;
  for (const auto& s : f.samples)
    if (s.airborne) {
      liftoff = s.t;
      break;
    }
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

// The issue's targets: take-off to landing within 3 %, each item reached within 3 % of its time,
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

namespace {

namespace df = wattswath::logs::dataflash;

// [s] The time t with f(t) = v on [lo, hi] for f increasing there (bisection).
template <class F>
double solveIncreasing(F f, double v, double lo, double hi) {
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < v ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

}  // namespace

// The S-curve target itself, as the log's position controller records it (PSCN/PSCE desired
// velocity, 10 Hz), on every leg of plan_sharp_hold1s (a stop at each waypoint): its start and its
// end have the shape of our SCurveProfile to the millisecond, it starts when the previous item is
// reported reached, and it lasts as long as the flight model's (the clock scaler included). Where
// the S-curve ends is found from the last target speeds below 1 cm/s: each gives the time left by
// inverting our profile's tail, and they agree within 10 ms. What follows the end is the hold:
// ArduCopter reports the item reached 0.86-1.01 s (median 0.89 s) after it, where the source's
// 1 s timer would say 1.00 s (docs/validation.md 5.1); the model holds 1.00 s.
TEST(SitlMissions, EachHoldLegsTargetIsOurSCurveAndLastsAsTheFlightModelSays) {
  const std::string bin = sitl("plan_sharp_hold1s.BIN");
  std::ifstream in(bin, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const df::Log L = df::Log::parseAcceptingCutEnd(std::move(bytes), bin, false);
  const std::vector<double> t = L.times("PSCN"), te = L.times("PSCE");
  const std::vector<double> dvn = L.column("PSCN", "DVN"), dve = L.column("PSCE", "DVE");
  ASSERT_EQ(t.size(), te.size());
  std::vector<double> speed(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    ASSERT_NEAR(t[i], te[i], 1e-3);
    speed[i] = std::hypot(dvn[i], dve[i]);
  }
  std::map<int, double> reached;  // item -> log time of "Reached command #N"
  const auto msg_t = L.times("MSG");
  const auto msg = L.textColumn("MSG", "Message");
  for (std::size_t i = 0; i < msg.size(); ++i)
    if (msg[i].rfind("Reached command #", 0) == 0) reached[std::stoi(msg[i].substr(17))] = msg_t[i];

  const auto params = wattswath::logs::readAutopilotParameters(bin);
  const auto P = wattswath::logs::flightBehaviourParameters(params);
  // AC_WPNav::calc_scurve_jerk_and_snap: jerk WPNAV_JERK, snap from ATC_INPUT_TC (halved).
  const double jerk = P.at("WPNAV_JERK"), accel = P.at("WPNAV_ACCEL") / 100.0;
  const double snap = 0.5 * jerk * M_PI / (2.0 * std::max(P.at("ATC_INPUT_TC"), 0.1));

  ms::AutopilotConfig ap;
  ap.firmware = "ArduCopter";
  ap.version = params.firmware.version;
  ap.family = ms::familyOf(ap.firmware, ap.version);
  ap.parameters = P;
  const ms::Mission m = ms::readMission(sitl("plan_sharp_hold1s.waypoints"));
  const auto steps = ms::sequenceMission(m);
  const auto airframe = wattswath::logs::estimateAirframe(bin);
  ms::FlightSettings fs;
  fs.airframe.drag_linear_per_s = airframe.drag.drag_linear_per_s;
  fs.airframe.drag_quadratic_per_m = airframe.drag.drag_quadratic_per_m;
  fs.airframe.response_s = airframe.response.response_s;
  const ms::FlownMission f = ms::flyMission(steps, ap, fs);

  int legs = 0;
  std::vector<double> holds, diffs;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const std::size_t j = k - 1;
    if (steps[k].kind != ms::NavStep::Kind::Waypoint || steps[j].kind != ms::NavStep::Kind::Waypoint) continue;
    const int a = m.items[steps[j].item].seq, b = m.items[steps[k].item].seq;
    ASSERT_TRUE(reached.count(a) && reached.count(b)) << a << " " << b;
    const double t0 = reached[a], t1 = reached[b];
    const double length = (steps[k].target - steps[j].target).norm();
    const auto prof = ms::SCurveProfile::restToRest(length, {steps[k].speed_xy, accel, jerk, snap});
    const double T = prof.duration();
    const auto head = [&](double tau) { return prof.at(tau).vel; };
    const auto tail = [&](double tau) { return prof.at(T - tau).vel; };
    std::vector<double> starts, ends;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (speed[i] <= 1e-6 || speed[i] >= 0.01) continue;
      if (t[i] > t0 && t[i] < t0 + 1.0) starts.push_back(t[i] - solveIncreasing(head, speed[i], 0.0, prof.accelEndTime()) - t0);
      if (t[i] > t1 - 2.0 && t[i] < t1) ends.push_back(t[i] + solveIncreasing(tail, speed[i], 0.0, T - prof.decelStartTime()));
    }
    ASSERT_GE(starts.size(), 1u) << "leg to item " << b;
    ASSERT_GE(ends.size(), 2u) << "leg to item " << b;
    for (double s : starts) EXPECT_NEAR(s, 0.0, 0.015) << "the S-curve to item " << b << " starts as the previous item is reached";
    const auto [lo, hi] = std::minmax_element(ends.begin(), ends.end());
    EXPECT_LT(*hi - *lo, 0.01) << "the S-curve tail to item " << b << " is ours";
    const double end = median(ends);
    // The flight model's S-curve: from the previous item's completion to this one's reaching.
    const double model = f.events[k].reached_s - f.events[j].completed_s;
    diffs.push_back(model - (end - t0));
    holds.push_back(t1 - end);
    EXPECT_NEAR(model, end - t0, 0.4) << "leg to item " << b;
    std::printf("  leg to item %d: %.1f m, S-curve %.2f s in SITL, %.2f s predicted (%+.2f s); reported reached %.3f s after it\n", b,
                length, end - t0, model, model - (end - t0), t1 - end);
    ++legs;
  }
  EXPECT_GE(legs, 20);
  double mean_abs = 0.0;
  for (double d : diffs) mean_abs += std::abs(d) / static_cast<double>(diffs.size());
  EXPECT_LT(mean_abs, 0.15);
  std::printf("plan_sharp_hold1s: %d legs, S-curve durations within %.2f s on average; hold after the S-curve: median %.3f s\n", legs,
              mean_abs, median(holds));
}
