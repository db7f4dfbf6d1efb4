// The planner's finalists flown by the autopilot model (flight_score.hpp).
#include "wattswath/planner/flight_score.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "wattswath/mission/files.hpp"
#include "wattswath/mission/planned_mission.hpp"

namespace wattswath::planner {

mission::MissionPrediction flyWrittenMission(const PlanMission& written, const FlightScoring& s, const std::string& source) {
  // The very text `wattswath predict mission.plan` reads.
  const mission::Mission m = mission::parseQgcPlan(mission::toQgcPlan(written.mission), source);
  return mission::predictMission(m, *s.vehicle, *s.model, s.autopilot, s.settings);
}

std::vector<FlightScore> scoreByFlight(const std::vector<std::pair<std::string, const PlanCandidate*>>& candidates,
                                       const FlightScoring& s) {
  if (!s.problem || !s.frame || !s.vehicle || !s.model) throw std::invalid_argument("scoreByFlight: FlightScoring is incomplete");
  std::vector<FlightScore> out;
  for (const auto& [label, c] : candidates) {
    if (!c || !c->valid) continue;
    const bool has_arcs = std::any_of(c->flown.path.legs.begin(), c->flown.path.legs.end(),
                                      [](const geometry::PathLeg& l) { return l.kind == geometry::PrimitiveKind::Arc; });
    for (const bool arc_waypoints : {false, true}) {
      if (arc_waypoints && !has_arcs) continue;  // the same mission
      FlightScore f;
      f.label = has_arcs ? label + (arc_waypoints ? " (arcs as waypoints)" : " (arcs as chords)") : label;
      f.candidate = c;
      f.arc_waypoints = arc_waypoints;
      f.closed_form_energy_j = c->flown.energy;
      MissionOptions mo = s.mission;
      mo.arc_waypoints = arc_waypoints;
      f.mission = missionFromPlan(c->flown, *s.problem, *s.frame, s.home_altitude_amsl_m, mo);
      // A chord that comes within the no-fly margin is not offered (the waypoints along the arc are).
      if (!arc_waypoints && has_arcs && f.mission.legs_within_margin > 0) continue;
      f.prediction = flyWrittenMission(f.mission, s, label + " mission.plan");
      out.push_back(std::move(f));
    }
  }
  return out;
}

std::size_t cheapestFlight(const std::vector<FlightScore>& scores, double coverage_slack_pct) {
  if (scores.empty()) throw std::invalid_argument("cheapestFlight: no flight scored");
  const double best_cov = scores.front().candidate->coverage_pct;  // the search's choice
  std::size_t best = scores.size();
  double best_e = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (scores[i].candidate->coverage_pct < best_cov - coverage_slack_pct) continue;
    if (scores[i].prediction.total.energy_j < best_e) {
      best_e = scores[i].prediction.total.energy_j;
      best = i;
    }
  }
  return best;
}

}  // namespace wattswath::planner
