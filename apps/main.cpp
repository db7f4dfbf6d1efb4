// wattswath: minimum-energy coverage planning for multirotor drones, and a physical energy
// model to check against flight logs. Each subcommand is registered from its own cmd_*.cpp.
#include <exception>
#include <iostream>

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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "wattswath: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
