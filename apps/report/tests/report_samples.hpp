#pragma once
// Synthetic, seeded data for the report tests: shaped like real plans, logs and sweeps so that the
// rendered pages exercise every figure (numbers are illustrative, not physics).
#include <array>
#include <cmath>
#include <random>

#include "wattswath/report/reports.hpp"

namespace wattswath::test {

namespace wr = wattswath::report;

/// pi.
inline constexpr double kPi() { return 3.14159265358979323846; }

/// A boustrophedon over a 300 x 200 m field with a pond, a no-fly zone and a transit home.
inline wr::PlanReportData samplePlan() {
  wr::PlanReportData d;
  d.title = "Plan: sample field <test>";
  d.facts = {{"vehicle", "sample quad"}, {"area", "6.0 ha"}, {"total energy", "123.4 kJ"}};
  geometry::PolygonWithHoles a;
  a.outer = {{0, 0}, {300, 0}, {320, 200}, {0, 200}};
  a.holes = {{{120, 80}, {120, 120}, {170, 120}, {170, 80}}};
  d.areas = {a};
  d.no_fly = {{{250, 150}, {290, 150}, {290, 190}, {250, 190}}};
  d.home = geometry::Point(-20, -20);
  d.legs.push_back({{{-20, -20}, {10, 10}}, "transit", 6.0, 2500, 12, 42});
  for (int i = 0; i < 10; ++i) {
    const double y = 10 + 20 * i;
    const bool east = i % 2 == 0;
    const double x0 = east ? 10 : 300, x1 = east ? 300 : 10;
    d.legs.push_back({{{x0, y}, {x1, y}}, "sweep", 6.0 + 0.3 * i, 9000.0 + 300 * i, 45, 290});
    if (i < 9) {
      std::vector<geometry::Point> arc;
      for (int k = 0; k <= 8; ++k) {
        const double a0 = -kPi() / 2 + kPi() * k / 8.0;
        arc.push_back({x1 + (east ? 10 : -10) * std::cos(a0), y + 10 + 10 * std::sin(a0)});
      }
      d.legs.push_back({arc, "turn", 3.0, 800, 10, 31});
    }
  }
  d.legs.push_back({{{10, 190}, {-20, -20}}, "transit", 8.0, 6000, 30, 212});
  // Mission items as the ground station numbers them: take-off, a waypoint per sweep end, return.
  d.items.push_back({1, "NAV_TAKEOFF", std::nullopt});
  for (int i = 0; i < 10; ++i) {
    const bool east = i % 2 == 0;
    d.items.push_back({2 + i, "NAV_WAYPOINT", geometry::Point(east ? 300 : 10, 10 + 20 * i)});
  }
  d.items.push_back({12, "NAV_RETURN_TO_LAUNCH", std::nullopt});
  d.colour_by = wr::PlanColour::Speed;
  d.coverage.effects = {"hover", "kinetic", "parasitic_drag"};
  d.coverage.energy = {{8560, 27286, 6848, 1601, 0, 0, 0, 0}, {506, 0, 434, 0, 0, 0, 0, 0}, {131, 1096, 128, 13, 0, 0, 0, 0}};
  d.transit.effects = d.coverage.effects;
  d.transit.energy = {{900, 5000, 800, 0, 0, 0, 0, 0}, {60, 0, 50, 0, 0, 0, 0, 0}, {10, 300, 9, 0, 0, 0, 0, 0}};
  for (int deg = 0; deg < 180; deg += 15) {
    const double e = 120000 + 15000 * std::sin(deg * kPi() / 180.0) + 3000 * std::cos(3 * deg * kPi() / 180.0);
    d.candidates.push_back({"boustrophedon", deg * kPi() / 180.0, e, deg == 0});
  }
  d.candidates.push_back({"spiral", 0.0, 131000, false});
  d.baselines = {{"shortest path", 128000, 3400, 0}, {"ground-station default", 141000, 3500, 560}};
  wr::BatteryTrace b;
  b.model = "Hwang et al.";
  for (int s = 0; s <= 600; s += 10) {
    b.t.push_back(s);
    b.soc.push_back(100.0 - 0.11 * s);
    b.voltage.push_back(16.6 - 0.0025 * s - 0.3 * (s > 0));
  }
  b.reserve_pct = 25.0;
  d.battery = b;
  return d;
}

/// samplePlan split into three sorties flown by two vehicles (tracks, energies and schedule illustrative).
inline wr::PlanReportData samplePlanWithSorties() {
  wr::PlanReportData d = samplePlan();
  wr::PlanSorties s;
  const geometry::Point home(-20, -20);
  for (int k = 0; k < 3; ++k) {
    wr::PlanSortie so;
    so.vehicle = k < 2 ? 1 : 2;
    so.name = "vehicle " + std::to_string(so.vehicle) + ", sortie " + std::to_string(k < 2 ? k + 1 : 1);
    so.file = "vehicle_" + std::to_string(so.vehicle) + "_sortie_0" + std::to_string(k < 2 ? k + 1 : 1) + ".plan";
    so.track.push_back(home);
    for (int i = 3 * k; i < 3 * k + 4 && i < 10; ++i) {
      const double y = 10 + 20 * i;
      so.track.push_back({i % 2 == 0 ? 10.0 : 300.0, y});
      so.track.push_back({i % 2 == 0 ? 300.0 : 10.0, y});
    }
    so.track.push_back(home);
    so.energy_j = 40000.0 + 3000.0 * k;
    so.time_s = 300.0 + 20.0 * k;
    so.soc_landing_pct = 30.0 - 2.0 * k;
    so.photos = 120 + 10 * k;
    so.start_s = k == 0 ? 0.0 : k == 1 ? 420.0 : 30.0;
    so.delay_s = k == 2 ? 10.0 : 0.0;
    s.sorties.push_back(so);
  }
  s.single_energy_j = 110000.0;
  s.single_time_s = 800.0;
  s.single_base = "mission.plan flown by the sample autopilot, unlimited battery";
  s.vehicles = 2;
  s.makespan_s = 740.0;
  s.swap_time_s = 120.0;
  s.launch_interval_s = 30.0;
  s.separation_m = 15.0;
  s.min_separation_m = 21.5;
  d.sorties = s;
  return d;
}

/// A 300 s log with phases, a drag-like residual growing with speed, and leg energies.
inline wr::ValidationReportData sampleValidation() {
  wr::ValidationReportData d;
  d.facts = {{"log", "sample.csv"}, {"model", "marins"}};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 8.0);
  for (int i = 0; i < 6000; ++i) {
    const double t = 0.05 * i;
    const double ph = std::fmod(t, 60.0);
    const double v = ph < 8 ? ph : (ph < 40 ? 8.0 : (ph < 48 ? 48 - ph : 0.0));
    const double model = 180 + 0.4 * v * v + (ph < 8 ? 25 : 0);
    d.t.push_back(t);
    d.modelled_power.push_back(model);
    d.measured_power.push_back(model + 0.9 * v * v + noise(rng));
    d.speed.push_back(v);
    d.climb_rate.push_back(0.3 * std::sin(t / 7.0));
    d.heading.push_back(std::floor(t / 60.0) * 1.2 - 3.0);
  }
  for (int k = 0; k < 5; ++k) {
    const double t0 = 60.0 * k;
    d.phases.push_back({t0, t0 + 8, "accelerate"});
    d.phases.push_back({t0 + 8, t0 + 40, "cruise"});
    d.phases.push_back({t0 + 40, t0 + 48, "brake"});
    d.phases.push_back({t0 + 48, t0 + 60, "turn"});
    d.legs.push_back({"leg " + std::to_string(k + 1), 14000.0 + 500 * k, 12000.0 + 450 * k});
  }
  d.staircase = {{"vehicle physics", 62.0}, {"refit base", 35.0}, {"+ parasitic_drag", 9.5}, {"+ climb", 8.9}};
  d.diagnosis = {{"parasitic_drag", 72.9, "C_D A = 0.031 +- 0.002 m^2", "drag area of a 0.3 m^2 frame", true},
                 {"climb", 6.3, "k = 0.8 +- 0.5 W s/m", "barely distinguishable from noise", false}};
  return d;
}

