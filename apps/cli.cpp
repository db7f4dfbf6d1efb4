#include "cli.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace wattswath::apps {

void printJson(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

CLI::Option* addVehicleOption(CLI::App* cmd, std::string& path) {
  return cmd->add_option("--vehicle", path, "Vehicle description (JSON, e.g. data/vehicles/iris.json)")
      ->required()
      ->check(CLI::ExistingFile);
}

CLI::Option* addJsonFlag(CLI::App* cmd, bool& json) {
  return cmd->add_flag("--json", json, "Print one JSON object on stdout instead of text");
}

void addAreaSelectOptions(CLI::App* cmd, std::string& layer, std::string& where) {
  cmd->add_option("--layer", layer, "GIS area files (GeoPackage, Shapefile, KMZ, GPX, ...): read only this layer");
  cmd->add_option("--where", where, "GIS area files: read only features matching this OGR SQL filter, e.g. \"name = 'field 3'\"");
}

std::string formatNumber(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

void addLogReadOptions(CLI::App* cmd, logs::LogReadOptions& o) {
  cmd->add_option("--from", o.from_s, "Keep samples from this time on [s, log clock: autopilot boot time]");
  cmd->add_option("--to", o.to_s, "Keep samples up to this time [s, log clock]");
  cmd->add_flag("--airborne", o.airborne_only, "Keep only the airborne part (first take-off to last landing)");
  cmd->add_flag("--lenient", o.lenient,
                "Read past corrupt or truncated parts of .bin/.ulg files (each skip is listed as a warning)");
  cmd->add_option("--battery-instance", o.battery_instance,
                  "Battery instance to use (default: the first with a voltage above 1 V)")
      ->check(CLI::Range(0, 255));
  cmd->add_option("--position-source", o.position_source,
                  "Position message/topic: XKF1, NKF1, NKF6, EKF1 (.bin) or vehicle_local_position (.ulg)");
  cmd->add_option("--airborne-current", o.airborne.current_threshold_a,
                  "Current above which the vehicle counts as flying where no take-off/landing is logged [A]")
      ->check(CLI::PositiveNumber);
}

void progress(const std::string& message) { std::cerr << message << std::endl; }

void writeTextFileAtomic(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  // Renaming over a device, FIFO or folder would replace it with a plain file (seen: /dev/null).
  if (fs::exists(fs::symlink_status(target, ec)) && !fs::is_regular_file(fs::symlink_status(target, ec))) {
    throw std::runtime_error(path + ": exists and is not a regular file; expected a file path to write");
  }
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const fs::path tmp = target.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write (" + tmp.string() + " could not be created)");
    out << text;
    out.flush();
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      throw std::runtime_error(path + ": write failed");
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error(path + ": cannot rename temporary file into place");
  }
}

CLI::Option* addForceFlag(CLI::App* cmd, bool& force) {
  return cmd->add_flag("--force", force, "Replace output files that already exist");
}

void checkWritable(const std::string& path, bool force, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  if (path.empty()) throw std::runtime_error("output path is empty, expected a file name");
  if (fs::is_directory(target, ec)) throw std::runtime_error(path + ": is a folder, expected an output file name");
  if (!fs::exists(target, ec)) return;
  if (!fs::is_regular_file(target, ec)) throw std::runtime_error(path + ": exists and is not a regular file");
  for (const auto& in : inputs) {
    if (fs::equivalent(target, fs::path(in), ec)) {
      throw std::runtime_error(path + ": is also an input file; refusing to overwrite an input, choose another output");
    }
  }
  if (!force) throw std::runtime_error(path + ": already exists; use --force to replace it");
}

}  // namespace wattswath::apps
