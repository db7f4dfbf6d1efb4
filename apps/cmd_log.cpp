// `wattswath log info` and `wattswath log convert`: native autopilot logs (ArduPilot .bin, PX4 .ulg)
// and canonical CSV logs, summarised or converted to the canonical CSV.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

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

struct Range {
  double min = INFINITY, max = -INFINITY;
  std::vector<double> air;  // values inside airborne windows
};

bool airborne(const logs::FlightLog& log, double t) {
  return std::any_of(log.airborne.begin(), log.airborne.end(),
                     [t](const logs::TimeWindow& w) { return t >= w.begin && t <= w.end; });
}

nlohmann::json rangeJson(Range r) {
  nlohmann::json j = {{"min", r.min}, {"max", r.max}};
  if (!r.air.empty()) {
    std::nth_element(r.air.begin(), r.air.begin() + static_cast<std::ptrdiff_t>(r.air.size() / 2), r.air.end());
    j["median_airborne"] = r.air[r.air.size() / 2];
  } else {
    j["median_airborne"] = nullptr;
  }
  return j;
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
      {"sample_rates_hz", {{"battery", metaNumber(log, "battery_rate_hz")}, {"position", metaNumber(log, "position_rate_hz")}}},
      {"voltage_v", rangeJson(v)},
      {"current_a", rangeJson(i)},
      {"power_w", rangeJson(p)},
      {"modes", modes},
      {"events", log.events.size()},
      {"warnings", meta(log, "warnings")},
  };
  return j;
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
    std::cout << "file:      " << log.source << " (" << log.format << ")\n"
              << "firmware:  " << j["firmware"].get<std::string>() << "\n"
              << "vehicle:   " << j["vehicle"].get<std::string>() << "\n"
              << "span:      " << j["start_s"] << " s to " << j["end_s"] << " s (" << log.duration() << " s, "
              << log.samples.size() << " samples)\n"
              << "battery:   " << j["battery_source"].get<std::string>() << ", " << j["sample_rates_hz"]["battery"] << " Hz\n"
              << "position:  " << j["position_source"].get<std::string>() << ", " << j["sample_rates_hz"]["position"] << " Hz\n"
              << "voltage:   " << j["voltage_v"]["min"] << " to " << j["voltage_v"]["max"] << " V\n"
              << "current:   " << j["current_a"]["min"] << " to " << j["current_a"]["max"] << " A, median in the air "
              << j["current_a"]["median_airborne"] << " A\n"
              << "airborne (" << j["airborne_source"].get<std::string>() << "):\n";
    for (const auto& w : log.airborne) std::cout << "  " << w.begin << " s to " << w.end << " s (" << w.end - w.begin << " s)\n";
    for (const auto& m : j["modes"]) std::cout << "mode at " << m["t_s"] << " s: " << m["mode"].get<std::string>() << "\n";
    if (!meta(log, "warnings").empty()) std::cout << "warnings:  " << meta(log, "warnings") << "\n";
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