/// Table V-like rows at three angles.
inline wr::TurnReportData sampleTurns() {
  wr::TurnReportData d;
  d.facts = {{"vehicle", "sample quad"}};
  for (const double deg : {45.0, 90.0, 135.0}) {
    for (const double L : {10.0, 20.0, 50.0, 100.0}) {
      const double b = deg * kPi() / 180.0;
      wr::TurnRow r;
      r.beta = b;
      r.leg_length = L;
      r.sharp_energy = 2 * (1800 + 250 * L) + 600 * (kPi() - b);
      r.rounded_energy = 2 * 240 * L + 900 * (kPi() + b) / 2;
      r.sharp_speed = std::min(8.0, std::sqrt(L));
      r.rounded_speed = 4.0;
      if (L == 50.0) r.paper_saving_pct = 100.0 * (r.sharp_energy - r.rounded_energy) / r.sharp_energy + 1.0;
      d.rows.push_back(r);
    }
  }
  return d;
}

/// Fig. 3-like curves and a few E(v) curves.
inline wr::SpeedReportData sampleSpeed() {
  wr::SpeedReportData d;
  d.facts = {{"vehicle", "sample quad"}};
  d.v_max = 15.0;
  for (int variant = 0; variant < 3; ++variant) {
    wr::SpeedCurve c;
    c.name = variant == 0 ? "full model" : (variant == 1 ? "no drag" : "no kinetic");
    for (double L = 2; L <= 1000; L *= 1.4) {
      c.distance.push_back(L);
      c.speed.push_back(std::min(15.0, (variant == 1 ? 1.6 : 1.2) * std::sqrt(L) + (variant == 2 ? 2.0 : 0.0)));
    }
    d.curves.push_back(c);
  }
  for (const double L : {20.0, 100.0}) {
    wr::LegEnergyCurve e;
    e.distance = L;
    for (double v = 1; v <= 15; v += 0.5) {
      e.speed.push_back(v);
      e.energy.push_back(L * (180 / v + 0.2 * v * v) + 15 * v * v);
    }
    e.best_speed = 5.0;
    e.best_energy = L * (180 / 5.0 + 5.0) + 375;
    d.legs.push_back(e);
  }
  return d;
}

