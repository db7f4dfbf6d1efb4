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

std::string formatNumber(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

void progress(const std::string& message) { std::cerr << message << std::endl; }

void writeTextFileAtomic(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
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

}  // namespace wattswath::apps
