// `wattswath endurance` (Hwang et al. forward flight + battery) and `wattswath models` (every
// power model side by side).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/forward_flight.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/peers.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;

std::vector<double> parseSpeedList(const std::string& text) {
  auto num = [&](const std::string& s) {
    size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || !std::isfinite(x) || x < 0.0) {
      throw std::invalid_argument("--speed '" + text + "': '" + s + "' is not a speed >= 0 in m/s");
    }
    return x;
  };
  const auto c1 = text.find(':');
  if (c1 == std::string::npos) return {num(text)};
  const auto c2 = text.find(':', c1 + 1);
  if (c2 == std::string::npos) throw std::invalid_argument("--speed '" + text + "': expected U or FROM:TO:STEP");
  const double from = num(text.substr(0, c1)), to = num(text.substr(c1 + 1, c2 - c1 - 1));
  const double step = num(text.substr(c2 + 1));
  if (!(step > 0.0) || to < from || (to - from) / step > 10000.0) {
    throw std::invalid_argument("--speed '" + text + "': expected FROM <= TO and 0 < STEP, at most 10000 steps");
  }
  std::vector<double> out;
  for (int k = 0; from + k * step <= to + 1e-9 * step; ++k) out.push_back(from + k * step);
  return out;
}

namespace {

nlohmann::json flightJson(const en::ForwardFlightState& s, const en::EnduranceResult& r) {
  return {{"speed_mps", s.speed_mps},
          {"endurance_min", r.endurance_s / 60.0},
          {"power_w", s.electrical_power_w},
          {"thrust_n", s.thrust_n},
          {"induced_velocity_mps", s.induced_velocity_mps},
          {"tilt_deg", s.tilt_rad * 180.0 / M_PI},
          {"drag_n", s.drag_n},
          {"rotor_power_w", s.rotor_power_w},
          {"efficiency", s.efficiency},
          {"energy_wh", r.energy_j / 3600.0}};
}

// The speed of longest endurance between the neighbours of the best of `speeds` (`best_u`), with its
// endurance [min] (the one minimiser of the energy library, on minus the endurance): the best of a
// coarse list is a grid point, not the optimum.
std::pair<double, double> refineBest(const en::ForwardFlightParameters& params, const en::Battery& battery, double dt,
                                     const std::vector<double>& speeds, double best_u) {
  const auto minutes = [&](double u) {
    en::DischargeSettings ds;
    ds.dt_s = dt;
    ds.keep_series = false;
    return en::endurance(battery, en::forwardFlight(params, u).electrical_power_w, ds).endurance_s / 60.0;
  };
  std::vector<double> sorted = speeds;
  std::sort(sorted.begin(), sorted.end());
  const auto at = std::find(sorted.begin(), sorted.end(), best_u);
  const double lo = at == sorted.begin() ? *at : *(at - 1), hi = at + 1 == sorted.end() ? *at : *(at + 1);
  const double at_best = minutes(best_u);
  if (!(hi > lo)) return {best_u, at_best};
  en::CruiseSpeedSettings search;
  search.speed_tolerance = 1e-4;
  const double u = en::minimiseOnInterval([&](double x) { return -minutes(x); }, lo, hi, search);
  const double t = minutes(u);
  return t > at_best ? std::make_pair(u, t) : std::make_pair(best_u, at_best);
}

// What the endurance table cannot show: where the efficiency comes from, a best speed at the end of
// the range given (the best may lie beyond it), speeds above the vehicle's limit.
std::vector<std::string> enduranceNotes(const en::ForwardFlightParameters& params, const en::Vehicle& v,
                                        const std::vector<double>& speeds, double best_u) {
  std::vector<std::string> notes;
  if (!params.efficiency_note.empty()) notes.push_back(params.efficiency_note);
  const auto [lo_it, hi_it] = std::minmax_element(speeds.begin(), speeds.end());
  const double lo = *lo_it, hi = *hi_it;
  if (speeds.size() > 1 && ((best_u == lo && lo > 0.0) || best_u == hi)) {
    std::ostringstream os;
    os << "the longest endurance is at the " << (best_u == lo ? "lowest" : "highest") << " speed given (" << best_u
       << " m/s): the best speed may lie beyond the range; widen --speed";
    notes.push_back(os.str());
  }
  if (hi > v.max_speed_mps) {
    std::ostringstream os;
    os << "speeds above the vehicle's max_speed_mps (" << v.max_speed_mps << " m/s) are computed but cannot be flown";
    notes.push_back(os.str());
  }
  return notes;
}

void registerEndurance(CLI::App& app) {
  struct Opts {
    std::string vehicle, speed = "0", battery;
    double payload = 0.0, dt = 1.0;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "endurance", "Endurance in steady level flight: Hwang et al. forward-flight power (Eq. 1-8) and battery (Eq. 9-15)");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--speed", o->speed, "Speed U [m/s], or a range FROM:TO:STEP (then: the curve and the best speed)")
      ->capture_default_str();
  cmd->add_option("--payload", o->payload, "Payload added to the vehicle mass [kg]")->check(CLI::Range(0.0, 1e4));
  cmd->add_option("--battery", o->battery,
                  "Battery configuration of the vehicle's pack, e.g. 2S2P (mass = extensions.hwang.airframe_mass_kg + packs)");
  cmd->add_option("--dt", o->dt, "Time step of the discharge [s]")->check(CLI::Range(1e-3, 600.0))->capture_default_str();
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    en::Vehicle v = en::loadVehicle(o->vehicle);
    if (!v.battery) throw std::runtime_error(o->vehicle + ": no 'battery' object: endurance needs one (data/README.md)");
    if (!o->battery.empty()) {
      const auto [s, p] = en::parseBatteryConfiguration(o->battery);
      v = en::withBatteryConfiguration(v, s, p);
    }
    const auto params = en::forwardFlightParameters(v, o->payload);
    const auto speeds = parseSpeedList(o->speed);
    nlohmann::json curve = nlohmann::json::array();
    double best_u = 0.0, best_t = -1.0;
    for (double u : speeds) {
      const auto s = en::forwardFlight(params, u);
      if (!params.efficiency.inTableRange(s.thrust_n)) {
        progress("warning: thrust " + std::to_string(s.thrust_n) + " N at " + std::to_string(u) +
                 " m/s is outside the efficiency table; eta held at the table's end value");
      }
      en::DischargeSettings ds;
      ds.dt_s = o->dt;
      ds.keep_series = false;
      const auto r = en::endurance(*v.battery, s.electrical_power_w, ds);
      curve.push_back(flightJson(s, r));
      if (r.endurance_s / 60.0 > best_t) best_t = r.endurance_s / 60.0, best_u = u;
    }
    if (speeds.size() > 1) std::tie(best_u, best_t) = refineBest(params, *v.battery, o->dt, speeds, best_u);
    nlohmann::json out = {{"vehicle", v.name}, {"mass_kg", params.mass_kg}, {"payload_kg", o->payload},
                          {"battery", std::to_string(v.battery->series) + "S" + std::to_string(v.battery->parallel) + "P"}};
    const std::vector<std::string> notes = enduranceNotes(params, v, speeds, best_u);
    if (speeds.size() == 1) {
      for (auto it = curve[0].begin(); it != curve[0].end(); ++it) out[it.key()] = it.value();
    } else {
      out["curve"] = curve;
      out["max_endurance_speed_mps"] = best_u;
      out["max_endurance_min"] = best_t;
      const auto [lo, hi] = std::minmax_element(speeds.begin(), speeds.end());
      out["max_endurance_at_range_end"] = best_u == *lo || best_u == *hi;
    }
    out["notes"] = notes;
    if (o->json) {
      printJson(out);
      return;
    }
    std::cout << "vehicle: " << v.name << " (" << params.mass_kg << " kg, battery " << out["battery"].get<std::string>()
              << ")\n"
              << "  U [m/s]  endurance [min]  power [W]  thrust [N]  U_i [m/s]  tilt [deg]  eta\n"
              << std::fixed;
    for (const auto& c : curve) {
      std::cout << std::setprecision(2) << std::setw(9) << c["speed_mps"].get<double>() << std::setw(17)
                << c["endurance_min"].get<double>() << std::setprecision(1) << std::setw(11) << c["power_w"].get<double>()
                << std::setw(12) << c["thrust_n"].get<double>() << std::setprecision(3) << std::setw(11)
                << c["induced_velocity_mps"].get<double>() << std::setprecision(2) << std::setw(12)
                << c["tilt_deg"].get<double>() << std::setprecision(3) << std::setw(7) << c["efficiency"].get<double>()
                << "\n";
    }
    if (speeds.size() > 1) std::cout << "max endurance " << best_t << " min at " << best_u << " m/s\n";
    for (const auto& n : notes) std::cout << "note: " << n << "\n";
  });
}

