// replay --mission: each logged flight against its mission's prediction, leg by leg, as JSON, text
// and the replay report's mission section.
#include "replay_mission.hpp"

#include "log_inputs.hpp"

#include "predict_spread.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;
using nlohmann::json;

namespace {

json numOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

/// The numbers (seq) of the waypoints compareFlight matches passages to (calibration::flownWaypoints).
std::vector<std::string> waypointLabels(const mission::Mission& m, const std::vector<mission::NavStep>& steps) {
  using K = mission::NavStep::Kind;
  std::vector<std::string> out;
  for (const auto& s : steps) {
    if (!((s.kind == K::Waypoint || s.kind == K::SplineWaypoint || s.kind == K::LoiterTime) && s.has_position))
      continue;
    out.push_back(s.item >= 0 && s.item < static_cast<int>(m.items.size()) ? std::to_string(m.items[s.item].seq) : "?");
  }
  return out;
}

/// The report's view of one flight: speed series, passages, legs and totals.
report::MissionReplayFlight reportFlight(const calibration::MissionFlight& f, const std::string& mission_path,
                                         const calibration::FlightComparison& c, const mission::MissionPrediction& pred,
                                         double replay_j) {
  report::MissionReplayFlight r;
  r.name = std::filesystem::path(f.name).filename().string();
  r.mission = std::filesystem::path(mission_path).filename().string();
  const double t0 = f.log.samples.empty() ? 0.0 : f.log.samples.front().t;
  for (const auto& s : f.log.samples) {
    r.measured_t.push_back(s.t - t0);
    r.measured_speed.push_back(s.velocity.norm());
  }
  for (const auto& s : pred.flight.samples) {
    r.predicted_t.push_back(s.t);
    r.predicted_speed.push_back(s.velocity.norm());
  }
  r.waypoint_labels = waypointLabels(f.mission, pred.flight.steps);
  r.measured_passage_s = c.measured.passage_s;
  r.predicted_passage_s = c.predicted.passage_s;
  r.predicted_passage_s.resize(r.measured_passage_s.size(), std::nan(""));
  if (r.waypoint_labels.size() != r.measured_passage_s.size()) r.waypoint_labels.clear();
  for (std::size_t k = 0; k < c.measured.leg_s.size() && k < c.predicted.leg_s.size(); ++k) {
    const std::string label = r.waypoint_labels.empty() ? std::to_string(k + 1) + "-" + std::to_string(k + 2)
                                                        : r.waypoint_labels[k] + "-" + r.waypoint_labels[k + 1];
    r.legs.push_back(
        {label, c.measured.leg_s[k], c.predicted.leg_s[k], c.measured.leg_energy_j[k], c.predicted.leg_energy_j[k]});
  }
  r.measured_energy_j = c.measured.energy_j;
  r.predicted_energy_j = c.predicted.energy_j;
  r.replay_energy_j = replay_j;
  r.measured_time_s = c.measured.total_s;
  r.predicted_time_s = c.predicted.total_s;
  r.leg_time_mape_pct = c.leg_time_mape_pct;
  return r;
}

json flightJson(const calibration::FlightComparison& c, const std::string& log, const std::string& mission_path,
                const std::string& model, const std::string& autopilot, double replay_j) {
  json legs = json::array();
  for (std::size_t k = 0; k < c.measured.leg_s.size() && k < c.predicted.leg_s.size(); ++k) {
    legs.push_back({{"leg", k + 1},
                    {"measured_time_s", numOrNull(c.measured.leg_s[k])},
                    {"predicted_time_s", numOrNull(c.predicted.leg_s[k])},
                    {"measured_speed_mps", numOrNull(c.measured.leg_speed_mps[k])},
                    {"predicted_speed_mps", numOrNull(c.predicted.leg_speed_mps[k])},
                    {"measured_peak_mps", numOrNull(k < c.measured.leg_peak_mps.size() ? c.measured.leg_peak_mps[k] : std::nan(""))},
                    {"predicted_peak_mps", numOrNull(k < c.predicted.leg_peak_mps.size() ? c.predicted.leg_peak_mps[k] : std::nan(""))},
                    {"measured_energy_j", numOrNull(c.measured.leg_energy_j[k])},
                    {"predicted_energy_j", numOrNull(c.predicted.leg_energy_j[k])}});
  }
  return {{"log", log},
          {"mission", mission_path},
          {"model", model},
          {"autopilot", autopilot},
          {"measured_energy_j", c.measured.energy_j},
          {"predicted_energy_j", c.predicted.energy_j},
          {"replay_energy_j", replay_j},
          {"kinematics_error_j", c.predicted.energy_j - replay_j},
          {"physics_error_j", replay_j - c.measured.energy_j},
          {"measured_time_s", c.measured.total_s},
          {"predicted_time_s", c.predicted.total_s},
          {"time_error_pct", c.time_error_pct},
          {"energy_error_pct", c.energy_error_pct},
          {"leg_time_mape_pct", numOrNull(c.leg_time_mape_pct)},
          {"legs_matched", c.legs_matched},
          // Why the log may not be of this mission (few legs found, alignment at its limit); null when it fits.
          {"match_problem", c.match_problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.match_problem)},
          // Where the kinematics differ: time spent slow (stops, sharp corners) and how fast the legs peak.
          {"slow_time_s", {{"measured", numOrNull(c.measured.slow_s)}, {"predicted", numOrNull(c.predicted.slow_s)}}},
          {"leg_peak_speed_ratio", numOrNull(c.leg_peak_ratio)},
          {"log_offset_m", {c.offset.x(), c.offset.y()}},
          {"launch_from_mission_home_m", {c.launch.x(), c.launch.y()}},
          {"legs", legs}};
}

}  // namespace

