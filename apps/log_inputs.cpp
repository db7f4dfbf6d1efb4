// Flight logs read for replay, diagnose and fit, each checked as a measurement first (issue 19).
#include "log_inputs.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <iostream>
#include <stdexcept>

#include "cli.hpp"
#include "wattswath/calibration/measurement_check.hpp"

namespace wattswath::apps {
using nlohmann::json;

json MeasurementReport::toJson() const { return {{"trust_power", trust_power}, {"logs", logs}}; }

void MeasurementReport::print() const {
  for (const auto& l : lines) std::cout << "note: " << l << "\n";
}

CLI::Option* addTrustPowerFlag(CLI::App* cmd, bool& trust) {
  return cmd->add_flag("--trust-power", trust,
                       "Use the measured power even when it cannot be a flying multirotor's (current stuck at 0 A or "
                       "constant, median power below 0.25 or above 8 times the vehicle's hover power from physics); "
                       "the output says so");
}

void checkLog(logs::FlightLog& log, const std::string& p, const energy::Vehicle& vehicle, MeasurementReport& report) {
  const auto c = calibration::checkMeasurement(log, vehicle);
  if (!c.position_problem.empty()) throw std::runtime_error(p + ": " + c.position_problem);
  if (!c.power_problem.empty() && !report.trust_power) {
    throw std::runtime_error(p + ": " + c.power_problem +
                             ". Refused: a model compared with this power says nothing; use --trust-power to use it anyway");
  }
  // What the reader skipped or found (a truncated file, samples out of time order, a log that ends in
  // the air): said with every number drawn from the log, not only by `log info`.
  const std::vector<std::string> reader_warnings = logs::readerWarnings(log);
  for (const auto& n : reader_warnings) report.lines.push_back(p + ": " + n);
  for (const auto& n : c.notes) report.lines.push_back(p + ": " + n);
  if (!c.power_problem.empty()) {
    report.lines.push_back(p + ": measured power used only because of --trust-power: " + c.power_problem);
  }
  auto num = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  report.logs.push_back({{"log", p},
                         {"power", c.power_problem.empty() ? "plausible" : "implausible, used because of --trust-power"},
                         {"power_problem", c.power_problem},
                         {"airborne_samples", c.airborne_samples},
                         {"median_power_w", num(c.median_power_w)},
                         {"median_current_a", num(c.median_current_a)},
                         {"hover_power_w", num(c.hover_power_w)},
                         {"position_cut_at_s", c.cut ? json(c.cut_at_s) : json(nullptr)},
                         {"reader_warnings", reader_warnings},
                         {"notes", c.notes}});
}

std::vector<calibration::PreparedLog> readCheckedLogs(const std::vector<std::string>& paths,
                                                      const logs::LogReadOptions& read,
                                                      const energy::Vehicle& vehicle, MeasurementReport& report) {
  std::vector<calibration::PreparedLog> out;
  for (const auto& p : paths) {
    progress("reading " + p);
    auto log = logs::readFlightLog(p, read);
    checkLog(log, p, vehicle, report);
    out.push_back(calibration::prepareLog(log));
  }
  return out;
}

void checkDistinctLogs(const std::vector<std::string>& paths, std::size_t test_from) {
  namespace fs = std::filesystem;
  // Only files of one size are read and compared: the logs are read again for use right after.
  const auto bytesOf = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  std::vector<std::uintmax_t> size;
  for (const auto& p : paths) {
    std::error_code ec;
    size.push_back(fs::file_size(p, ec));
    if (ec) size.back() = static_cast<std::uintmax_t>(-1);  // unreadable: the reader names it
  }
  for (std::size_t a = 0; a < paths.size(); ++a) {
    for (std::size_t b = a + 1; b < paths.size(); ++b) {
      if (size[a] != size[b] || size[a] == static_cast<std::uintmax_t>(-1) || bytesOf(paths[a]) != bytesOf(paths[b])) continue;
      const bool test = b >= test_from && a < test_from;
      throw std::runtime_error(paths[a] + " and " + paths[b] + " are the same file" +
                               (paths[a] == paths[b] ? "" : " (identical bytes)") + ": " +
                               (test ? "a test log must be a flight the fit did not see"
                                     : "one flight given twice would be counted twice (and held out against itself)") +
                               "; give each flight once");
    }
  }
}

MissionLog readMissionLog(const std::string& path, const logs::LogReadOptions& read) {
  logs::LogReadOptions whole = read;
  whole.max_gap_s = std::numeric_limits<double>::infinity();  // checked on the part kept, below
  MissionLog out;
  out.log = logs::readFlightLog(path, whole);
  const bool user = out.log.metadata.count("window") != 0;
  const logs::MissionCut cut = logs::cutToMission(out.log);
  logs::checkSampleGaps(out.log, read.max_gap_s);
  out.note = cut.note;
  const bool cut_here = !cut.source.empty();
  out.window = {{"from_s", cut_here ? cut.from_s : out.log.samples.front().t},
                {"to_s", cut_here ? cut.to_s : out.log.samples.back().t},
                {"source", cut_here ? cut.source : user ? "--from / --to / --airborne" : "the CSV as given"},
                {"note", out.note}};
  return out;
}

}  // namespace wattswath::apps
