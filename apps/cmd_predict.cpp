// wattswath predict MISSION --vehicle V: energy, time and battery of a mission file flown by the
// vehicle's autopilot (mission/predict.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <utility>
#include <sstream>
#include <vector>

#include "cli.hpp"
#include "predict_options.hpp"
#include "predict_spread.hpp"
#include "prediction_setup.hpp"
#include "report_data.hpp"
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace {

namespace en = wattswath::energy;
namespace ms = wattswath::mission;

struct PredictOptions {
  std::string mission, vehicle, effects, samples_out, report, report_svg, launch, wind;
  double reserve_pct = 25.0;
  double energy_margin_pct = 10.0;
  bool json = false, lenient = false, force = false;
};

nlohmann::json totalsJson(const ms::Totals& t) {
  return {{"energy_j", t.energy_j}, {"energy_wh", t.energy_j / 3600.0}, {"time_s", t.time_s}, {"distance_m", t.distance_m}};
}

std::string minutesSeconds(double s) { return report::formatMinSec(s); }

// Which energy model predicted: its effects as the prediction used them (in wind, parasitic_drag
// is the wind effect) and where they come from.
std::string modelText(const ms::MissionPrediction& p, bool calibrated) {
  std::string names;
  for (const auto& e : p.breakdown.effects) names += (names.empty() ? "" : ", ") + e;
  return names + (calibrated ? " (the vehicle file's calibration)" : " (the vehicle's physics)");
}

// The mission report: the prediction's figures and tables with the inputs as facts.
report::HtmlReport missionReport(const ms::MissionPrediction& p, const ms::AutopilotConfig& ap, const en::Vehicle& v,
                                 const std::string& model, const std::vector<std::pair<std::string, std::string>>& extra,
                                 const PredictOptions& o) {
  auto d = missionReportData(p, o.reserve_pct);
  d.title = "wattswath predict: " + std::filesystem::path(o.mission).filename().string();
  d.facts = {{"mission", o.mission},
             {"vehicle", v.name + " (" + o.vehicle + ")"},
             {"flown by", ap.firmware + " " + ap.version + " (" + ms::toString(ap.family) + " model" +
                              (ap.from_file ? ")" : ", firmware defaults)")},
             {"energy model", model},
             {"take-off to landing", minutesSeconds(p.total.time_s) + " min:s, " + report::formatNumber(p.total.energy_j / 3600.0, 1) +
                                         " Wh (" + report::formatNumber(p.total.energy_j, 0) + " J), " +
                                         report::formatNumber(p.total.distance_m, 0) + " m"}};
  if (p.battery.known) {
    d.facts.push_back({"battery at landing", report::formatNumber(100.0 * p.battery.usable_left_end, 1) + " % usable left (reserve " +
                                                 report::formatNumber(o.reserve_pct, 0) + " %)"});
    if (p.battery.energy_margin > 0.0) {
      d.facts.push_back({"with " + report::formatNumber(100.0 * p.battery.energy_margin, 0) + " % more energy",
                         report::formatNumber(100.0 * p.battery.usable_left_end_with_margin, 1) +
                             " % usable left (the prediction's error margin, --energy-margin)"});
    }
  }
  for (const auto& [label, text] : extra) d.facts.push_back({label, text});
  for (const auto& w : p.warnings) d.facts.push_back({"note", w});
  return report::missionReport(d);
}

nlohmann::json toJson(const ms::MissionPrediction& p, const ms::AutopilotConfig& ap, const PredictOptions& o) {
  nlohmann::json j;
  j["mission"] = o.mission;
  j["autopilot"] = {{"firmware", ap.firmware}, {"version", ap.version}, {"model", ms::toString(ap.family)},
                    {"parameters_from_vehicle_file", ap.from_file}};
  j["energy_j"] = p.total.energy_j;
  j["energy_wh"] = p.total.energy_j / 3600.0;
  j["time_s"] = p.total.time_s;
  j["distance_m"] = p.total.distance_m;
  for (int k = 0; k < ms::kFlightPhaseCount; ++k) j["phases"][ms::toString(static_cast<ms::FlightPhase>(k))] = totalsJson(p.phases[k]);
  j["items"] = nlohmann::json::array();
  for (const auto& it : p.items) {
    nlohmann::json ji = totalsJson(it.totals);
    ji["seq"] = it.seq;
    ji["command"] = it.command;
    ji["reached_s"] = std::isfinite(it.reached_s) ? nlohmann::json(it.reached_s) : nlohmann::json();
    ji["completed_s"] = std::isfinite(it.completed_s) ? nlohmann::json(it.completed_s) : nlohmann::json();
    j["items"].push_back(ji);
  }
  for (const auto& name : p.breakdown.effects) j["breakdown"][name] = p.breakdown.byEffect(name);
  if (p.battery.known) {
    j["battery"] = {{"known", true},
                    {"usable_left_at_landing", p.battery.usable_left_end},
                    {"reserve_fraction", p.battery.reserve_fraction},
                    {"fits", p.battery.fits},
                    {"energy_margin", p.battery.energy_margin},
                    {"usable_left_at_landing_with_margin", p.battery.usable_left_end_with_margin},
                    {"fits_with_margin", p.battery.fits_with_margin},
                    {"depleted", p.battery.depleted},
                    {"verdict", p.battery.verdict}};
    if (p.battery.depleted) j["battery"]["depleted_at_s"] = p.battery.depleted_at_s;
  } else {
    j["battery"] = {{"known", false}, {"verdict", "The vehicle file has no battery: no state of charge can be given."}};
  }
  j["warnings"] = p.warnings;
  return j;
}

// The prediction as text: totals and phases, the battery, the facts in `extra` on stdout; notes on stderr.
void printText(const ms::MissionPrediction& p, const ms::AutopilotConfig& ap,
               const std::vector<std::pair<std::string, std::string>>& extra) {
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "flown by " << ap.firmware << " " << ap.version << " (" << ms::toString(ap.family) << " model"
            << (ap.from_file ? "" : ", firmware defaults: the vehicle file has no autopilot object") << ")\n";
  std::cout << "total    " << minutesSeconds(p.total.time_s) << " min:s  " << p.total.energy_j / 3600.0 << " Wh  ("
            << p.total.energy_j << " J)  " << p.total.distance_m << " m\n";
  for (int k = 0; k < ms::kFlightPhaseCount; ++k) {
    const auto& t = p.phases[k];
    std::cout << "  " << std::left << std::setw(8) << ms::toString(static_cast<ms::FlightPhase>(k)) << std::right << " "
              << minutesSeconds(t.time_s) << "  " << t.energy_j / 3600.0 << " Wh  " << t.distance_m << " m\n";
  }
  std::cout << "battery: " << (p.battery.known ? p.battery.verdict : "unknown (no battery in the vehicle file)") << "\n";
  for (const auto& [label, text] : extra) std::cout << label << ": " << text << "\n";
  std::cout.flush();
  for (const auto& w : p.warnings) std::cerr << "note: " << w << "\n";
}

std::string samplesCsv(const ms::MissionPrediction& p) {
  std::ostringstream os;
  os.precision(10);
  os << "t_s,x_m,y_m,z_m,speed_mps,phase,seq\n";
  for (const auto& s : p.flight.samples) {
    const int seq = s.step >= 0 && s.step < static_cast<int>(p.items.size()) ? p.items[s.step].seq : -1;
    os << s.t << "," << s.position.x() << "," << s.position.y() << "," << s.position.z() << "," << s.velocity.norm() << ","
       << ms::toString(s.phase) << "," << seq << "\n";
  }
  return os.str();
}

}  // namespace