MissionReplays missionReplays(const en::Vehicle& v, const PredictionSetup& setup, const std::vector<std::string>& log_paths,
                              const std::vector<std::string>& mission_paths, const std::vector<calibration::LogReplay>& reps,
                              const logs::LogReadOptions& read, const mission::ReadOptions& mission_read) {
  const bool use_cal = setup.calibrated;
  const en::EnergyModel& model = setup.model;
  const std::string model_text = use_cal ? "the vehicle file's calibration" : "the vehicle's physics";
  MissionReplays out;
  std::string effects;
  for (const auto& e : model.effectNames()) effects += (effects.empty() ? "" : ", ") + e;
  out.report.model = effects + " (" + model_text + ")";
  out.report.autopilot = mission::toString(setup.autopilot.family);
  for (std::size_t i = 0; i < log_paths.size(); ++i) {
    MissionLog ml = readMissionLog(log_paths[i], read);
    calibration::MissionFlight f{log_paths[i], mission::readMission(mission_paths[i], mission_read), std::move(ml.log)};
    for (const auto& w : f.mission.warnings) out.notes.push_back(w);  // what lenient reading skipped, and other readings
    // As predict: the calibration flights of the mission's kind decide a disputed acceleration.
    mission::AutopilotConfig ap = setup.autopilot;
    const auto choice = kindChoiceOf(calibration::missionKind(mission::sequenceMission(f.mission), ap), setup);
    if (choice) ap.parameters[setup.disputed_parameter] = choice->value;
    const auto c = calibration::compareFlight(f, v, model, ap, setup.settings);
    // Physics: the same model on the logged kinematics (replay) against the measurement;
    // kinematics: the predicted flight against that replay.
    const double replay_j = use_cal ? calibration::replay(model, calibration::prepareLog(f.log)).flight.modelled_j
                                    : reps[i].flight.modelled_j;
    out.json.push_back(
        flightJson(c, log_paths[i], mission_paths[i], model_text, mission::toString(ap.family), replay_j));
    out.json.back()["log_window"] = ml.window;  // the part of the log compared with the prediction
    if (!ml.note.empty()) out.notes.push_back(ml.note);
    if (!c.match_problem.empty()) out.notes.push_back(log_paths[i] + " against " + mission_paths[i] + ": " + c.match_problem);
    out.json.back()["calibration_chosen"] =
        choice ? nlohmann::json{{"parameter", setup.disputed_parameter}, {"value", choice->value}, {"flights", choice->flights}}
               : nlohmann::json(nullptr);
    // The predicted trajectory for the report's speed figure (compareFlight keeps only its times).
    const auto pred =
        mission::predictMission(calibration::missionLaunchedAt(f.mission, c.launch), v, model, ap, setup.settings);
    // What predict would say of this mission (started in the air, ends in the air, ...), once each.
    for (const auto& w : pred.warnings)
      if (std::find(out.notes.begin(), out.notes.end(), w) == out.notes.end()) out.notes.push_back(w);
    out.report.flights.push_back(reportFlight(f, mission_paths[i], c, pred, replay_j));
    out.report.flights.back().kinematics_note = kinematicsSentence(out.json.back());
  }
  return out;
}

