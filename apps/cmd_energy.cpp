// Energy commands of the closed-form model: hover, leg (vopt and turns come with issue 2).
#include <iostream>
#include <memory>

#include "cli.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;

namespace {

void registerHover(CLI::App& app) {
  struct Opts {
    std::string vehicle;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("hover", "Hover power of a vehicle (Marins et al. Eq. 4-5)");
  addVehicleOption(cmd, o->vehicle);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    const auto v = en::loadVehicle(o->vehicle);
    const double p0 = en::marinsRotorPowerW(v), ph = en::marinsHoverPowerW(v), pi = en::idealHoverPowerW(v);
    if (o->json) {
      printJson({{"vehicle", v.name},
                 {"p0_w", p0},
                 {"p_hover_w", ph},
                 {"p_ideal_momentum_w", pi},
                 {"total_efficiency", v.totalEfficiency()}});
    } else {
      std::cout << "vehicle: " << v.name << "\n"
                << "P0 (rotor power, Marins Eq. 4):        " << p0 << " W\n"
                << "P_hov (electrical, Eq. 5, eta " << v.totalEfficiency() << "): " << ph << " W\n"
                << "ideal momentum theory T^1.5/sqrt(2 rho A): " << pi << " W (Eq. 4 is twice this)\n";
    }
  });
}

}  // namespace

void registerEnergyCommands(CLI::App& app) { registerHover(app); }

}  // namespace wattswath::apps
