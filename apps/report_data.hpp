#pragma once
/// @file report_data.hpp
/// Fills the report structs (apps/report) from library results: sweeps of the turn comparison and
/// the optimal speed for the turns/vopt reports, and replays/diagnoses for the validation report.
/// Points a sweep cannot compute are listed in the report's facts, never dropped silently.

#include <string>
#include <utility>
#include <vector>

#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/turns.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/mission.hpp"
#include "wattswath/mission/predict.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/report/reports.hpp"

namespace wattswath::apps {

/// The turn comparison over Table V's angles (30, 45, 60, 90 deg) and `angle_deg` [deg], for leg
/// lengths from 25 m to 2400 m and `distance` [m], with the command's model and settings; rows at
/// Table V's points carry the paper's saving (Marins et al. Table V, as printed).
report::TurnReportData turnReportData(const energy::EnergyModel& model, const energy::ProfileLimits& limits,
                                      double max_yaw_rate, double v_max, const energy::TurnSettings& settings,
                                      double angle_deg, double distance);

/// v_opt against leg length (5 m to 5 km, log-spaced) for each named model variant (Marins et al.
/// Fig. 3), and energy against cruise speed of `model` for legs of `distance` [m] and 5x it.
/// `entry`, `exit` [m/s] are the leg's end speeds, `v_max` [m/s] the speed limit.
report::SpeedReportData speedReportData(const std::vector<std::pair<std::string, energy::EnergyModel>>& variants,
                                        const energy::EnergyModel& model, const energy::ProfileLimits& limits,
                                        double distance, double entry, double exit, double v_max);

/// The validation report's time series and leg energies from replays: power, speed, climb and
/// heading of the first replay, phases as spans, and the legs of every replay.
report::ValidationReportData validationFromReplays(const std::vector<calibration::LogReplay>& replays);

/// "name = value +- sigma unit; ..." for the coefficients of `effect` (all when empty).
std::string fittedValuesText(const std::vector<calibration::FittedCoefficient>& coefficients, const std::string& effect = "");

/// The diagnosis table rows (best first) from a diagnosis.
std::vector<report::DiagnosisRow> diagnosisRows(const calibration::Diagnosis& d);

/// The items of a mission (numbers as in the mission file) for the plan map, positioned in `frame` [m].
std::vector<report::MissionMark> planMapItems(const mission::Mission& m, const geometry::LocalFrame& frame);

/// [m/s] The cruise speed of leg `i` of `f` as flown: 0 for a turn in place, which does not move
/// (the planner's floor speed on it, 0.05 m/s, is not a speed flown).
double cruiseSpeedFlown(const planner::FlownPath& f, std::size_t i);

/// The report fact on the battery where the flight ends, as a (label, text) pair: the usable charge
/// left at landing (or where a mission that ends in the air ends) with `detail` appended, or, when the
/// cut-off is reached in flight, when it is reached (a "0 % at landing" would say it lands).
std::pair<std::string, std::string> batteryEndFact(const mission::BatteryPrediction& b, const std::string& detail);

/// The mission report's trajectory, items, phase totals, battery and verdict from a prediction
/// (facts are left to the command); `reserve_pct` [%] is the reserve line.
report::MissionReportData missionReportData(const mission::MissionPrediction& p, double reserve_pct);

/// The plan report's data from the planner's result for `area_file`: the facts a pilot reads first,
/// the map legs with the coverage and transit breakdowns, the plan and baselines as scored
/// candidates, and the battery along `flight` (the written mission as the autopilot model flies it,
/// whose take-off-to-landing time and energy lead the facts) when it is known.
report::PlanReportData planReportData(const planner::PlanResult& r, const planner::SurveyProblem& pr, const energy::Vehicle& v,
                                      const energy::EnergyModel& model, const std::string& area_file,
                                      const mission::MissionPrediction& flight);

}  // namespace wattswath::apps
