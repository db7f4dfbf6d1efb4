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
    d.facts.push_back(batteryEndFact(p.battery, report::formatNumber(100.0 * p.battery.usable_left_end, 1) +
                                                    " % usable left (reserve " + report::formatNumber(o.reserve_pct, 0) + " %)"));
    if (p.battery.energy_margin > 0.0 && !p.battery.depleted) {
      d.facts.push_back({"with " + report::formatNumber(100.0 * p.battery.energy_margin, 0) + " % more energy",
                         report::formatNumber(100.0 * p.battery.usable_left_end_with_margin, 1) +
                             " % usable left (the prediction's error margin, --energy-margin)"});
    }
  }
  // A flight that does not fit says so first: the figures below show it as if the battery held out.
  if (p.battery.known && !p.battery.fits) d.facts.insert(d.facts.begin(), {"battery verdict", p.battery.verdict});
  for (const auto& [label, text] : extra) d.facts.push_back({label, text});
  if (!p.flight.model.empty()) d.facts.push_back({"model", p.flight.model});
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
                    {"ends_in_air", p.battery.ends_in_air},
                    {"verdict", p.battery.verdict}};
    if (p.battery.depleted) j["battery"]["depleted_at_s"] = p.battery.depleted_at_s;
  } else {
    j["battery"] = {{"known", false}, {"verdict", "The vehicle file has no battery: no state of charge can be given."}};
  }
  j["model"] = p.flight.model;
  j["warnings"] = p.warnings;
  return j;
}

constexpr std::size_t kItemRows = 60;  // rows of the text output's item table; the rest are in --json and --report

// The text output's table of the items as flown (one row per step: an item a DO_JUMP repeats has a
// row each time): number, command, when reached [min:s], distance [m] and energy [kJ] while it was
// the active item; the first kItemRows rows, then how many more.
void printItemTable(const ms::MissionPrediction& p) {
  std::cout << "items    (reached: min:s from the take-off command; distance and energy while the item is active)\n";
  std::cout << "  " << std::setw(5) << "item" << "  " << std::left << std::setw(22) << "command" << std::right << std::setw(9)
            << "reached" << std::setw(12) << "distance" << std::setw(12) << "energy" << "\n";
  const std::size_t rows = std::min(p.items.size(), kItemRows);
  for (std::size_t k = 0; k < rows; ++k) {
    const ms::ItemPrediction& it = p.items[k];
    std::cout << "  " << std::setw(5) << (it.seq >= 0 ? std::to_string(it.seq) : std::string("-")) << "  " << std::left
              << std::setw(22) << it.command << std::right << std::setw(9)
              << (std::isfinite(it.reached_s) ? minutesSeconds(it.reached_s) : std::string("-")) << std::setw(10)
              << std::setprecision(0) << it.totals.distance_m << " m" << std::setw(9) << std::setprecision(2)
              << it.totals.energy_j / 1000.0 << " kJ\n";
  }
  if (p.items.size() > rows) {
    std::cout << "  ... " << p.items.size() - rows << " more, see --json (items) or --report\n";
  }
  std::cout << std::setprecision(1);
}

// The prediction as text: totals, phases and items, the battery, the facts in `extra` on stdout;
// notes on stderr.
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
  printItemTable(p);
  std::cout << "battery: " << (p.battery.known ? p.battery.verdict : "unknown (no battery in the vehicle file)") << "\n";
  for (const auto& [label, text] : extra) std::cout << label << ": " << text << "\n";
  if (!p.flight.model.empty()) std::cout << "model: " << p.flight.model << "\n";
  std::cout.flush();
  for (const auto& w : p.warnings) std::cerr << "note: " << w << "\n";
}

// The predicted trajectory at 10 Hz with the modelled power of the step ending at each sample and
// the energy drawn so far (toPieces makes one piece per step of positive duration, in order).
std::string samplesCsv(const ms::MissionPrediction& p) {
  std::ostringstream os;
  os.precision(10);
  os << "t_s,x_m,y_m,z_m,speed_mps,phase,seq,power_w,energy_j\n";
  std::size_t piece = 0;
  double energy = 0.0;
  for (std::size_t i = 0; i < p.flight.samples.size(); ++i) {
    const auto& s = p.flight.samples[i];
    double power = 0.0;
    if (i > 0 && s.t > p.flight.samples[i - 1].t && piece < p.piece_energy_j.size()) {
      const double e = p.piece_energy_j[piece++];
      energy += e;
      power = e / (s.t - p.flight.samples[i - 1].t);
    }
    const int seq = s.step >= 0 && s.step < static_cast<int>(p.items.size()) ? p.items[s.step].seq : -1;
    os << s.t << "," << s.position.x() << "," << s.position.y() << "," << s.position.z() << "," << s.velocity.norm() << ","
       << ms::toString(s.phase) << "," << seq << "," << power << "," << energy << "\n";
  }
  return os.str();
}

