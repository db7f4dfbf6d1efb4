// wattswath: minimum-energy coverage planning for multirotor drones, and a physical energy
// model to check against flight logs. Each subcommand is registered from its own cmd_*.cpp.
#include <exception>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"wattswath: plan minimum-energy drone coverage flights and check the energy model against flight logs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "wattswath 0.1.0");
  wattswath::apps::registerEnergyCommands(app);
  wattswath::apps::registerReproduceCommand(app);
  wattswath::apps::registerLogCommands(app);
  wattswath::apps::registerLogFileCommands(app);
  wattswath::apps::registerAreaCommands(app);
  wattswath::apps::registerPlanCommand(app);
  wattswath::apps::registerEnduranceCommands(app);
  wattswath::apps::registerCoverageCommand(app);
  wattswath::apps::registerPredictCommand(app);
  wattswath::apps::registerCalibrateCommand(app);
  wattswath::apps::registerVehicleCommands(app);
  // With --json an error is also one JSON object on stdout, {"error": message}, so that a pipeline
  // reading stdout gets a document; the exit status says it failed either way.
  bool json = false;
  for (int k = 1; k < argc; ++k) json = json || std::string(argv[k]) == "--json";
  const auto jsonError = [&](const std::string& what) {
    if (json) std::cout << nlohmann::json{{"error", what}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) jsonError(e.what());
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "wattswath: error: " << e.what() << std::endl;
    jsonError(e.what());
    return 1;
  }
  return 0;
}
