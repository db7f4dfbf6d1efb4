// `wattswath log info` and `wattswath log convert`: native autopilot logs (ArduPilot .bin, PX4 .ulg)
// and canonical CSV logs, summarised or converted to the canonical CSV.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/log_io.hpp"

namespace wattswath::apps {

namespace {

std::string meta(const logs::FlightLog& log, const std::string& key) {
  auto it = log.metadata.find(key);
  return it == log.metadata.end() ? std::string() : it->second;
}

double metaNumber(const logs::FlightLog& log, const std::string& key) {
  try {
    return std::stod(meta(log, key));
  } catch (const std::exception&) {
    return std::nan("");
  }
}

// The rate the reader recorded under `key` [Hz], else the samples' own mean rate (a CSV has one clock).
double rateOf(const logs::FlightLog& log, const std::string& key) {
  const double r = metaNumber(log, key);
  if (std::isfinite(r)) return r;
  return log.samples.size() > 1 && log.duration() > 0.0 ? static_cast<double>(log.samples.size() - 1) / log.duration()
                                                        : std::nan("");
}

struct Range {
  double min = INFINITY, max = -INFINITY;
  std::vector<double> air;  // values inside airborne windows
};

bool airborne(const logs::FlightLog& log, double t) {
  return std::any_of(log.airborne.begin(), log.airborne.end(),
                     [t](const logs::TimeWindow& w) { return w.contains(t); });
}

nlohmann::json rangeJson(Range r) {
  // No finite value (a current that is not measured): null, not an infinite "number".
  const bool any = std::isfinite(r.min) && std::isfinite(r.max);
  nlohmann::json j = {{"min", any ? nlohmann::json(r.min) : nlohmann::json(nullptr)},
                      {"max", any ? nlohmann::json(r.max) : nlohmann::json(nullptr)}};
  if (!r.air.empty()) {
    std::nth_element(r.air.begin(), r.air.begin() + static_cast<std::ptrdiff_t>(r.air.size() / 2), r.air.end());
    j["median_airborne"] = r.air[r.air.size() / 2];
  } else {
    j["median_airborne"] = nullptr;
  }
  return j;
}

// Values no multirotor battery gives, with the unit mistake that usually makes them (the readers
// take volts and amperes; a CSV in mV or mA reads 1000 times too large).
std::vector<std::string> plausibility(const nlohmann::json& j) {
  std::vector<std::string> out;
  const auto& i = j["current_a"]["median_airborne"];
  if (i.is_number() && i.get<double>() > 500.0) {
    out.push_back("the median current in the air, " + fixedText(i.get<double>(), 0) +
                  " A, is more than a multirotor battery gives (a few to a few hundred A): is current_a logged in mA?");
  }
  const auto& v = j["voltage_v"]["max"];
  if (v.is_number() && v.get<double>() > 100.0) {
    out.push_back("the voltage reaches " + fixedText(v.get<double>(), 0) +
                  " V, more than a multirotor battery (up to about 60 V for 14S): is voltage_v logged in mV?");
  }
  return out;
}

nlohmann::json infoJson(const logs::FlightLog& log) {
  Range v, i, p;
  for (const auto& s : log.samples) {
    const bool air = airborne(log, s.t);
    auto add = [air](Range& r, double x) {
      if (!std::isfinite(x)) return;
      r.min = std::min(r.min, x);
      r.max = std::max(r.max, x);
      if (air) r.air.push_back(x);
    };
    add(v, s.voltage);
    add(i, s.current);
    add(p, s.power);
  }
  nlohmann::json windows = nlohmann::json::array();
  double air_total = 0.0;
  for (const auto& w : log.airborne) {
    windows.push_back({{"begin_s", w.begin}, {"end_s", w.end}, {"duration_s", w.end - w.begin}});
    air_total += w.end - w.begin;
  }
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& e : log.events)
    if (e.kind == "mode") modes.push_back({{"t_s", e.t}, {"mode", e.text}});
  nlohmann::json j = {
      {"file", log.source},
      {"format", log.format},
      {"firmware", meta(log, "firmware")},
      {"vehicle", meta(log, "vehicle")},
      {"samples", log.samples.size()},
      {"start_s", log.samples.empty() ? 0.0 : log.samples.front().t},
      {"end_s", log.samples.empty() ? 0.0 : log.samples.back().t},
      {"duration_s", log.duration()},
      {"airborne_windows", windows},
      {"airborne_s", air_total},
      {"airborne_source", meta(log, "airborne_source")},
      {"battery_source", meta(log, "battery_source")},
      {"position_source", meta(log, "position_source")},
      {"sample_rates_hz", {{"battery", rateOf(log, "battery_rate_hz")}, {"position", rateOf(log, "position_rate_hz")}}},
      {"voltage_v", rangeJson(v)},
      {"current_a", rangeJson(i)},
      {"power_w", rangeJson(p)},
      {"modes", modes},
      {"events", log.events.size()},
      {"warnings", meta(log, "warnings")},
  };
  j["plausibility"] = plausibility(j);
  return j;
}

// `x` [unit] with `decimals`, or "not logged" when null.
std::string shown(const nlohmann::json& x, int decimals, const std::string& unit) {
  if (!x.is_number() || !std::isfinite(x.get<double>())) return "not logged";
  return fixedText(x.get<double>(), decimals) + (unit.empty() ? "" : " " + unit);
}

// One line "name: min to max unit[, median in the air m unit]", or "name: not logged".
std::string rangeText(const nlohmann::json& r, int decimals, const std::string& unit) {
  if (!r["min"].is_number()) return "not logged";
  std::string t = shown(r["min"], decimals, "") + " to " + shown(r["max"], decimals, unit);
  if (r["median_airborne"].is_number()) t += ", median in the air " + shown(r["median_airborne"], decimals, unit);
  return t;
}

// A field the log may not have (a CSV names no firmware, no sources): its text or "not in the log".
std::string orNotInLog(const std::string& s) { return s.empty() ? "not in the log" : s; }

void printInfo(const logs::FlightLog& log, const nlohmann::json& j) {
  const auto source = [&](const std::string& name, const std::string& rate) {
    const std::string src = j[name].get<std::string>();
    const std::string hz = shown(j["sample_rates_hz"][rate], 2, "Hz");
    return (src.empty() ? std::string("the log's own samples") : src) + ", " + hz;
  };
  std::cout << "file:      " << log.source << " (" << log.format << ")\n"
            << "firmware:  " << orNotInLog(j["firmware"].get<std::string>()) << "\n"
            << "vehicle:   " << orNotInLog(j["vehicle"].get<std::string>()) << "\n"
            << "span:      " << fixedText(j["start_s"].get<double>(), 2) << " s to " << fixedText(j["end_s"].get<double>(), 2)
            << " s (" << fixedText(log.duration(), 1) << " s, " << log.samples.size() << " samples)\n"
            << "battery:   " << source("battery_source", "battery") << "\n"
            << "position:  " << source("position_source", "position") << "\n"
            << "voltage:   " << rangeText(j["voltage_v"], 2, "V") << "\n"
            << "current:   " << rangeText(j["current_a"], 2, "A") << "\n"
            << "power:     " << rangeText(j["power_w"], 1, "W") << "\n";
    const std::string how = j["airborne_source"].get<std::string>();
  std::cout << "airborne" << (how.empty() ? std::string() : " (" + how + ")") << ": "
            << (log.airborne.empty() ? "no window found" : fixedText(j["airborne_s"].get<double>(), 1) + " s in all") << "\n";
  for (const auto& w : log.airborne)
    std::cout << "  " << fixedText(w.begin, 2) << " s to " << fixedText(w.end, 2) << " s (" << fixedText(w.end - w.begin, 1) << " s)\n";
  for (const auto& m : j["modes"])
    std::cout << "mode at " << fixedText(m["t_s"].get<double>(), 2) << " s: " << m["mode"].get<std::string>() << "\n";
  if (!meta(log, "warnings").empty()) std::cout << "warnings:  " << meta(log, "warnings") << "\n";
  for (const auto& n : j["plausibility"]) std::cout << "check:     " << n.get<std::string>() << "\n";
}

void registerInfo(CLI::App& log_cmd) {
  struct Opts {
    std::string file;
    logs::LogReadOptions read;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = log_cmd.add_subcommand("info", "Summarise a flight log (.bin, .ulg or canonical .csv)");
  cmd->add_option("FILE", o->file, "Flight log: ArduPilot DataFlash .bin, PX4 .ulg or canonical CSV")
      ->required()
      ->check(CLI::ExistingFile);
  addLogReadOptions(cmd, o->read);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    const auto log = logs::readFlightLog(o->file, o->read);
    const auto j = infoJson(log);
    if (o->json) {
      printJson(j);
      return;
    }
    printInfo(log, j);
  });
}