struct ModelColumn {
  std::string name, applies_to;
  en::EnergyModel model;
};

std::vector<ModelColumn> peerModels(const en::Vehicle& v) {
  std::vector<ModelColumn> out;
  out.push_back({"marins", "this vehicle (Marins et al. 2018 closed form)", en::marinsModel(v)});
  out.push_back({"hwang", "this vehicle (Hwang et al. 2018 Eq. 1-8; efficiency from extensions.hwang, else eta_mot*eta_prop / 2: Marins Eq. 4 is twice ideal momentum theory)",
                 en::hwangModel(v)});
  en::LiuParameters liu;
  liu.mass_kg = v.mass_kg;
  liu.gravity_mps2 = v.gravity_mps2;
  out.push_back({"liu", "this vehicle's weight with the IRIS+ fit of Liu et al. 2017 (k1, k2, c2, c4, c5)",
                 en::singleEffectModel(en::LiuEffect(liu))});
  out.push_back({"difranco", "3DR IRIS+ only (measured polynomial of Di Franco & Buttazzo)",
                 en::singleEffectModel(en::DiFrancoEffect())});
  out.push_back({"zeng", "published defaults of Zeng, Xu & Zhang 2019 (W 20 N, single rotor), not this vehicle",
                 en::singleEffectModel(en::ZengRotaryWingEffect())});
  return out;
}