/// A 5-minute survey mission at 10 m: take-off, a lawnmower of 6 waypoints (two at the same spot),
/// return and landing, 10 Hz samples, with a battery.
inline wr::MissionReportData sampleMission() {
  wr::MissionReportData d;
  d.title = "Mission: sample <survey>";
  d.facts = {{"mission", "sample.waypoints"}, {"vehicle", "sample quad"}};
  const std::vector<std::pair<double, double>> wps = {{0, 40}, {120, 40}, {120, 80}, {0, 80}, {0, 40}, {60, 120}};
  auto addPhase = [&](const std::string& phase, double t0, double t1, auto pos) {
    for (double t = t0; t < t1 - 1e-9; t += 0.1) {
      const auto p = pos(t);
      d.t.push_back(t);
      d.x.push_back(p[0]);
      d.y.push_back(p[1]);
      d.z.push_back(p[2]);
      d.speed.push_back(p[3]);
      d.phase.push_back(phase);
    }
  };
  addPhase("takeoff", 0, 5, [](double t) { return std::array<double, 4>{0, 0, 2 * t, 2}; });
  const double legT = 40.0;  // every leg flown in 40 s, speed a sine bump
  addPhase("mission", 5, 5 + legT * 7, [&](double t) {
    const int k = std::min(6, static_cast<int>((t - 5) / legT));
    const double f = (t - 5 - k * legT) / legT;
    const auto a = k == 0 ? std::pair<double, double>{0, 0} : wps[k - 1], b = wps[std::min<std::size_t>(k, wps.size() - 1)];
    return std::array<double, 4>{a.first + f * (b.first - a.first), a.second + f * (b.second - a.second), 10,
                                 4.5 * std::sin(kPi() * f)};
  });
  addPhase("return", 285, 300, [](double t) { return std::array<double, 4>{60 - 4 * (t - 285), 120 - 8 * (t - 285), 10, 6}; });
  addPhase("landing", 300, 310, [](double t) { return std::array<double, 4>{0, 0, 10 - (t - 300), 1}; });
  for (std::size_t k = 0; k < wps.size(); ++k) {
    wr::MissionMark m;
    m.seq = static_cast<int>(2 * k + 2);
    m.command = "NAV_WAYPOINT";
    m.position = geometry::Point(wps[k].first, wps[k].second);
    m.reached_s = 5 + legT * (k + 1);
    m.energy_j = 9000;
    m.time_s = legT;
    m.distance_m = 100;
    d.items.push_back(m);
  }
  d.items.push_back({-1, "NAV_RETURN_TO_LAUNCH", std::nullopt, 300.0, 4000, 15, 120});
  d.phases = {{"takeoff", 5, 1500, 10}, {"mission", 280, 60000, 900}, {"return", 15, 4000, 120}, {"landing", 10, 2500, 10}};
  d.total = {"total", 310, 68000, 1040};
  wr::BatteryTrace b;
  b.model = "Hwang et al.";
  for (double t = 0; t <= 310; t += 1) {
    b.t.push_back(t);
    b.soc.push_back(100.0 - 0.15 * t);
  }
  d.battery = b;
  d.reserve_pct = 25;
  d.verdict = "Fits: lands with 53.5 % of the usable charge (reserve 25 %).";
  return d;
}

