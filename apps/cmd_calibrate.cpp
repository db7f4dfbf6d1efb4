// wattswath calibrate --vehicle V --log F --mission M [...] --out V2.json: fits the autopilot's
// flight-behaviour parameters and the energy coefficients to logged flights of known missions
// (calibration/mission_calibration.hpp) and writes the calibrated vehicle file.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <utility>

#include "cli.hpp"
#include "log_inputs.hpp"
#include "predict_spread.hpp"
#include "prediction_setup.hpp"
#include "replay_mission.hpp"
#include "wattswath/report/svg.hpp"
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/mission/files.hpp"

namespace wattswath::apps {
namespace {

namespace cal = wattswath::calibration;
namespace en = wattswath::energy;
namespace ms = wattswath::mission;

struct CalibrateOptions {
  std::string vehicle, out, effects = "hover,kinetic,parasitic_drag,climb,translational_lift";
  std::vector<std::string> logs, missions;
  int evaluations = 150;
  bool json = false, force = false, lenient = false, keep_energy = false, no_held_out = false;
  logs::LogReadOptions read;
  MeasurementReport measurement;  // the power and position checks of each log (--trust-power)
};

// Leg by leg: measured and predicted time [s] and energy [J] (null where a passage was not matched).
nlohmann::json legsJson(const cal::FlightComparison& c) {
  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  nlohmann::json legs = nlohmann::json::array();
  for (std::size_t k = 0; k < c.measured.leg_s.size() && k < c.predicted.leg_s.size(); ++k) {
    legs.push_back({{"leg", k + 1}, {"measured_time_s", num(c.measured.leg_s[k])}, {"predicted_time_s", num(c.predicted.leg_s[k])},
                    {"measured_energy_j", num(c.measured.leg_energy_j[k])}, {"predicted_energy_j", num(c.predicted.leg_energy_j[k])}});
  }
  return legs;
}

nlohmann::json comparisonJson(const cal::FlightComparison& c) {
  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  return {{"flight", c.name},
          {"time_error_pct", c.time_error_pct},
          {"energy_error_pct", c.energy_error_pct},
          {"leg_time_mape_pct", num(c.leg_time_mape_pct)},
          {"legs_matched", c.legs_matched},
          {"legs_total", c.measured.leg_s.size()},
          {"measured", {{"time_s", c.measured.total_s}, {"energy_j", c.measured.energy_j}, {"takeoff_s", num(c.measured.takeoff_s)},
                        {"mission_s", num(c.measured.mission_s)}, {"return_s", num(c.measured.return_s)}}},
          {"predicted", {{"time_s", c.predicted.total_s}, {"energy_j", c.predicted.energy_j}, {"takeoff_s", num(c.predicted.takeoff_s)},
                         {"mission_s", num(c.predicted.mission_s)}, {"return_s", num(c.predicted.return_s)}}},
          {"log_offset_m", {c.offset.x(), c.offset.y()}},
          {"launch_from_mission_home_m", {c.launch.x(), c.launch.y()}},
          {"legs", legsJson(c)}};
}

void printComparisons(const char* title, const std::vector<cal::FlightComparison>& cs) {
  std::cout << title << "\n" << std::fixed << std::setprecision(1);
  for (const auto& c : cs) {
    std::cout << "  " << c.name << ": time " << c.predicted.total_s << " s vs " << c.measured.total_s << " s measured ("
              << std::showpos << c.time_error_pct << std::noshowpos << " %), energy " << c.predicted.energy_j / 3600.0 << " Wh vs "
              << c.measured.energy_j / 3600.0 << " Wh (" << std::showpos << c.energy_error_pct << std::noshowpos
              << " %), leg time MAPE "
              << (std::isfinite(c.leg_time_mape_pct) ? report::formatNumber(c.leg_time_mape_pct, 1) + " %" : std::string("-"))
              << " over " << c.legs_matched << " of " << c.measured.leg_s.size() << " legs\n    "
              << launchSentence(c.launch.x(), c.launch.y()) << "\n";
  }
}

// Leave one flight out: each flight predicted as `predict` and `replay --mission` would with the
// vehicle file a calibration on the other flights writes (its model, behaviour and, where those
// flights disagree, the value the flights of this mission's kind chose).
std::vector<cal::FlightComparison> heldOut(const std::vector<cal::MissionFlight>& flights, const en::Vehicle& v,
                                           const en::EnergyModel& model, const ms::AutopilotConfig& ap,
                                           const cal::CalibrationSettings& cs) {
  std::vector<cal::FlightComparison> out;
  for (std::size_t i = 0; i < flights.size(); ++i) {
    progress("calibrate: held out " + flights[i].name + ", calibrating on the other " + std::to_string(flights.size() - 1));
    std::vector<cal::MissionFlight> others;
    for (std::size_t k = 0; k < flights.size(); ++k)
      if (k != i) others.push_back(flights[k]);
    const en::Vehicle vi = cal::calibratedVehicle(v, cal::calibrateMissions(others, v, model, ap, cs));
    const PredictionSetup setup = predictionSetup(vi, "the calibration without " + flights[i].name, "", 0.0);
    ms::AutopilotConfig api = setup.autopilot;
    const auto choice = kindChoiceOf(cal::missionKind(ms::sequenceMission(flights[i].mission), api), setup);
    if (choice) api.parameters[setup.disputed_parameter] = choice->value;
    out.push_back(cal::compareFlight(flights[i], vi, setup.model, api, setup.settings));
  }
  return out;
}

}  // namespace

void registerCalibrateCommand(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  auto* cmd = app.add_subcommand("calibrate",
                                 "Fit the autopilot's flight-behaviour parameters and the energy coefficients to logged "
                                 "flights of known missions; write the calibrated vehicle file");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--log", o->logs, "Flight log (.csv, .bin, .ulg) of a mission; repeat, paired with --mission in order")->required();
  cmd->add_option("--mission", o->missions, "The mission (.plan or .waypoints) the log flew; one per --log")->required();
  cmd->add_option("--out", o->out, "Calibrated vehicle file to write")->required();
  cmd->add_option("--effects", o->effects, "Effects of the energy model to fit")->capture_default_str();
  cmd->add_option("--evaluations", o->evaluations, "Simulated flights per parameter fit")->check(CLI::Range(10, 5000))->capture_default_str();
  cmd->add_flag("--keep-energy", o->keep_energy, "Calibrate the flight behaviour only; keep the energy coefficients (the vehicle file's calibration when it has one, else the --effects from its physics)");
  cmd->add_flag("--lenient-mission", o->lenient, "Skip unsupported mission commands that do not move the vehicle (not navigation commands) with a warning");
  cmd->add_flag("--no-held-out", o->no_held_out,
                "With two flights or more, skip the leave-one-flight-out check (by default each flight is also "
                "predicted by a calibration on the others: one more calibration per flight)");
  addLogReadOptions(cmd, o->read);
  addTrustPowerFlag(cmd, o->measurement.trust_power);
  addForceFlag(cmd, o->force);
  addJsonFlag(cmd, o->json);
  cmd->callback([o] {
    if (o->logs.size() != o->missions.size()) {
      throw std::runtime_error("calibrate: " + std::to_string(o->logs.size()) + " --log but " + std::to_string(o->missions.size()) +
                               " --mission; give one mission per log, in the same order");
    }
    std::vector<std::string> inputs = o->logs;
    inputs.insert(inputs.end(), o->missions.begin(), o->missions.end());
    inputs.push_back(o->vehicle);
    checkWritable(o->out, o->force, inputs);
    en::Vehicle v = en::loadVehicle(o->vehicle);
    en::EnergyModel model = en::buildModel(v, en::splitEffectList(o->effects));
    std::vector<std::string> model_notes;
    if (o->keep_energy) {
      if (const auto kept = cal::calibratedModel(v)) {  // keep what the file holds, not the physics
        model = kept->model;
        std::string names;
        for (const auto& n : kept->model.effectNames()) names += (names.empty() ? "" : ",") + n;
        model_notes.push_back("--keep-energy: the energy model of " + o->vehicle + "'s calibration is kept (" + names +
                              " with their calibrated coefficients; --effects is not used)");
      }
    }
    const ms::AutopilotConfig ap = ms::parseAutopilot(v.autopilot_json, o->vehicle);
    std::vector<cal::MissionFlight> flights;
    ms::ReadOptions ro;
    ro.lenient = o->lenient;
    ro.lenient_option = "--lenient-mission";
    std::vector<std::string> window_notes;
    nlohmann::json windows = nlohmann::json::array();
    checkDistinctLogs(o->logs, o->logs.size());
    for (std::size_t i = 0; i < o->logs.size(); ++i) {
      progress("calibrate: reading " + o->logs[i] + " and " + o->missions[i]);
      MissionLog ml = readMissionLog(o->logs[i], o->read);
      checkLog(ml.log, o->logs[i], v, o->measurement);  // as replay, fit and diagnose check theirs
      if (!ml.note.empty()) window_notes.push_back(ml.note);
      ml.window["log"] = o->logs[i];
      windows.push_back(ml.window);
      ms::Mission m = ms::readMission(o->missions[i], ro);
      for (const auto& w : m.warnings) window_notes.push_back(w);  // what --lenient-mission skipped, and other readings
      flights.push_back({o->logs[i], std::move(m), std::move(ml.log)});
    }
    cal::CalibrationSettings cs;
    cs.max_evaluations = o->evaluations;
    cs.fit_energy = !o->keep_energy;
    const bool held_out = !o->no_held_out && flights.size() >= 2;
    progress("calibrate: fitting " + std::string(ms::toString(ap.family)) + " parameters on " + std::to_string(flights.size()) +
             " flight(s), up to " + std::to_string(o->evaluations) + " simulated flights" +
             (held_out ? "; then once more per flight, on the others, to predict the one left out" : ""));
    const cal::CalibrationResult r = cal::calibrateMissions(flights, v, model, ap, cs);
    const std::vector<cal::FlightComparison> held = held_out ? heldOut(flights, v, model, ap, cs) : std::vector<cal::FlightComparison>{};
    v = cal::calibratedVehicle(std::move(v), r);
    writeTextFileAtomic(o->out, en::vehicleToJson(v));
    progress("calibrate: wrote " + o->out);
    if (o->json) {
      nlohmann::json j;
      j["out"] = o->out;
      j["autopilot"] = nlohmann::json::parse(v.autopilot_json);
      j["takeoff_delay_s"] = r.takeoff_delay_s;
      // Measured on the logs' cruise, not fitted; null when too few samples measure it.
      j["tracking_error_m"] = r.tracking.measured ? nlohmann::json{{"horizontal", r.tracking.error.horizontal_m},
                                                                   {"vertical", r.tracking.error.vertical_m},
                                                                   {"samples", r.tracking.samples}}
                                                  : nlohmann::json(nullptr);
      j["log_windows"] = windows;  // the part of each log compared with its mission's prediction
      j["reading_notes"] = window_notes;  // which part of each log, and what reading each mission noted
      j["measurement"] = o->measurement.toJson();
      j["fitted"] = r.fitted;
      std::vector<std::string> notes = model_notes;
      notes.insert(notes.end(), r.notes.begin(), r.notes.end());
      j["notes"] = notes;
      j["kept_at_start"] = r.kept_at_start;  // behaviour parameters the flights do not call to change
      j["flights_agree"] = r.flights_agree;
      j["per_flight"] = nlohmann::json::array();
      for (const auto& f : r.per_flight) {
        j["per_flight"].push_back({{"flight", f.flight}, {"parameter", r.acceleration_parameter}, {"value", f.value},
                                   {"time_misfit_alone", f.misfit_alone}, {"time_misfit_joint", f.misfit_joint},
                                   {"determined", f.determined}});
      }
      for (const auto& c : r.before) j["before"].push_back(comparisonJson(c));
      for (const auto& c : r.after) j["after"].push_back(comparisonJson(c));
      // "after" is in-sample (the flights fitted); "held_out" predicts each flight from the others.
      j["after_is_in_sample"] = true;
      j["held_out"] = nlohmann::json::array();
      for (const auto& c : held) j["held_out"].push_back(comparisonJson(c));
      if (held.empty()) j["held_out"] = nullptr;
      printJson(j);
      return;
    }
    for (const auto& n : window_notes) std::cout << "note: " << n << "\n";
    o->measurement.print();
    printComparisons("before (firmware defaults / given parameters, vehicle physics):", r.before);
    printComparisons("after calibration, in-sample (on the flights it was fitted to; says little about other flights):",
                     r.after);
    if (!held.empty()) {
      printComparisons("held out (each flight predicted by a calibration on the other flights only, as predict flies it "
                       "with that calibration's vehicle file):", held);
    } else if (flights.size() == 1) {
      std::cout << "  (one flight: no held-out check; calibrate on several flights, or replay --mission another flight "
                   "with the file written)\n";
    }
    std::cout << "fitted:\n";
    for (const auto& f : r.fitted) std::cout << "  " << f << "\n";
    for (const auto& n : model_notes) std::cout << "note: " << n << "\n";
    for (const auto& n : r.notes) std::cout << "note: " << n << "\n";
  });
}

}  // namespace wattswath::apps