// A wind from any direction (predict --wind SPEED): the mission flown from each of kWindDirections.
struct AnyDirection {
  nlohmann::json directions = nlohmann::json::array();  // {from_deg, energy_j, time_s} of each direction flown
  std::optional<ms::MissionPrediction> dearest;          // the dearest direction's prediction
};

// Flies `m` in `wind` from each of kWindDirections; sets wind.from_deg to the dearest direction and
// setup's wind to it.
AnyDirection flyEveryDirection(const ms::Mission& m, const en::Vehicle& v, PredictionSetup& setup, Wind& wind) {
  AnyDirection r;
  for (int k = 0; k < kWindDirections; ++k) {
    Wind w = wind;
    w.from_deg = 360.0 * k / kWindDirections;
    setup.settings.wind = w.air();
    ms::MissionPrediction pk = ms::predictMission(m, v, setup.model, setup.autopilot, setup.settings);
    r.directions.push_back({{"from_deg", w.from_deg}, {"energy_j", pk.total.energy_j}, {"time_s", pk.total.time_s}});
    if (!r.dearest || pk.total.energy_j > r.dearest->total.energy_j) {
      r.dearest = std::move(pk);
      wind.from_deg = w.from_deg;
    }
  }
  setup.settings.wind = wind.air();
  return r;
}

// Everything one predict run found: the prediction and what it was checked against.
struct PredictRun {
  ms::Mission mission;
  std::optional<Launch> launch;
  std::optional<Wind> wind;
  AnyDirection any_direction;
  std::optional<KindChoice> choice;
  std::optional<Dispute> dispute;
  std::optional<Coverage> coverage;
  ms::MissionPrediction prediction;
  std::vector<std::pair<std::string, std::string>> extra;  // facts for the text, the report and the JSON
};

// Predicts the mission of `o` with `setup`: the calibration's flights of the mission's kind decide a
// disputed parameter, a wind from any direction is flown from each direction, and the reserve is
// also checked for the dearer of the flights the calibration stands for and for the behaviour before
// the calibration when the mission is outside what it flew (predict_spread.hpp).
PredictRun runPrediction(const PredictOptions& o, const en::Vehicle& v, PredictionSetup& setup) {
  PredictRun r;
  r.wind = windOption(o.wind, true);
  if (r.wind) setup.settings.wind = r.wind->air();
  ms::ReadOptions ro;
  ro.lenient = o.lenient;
  if (!o.launch.empty()) ro.distances_from = launchPoint(o.launch);
  r.mission = ms::readMission(o.mission, ro);
  const ms::Mission& m = r.mission;
  if (!o.launch.empty()) r.launch = moveHomeTo(r.mission, o.launch);
  const calibration::MissionKind kind = calibration::missionKind(ms::sequenceMission(m), setup.autopilot);
  r.choice = kindChoiceOf(kind, setup);
  if (r.choice) setup.autopilot.parameters[setup.disputed_parameter] = r.choice->value;
  if (r.wind && r.wind->any_direction) r.any_direction = flyEveryDirection(m, v, setup, *r.wind);
  r.dispute = disputeOf(m, v, setup);
  r.prediction = r.any_direction.dearest ? std::move(*r.any_direction.dearest)
                                         : ms::predictMission(m, v, setup.model, setup.autopilot, setup.settings);
  r.coverage = coverageOf(m, kind, v, setup);
  double dearest = r.dispute ? r.dispute->energy_hi_j : 0.0;
  if (r.coverage) dearest = std::max(dearest, r.coverage->energy_j);
  const double wider = std::clamp(dearest / r.prediction.total.energy_j - 1.0, 0.0, 1.0);
  if (wider > setup.settings.energy_margin) {
    setup.settings.energy_margin = wider;
    r.prediction = ms::predictMission(m, v, setup.model, setup.autopilot, setup.settings);
  }
  return r;
}

