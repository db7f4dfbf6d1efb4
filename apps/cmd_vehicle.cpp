// `wattswath vehicle params`: the autopilot's firmware and flight parameters read from a log of the
// vehicle and written into a copy of a vehicle file, as its `autopilot` object (data/README.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/io/text_file.hpp"
#include "wattswath/logs/airframe.hpp"
#include "wattswath/logs/parameters.hpp"

namespace wattswath::apps {

namespace {

using OrderedJson = nlohmann::ordered_json;

struct ParamsOptions {
  std::string log, vehicle, out;
  logs::LogReadOptions read;
  bool force = false, json = false, all = false;
};

// A parameter value as JSON: an integer when whole; else the shortest decimal that reads back to the
// same 32-bit float (ArduPilot logs floats: 0.15000000596 is written 0.15), else the double.
OrderedJson parameterValue(double v) {
  if (std::round(v) == v && std::fabs(v) < 9e15) return static_cast<long long>(v);
  const float f = static_cast<float>(v);
  if (static_cast<double>(f) != v) return v;
  for (int digits = 6; digits <= 9; ++digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
    if (std::strtof(text, nullptr) == f) return std::strtod(text, nullptr);
  }
  return v;
}

OrderedJson parameterObject(const std::map<std::string, double>& parameters) {
  OrderedJson j = OrderedJson::object();
  for (const auto& [name, value] : parameters) j[name] = parameterValue(value);
  return j;
}

// The `autopilot` object: firmware, version (when the log says) and parameters.
OrderedJson autopilotObject(const logs::AutopilotParameters& p, const std::map<std::string, double>& kept) {
  OrderedJson a = {{"firmware", p.firmware.family}};
  if (!p.firmware.version.empty()) a["version"] = p.firmware.version;
  a["parameters"] = parameterObject(kept);
  return a;
}

std::string readText(const std::string& path) {
  return io::readTextFile(path, {energy::kMaxVehicleFileBytes, "vehicle files", ""});  // a runtime_error naming the file
}

// BASE's JSON text (validated as a vehicle first, so every error names the file and field) with
// its `autopilot` object replaced; the other fields keep their order and text.
// A calibration in BASE (extensions.calibration) was fitted with BASE's autopilot parameters, so it
// is left out (`notes` says so); a BASE airframe is kept unless the log determines one, and
// `base_airframe` says whether BASE had one.
std::string vehicleWithAutopilot(const std::string& base_path, const OrderedJson& autopilot, const OrderedJson& airframe,
                                 std::vector<std::string>& notes, bool& base_airframe) {
  energy::loadVehicle(base_path);
  OrderedJson j = OrderedJson::parse(readText(base_path));
  base_airframe = j.contains("extensions") && j["extensions"].is_object() && j["extensions"].contains("airframe");
  j["autopilot"] = autopilot;
  if (j.contains("extensions") && j["extensions"].is_object() && j["extensions"].contains("calibration")) {
    j["extensions"].erase("calibration");
    notes.push_back(base_path + "'s calibration (extensions.calibration) was fitted with its own autopilot parameters, so "
                    "it is left out of the file written; calibrate again with logs of this vehicle's missions");
  }
  if (!airframe.is_null()) j["extensions"]["airframe"] = airframe;
  return j.dump(2) + "\n";
}

// The airframe identified from the log (DataFlash only): the extension object with what the log
// determines (drag, response), or null when it determines neither (said in words).
OrderedJson airframeObject(const logs::AirframeEstimate& a, const std::string& log) {
  const auto& d = a.drag;
  const auto& r = a.response;
  if (!d.determined && !r.determined) return nullptr;
  OrderedJson j = OrderedJson::object();
  std::string source = "identified from " + log + " (";
  if (d.determined) {
    j["drag_linear_per_s"] = d.drag_linear_per_s;
    j["drag_quadratic_per_m"] = d.drag_quadratic_per_m;
    source += "drag: " + std::to_string(d.samples) + " samples, R^2 " + std::to_string(d.r2).substr(0, 5) + ", velocity " +
              d.velocity_source;
  }
  if (r.determined) {
    j["response_s"] = r.response_s;
    source += std::string(d.determined ? "; " : "") + "response: " + std::to_string(r.samples) + " samples, R^2 " +
              std::to_string(r.r2).substr(0, 5) + ", PSCN/PSCE";
  }
  j["source"] = source + ")";
  return j;
}

logs::AirframeEstimate identifyAirframe(const ParamsOptions& o) {
  try {
    return logs::estimateAirframe(o.log, o.read);
  } catch (const std::exception& e) {
    logs::AirframeEstimate none;
    none.drag.reason = none.response.reason = e.what();
    return none;
  }
}

// The airframe part of `vehicle params --json`.
OrderedJson airframeJson(const logs::AirframeEstimate& a) {
  const auto& d = a.drag;
  const auto& r = a.response;
  return {{"determined", d.determined},
          {"reason", d.reason},
          {"drag_linear_per_s", d.determined ? OrderedJson(d.drag_linear_per_s) : OrderedJson()},
          {"drag_quadratic_per_m", d.determined ? OrderedJson(d.drag_quadratic_per_m) : OrderedJson()},
          {"r2", d.r2},
          {"samples", d.samples},
          {"response", {{"determined", r.determined},
                        {"reason", r.reason},
                        {"response_s", r.determined ? OrderedJson(r.response_s) : OrderedJson()},
                        {"r2", r.r2},
                        {"samples", r.samples}}}};
}

void warnAbout(const logs::AutopilotParameters& p) {
  const std::string& family = p.firmware.family;
  if (family != "ArduCopter" && family != "PX4")
    progress("warning: " + p.source + ": firmware " + family + " (" + (p.firmware_text.empty() ? "no version text" : p.firmware_text) +
             "); the mission flight models know ArduCopter and PX4 only");
  for (const auto& w : p.warnings) progress("warning: " + w);
  if (!p.changed_after_takeoff.empty()) {
    std::string names;
    for (const auto& n : p.changed_after_takeoff) names += (names.empty() ? "" : ", ") + n;
    progress("note: changed after take-off (the value before take-off is kept): " + names);
  }
}

void runParams(const ParamsOptions& o) {
  checkWritable(o.out, o.force, {o.log, o.vehicle});
  energy::loadVehicle(o.vehicle);  // a bad BASE fails before the (possibly large) log is read
  const auto p = logs::readAutopilotParameters(o.log, o.read);
  const auto kept = o.all ? p.parameters : logs::flightBehaviourParameters(p);
  const auto airframe = identifyAirframe(o);
  const auto& drag = airframe.drag;
  std::vector<std::string> notes;
  bool base_airframe = false;  // BASE has an extensions.airframe (predict flies with it)
  const std::string text =
      vehicleWithAutopilot(o.vehicle, autopilotObject(p, kept), airframeObject(airframe, o.log), notes, base_airframe);
  energy::parseVehicle(text, o.out);  // what is written reads back
  writeTextFileAtomic(o.out, text);
  warnAbout(p);
  if (p.firmware.version.empty()) {
    notes.push_back(p.source + ": the log does not say the firmware version, so the file gives none and predict flies it as " +
                    std::string(p.firmware.family == "PX4" ? "PX4 1.14" : "ArduCopter 4.5 (S-curve model)") +
                    ", saying so; set autopilot.version by hand");
  }
  const std::string drag_fallback = base_airframe ? " (predict uses " + o.vehicle + "'s extensions.airframe, kept in the file)"
                                                  : " (predict uses the vehicle's drag area)";
  if (o.json) {
    printJson({{"log", o.log},
               {"out", o.out},
               {"firmware", p.firmware.family},
               {"version", p.firmware.version},
               {"firmware_text", p.firmware_text},
               {"vehicle_type", p.vehicle_type},
               {"parameter_count", p.parameters.size()},
               {"kept_count", kept.size()},
               {"selection", p.selection},
               {"changed_after_takeoff", p.changed_after_takeoff},
               {"kept", parameterObject(kept)},
               {"airframe", airframeJson(airframe)},
               {"notes", notes}});
  } else {
    progress("wrote " + o.out + ": " + p.firmware.family + (p.firmware.version.empty() ? "" : " " + p.firmware.version) +
             ", " + std::to_string(kept.size()) + " of the log's " + std::to_string(p.parameters.size()) +
             " parameters (" + (o.all ? "all" : "flight behaviour") + ")");
    progress(drag.determined ? "airframe drag (extensions.airframe): " + std::to_string(drag.drag_linear_per_s) + " 1/s x v + " +
                                   std::to_string(drag.drag_quadratic_per_m) + " 1/m x v^2, R^2 " + std::to_string(drag.r2)
                             : "airframe drag not determined by this log: " + drag.reason + drag_fallback);
    const auto& r = airframe.response;
    progress(r.determined ? "airframe response (extensions.airframe.response_s): " + std::to_string(r.response_s) +
                                " s lag of the acceleration behind the position controller's, R^2 " + std::to_string(r.r2)
                          : "airframe response not determined by this log: " + r.reason +
                                (p.firmware.family == "PX4"
                                     ? std::string(" (predict's PX4 model follows its jerk-limited setpoints without a lag)")
                                     : base_airframe ? drag_fallback
                                                     : std::string(" (predict takes the attitude time constant, ArduCopter ATC_INPUT_TC)")));
    for (const auto& n : notes) progress("note: " + n);
  }
}

constexpr const char* kParamsHelp = R"(
Reads the autopilot's firmware (family and version) and parameters from a log of the vehicle
(ArduPilot DataFlash .bin: MSG/VER text and PARM messages; PX4 .ulg: ver_sw_release and the 'P'
parameters) and writes BASE, unchanged otherwise, with an `autopilot` object:
  {"firmware": "ArduCopter", "version": "4.7.0-dev", "parameters": {"WPNAV_SPEED": 1000, ...}}
Values are in the autopilot's own units (WPNAV_SPEED cm/s, RTL_ALT cm, MPC_XY_CRUISE m/s).
A parameter logged several times keeps its last value before take-off (ArduPilot).
Kept by default, the parameters that shape how the vehicle flies a mission:
  ArduPilot: WPNAV_*, PSC_JERK_*, PSC_POSXY_*, PSC_VELXY_*, PSC_POSZ_*, PSC_VELZ_*, PSC_ACCZ_*, PSC_ANGLE_MAX,
    ANGLE_MAX, ATC_INPUT_TC, ATC_ACCEL_*_MAX, ATC_RATE_*_MAX, ATC_SLEW_YAW, WP_YAW_BEHAVIOR, RTL_*, LAND_*,
    PILOT_SPEED_UP/DN, PILOT_TKOFF_ALT, TKOFF_*, WP_NAVALT_MIN, LOIT_*, MOT_THST_HOVER, MOT_SPOOL_TIME
    (3.x: POS_XY_P, POS_Z_P, VEL_XY_*, VEL_Z_*, ACCEL_Z_*, RC_FEEL_RP, PILOT_VELZ_MAX, PILOT_ACCEL_Z;
    3.2: THR_MID, THR_ALT_P, THR_RATE_P, THR_ACCEL_P/I)
  PX4: MPC_* (incl. MPC_TKO_*, MPC_LAND_*), NAV_ACC_RAD, NAV_MC_ALT_RAD, RTL_*, MIS_*
--all keeps every parameter. Parameters left out take the firmware's documented defaults.
From a DataFlash log it also identifies the airframe's horizontal drag, c1 v + c2 v^2, from the
lean angle (ATT) against the EKF velocity, and writes it as `extensions.airframe` when the log
determines it (enough flight above 3 m/s, R^2 >= 0.8); the S-curve model's vehicle flies against
it (docs/autopilots.md, "Tracking error"). Otherwise it says why and predict uses the drag area.
From ArduCopter 4.5+ logs it also identifies the airframe's response: the first-order lag of the
acceleration its lean angles give behind the position controller's target (PSCN/PSCE), written
as `extensions.airframe.response_s` when the lag explains at least 80 % of the variance; else
predict takes the attitude time constant (ATC_INPUT_TC).
Example: wattswath vehicle params flight.bin --vehicle data/vehicles/iris.json --out my-iris.json
)";

void registerParams(CLI::App& vehicle_cmd) {
  auto o = std::make_shared<ParamsOptions>();
  auto* cmd = vehicle_cmd.add_subcommand("params", "Write a vehicle file with the autopilot firmware and flight parameters of a log");
  cmd->footer(kParamsHelp);
  cmd->add_option("LOG", o->log, "Log of the vehicle: ArduPilot DataFlash .bin or PX4 .ulg")->required()->check(CLI::ExistingFile);
  addVehicleOption(cmd, o->vehicle)->description("Vehicle file to start from (JSON, e.g. data/vehicles/iris.json)");
  cmd->add_option("--out", o->out, "Vehicle file to write (JSON): BASE with the log's `autopilot` object")->required();
  cmd->add_flag("--all", o->all, "Keep every parameter of the log, not only the flight-behaviour ones");
  cmd->add_flag("--lenient", o->read.lenient,
                "Read past corrupt parts of the log (each skip is a warning); a cut final record of a .bin is always accepted");
  addMaxLogSizeOption(cmd, o->read);
  addForceFlag(cmd, o->force);
  addJsonFlag(cmd, o->json)->description(
      "Print a summary on stdout: {firmware, version, parameter_count, kept: {...}, ...}");
  cmd->callback([o]() { runParams(*o); });
}

}  // namespace

void registerVehicleCommands(CLI::App& app) {
  auto* vehicle_cmd = app.add_subcommand("vehicle", "Vehicle files: fill in the autopilot parameters from a log");
  vehicle_cmd->require_subcommand(1);
  registerParams(*vehicle_cmd);
}

}  // namespace wattswath::apps
