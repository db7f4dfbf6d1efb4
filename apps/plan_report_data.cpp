// The plan report's data (apps/report) from the planner's result: facts, map legs with their
// energy breakdowns, the scored candidates and baselines, and the battery trace (report_data.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli.hpp"
#include "report_data.hpp"
#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/path_profile.hpp"
#include "wattswath/geometry/geojson.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace geo = wattswath::geometry;
namespace pl = wattswath::planner;
namespace fs = std::filesystem;

double cruiseSpeedFlown(const pl::FlownPath& f, std::size_t i) {
  return f.path.legs[i].kind == geo::PrimitiveKind::TurnInPlace ? 0.0 : f.speeds.cruise[i];
}

namespace {

/// Polyline of one leg for the map [m] (arcs sampled every 10 deg; a turn in place is one point).
std::vector<geo::Point> legPolyline(const geo::PathLeg& leg) {
  if (leg.kind == geo::PrimitiveKind::TurnInPlace) return {leg.start};
  if (leg.kind == geo::PrimitiveKind::Line) return {leg.start, leg.end};
  const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
  const int n = std::max(2, static_cast<int>(std::ceil(std::abs(leg.turn_angle) / (M_PI / 18.0))) + 1);
  std::vector<geo::Point> pts;
  for (int i = 0; i < n; ++i) {
    const double a = a0 + leg.turn_angle * i / (n - 1);
    pts.emplace_back(leg.center.x() + leg.radius * std::cos(a), leg.center.y() + leg.radius * std::sin(a));
  }
  return pts;
}

/// The facts a pilot reads first, of the flight as the autopilot model flies mission.plan from
/// take-off to landing (what `predict` gives for it): time in min:s, energy in Wh, the battery on
/// one basis (the usable charge, counted as the autopilot counts it, as predict's verdict says it),
/// then the area in ha and the farthest distance from home.
report::Facts pilotFacts(const pl::PlanResult& r, const pl::SurveyProblem& pr, const mission::MissionPrediction& flight) {
  const auto& t = flight.total;
  report::Facts facts = {{"flight time", report::formatMinSec(t.time_s) + " min:s (" + fixedText(t.time_s, 0) +
                                             " s), take-off to landing as mission.plan is flown"},
                         {"energy (Wh)", fixedText(t.energy_j / 3600.0, 1) + " Wh (" + fixedText(t.energy_j, 0) +
                                             " J), take-off to landing as mission.plan is flown"}};
  if (flight.battery.known) {
    std::string text = flight.battery.verdict;
    if (r.battery && r.battery->usable_energy_j > 0.0 && !flight.battery.fits) {
      const double packs = std::ceil(r.battery->mission_energy_j / r.battery->usable_energy_j - 1e-9);
      if (packs > 1.0) text += " About " + fixedText(packs, 0) + " batteries' usable energy is needed: plan --sorties splits it.";
    }
    if (flight.battery.depleted) facts.push_back({"battery verdict", text});
    facts.push_back(batteryEndFact(flight.battery, text));
  }
  facts.push_back({"area size", fixedText(geo::area(pr.area) / 1e4, 3) + " ha (" + fixedText(geo::area(pr.area), 0) + " m^2)"});
  double farthest = 0.0;
  for (const auto& leg : r.plan.flown.path.legs) farthest = std::max({farthest, (leg.start - pr.home).norm(), (leg.end - pr.home).norm()});
  facts.push_back({"farthest from home", fixedText(farthest, 0) + " m"});
  return facts;
}

/// The map legs and the Table III-style breakdown of the coverage and transit legs, each leg
/// re-profiled with energy::profileFromPath and the same model, into `d`.
void addLegsAndBreakdowns(report::PlanReportData& d, const pl::FlownPath& f, const energy::Vehicle& v,
                          const energy::EnergyModel& model) {
  const energy::ProfileLimits lim{v.max_acceleration_mps2, v.max_acceleration_mps2};
  d.coverage = model.emptyBreakdown();
  d.transit = model.emptyBreakdown();
  bool any_transit = false;
  for (size_t i = 0; i < f.path.legs.size(); ++i) {
    const auto& leg = f.path.legs[i];
    report::PlanLeg pl_leg;
    pl_leg.points = legPolyline(leg);
    pl_leg.role = geo::roleName(leg.role);
    pl_leg.speed = cruiseSpeedFlown(f, i);
    pl_leg.energy = f.leg_energy[i];
    pl_leg.time = f.leg_time[i];
    pl_leg.length = leg.length();
    d.legs.push_back(pl_leg);
    geo::CoveragePath one;
    one.legs = {leg};
    const energy::SpeedPlan sp{{f.speeds.cruise[i]}, {f.speeds.junction[i], f.speeds.junction[i + 1]}};
    const bool transit = leg.role == geo::LegRole::Transit || leg.role == geo::LegRole::Climb;
    any_transit = any_transit || transit;
    model.accumulate(energy::profileFromPath(one, sp, lim, v.max_yaw_rate_radps), transit ? d.transit : d.coverage);
  }
  if (!any_transit) d.transit = energy::Breakdown{};
}

/// The plan and the sweep angles tried as scored candidates, the per-cell plans and the baselines.
void addCandidates(report::PlanReportData& d, const pl::PlanResult& r) {
  const auto cand = [&](const pl::PlanCandidate& c, bool chosen) {
    return report::PlanCandidate{c.pattern, c.sweep_angle_deg * M_PI / 180.0, c.flown.energy, chosen};
  };
  d.candidates.push_back(cand(r.plan, true));
  for (const auto& a : r.sweep_scan)
    if (std::isfinite(a.energy_j)) d.candidates.push_back({"boustrophedon, one angle", a.sweep_angle_deg * M_PI / 180.0, a.energy_j, false});
  for (const auto& cp : r.plan.cell_plans) d.cells.push_back({cp.pattern, cp.sweep_angle_deg * M_PI / 180.0, cp.energy_j, cp.area_m2});
  d.baselines.push_back({"shortest path", r.shortest_path.flown.energy, r.shortest_path.flown.length,
                         r.shortest_path.flown.time});
  d.baselines.push_back({"ground-station default", r.ground_station_default.flown.energy,
                         r.ground_station_default.flown.length, r.ground_station_default.flown.time});
  if (r.best_spiral)
    d.baselines.push_back({"best spiral", r.best_spiral->flown.energy, r.best_spiral->flown.length,
                           r.best_spiral->flown.time});
}

/// The battery's usable charge left and voltage along the written mission's predicted flight.
report::BatteryTrace batteryTrace(const mission::BatteryPrediction& b) {
  report::BatteryTrace bt;
  bt.model = "Hwang et al. 2018; mission.plan as flown";  // the charge counted as the autopilot counts it
  bt.reserve_pct = 100.0 * b.reserve_fraction;
  if (b.depleted) bt.cutoff_s = b.depleted_at_s;
  bt.t = b.t_s;
  for (const double u : b.usable_left) bt.soc.push_back(100.0 * u);
  bt.voltage = b.voltage_v;
  return bt;
}

}  // namespace

