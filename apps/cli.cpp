#include "cli.hpp"

#include <iostream>

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

void progress(const std::string& message) { std::cerr << message << std::endl; }

}  // namespace wattswath::apps
