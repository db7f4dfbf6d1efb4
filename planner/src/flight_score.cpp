// The planner's finalists flown by the autopilot model (flight_score.hpp).
#include "wattswath/planner/flight_score.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>

#include "wattswath/mission/files.hpp"
#include "wattswath/mission/planned_mission.hpp"

namespace wattswath::planner {

namespace {

// The .plan text `text` read back and flown, as `wattswath predict` flies it.
mission::MissionPrediction flyPlanText(const std::string& text, const FlightScoring& s, const std::string& source) {
  const mission::Mission m = mission::parseQgcPlan(text, source);
  return mission::predictMission(m, *s.vehicle, *s.model, s.autopilot, s.settings);
}

// Runs `fly(k)` for k = 0 .. n - 1 on up to `threads` threads; rethrows the exception of the lowest
// k that threw, as a loop in order would have.
void onThreads(std::size_t n, int threads, const std::function<void(std::size_t)>& fly) {
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < n; k = next++) {
      try {
        fly(k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  const std::size_t extra = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(threads, 1))) - (n > 0 ? 1 : 0);
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < extra; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace

void setAutopilot(FlightScoring& scoring, const mission::AutopilotConfig& autopilot) {
  scoring.autopilot = autopilot;
  scoring.mission.firmware = autopilot.firmware == "PX4" ? mission::Firmware::PX4 : mission::Firmware::ArduPilot;
  scoring.mission.repeat_first_speed_change =
      autopilot.family == mission::AutopilotFamily::ArduCopterSCurve && !mission::versionAtLeast(autopilot.version, 4, 5);
}

mission::MissionPrediction flyWrittenMission(const PlanMission& written, const FlightScoring& s, const std::string& source) {
  // The very text `wattswath predict mission.plan` reads.
  return flyPlanText(mission::toQgcPlan(written.mission), s, source);
}

std::vector<FlightScore> scoreByFlight(const std::vector<std::pair<std::string, const PlanCandidate*>>& candidates,
                                       const FlightScoring& s) {
  if (!s.problem || !s.frame || !s.vehicle || !s.model) throw std::invalid_argument("scoreByFlight: FlightScoring is incomplete");
  // Each candidate's missions (with arcs: as chords and as waypoints), written on threads.
  std::vector<FlightScore> all;
  std::vector<std::string> all_sources;  // names of the .plan texts in errors
  std::vector<char> has_arcs;
  // ArduCopter flies a speed command late: before 4.1 an increase takes effect a waypoint late (the
  // stale leash), from 4.1 on the leg after a waypoint flown through is planned before the command
  // runs and re-planned in flight (a second acceleration after the first, SCurve::set_speed_max).
  const bool late_speeds = s.autopilot.family == mission::AutopilotFamily::ArduCopterLeash ||
                           s.autopilot.family == mission::AutopilotFamily::ArduCopterSCurve;
  for (const auto& [label, c] : candidates) {
    if (!c || !c->valid) continue;
    const bool arcs = std::any_of(c->flown.path.legs.begin(), c->flown.path.legs.end(),
                                  [](const geometry::PathLeg& l) { return l.kind == geometry::PrimitiveKind::Arc; });
    const bool baseline = std::find(s.as_written.begin(), s.as_written.end(), c) != s.as_written.end();
    for (const bool early : {false, true}) {
      if (early && (!late_speeds || baseline)) continue;  // PX4 applies a speed command at once
      for (const bool arc_waypoints : {false, true}) {
        if (arc_waypoints && !arcs) continue;  // the same mission
        std::vector<std::string> how;
        if (arcs) how.push_back(arc_waypoints ? "arcs as waypoints" : "arcs as chords");
        if (early) how.push_back("speeds a waypoint early");
        FlightScore f;
        f.label = label;
        for (std::size_t k = 0; k < how.size(); ++k) f.label += (k ? ", " : " (") + how[k] + (k + 1 == how.size() ? ")" : "");
        f.candidate = c;
        f.arc_waypoints = arc_waypoints;
        f.speeds_a_waypoint_early = early;
        f.closed_form_energy_j = c->flown.energy;
        all.push_back(std::move(f));
        all_sources.push_back(label + " mission.plan");
        has_arcs.push_back(arcs);
      }
    }
  }
  std::vector<std::string> all_texts(all.size());
  onThreads(all.size(), s.threads, [&](std::size_t i) {
    MissionOptions mo = s.mission;
    mo.arc_waypoints = all[i].arc_waypoints;
    mo.speeds_a_waypoint_early = all[i].speeds_a_waypoint_early;
    all[i].mission = missionFromPlan(all[i].candidate->flown, *s.problem, *s.frame, s.home_altitude_amsl_m, mo);
    all_texts[i] = mission::toQgcPlan(all[i].mission.mission);  // the very text `wattswath predict` reads
  });
  std::vector<FlightScore> out;
  std::vector<std::string> sources, texts;
  for (std::size_t i = 0; i < all.size(); ++i) {
    // A chord that comes within the no-fly margin is not offered (the waypoints along the arc are).
    if (!all[i].arc_waypoints && has_arcs[i] && all[i].mission.legs_within_margin > 0) continue;
    // Speeds a waypoint early that change nothing (one speed throughout) are not a variant of their own.
    bool same_variant = false;
    for (std::size_t j = 0; j < i && all[i].speeds_a_waypoint_early; ++j)
      same_variant = same_variant || (all[j].candidate == all[i].candidate && all_texts[j] == all_texts[i]);
    if (same_variant) continue;
    out.push_back(std::move(all[i]));
    sources.push_back(std::move(all_sources[i]));
    texts.push_back(std::move(all_texts[i]));
  }
  // Each distinct .plan text flown once (a finalist that is another's route, e.g. the plan when it
  // is the shortest path, writes the same text and gets the same flight), the flights on threads.
  std::vector<std::size_t> same_as(out.size()), distinct;
  for (std::size_t i = 0; i < out.size(); ++i) {
    same_as[i] = static_cast<std::size_t>(std::find(texts.begin(), texts.begin() + static_cast<std::ptrdiff_t>(i), texts[i]) - texts.begin());
    if (same_as[i] == i) distinct.push_back(i);
  }
  onThreads(distinct.size(), s.threads, [&](std::size_t k) {
    const std::size_t i = distinct[k];
    out[i].prediction = flyPlanText(texts[i], s, sources[i]);
  });
  for (std::size_t i = 0; i < out.size(); ++i)
    if (same_as[i] != i) out[i].prediction = out[same_as[i]].prediction;
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