/// The plan report's data from the planner's result: the facts, map legs and breakdowns
/// (addLegsAndBreakdowns), the plan and baselines as scored candidates, and the battery along the
/// written mission's flight when the vehicle has a battery.
report::PlanReportData planReportData(const pl::PlanResult& r, const pl::SurveyProblem& pr, const energy::Vehicle& v,
                                      const energy::EnergyModel& model, const std::string& area_file,
                                      const mission::MissionPrediction& flight) {
  report::PlanReportData d;
  d.title = "wattswath plan: " + fs::path(area_file).filename().string();
  const auto& f = r.plan.flown;
  const auto num = fixedText;
  d.facts = {{"area", area_file},
             {"vehicle", v.name},
             {"plan", r.plan.pattern + " at " + num(r.plan.sweep_angle_deg, 0) + " deg, " + std::to_string(r.plan.cells) +
                          " cell(s), coverage " + num(r.plan.coverage_pct, 1) + " %"},
             {"planner's survey model", num(f.energy / 3600.0, 1) + " Wh (" + num(f.energy, 0) + " J) over " +
                                            report::formatMinSec(f.time) + " min:s (" + num(f.time, 0) + " s) and " +
                                            num(f.length, 0) + " m: the closed-form model the search scored the "
                                            "candidates with, not the flight above"},
             {"lower bound", num(r.lower_bound_j, 0) + " J (plan / bound " +
                                 num(r.lower_bound_j > 0 ? f.energy / r.lower_bound_j : 0.0, 2) + ", in the survey model)"},
             {"spacing", num(pr.spacing, 2) + " m, altitude " + num(pr.altitude, 1) + " m"}};
  const auto pilot = pilotFacts(r, pr, flight);
  d.facts.insert(d.facts.begin() + 1, pilot.begin(), pilot.end());
  d.areas = {pr.area};
  d.no_fly = pr.no_fly;
  d.home = pr.home;
  addLegsAndBreakdowns(d, f, v, model);
  addCandidates(d, r);
  if (flight.battery.known) d.battery = batteryTrace(flight.battery);
  return d;
}

}  // namespace wattswath::apps