// The facts a run adds to the text and the report: launch, wind, calibration dispute and coverage.
void addFacts(PredictRun& r) {
  const ms::MissionPrediction& p = r.prediction;
  if (r.launch) {
    r.launch->absolute_items = absoluteItems(r.mission, p.flight.steps);
    r.extra.push_back({"launch", launchText(*r.launch)});
  }
  if (r.wind) {
    std::string by_direction;
    if (!r.any_direction.directions.empty()) {
      double lo = 1e300, hi = 0.0;
      for (const auto& d : r.any_direction.directions) {
        lo = std::min(lo, d["energy_j"].get<double>());
        hi = std::max(hi, d["energy_j"].get<double>());
      }
      by_direction = "; by direction " + report::formatNumber(lo / 3600.0, 1) + "-" + report::formatNumber(hi / 3600.0, 1) + " Wh";
    }
    r.extra.push_back({"wind", r.wind->text() + by_direction});
  }
  if (r.dispute) r.extra.push_back({"calibration", disputeText(*r.dispute, p, r.choice)});
  if (r.coverage) r.extra.push_back({"calibration coverage", coverageText(*r.coverage, p)});
}

// The JSON of a run: the prediction (toJson) with launch, wind, calibration_dispute and
// calibration_coverage, each null when it does not apply.
nlohmann::json runJson(const PredictRun& r, const ms::AutopilotConfig& ap, const PredictOptions& o) {
  const ms::MissionPrediction& p = r.prediction;
  nlohmann::json j = toJson(p, ap, o);
  j["launch"] = nullptr;
  if (r.launch) {
    j["launch"] = {{"lat_deg", r.mission.home.lat_deg},
                   {"lon_deg", r.mission.home.lon_deg},
                   {"from_mission_home_m", r.launch->from_home_m},
                   {"alt_m", r.launch->alt_m ? nlohmann::json(*r.launch->alt_m) : nlohmann::json(nullptr)},
                   {"absolute_items", r.launch->absolute_items},
                   {"text", launchText(*r.launch)}};
  }
  j["wind"] = windJson(r.wind);
  if (r.wind) j["wind"]["directions"] = r.any_direction.directions;  // each direction flown (empty: the one given)
  j["calibration_dispute"] = nullptr;
  if (r.dispute) {
    const Dispute& d = *r.dispute;
    j["calibration_dispute"] = {{"parameter", d.parameter}, {"values", {d.lo, d.hi}},
                                {"energy_j", {d.energy_lo_j, d.energy_hi_j}},
                                {"time_s", {d.time_lo_s, d.time_hi_s}},
                                {"chosen", r.choice ? nlohmann::json{{"value", r.choice->value}, {"flights", r.choice->flights}}
                                                    : nlohmann::json(nullptr)},
                                {"text", disputeText(d, p, r.choice)}};
  }
  // null: uncalibrated, or the mission is of the kind the calibration flew (or the file predates the check).
  j["calibration_coverage"] = nullptr;
  if (r.coverage) {
    j["calibration_coverage"] = {{"outside", r.coverage->reasons},
                                 {"behaviour_before", {{"energy_j", r.coverage->energy_j}, {"time_s", r.coverage->time_s}}},
                                 {"text", coverageText(*r.coverage, p)}};
  }
  return j;
}

