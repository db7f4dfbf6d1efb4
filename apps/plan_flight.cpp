// `plan`'s finalists flown by the vehicle's autopilot model (plan_flight.hpp).
#include "plan_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <iostream>

#include "predict_spread.hpp"
#include "prediction_setup.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace {

// One row of the table: the flight of score `s`.
FlightRow rowOf(const planner::FlightScore& s, bool baseline) {
  const auto& mission = s.prediction.phases[static_cast<int>(mission::FlightPhase::Mission)];
  return {s.label,          s.closed_form_energy_j, s.prediction.total.energy_j, s.prediction.total.time_s,
          mission.energy_j, mission.time_s,         s.candidate->coverage_pct,   baseline};
}

std::string kj(double j) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f kJ", j / 1000.0);
  return buf;
}

// The note on a mission (its sequenced `steps`) outside what the calibration of `setup` flew.
std::optional<std::string> calibrationNote(const std::vector<mission::NavStep>& steps, const PredictionSetup& setup) {
  if (!setup.calibrated || !setup.coverage) return std::nullopt;
  const auto why = calibration::outsideCalibration(calibration::missionKind(steps, setup.autopilot), *setup.coverage);
  if (why.empty()) return std::nullopt;
  std::string text = "calibration: the written mission is outside what the vehicle's calibration flew (";
  for (std::size_t i = 0; i < why.size(); ++i) text += (i ? "; " : "") + why[i];
  return text + "): its flight figures rest on behaviour the calibration did not see; `wattswath predict mission.plan` "
                "gives the range with the behaviour before the calibration";
}

}  // namespace

planner::FlightScoring withSetup(planner::FlightScoring scoring, const PredictionSetup& setup) {
  scoring.model = &setup.model;
  planner::setAutopilot(scoring, setup.autopilot);
  scoring.settings = setup.settings;
  return scoring;
}

PlanFlight flyFinalists(planner::PlanResult& r, planner::FlightScoring scoring, const std::string& vehicle_path,
                        std::vector<std::string>& notes) {
  PredictionSetup setup = predictionSetup(*scoring.vehicle, vehicle_path, "", 25.0);
  setup.settings.wind = scoring.settings.wind;  // this run's (plan --wind), as predict --wind sets it
  setup.settings.reserve_fraction = scoring.settings.reserve_fraction;  // plan --reserve
  std::vector<std::pair<std::string, const planner::PlanCandidate*>> cands = {{"plan", &r.plan}};
  if (r.per_cell && r.per_cell->valid) cands.push_back({"per-cell", &*r.per_cell});
  if (r.best_spiral && r.best_spiral->valid) cands.push_back({"best spiral", &*r.best_spiral});
  cands.push_back({"shortest path", &r.shortest_path});
  // The ground-station default flown too (in the same batch of flights), as a baseline: never written.
  cands.push_back({"ground-station default", &r.ground_station_default});
  scoring.as_written = {&r.ground_station_default};  // what a ground station writes: not rewritten with our speed commands
  std::vector<planner::FlightScore> scores, baselines;
  const auto fly = [&] {
    scores = planner::scoreByFlight(cands, withSetup(scoring, setup));
    const auto baseline = std::stable_partition(scores.begin(), scores.end(), [&](const planner::FlightScore& s) {
      return s.candidate != &r.ground_station_default;
    });
    baselines.assign(std::make_move_iterator(baseline), std::make_move_iterator(scores.end()));
    scores.erase(baseline, scores.end());
  };
  fly();
  // A calibration whose flights disagree: flown again as `predict` flies the mission written, with
  // the value of the calibration flights of its kind (predict_spread.hpp, KindChoice).
  const auto kind = calibration::missionKind(scores[planner::cheapestFlight(scores)].prediction.flight.steps, setup.autopilot);
  if (const auto choice = kindChoiceOf(kind, setup)) {
    setup.autopilot.parameters[setup.disputed_parameter] = choice->value;
    fly();
    std::string from;
    for (const auto& name : choice->flights) from += (from.empty() ? "" : ", ") + name;
    char value[32];
    std::snprintf(value, sizeof value, "%.3g", choice->value);
    notes.push_back("calibration: its flights disagree on " + setup.disputed_parameter + "; the plan is flown with " + value +
                    ", fitted on " + from + ", the calibration flight(s) of the written mission's kind, as `wattswath predict` flies it");
  }
  PlanFlight f;
  for (const auto& s : scores) f.rows.push_back(rowOf(s, false));
  f.chosen = planner::cheapestFlight(scores);
  for (const auto& g : baselines) f.rows.push_back(rowOf(g, true));
  f.chosen_by_search = r.plan.pattern;
  f.flown_by = setup.autopilot;
  f.autopilot = setup.autopilot.firmware + " " + setup.autopilot.version + " (" + mission::toString(setup.autopilot.family) +
                " model" + (setup.autopilot.from_file ? "" : ", firmware defaults") + (setup.calibrated ? ", calibrated" : "") + ")";
  const auto& best = scores[f.chosen];
  double search_best = 1e300;
  for (const auto& s : scores)
    if (s.candidate == &r.plan) search_best = std::min(search_best, s.prediction.total.energy_j);
  if (best.candidate != &r.plan) {
    notes.push_back("flight model: the " + best.label + " candidate flies cheaper than the search's choice (" + kj(best.prediction.total.energy_j) +
                    " against " + kj(search_best) + " take-off to landing as " + f.autopilot +
                    " flies them); it is the plan written");
    const planner::PlanCandidate chosen = *best.candidate;
    r.plan = chosen;
  }
  if (best.speeds_a_waypoint_early) {
    const bool scurve = setup.autopilot.family == mission::AutopilotFamily::ArduCopterSCurve;
    notes.push_back("flight model: each speed command is written a waypoint early (the faster of its leg's planned speed and "
                    "the next leg's, but never above a camera leg's own where a leg with photos meets one without): " + f.autopilot +
                    (scurve ? " plans the leg after a waypoint it flies through before that leg's speed command runs and "
                              "reaches a faster speed by a second acceleration after the first;"
                            : " flies a speed increase only from the next waypoint on;") +
                    " this mission flies cheaper so");
  }
  f.arc_waypoints = best.arc_waypoints;
  f.speeds_a_waypoint_early = best.speeds_a_waypoint_early;
  for (const auto& l : best.candidate->flown.path.legs)
    if (l.kind == geometry::PrimitiveKind::Arc)
      f.max_chord_offset_m = std::max(f.max_chord_offset_m, l.radius * (1.0 - std::cos(0.5 * std::abs(l.turn_angle))));
  f.mission = best.mission;
  f.prediction = best.prediction;
  f.calibration_note = calibrationNote(best.prediction.flight.steps, setup);  // the steps of the mission written
  return f;
}

