#pragma once
/// @file replay_mission.hpp
/// `replay --mission`: each logged flight against the flight predicted from its mission file, leg
/// by leg (calibration/mission_calibration.hpp), as JSON and as the replay report's mission section.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "prediction_setup.hpp"
#include "wattswath/calibration/replay.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/report/reports.hpp"

namespace wattswath::apps {

/// The comparisons of `replay --mission`, as the --json array and as report data.
struct MissionReplays {
  nlohmann::json json = nlohmann::json::array();  ///< one object per flight (mission_prediction in --json)
  report::MissionReplayData report;               ///< the report's mission section
  std::vector<std::string> notes;                 ///< which part of each log was compared (readMissionLog)
};

/// Compares each log of `log_paths` with the prediction, under `setup` (as `predict` flies it), of
/// the mission of `mission_paths` at the same index; `reps` are the replays of the --effects model
/// on the same logs (the kinematics / physics split when `setup` is not calibrated); the missions are
/// read with `mission_read` (what its lenient reading skipped is among the notes).
MissionReplays missionReplays(const energy::Vehicle& v, const PredictionSetup& setup, const std::vector<std::string>& log_paths,
                              const std::vector<std::string>& mission_paths, const std::vector<calibration::LogReplay>& reps,
                              const logs::LogReadOptions& read, const mission::ReadOptions& mission_read);

/// One sentence on where the log's vehicle took off, `east_m` and `north_m` [m] from the mission's
/// home (FlightComparison::launch), and that the prediction flies from there.
std::string launchSentence(double east_m, double north_m);

/// One sentence on where one comparison's kinematics differ (an element of missionReplays' `json`):
/// time below 1 m/s between the first and last waypoint, logged and predicted, and the median leg's
/// peak speed against the prediction's.
std::string kinematicsSentence(const nlohmann::json& mission_replay);

/// Prints the comparisons (the `json` of missionReplays) as text on stdout.
void printMissionReplays(const nlohmann::json& missions);

}  // namespace wattswath::apps