std::string launchSentence(double east_m, double north_m) {
  const double d = std::hypot(east_m, north_m);
  std::ostringstream o;
  o << std::fixed << std::setprecision(1);
  if (d < 0.05) {
    o << "The vehicle took off at the mission's home.";
    return o.str();
  }
  o << "The vehicle took off " << d << " m from the mission's home (" << std::abs(east_m) << " m " << (east_m >= 0 ? "E" : "W")
    << ", " << std::abs(north_m) << " m " << (north_m >= 0 ? "N" : "S")
    << "; the log's track laid onto the waypoints): the prediction takes off and returns there, as the autopilot sets home "
       "where it arms.";
  return o.str();
}

std::string kinematicsSentence(const json& m) {
  const auto& slow = m["slow_time_s"];
  std::ostringstream o;
  o << std::fixed << std::setprecision(0);
  if (slow["measured"].is_null() || slow["predicted"].is_null()) {
    o << "Time below 1 m/s and peak speeds: not compared (fewer than two waypoint passages matched).";
    return o.str();
  }
  o << "Between the first and last waypoint the vehicle spent " << slow["measured"].get<double>() << " s below 1 m/s, the prediction "
    << slow["predicted"].get<double>() << " s";
  const json& r = m["leg_peak_speed_ratio"];
  if (r.is_null()) {
    o << "; no leg to compare peak speeds on.";
  } else {
    const double pct = 100.0 * (r.get<double>() - 1.0);
    if (std::abs(pct) < 1.0) {
      o << "; on the median leg it peaked within 1 % of the prediction's speed.";
    } else {
      o << "; on the median leg it peaked " << std::abs(pct) << " % " << (pct >= 0.0 ? "faster" : "slower") << " than predicted.";
    }
  }
  return o.str();
}

void printMissionReplays(const json& missions) {
  // Rounded as measured: times to 0.1 s, energies to 1 J, errors to 0.1 %.
  const auto num = [](const json& x, int decimals) {
    return x.is_null() ? std::string("-") : report::formatNumber(x.get<double>(), decimals);
  };
  for (const auto& m : missions) {
    std::cout << m["log"].get<std::string>() << " against " << m["mission"].get<std::string>() << " ("
              << m["autopilot"].get<std::string>() << ", " << m["model"].get<std::string>() << "):\n  time "
              << num(m["predicted_time_s"], 1) << " s predicted vs " << num(m["measured_time_s"], 1) << " s measured ("
              << num(m["time_error_pct"], 1) << " %), energy " << num(m["predicted_energy_j"], 0) << " J vs "
              << num(m["measured_energy_j"], 0) << " J (" << num(m["energy_error_pct"], 1) << " %): kinematics "
              << num(m["kinematics_error_j"], 0) << " J, physics " << num(m["physics_error_j"], 0) << " J\n"
              << "  " << launchSentence(m["launch_from_mission_home_m"][0].get<double>(), m["launch_from_mission_home_m"][1].get<double>())
              << "\n  " << kinematicsSentence(m) << "\n  leg  measured s  predicted s  measured J  predicted J\n";
    for (const auto& l : m["legs"]) {
      std::cout << "  " << l["leg"].get<int>() << "  " << num(l["measured_time_s"], 1) << "  " << num(l["predicted_time_s"], 1)
                << "  " << num(l["measured_energy_j"], 0) << "  " << num(l["predicted_energy_j"], 0) << "\n";
    }
  }
}

}  // namespace wattswath::apps