void registerConvert(CLI::App& log_cmd) {
  struct Opts {
    std::string file, out;
    logs::LogReadOptions read;
    bool json = false, force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = log_cmd.add_subcommand("convert", "Convert a flight log (.bin, .ulg, .csv) to the canonical CSV");
  cmd->add_option("FILE", o->file, "Flight log: ArduPilot DataFlash .bin, PX4 .ulg or canonical CSV")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out, "Canonical CSV to write")->required();
  addLogReadOptions(cmd, o->read);
  addForceFlag(cmd, o->force);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    checkWritable(o->out, o->force, {o->file});
    auto log = logs::readFlightLog(o->file, o->read);
    std::string windows;
    for (const auto& w : log.airborne)
      windows += (windows.empty() ? "" : "; ") + std::to_string(w.begin) + "-" + std::to_string(w.end);
    if (!windows.empty()) log.metadata["airborne_windows_s"] = windows;
    writeTextFileAtomic(o->out, logs::writeCsvLog(log));
    if (o->json) {
      printJson({{"file", o->file},
                 {"out", o->out},
                 {"format", log.format},
                 {"samples", log.samples.size()},
                 {"start_s", log.samples.front().t},
                 {"end_s", log.samples.back().t},
                 {"battery_source", meta(log, "battery_source")},
                 {"position_source", meta(log, "position_source")}});
    } else {
      progress("wrote " + o->out + ": " + std::to_string(log.samples.size()) + " samples from " + o->file);
    }
  });
}

}  // namespace

void registerLogFileCommands(CLI::App& app) {
  auto* log_cmd = app.add_subcommand("log", "Flight logs: inspect and convert ArduPilot .bin, PX4 .ulg and CSV logs");
  log_cmd->require_subcommand(1);
  registerInfo(*log_cmd);
  registerConvert(*log_cmd);
}

}  // namespace wattswath::apps