void printFlight(const PlanFlight& f) {
  const auto& p = f.prediction;
  const auto& m = p.phases[static_cast<int>(mission::FlightPhase::Mission)];
  std::cout << "flown by " << f.autopilot << ": " << kj(p.total.energy_j) << ", " << report::formatMinSec(p.total.time_s)
            << " min:s from take-off to landing (survey part " << kj(m.energy_j) << ", " << report::formatMinSec(m.time_s)
            << "); `wattswath predict` on mission.plan gives these numbers\n";
  if (f.max_chord_offset_m > 0.0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, f.arc_waypoints ? "arcs: written as waypoints along them (every chord within %.1f m of the arc)\n"
                                                   : "arcs: one waypoint at each end, flown by the autopilot's own cornering (the chord passes up to %.1f m inside the planned arc; the no-fly margin holds)\n",
                  f.arc_waypoints ? 0.5 : f.max_chord_offset_m);
    std::cout << buf;
  }
  std::cout << "finalists as flown:";
  for (std::size_t i = 0; i < f.rows.size(); ++i)
    std::cout << (i ? "; " : " ") << f.rows[i].label << " " << kj(f.rows[i].energy_j)
              << (i == f.chosen ? " (written)" : f.rows[i].baseline ? " (baseline)" : "");
  std::cout << "\n";
}

nlohmann::json flightJson(const PlanFlight& f) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : f.rows)
    rows.push_back({{"label", r.label}, {"baseline", r.baseline}, {"closed_form_energy_j", r.closed_form_j}, {"energy_j", r.energy_j}, {"time_s", r.time_s},
                    {"mission_energy_j", r.mission_energy_j}, {"mission_time_s", r.mission_time_s}, {"coverage_pct", r.coverage_pct}});
  const auto& p = f.prediction;
  nlohmann::json phases = nlohmann::json::object();
  for (int i = 0; i < mission::kFlightPhaseCount; ++i)
    phases[mission::toString(static_cast<mission::FlightPhase>(i))] = {{"energy_j", p.phases[i].energy_j}, {"time_s", p.phases[i].time_s},
                                                                       {"distance_m", p.phases[i].distance_m}};
  return {{"autopilot", f.autopilot}, {"energy_j", p.total.energy_j}, {"time_s", p.total.time_s},
          {"distance_m", p.total.distance_m}, {"phases", phases}, {"written", f.rows[f.chosen].label},
          {"arcs", f.arc_waypoints ? "waypoints along each arc (within 0.5 m)" : "chords flown by the autopilot's cornering"},
          {"max_chord_offset_m", f.arc_waypoints ? std::min(0.5, f.max_chord_offset_m) : f.max_chord_offset_m},
          {"finalists", rows}};
}

}  // namespace wattswath::apps