// The options of `predict`.
void addPredictOptions(CLI::App* cmd, PredictOptions& o) {
  cmd->add_option("MISSION", o.mission, "QGroundControl .plan or QGC WPL 110 .waypoints file")->required();
  addVehicleOption(cmd, o.vehicle);
  cmd->add_option("--effects", o.effects,
                  "Comma-separated effects of the energy model (default: the vehicle file's calibration when it has one, "
                  "else hover,kinetic,parasitic_drag from its physics)");
  cmd->add_option("--reserve", o.reserve_pct, "Usable charge to keep on landing [%]")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  cmd->add_option("--energy-margin", o.energy_margin_pct,
                  "Extra energy the reserve verdict also checks, for the prediction's own error [%] (uncalibrated "
                  "predictions of real flights were off by up to 8 %: docs/validation.md; 0: none)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--launch", o.launch,
                  "Where the vehicle will arm and take off, LAT,LON [deg] or LAT,LON,ALT (ALT [m] in the home row's "
                  "reference, usually above sea level), when not at the mission file's home: the autopilot sets home there "
                  "and returns to it; without ALT its altitude is taken as the file's home's");
  cmd->add_option("--wind", o.wind,
                  "Steady wind SPEED,FROM: SPEED [m/s] blowing from the compass bearing FROM [deg] (0 north, 90 east), "
                  "as a forecast gives it, e.g. 6,45; or SPEED alone for any direction (the dearest of 8 is predicted); the "
                  "ArduCopter models fly against the drag at air speed and the energy model's drag is taken at air speed "
                  "(default: still air)");
  cmd->add_option("--samples-out", o.samples_out,
                  "Write the predicted trajectory (10 Hz) as CSV here: t_s, x_m, y_m, z_m (east, north, up of home), "
                  "speed_mps, phase, seq (the mission item flown), power_w (modelled, over the step ending there), "
                  "energy_j (drawn so far)");
  cmd->add_flag("--lenient", o.lenient,
                "Warnings instead of errors: skip unsupported mission commands that do not move the vehicle (a navigation "
                "command is never skipped), and predict as written the items below home's height and, for a PX4 vehicle, "
                "the items in a frame PX4 refuses at upload");
  addReportOptions(cmd, o.report, o.report_svg, o.force);
  addJsonFlag(cmd, o.json);
}

// Runs `predict` with options `o`: checks the outputs can be written, predicts, writes the samples
// and the report, prints JSON or text.
void runPredict(const PredictOptions& o) {
  if (!o.samples_out.empty()) checkWritable(o.samples_out, o.force, {o.mission, o.vehicle});
  checkReportWritable(o.report, o.report_svg, o.force, {o.mission, o.vehicle, o.samples_out});
  const en::Vehicle v = en::loadVehicle(o.vehicle);
  PredictionSetup setup = predictionSetup(v, o.vehicle, o.effects, o.reserve_pct);
  setup.settings.energy_margin = o.energy_margin_pct / 100.0;
  setup.settings.lenient = o.lenient;
  PredictRun r = runPrediction(o, v, setup);
  addFacts(r);
  const ms::AutopilotConfig& ap = setup.autopilot;
  if (!o.samples_out.empty()) writeTextFileAtomic(o.samples_out, samplesCsv(r.prediction));
  if (!o.report.empty() || !o.report_svg.empty()) {
    writeReport(missionReport(r.prediction, ap, v, modelText(r.prediction, setup.calibrated), r.extra, o), o.report,
                o.report_svg, o.force);
  }
  if (o.json) {
    printJson(runJson(r, ap, o));
  } else {
    printText(r.prediction, ap, r.extra);
  }
}

}  // namespace

void registerPredictCommand(CLI::App& app) {
  auto o = std::make_shared<PredictOptions>();
  auto* cmd = app.add_subcommand(
      "predict",
      "Energy, time and battery of a mission file (.plan or .waypoints) as the vehicle's autopilot flies it: "
      "take-off to landing, by phase and by item");
  addPredictOptions(cmd, *o);
  cmd->footer(
      "\nThe mission is flown by the vehicle file's `autopilot` (firmware, version, parameters; firmware defaults "
      "without one): docs/autopilots.md says what each model follows. Times count from the take-off command.\n"
      "--json: energy_j, energy_wh, time_s, distance_m; phases.{takeoff,mission,return,landing}.{energy_j, time_s, "
      "distance_m}; items[] (seq, command, reached_s: [s] from the take-off command until the autopilot declares the item "
      "reached (NAV_RETURN_TO_LAUNCH: over home, before RTL_LOIT_TIME or RTL_LAND_DELAY and the descent; a take-off: at its "
      "altitude, for PX4 at its position), completed_s: when it moves on (after any hold; the return: landed), energy_j, "
      "time_s, distance_m); breakdown (energy by "
      "effect); battery (known, usable_left_at_landing, reserve_fraction, fits, energy_margin, usable_left_at_landing_with_margin, "
      "fits_with_margin, depleted, ends_in_air, verdict); autopilot; model; warnings[]; launch; wind; "
      "calibration_dispute and calibration_coverage (null when none).");
  cmd->callback([o] { runPredict(*o); });
}

}  // namespace wattswath::apps
