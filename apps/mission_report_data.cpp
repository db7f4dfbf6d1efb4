// Fills the mission report (predict --report) from a mission prediction.
#include <cmath>

#include "report_data.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {

namespace ms = wattswath::mission;

namespace {

/// True for the steps drawn as numbered points on the map (they fly to a position of their own; a
/// LOITER_TURNS at its centre).
bool drawnOnMap(const ms::NavStep& s) {
  using K = ms::NavStep::Kind;
  return s.has_position && (s.kind == K::Waypoint || s.kind == K::SplineWaypoint || s.kind == K::LoiterTime ||
                            s.kind == K::LoiterTurns || s.kind == K::Land);
}

report::MissionPhaseTotals phaseTotals(const std::string& name, const ms::Totals& t) {
  return {name, t.time_s, t.energy_j, t.distance_m};
}

}  // namespace

std::vector<report::MissionMark> planMapItems(const ms::Mission& m, const geometry::LocalFrame& frame) {
  std::vector<report::MissionMark> out;
  for (const auto& it : m.items) {
    report::MissionMark k;
    k.seq = it.seq;
    k.command = ms::commandName(it.command);
    const bool positioned = std::isfinite(it.lat_deg) && std::isfinite(it.lon_deg) && (it.lat_deg != 0.0 || it.lon_deg != 0.0);
    // Only the waypoints get a numbered dot; take-off and return are named at home by the report.
    if (positioned && it.command == static_cast<int>(ms::Command::NavWaypoint)) k.position = frame.toLocal(it.lat_deg, it.lon_deg);
    out.push_back(std::move(k));
  }
  return out;
}

std::pair<std::string, std::string> batteryEndFact(const ms::BatteryPrediction& b, const std::string& detail) {
  if (b.depleted) {
    return {"battery cut-off", "reached " + report::formatMinSec(b.depleted_at_s) +
                                   " min:s after the take-off, in the air: the flight does not reach its landing "
                                   "(the figures past it assume the battery held out)"};
  }
  return {b.ends_in_air ? "battery at the end (in the air)" : "battery at landing", detail};
}

report::MissionReportData missionReportData(const ms::MissionPrediction& p, double reserve_pct) {
  report::MissionReportData d;
  for (const auto& s : p.flight.samples) {
    d.t.push_back(s.t);
    d.x.push_back(s.position.x());
    d.y.push_back(s.position.y());
    d.z.push_back(s.position.z());
    d.speed.push_back(s.velocity.norm());
    d.phase.push_back(ms::toString(s.phase));
  }
  for (const auto& it : p.items) {
    report::MissionMark m;
    m.seq = it.seq;
    m.command = it.command;
    if (it.step >= 0 && it.step < static_cast<int>(p.flight.steps.size()) && drawnOnMap(p.flight.steps[it.step])) {
      const auto& target = p.flight.steps[it.step].target;
      m.position = geometry::Point(target.x(), target.y());
    }
    m.reached_s = it.reached_s;
    m.energy_j = it.totals.energy_j;
    m.time_s = it.totals.time_s;
    m.distance_m = it.totals.distance_m;
    d.items.push_back(std::move(m));
  }
  for (int k = 0; k < ms::kFlightPhaseCount; ++k) {
    d.phases.push_back(phaseTotals(ms::toString(static_cast<ms::FlightPhase>(k)), p.phases[k]));
  }
  d.total = phaseTotals("total", p.total);
  d.reserve_pct = reserve_pct;
  if (p.battery.known) {
    report::BatteryTrace b;
    b.t = p.battery.t_s;
    for (const double u : p.battery.usable_left) b.soc.push_back(100.0 * u);
    b.voltage = p.battery.voltage_v;
    b.model = "Hwang et al. Eq. 9-15";
    b.reserve_pct = reserve_pct;
    if (p.battery.depleted) b.cutoff_s = p.battery.depleted_at_s;
    d.battery = std::move(b);
    d.verdict = p.battery.verdict;
  } else {
    d.verdict = "The vehicle file has no battery: no state of charge or reserve verdict can be given.";
  }
  return d;
}

}  // namespace wattswath::apps
