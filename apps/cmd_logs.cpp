// Model versus measurement on flight logs: replay, diagnose, fit, simulate (issue 6).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "cli.hpp"
#include "diagnose_output.hpp"
#include "log_inputs.hpp"
#include "log_json.hpp"
#include "predict_options.hpp"
#include "replay_mission.hpp"
#include "report_data.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/calibration/plan_prediction.hpp"
#include "wattswath/calibration/user_effect.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/tolerances.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;
using nlohmann::json;

namespace {

constexpr const char* kPaperEffects = "hover,kinetic,parasitic_drag";

// Path length flown in a log [m] (sum of its legs).
double loggedDistance(const calibration::PreparedLog& l) {
  double d = 0.0;
  for (const auto& leg : l.legs) d += leg.distance;
  return d;
}

void registerReplay(CLI::App& app) {
  struct Opts {
    std::string vehicle, effects = kPaperEffects, samples_out, plan, report, report_svg, wind;
    std::vector<std::string> logs, missions;
    logs::LogReadOptions read;
    calibration::PlanPredictionSettings plan_settings;
    MeasurementReport measurement;
    mission::ReadOptions mission_read;
    bool json = false, force = false;
  };
  auto o = std::make_shared<Opts>();
  o->mission_read.lenient_option = "--lenient-mission";
  auto* cmd = app.add_subcommand("replay", "Replay a model on measured kinematics: power per sample, energy per leg, "
                                           "phase and flight, residuals binned by speed, climb, acceleration, heading, time");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--effects", o->effects,
                  "Comma-separated effects of the model, with the vehicle's physics (without it, a vehicle file with a "
                  "calibration (wattswath calibrate) replays that calibration, else these)")
      ->capture_default_str();
  cmd->add_option("--log", o->logs, "Flight log: canonical CSV, ArduPilot .bin or PX4 .ulg (repeatable)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--samples-out", o->samples_out, "Write per-sample measured/modelled power as CSV here");
  cmd->add_option("--plan", o->plan, "Plan (QGC .waypoints survey area, home = the logs' home): also predict each "
                                     "flight from its planned legs and split the error into kinematics and physics")
      ->check(CLI::ExistingFile);
  auto* effects_opt = cmd->get_option("--effects");
  cmd->add_option("--mission", o->missions,
                  "The mission (.plan or .waypoints) each --log flew, in the same order: the logged flight against the "
                  "predicted one leg by leg (time, speed along the path, energy), the error split into kinematics and "
                  "physics; the model is the vehicle file's calibration unless --effects is given")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--lenient-mission", o->mission_read.lenient,
                "Skip unsupported --mission commands that do not move the vehicle (not navigation commands) with a "
                "warning, as calibrate --lenient-mission reads them");
  cmd->add_option("--wind", o->wind,
                  "The day's steady wind SPEED,FROM (m/s, compass bearing it blows from), when known: the model's drag is "
                  "taken at air speed on the logged kinematics and in the --mission predictions, which fly in it");
  cmd->add_option("--plan-corner-fraction", o->plan_settings.corner_speed_fraction,
                  "Planned corners: 0 = stop and turn in place, else pass at this share of the leg speed")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--plan-snap", o->plan_settings.snap_distance,
                  "Snap leg end points to plan vertices within this distance [m]")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
  addLogReadOptions(cmd, o->read);
  addTrustPowerFlag(cmd, o->measurement.trust_power);
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  addJsonFlag(cmd, o->json);
  cmd->callback([o, effects_opt]() {
    if (!o->missions.empty() && o->missions.size() != o->logs.size()) {
      throw std::runtime_error("replay: " + std::to_string(o->logs.size()) + " --log but " + std::to_string(o->missions.size()) +
                               " --mission; give one mission per log, in the same order");
    }
    auto inputs = o->logs;
    inputs.insert(inputs.end(), o->missions.begin(), o->missions.end());
    inputs.push_back(o->vehicle);
    if (!o->samples_out.empty()) checkWritable(o->samples_out, o->force, inputs);
    inputs.push_back(o->samples_out);  // the report must not take its name either
    checkReportWritable(o->report, o->report_svg, o->force, inputs);
    const std::optional<Wind> wind = windOption(o->wind);
    const auto v = en::loadVehicle(o->vehicle);
    // One model for the logs and the missions: the vehicle file's calibration unless --effects is
    // given (predictionSetup below chooses the same way), else the vehicle's physics.
    const auto cal = calibration::calibratedModel(v);
    const bool use_cal = cal && effects_opt->count() == 0;
    const auto still = use_cal ? cal->model : en::buildModel(v, en::splitEffectList(o->effects));
    const auto model = wind ? en::withWind(still, v, wind->air().x(), wind->air().y()) : still;
    std::string model_name;
    for (const auto& e : still.effectNames()) model_name += (model_name.empty() ? "" : ",") + e;
    model_name += use_cal ? " (the vehicle file's calibration)" : " (the vehicle's physics)";
    const auto logs = readCheckedLogs(o->logs, o->read, v, o->measurement);
    std::vector<calibration::LogReplay> reps;
    for (const auto& l : logs) reps.push_back(calibration::replay(model, l));
    const auto m = calibration::errorMetrics(reps);
    json plans = json::array();
    if (!o->plan.empty()) {
      const auto area = wattswath::geometry::readSurveyArea(o->plan);
      if (!area.home) throw std::runtime_error(o->plan + ": the plan has no home row to place it in the logs' frame");
      std::vector<Eigen::Vector3d> vertices;
      for (const auto& r : area.regions)
        for (const auto& q : r.outer) vertices.emplace_back(q.x() - area.home->x(), q.y() - area.home->y(), 0.0);
      for (std::size_t i = 0; i < logs.size(); ++i) {
        const auto p = calibration::predictFromPlan(model, v, logs[i], vertices, o->plan_settings);
        const auto c = calibration::comparePlan(reps[i], p);
        plans.push_back({{"source", reps[i].source},
                         {"energy_j", p.energy_j},
                         {"time_s", p.time_s},
                         {"distance_m", p.distance_m},
                         {"measured_distance_m", loggedDistance(logs[i])},
                         {"legs", p.leg_speed.size()},
                         {"snapped_waypoints", p.snapped},
                         {"corner_speed_fraction", o->plan_settings.corner_speed_fraction},
                         {"measured_j", c.measured_j},
                         {"measured_time_s", c.measured_time_s},
                         {"replay_j", c.replay_j},
                         {"kinematics_error_j", c.kinematicsErrorJ()},
                         {"physics_error_j", c.physicsErrorJ()}});
      }
    }
    // The missions are flown as predict flies them (the file's calibration unless --effects).
    MissionReplays missions;
    if (!o->missions.empty()) {
      PredictionSetup setup = predictionSetup(v, o->vehicle, model, effects_opt->count() > 0, 25.0);
      if (wind) setup.settings.wind = wind->air();
      missions = missionReplays(v, setup, o->logs, o->missions, reps, o->read, o->mission_read);
    }
    if (!o->report.empty() || !o->report_svg.empty()) {
      // With --mission the mission section comes first, then the model on the logged kinematics.
      auto data = validationFromReplays(reps);
      data.facts.insert(data.facts.begin(), {{"vehicle", v.name}, {"model", model_name}});
      report::HtmlReport page(o->missions.empty() ? "wattswath replay" : "wattswath replay: missions against their logs");
      page.facts(data.facts);
      if (!o->missions.empty()) report::addMissionReplay(page, missions.report);
      report::addValidation(page, data);
      writeReport(page, o->report, o->report_svg, o->force);
    }
    if (!o->samples_out.empty()) {
      std::ostringstream os;
      os << "log,time_s,phase,leg,measured_w,modelled_w,speed_mps,climb_rate_mps,acceleration_mps2,heading_rad\n";
      for (const auto& r : reps)
        for (const auto& s : r.samples)
          os << r.source << "," << s.t << "," << en::toString(s.phase) << "," << s.leg << "," << s.measured_w << ","
             << s.modelled_w << "," << s.speed << "," << s.climb_rate << "," << s.acceleration << "," << s.heading
             << "\n";
      writeTextFileAtomic(o->samples_out, os.str());
    }
    if (o->json) {
      printJson({{"effects", model.effectNames()},
                 {"calibrated", use_cal},
                 {"metrics", metricsJson(m)},
                 {"flights", flightsJson(reps)},
                 {"residuals", residualsJson(calibration::residualTables(reps))},
                 {"plan_prediction", o->plan.empty() ? json(nullptr) : plans},
                 {"mission_prediction", o->missions.empty() ? json(nullptr) : missions.json},
                 {"mission_notes", missions.notes},
                 {"measurement", o->measurement.toJson()},
                 {"wind", windJson(wind)}});
      return;
    }
    o->measurement.print();
    for (const auto& n : missions.notes) std::cout << "note: " << n << "\n";
    if (!o->missions.empty()) printMissionReplays(missions.json);
    printMetrics("model " + model_name, m);
    for (const auto& r : reps) {
      std::cout << r.source << ": measured " << report::formatNumber(r.flight.measured_j, 0) << " J, modelled "
                << report::formatNumber(r.flight.modelled_j, 0) << " J (" << report::formatNumber(r.flight.errorPct(), 2) << " %), "
                << r.legs.size() << " segments (cut at stops and slow-downs)\n";
    }
    for (const auto& p : plans) {
      std::cout << p["source"].get<std::string>() << ": from the plan " << p["energy_j"].get<double>() << " J in "
                << p["time_s"].get<double>() << " s (kinematics error " << p["kinematics_error_j"].get<double>()
                << " J, physics error " << p["physics_error_j"].get<double>() << " J)\n";
    }
  });
}