void registerPredictCommand(CLI::App& app) {
  auto o = std::make_shared<PredictOptions>();
  auto* cmd = app.add_subcommand(
      "predict",
      "Energy, time and battery of a mission file (.plan or .waypoints) as the vehicle's autopilot flies it: "
      "take-off to landing, by phase and by item");
  cmd->add_option("MISSION", o->mission, "QGroundControl .plan or QGC WPL 110 .waypoints file")->required();
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--effects", o->effects,
                  "Comma-separated effects of the energy model (default: the vehicle file's calibration when it has one, "
                  "else hover,kinetic,parasitic_drag from its physics)");
  cmd->add_option("--reserve", o->reserve_pct, "Usable charge to keep on landing [%]")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  cmd->add_option("--energy-margin", o->energy_margin_pct,
                  "Extra energy the reserve verdict also checks, for the prediction's own error [%] (uncalibrated "
                  "predictions of real flights were off by up to 8 %: docs/validation.md; 0: none)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--launch", o->launch,
                  "Where the vehicle will arm and take off, LAT,LON [deg] or LAT,LON,ALT (ALT [m] in the home row's "
                  "reference, usually above sea level), when not at the mission file's home: the autopilot sets home there "
                  "and returns to it; without ALT its altitude is taken as the file's home's");
  cmd->add_option("--wind", o->wind,
                  "Steady wind SPEED,FROM: SPEED [m/s] blowing from the compass bearing FROM [deg] (0 north, 90 east), "
                  "as a forecast gives it, e.g. 6,45; or SPEED alone for any direction (the dearest of 8 is predicted); the "
                  "ArduCopter models fly against the drag at air speed and the energy model's drag is taken at air speed "
                  "(default: still air)");
  cmd->add_option("--samples-out", o->samples_out, "Write the predicted trajectory (10 Hz) as CSV here");
  cmd->add_flag("--lenient", o->lenient, "Skip unsupported mission commands with a warning instead of an error");
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  addJsonFlag(cmd, o->json);
  cmd->callback([o] {
    if (!o->samples_out.empty()) checkWritable(o->samples_out, o->force, {o->mission, o->vehicle});
    checkReportWritable(o->report, o->report_svg, o->force, {o->mission, o->vehicle, o->samples_out});
    const en::Vehicle v = en::loadVehicle(o->vehicle);
    PredictionSetup setup = predictionSetup(v, o->vehicle, o->effects, o->reserve_pct);
    setup.settings.energy_margin = o->energy_margin_pct / 100.0;
    std::optional<Wind> wind = windOption(o->wind, true);
    if (wind) setup.settings.wind = wind->air();
    const en::EnergyModel& model = setup.model;
    const bool use_calibration = setup.calibrated;
    const ms::AutopilotConfig& ap = setup.autopilot;
    ms::ReadOptions ro;
    ro.lenient = o->lenient;
    ms::Mission m = ms::readMission(o->mission, ro);
    std::optional<Launch> launch;
    if (!o->launch.empty()) launch = moveHomeTo(m, o->launch);
    // What the mission asks of the vehicle, for the calibration's flights of its kind to decide a
    // disputed parameter (predict_spread.hpp, KindChoice) and for the coverage check.
    const calibration::MissionKind kind = calibration::missionKind(ms::sequenceMission(m), setup.autopilot);
    const std::optional<KindChoice> choice = kindChoiceOf(kind, setup);
    if (choice) setup.autopilot.parameters[setup.disputed_parameter] = choice->value;
    // A wind from any direction: the mission is flown from each of kWindDirections, and the dearest
    // is the prediction (the reserve is checked for it).
    nlohmann::json wind_directions = nlohmann::json::array();
    std::optional<ms::MissionPrediction> dearest_wind;  // the dearest direction's prediction
    if (wind && wind->any_direction) {
      for (int k = 0; k < kWindDirections; ++k) {
        Wind w = *wind;
        w.from_deg = 360.0 * k / kWindDirections;
        setup.settings.wind = w.air();
        ms::MissionPrediction pk = ms::predictMission(m, v, model, ap, setup.settings);
        wind_directions.push_back({{"from_deg", w.from_deg}, {"energy_j", pk.total.energy_j}, {"time_s", pk.total.time_s}});
        if (!dearest_wind || pk.total.energy_j > dearest_wind->total.energy_j) {
          dearest_wind = std::move(pk);
          wind->from_deg = w.from_deg;
        }
      }
      setup.settings.wind = wind->air();
    }
    const std::optional<Dispute> dispute = disputeOf(m, v, setup);
    ms::MissionPrediction p = dearest_wind ? std::move(*dearest_wind) : ms::predictMission(m, v, model, ap, setup.settings);
    const std::optional<Coverage> coverage = coverageOf(m, kind, v, setup);
    // The reserve is also checked for the dearer of the flights the calibration stands for, and for
    // the behaviour before the calibration when the mission is outside what it flew.
    double dearest = dispute ? dispute->energy_hi_j : 0.0;
    if (coverage) dearest = std::max(dearest, coverage->energy_j);
    const double wider = std::clamp(dearest / p.total.energy_j - 1.0, 0.0, 1.0);
    if (wider > setup.settings.energy_margin) {
      setup.settings.energy_margin = wider;
      p = ms::predictMission(m, v, model, ap, setup.settings);
    }
    std::vector<std::pair<std::string, std::string>> extra;  // facts for the text, the report and the JSON
    if (launch) {
      launch->absolute_items = absoluteItems(m, p.flight.steps);
      extra.push_back({"launch", launchText(*launch)});
    }
    if (wind) {
      std::string by_direction;
      if (!wind_directions.empty()) {
        double lo = 1e300, hi = 0.0;
        for (const auto& d : wind_directions) lo = std::min(lo, d["energy_j"].get<double>()), hi = std::max(hi, d["energy_j"].get<double>());
        by_direction = "; by direction " + report::formatNumber(lo / 3600.0, 1) + "-" + report::formatNumber(hi / 3600.0, 1) + " Wh";
      }
      extra.push_back({"wind", wind->text() + by_direction});
    }
    if (dispute) extra.push_back({"calibration", disputeText(*dispute, p, choice)});
    if (coverage) extra.push_back({"calibration coverage", coverageText(*coverage, p)});
    if (!o->samples_out.empty()) writeTextFileAtomic(o->samples_out, samplesCsv(p));
    if (!o->report.empty() || !o->report_svg.empty()) {
      writeReport(missionReport(p, ap, v, modelText(p, use_calibration), extra, *o), o->report, o->report_svg, o->force);
    }
    if (o->json) {
      nlohmann::json j = toJson(p, ap, *o);
      j["launch"] = nullptr;
      if (launch) {
        j["launch"] = {{"lat_deg", m.home.lat_deg},
                       {"lon_deg", m.home.lon_deg},
                       {"from_mission_home_m", launch->from_home_m},
                       {"alt_m", launch->alt_m ? nlohmann::json(*launch->alt_m) : nlohmann::json(nullptr)},
                       {"absolute_items", launch->absolute_items},
                       {"text", launchText(*launch)}};
      }
      j["wind"] = windJson(wind);
      if (wind) j["wind"]["directions"] = wind_directions;  // each direction flown (empty: the one given)
      j["calibration_dispute"] = nullptr;
      if (dispute) {
        j["calibration_dispute"] = {{"parameter", dispute->parameter}, {"values", {dispute->lo, dispute->hi}},
                                    {"energy_j", {dispute->energy_lo_j, dispute->energy_hi_j}},
                                    {"time_s", {dispute->time_lo_s, dispute->time_hi_s}},
                                    {"chosen", choice ? nlohmann::json{{"value", choice->value}, {"flights", choice->flights}}
                                                      : nlohmann::json(nullptr)},
                                    {"text", disputeText(*dispute, p, choice)}};
      }
      // null: uncalibrated, or the mission is of the kind the calibration flew (or the file predates the check).
      j["calibration_coverage"] = nullptr;
      if (coverage) {
        j["calibration_coverage"] = {{"outside", coverage->reasons},
                                     {"behaviour_before", {{"energy_j", coverage->energy_j}, {"time_s", coverage->time_s}}},
                                     {"text", coverageText(*coverage, p)}};
      }
      printJson(j);
    } else {
      printText(p, ap, extra);
    }
  });
}

}  // namespace wattswath::apps