void registerModels(CLI::App& app) {
  struct Opts {
    std::string vehicle, speed = "0:16:2";
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("models", "Level-flight power of every model (Marins, Hwang, Liu, Di Franco, Zeng) vs speed");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--speed", o->speed, "Speeds FROM:TO:STEP or one speed [m/s]")->capture_default_str();
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    const en::Vehicle v = en::loadVehicle(o->vehicle);
    const auto speeds = parseSpeedList(o->speed);
    const auto models = peerModels(v);
    nlohmann::json jm = nlohmann::json::array();
    for (const auto& m : models) {
      nlohmann::json p = nlohmann::json::array();
      for (double u : speeds) p.push_back(m.model.levelPower(u));
      jm.push_back({{"name", m.name}, {"applies_to", m.applies_to}, {"effects", m.model.effectNames()}, {"power_w", p}});
    }
    if (o->json) {
      printJson({{"vehicle", v.name}, {"speeds_mps", speeds}, {"models", jm}});
      return;
    }
    std::cout << "vehicle: " << v.name << "\nlevel-flight electrical power [W]\n  U [m/s]";
    for (const auto& m : models) std::cout << std::setw(11) << m.name;
    std::cout << "\n" << std::fixed;
    for (size_t i = 0; i < speeds.size(); ++i) {
      std::cout << std::setprecision(2) << std::setw(9) << speeds[i] << std::setprecision(1);
      for (const auto& m : jm) std::cout << std::setw(11) << m["power_w"][i].get<double>();
      std::cout << "\n";
    }
    for (const auto& m : models) std::cout << m.name << ": " << m.applies_to << "\n";
  });
}

}  // namespace

void registerEnduranceCommands(CLI::App& app) {
  registerEndurance(app);
  registerModels(app);
}

}  // namespace wattswath::apps