// --effect-file FILE (repeatable): user-defined effects (calibration/user_effect.hpp).
void addEffectFileOption(CLI::App* cmd, std::vector<std::string>& files, const std::string& what) {
  cmd->add_option("--effect-file", files, "JSON model file of " + what + " (repeatable; README, user-defined effects)")
      ->check(CLI::ExistingFile);
}

std::vector<calibration::FormulaEffectSpec> readEffectFiles(const std::vector<std::string>& files) {
  std::vector<calibration::FormulaEffectSpec> out;
  for (const auto& f : files) {
    const auto specs = calibration::readEffectFile(f);
    out.insert(out.end(), specs.begin(), specs.end());
  }
  return out;
}

void registerDiagnose(CLI::App& app) {
  struct Opts {
    std::string vehicle, effects = kPaperEffects;
    std::vector<std::string> logs;
    logs::LogReadOptions read;
    int folds = 5;
    double p_value = 1e-3;
    std::vector<std::string> effect_files;
    MeasurementReport measurement;
    bool json = false;
    std::string report, report_svg;
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("diagnose", "Say which physical effect a model is missing (kept only when its held-out "
                                             "improvement is significant against the data's noise), that nothing is, "
                                             "or that no candidate explains the residual and which signals carry it");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--effects", o->effects, "Comma-separated effects of the model to diagnose")->capture_default_str();
  cmd->add_option("--log", o->logs, "Flight log: canonical CSV, ArduPilot .bin or PX4 .ulg (repeatable; 2+ logs: leave-one-flight-out)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--folds", o->folds, "Folds of contiguous time blocks held out in turn when only one log is given (2: alternate quarters, so each training half spans the flight)")
      ->check(CLI::Range(2, 10))
      ->capture_default_str();
  cmd->add_option("--p-value", o->p_value,
                  "False-alarm probability of keeping a candidate (held-out likelihood ratio on effective samples)")
      ->check(CLI::Range(1e-9, 0.1))
      ->capture_default_str();
  addEffectFileOption(cmd, o->effect_files, "user-defined effects tried as candidates too");
  addLogReadOptions(cmd, o->read);
  addTrustPowerFlag(cmd, o->measurement.trust_power);
  addJsonFlag(cmd, o->json);
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  cmd->callback([o]() {
    auto inputs = o->logs;
    inputs.push_back(o->vehicle);
    inputs.insert(inputs.end(), o->effect_files.begin(), o->effect_files.end());
    checkReportWritable(o->report, o->report_svg, o->force, inputs);
    const auto v = en::loadVehicle(o->vehicle);
    const auto user = readEffectFiles(o->effect_files);
    const auto model = calibration::buildModelWith(v, en::splitEffectList(o->effects), user);
    checkDistinctLogs(o->logs, o->logs.size());
    const auto logs = readCheckedLogs(o->logs, o->read, v, o->measurement);
    calibration::DiagnoseSettings s;
    for (const auto& u : user)
      if (!model.has(u.name)) s.extra_candidates.push_back(calibration::makeFormulaEffect(u, v));
    s.folds = o->folds;
    s.p_value = o->p_value;
    progress("diagnosing " + std::to_string(logs.size()) + " log(s)");
    const auto d = calibration::diagnose(model, v, logs, s);
    if (!o->report.empty() || !o->report_svg.empty()) {
      auto data = validationFromReplays(d.physics_replay);
      data.title = "wattswath diagnosis";
      data.facts.insert(data.facts.begin(), {{"vehicle", v.name},
                                             {"model", o->effects + " (as given by the vehicle's physics)"},
                                             {"validation", d.validation},
                                             {"verdict", d.verdict + ": " + d.conclusion}});
      for (const auto& st : d.staircase) data.staircase.push_back({st.label, st.metrics.rmse_w});
      data.error_label = "held-out sample RMSE";
      data.diagnosis = diagnosisRows(d);
      data.verdict = "Verdict: " + d.verdict + ". " + d.conclusion;
      const bool any = std::any_of(d.signatures.begin(), d.signatures.end(), [](const auto& g) { return g.significant; });
      for (const auto& g : d.signatures) {  // the significant signals, or the three leads
        if (d.verdict != "unexplained" || data.signal_curves.size() >= 3 || (any && !g.significant)) break;
        report::SignalCurve sc{g.signal, g.unit, g.sentence, {}, {}, calibration::signalLabel(g.signal)};
        for (const auto& b : g.bins) {
          sc.x.push_back(0.5 * (b.lo + b.hi));
          sc.residual.push_back(b.residual_w);
        }
        data.signal_curves.push_back(std::move(sc));
      }
      writeReport(report::validationReport(data), o->report, o->report_svg, o->force);
    }
    if (o->json) {
      json base = metricsJson(d.baseline);
      base["validation"] = d.validation;
      json out = diagnosisJson(d);
      out.update({{"effects", model.effectNames()},
                  {"physics", metricsJson(d.physics)},
                  {"baseline", base},
                  {"flights", flightsJson(d.physics_replay)},
                  {"residuals", residualsJson(d.residuals)},
                  {"measurement", o->measurement.toJson()}});
      printJson(out);
      return;
    }
    o->measurement.print();
    std::cout << "validation: " << d.validation << "\n";
    printMetrics("model as given (vehicle physics)", d.physics);
    printMetrics("model refitted (held-out)", d.baseline);
    printDiagnosis(d);
  });
}

void registerFit(CLI::App& app) {
  struct Opts {
    std::string vehicle, effects = kPaperEffects;
    std::vector<std::string> logs, test_logs, effect_files;
    logs::LogReadOptions read;
    MeasurementReport measurement;
    bool json = false;
    std::string report, report_svg;
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("fit", "Fit the coefficients of a model's effects (bounded least squares, Ceres) and "
                                        "report the error before and after on training and test logs");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--effects", o->effects, "Comma-separated effects to fit")->capture_default_str();
  cmd->add_option("--log", o->logs, "Training log: CSV, .bin or .ulg (repeatable)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--test-log", o->test_logs, "Test log (repeatable)")->check(CLI::ExistingFile);
  addEffectFileOption(cmd, o->effect_files, "user-defined effects that --effects may name");
  addLogReadOptions(cmd, o->read);
  addTrustPowerFlag(cmd, o->measurement.trust_power);
  addJsonFlag(cmd, o->json);
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  cmd->callback([o]() {
    auto inputs = o->logs;
    inputs.insert(inputs.end(), o->test_logs.begin(), o->test_logs.end());
    inputs.push_back(o->vehicle);
    inputs.insert(inputs.end(), o->effect_files.begin(), o->effect_files.end());
    checkReportWritable(o->report, o->report_svg, o->force, inputs);
    const auto v = en::loadVehicle(o->vehicle);
    const auto model = calibration::buildModelWith(v, en::splitEffectList(o->effects), readEffectFiles(o->effect_files));
    std::vector<std::string> all = o->logs;
    all.insert(all.end(), o->test_logs.begin(), o->test_logs.end());
    checkDistinctLogs(all, o->logs.size());
    const auto train = readCheckedLogs(o->logs, o->read, v, o->measurement);
    const auto test = readCheckedLogs(o->test_logs, o->read, v, o->measurement);
    const auto r = calibration::fitAndCompare(model, train, test);
    if (!o->report.empty() || !o->report_svg.empty()) {
      // The fitted model on the test logs when there are any (an honest picture), else on training.
      auto data = validationFromReplays(test.empty() ? r.train_replay : r.test_replay);
      data.title = "wattswath fit";
      data.facts.insert(data.facts.begin(), {{"vehicle", v.name},
                                             {"model", o->effects + " (coefficients fitted)"},
                                             {"plots show", test.empty() ? "fitted model on the training logs"
                                                                         : "fitted model on the test logs"}});
      const std::string trainLogs = train.size() == 1 ? "training log" : "training logs";
      const std::string testLogs = test.size() == 1 ? "test log" : "test logs";
      data.staircase = {{"as given, train", r.train_before.rmse_w, trainLogs}, {"fitted, train", r.train_after.rmse_w, trainLogs}};
      if (!test.empty()) {
        data.staircase.push_back({"as given, test", r.test_before.rmse_w, testLogs});
        data.staircase.push_back({"fitted, test", r.test_after.rmse_w, testLogs});
      }
      data.error_label = "sample RMSE";
      data.staircase_title = "Error before and after the fit, on the " + trainLogs +
                             (test.empty() ? std::string() : " and on the " + testLogs);
      data.staircase_caption =
          "Sample RMSE of the model as given (the vehicle file's coefficients) and fitted (coefficients fitted on the " +
          trainLogs + "), computed on the " + trainLogs +
          (test.empty() ? std::string() : " and on the " + testLogs + " the fit never saw (colours: legend)") +
          "; lower is better.";
      data.diagnosis_caption = "Fitted effects (no held-out ranking: see diagnose)";
      for (const auto& e : model.effectNames()) {
        data.diagnosis.push_back({e, std::numeric_limits<double>::quiet_NaN(), fittedValuesText(r.fit.coefficients, e),
                                  calibration::describeEffect(e, r.fit.coefficients), true});
      }
      writeReport(report::validationReport(data), o->report, o->report_svg, o->force);
    }
    auto side = [&](const calibration::ErrorMetrics& before, const calibration::ErrorMetrics& after) {
      json j = metricsJson(after);
      j["before"] = metricsJson(before);
      return j;
    };
    if (o->json) {
      json summaries = json::object();
      for (const auto& e : model.effectNames()) summaries[e] = calibration::describeEffect(e, r.fit.coefficients);
      printJson({{"effects", model.effectNames()},
                 {"coefficients", coefficientsJson(r.fit.coefficients, false)},
                 {"uncertainty", coefficientsJson(r.fit.coefficients, true)},
                 {"identifiability", identifiabilityJson(r.fit.coefficients)},
                 {"summary", summaries},
                 {"notes", r.fit.notes},
                 {"train", side(r.train_before, r.train_after)},
                 {"test", test.empty() ? json(nullptr) : side(r.test_before, r.test_after)},
                 {"train_flights", flightsJson(r.train_replay)},
                 {"test_flights", flightsJson(r.test_replay)},
                 {"measurement", o->measurement.toJson()}});
      return;
    }
    o->measurement.print();
    for (const auto& e : model.effectNames()) std::cout << e << ": " << calibration::describeEffect(e, r.fit.coefficients) << "\n";
    for (const auto& n : r.fit.notes) std::cout << "note: " << n << "\n";
    printMetrics("train before", r.train_before);
    printMetrics("train after ", r.train_after);
    if (!test.empty()) {
      printMetrics("test before ", r.test_before);
      printMetrics("test after  ", r.test_after);
    }
  });
}

void registerSimulate(CLI::App& app) {
  struct Opts {
    std::string vehicle, effects = kPaperEffects, out, path;
    std::vector<std::string> sets, effect_files;
    calibration::SimulationSettings sim;
    bool json = false, force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("simulate", "Write a canonical CSV log of a model (with chosen hidden effects) flown "
                                             "along a path, with sensor noise and a fixed seed");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--effects", o->effects, "Effects of the true model (hidden ones included)")->capture_default_str();
  cmd->add_option("--set", o->sets, "Coefficient of the true model, effect.coefficient=value (repeatable), "
                                    "e.g. --effects hover,kinetic,wind --set wind.wind_east=3 (wind replaces parasitic_drag)");
  addEffectFileOption(cmd, o->effect_files, "user-defined effects that --effects may name");
  cmd->add_option("--path", o->path, "Waypoints x y z [m] per line (default: take-off to 15 m, a 160 m x 50 m lawnmower, a climb to 25 m, "
                                 "a diagonal to (80, 90) m and back over the start, landing)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--rate", o->sim.rate_hz, "Sample rate [Hz]")->check(CLI::Range(0.1, 1000.0))->capture_default_str();
  cmd->add_option("--speed", o->sim.cruise_speed, "Cruise speed [m/s]")->check(CLI::Range(0.5, 40.0))->capture_default_str();
  cmd->add_option("--noise-w", o->sim.power_noise_w, "Power noise standard deviation [W]")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--seed", o->sim.seed, "Random seed")->capture_default_str();
  cmd->add_option("--out", o->out, "Output CSV log")->required();
  addForceFlag(cmd, o->force);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    auto inputs = o->effect_files;
    inputs.insert(inputs.end(), {o->vehicle, o->path});
    checkWritable(o->out, o->force, inputs);
    const auto v = en::loadVehicle(o->vehicle);
    auto model = calibration::buildModelWith(v, en::splitEffectList(o->effects), readEffectFiles(o->effect_files));
    for (const auto& s : o->sets) {
      const auto dot = s.find('.'), eq = s.find('=');
      if (dot == std::string::npos || eq == std::string::npos || eq < dot) {
        throw std::runtime_error("--set '" + s + "': expected effect.coefficient=value");
      }
      const std::string eff = s.substr(0, dot), name = s.substr(dot + 1, eq - dot - 1), val = s.substr(eq + 1);
      auto& e = model.effect(eff);
      std::vector<double> vals;
      bool found = false;
      for (const auto& c : e.coefficients()) {
        if (c.name == name) {
          size_t used = 0;
          double x = 0.0;
          try {
            x = std::stod(val, &used);
          } catch (const std::exception&) {
            used = 0;
          }
          if (used != val.size()) throw std::runtime_error("--set '" + s + "': value '" + val + "' is not a number");
          if (x < c.lower || x > c.upper) {
            throw std::runtime_error("--set '" + s + "': " + val + " is outside " + std::to_string(c.lower) + ".." +
                                     std::to_string(c.upper) + " " + c.unit);
          }
          vals.push_back(x);
          found = true;
        } else {
          vals.push_back(c.value);
        }
      }
      if (!found) throw std::runtime_error("--set '" + s + "': effect '" + eff + "' has no coefficient '" + name + "'");
      e.setCoefficientValues(vals);
    }
    const std::vector<Eigen::Vector3d> path =
        o->path.empty() ? std::vector<Eigen::Vector3d>{{0, 0, 0},    {0, 0, 15},    {160, 0, 15}, {160, 25, 15},
                                                       {0, 25, 15},  {0, 50, 15},   {160, 50, 15}, {160, 50, 25},
                                                       {80, 90, 25}, {0, 0, 25},    {0, 0, 0}}
                        : logs::readWaypointPath(o->path);
    logs::FlightLog log;
    try {
      log = calibration::simulateFlight(path, model, o->sim);
    } catch (const std::invalid_argument& e) {
      if (o->path.empty()) throw;
      throw std::runtime_error(o->path + ": " + e.what());
    }
    log.metadata["vehicle"] = v.name;
    writeTextFileAtomic(o->out, logs::writeCsvLog(log));
    if (o->json) {
      printJson({{"out", o->out}, {"samples", log.samples.size()}, {"duration_s", log.duration()}});
    } else {
      std::cout << "wrote " << o->out << ": " << log.samples.size() << " samples, " << log.duration() << " s\n";
    }
  });
}

}  // namespace

void registerLogCommands(CLI::App& app) {
  registerReplay(app);
  registerDiagnose(app);
  registerFit(app);
  registerSimulate(app);
}

}  // namespace wattswath::apps