/// Two logged flights of a mission against their prediction; the second has an unmatched waypoint.
inline wr::MissionReplayData sampleMissionReplay() {
  wr::MissionReplayData d;
  d.model = "the vehicle file's calibration";
  d.autopilot = "arducopter-leash";
  for (int flight = 0; flight < 2; ++flight) {
    wr::MissionReplayFlight f;
    f.name = "flight" + std::to_string(flight + 1) + ".csv";
    f.mission = "mission <" + std::to_string(flight + 1) + ">.waypoints";
    for (double t = 0; t <= 300; t += 1.0) {
      f.measured_t.push_back(t);
      f.measured_speed.push_back(5 + 4 * std::sin(t / 9.0));
    }
    for (double t = 0; t <= 290; t += 0.1) {
      f.predicted_t.push_back(t);
      f.predicted_speed.push_back(5.5 + 4 * std::sin(t / 8.5));
    }
    for (int k = 0; k < 8; ++k) {
      f.waypoint_labels.push_back(std::to_string(2 * k + 3));
      f.measured_passage_s.push_back(10 + 36.0 * k);
      f.predicted_passage_s.push_back(flight == 1 && k == 4 ? std::nan("") : 10 + 34.5 * k);
    }
    for (int k = 0; k + 1 < 8; ++k) {
      const bool unmatched = flight == 1 && (k == 3 || k == 4);
      f.legs.push_back({f.waypoint_labels[k] + "-" + f.waypoint_labels[k + 1], 36.0, unmatched ? std::nan("") : 34.5,
                        9000.0 + 300 * k, unmatched ? std::nan("") : 8600.0 + 250 * k});
    }
    f.measured_energy_j = 74735;
    f.predicted_energy_j = 67597;
    f.replay_energy_j = 72746;
    f.measured_time_s = 332;
    f.predicted_time_s = 307;
    f.leg_time_mape_pct = 14.4;
    d.flights.push_back(f);
  }
  return d;
}

}  // namespace wattswath::test
