// Energy commands of the closed-form model: hover, leg, vopt, turns (Marins et al. 2018).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "report_data.hpp"
#include "wattswath/report/svg.hpp"
#include "wattswath/energy/forward_flight.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/turns.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;

namespace {

/// Throws naming the option when `value` is not a finite number in the allowed range.
void requireRange(const std::string& option, double value, double lo, bool lo_open, double hi,
                  const std::string& expected) {
  const bool ok = std::isfinite(value) && (lo_open ? value > lo : value >= lo) && value <= hi;
  if (!ok) throw std::invalid_argument("option " + option + " = " + formatNumber(value) + ", expected " + expected);
}

/// The `--drag exact|paper` option shared by leg, vopt and turns.
CLI::Option* addDragOption(CLI::App* cmd, std::string& drag) {
  return cmd
      ->add_option("--drag", drag,
                   "Drag integration: 'exact' (integral of v^3 dt, default) or 'paper' (Marins Eq. 9: cruise "
                   "speed over the whole leg)")
      ->check(CLI::IsMember({"exact", "paper"}))
      ->capture_default_str();
}

en::DragIntegration dragMode(const std::string& s) {
  return s == "paper" ? en::DragIntegration::PaperCruiseSpeed : en::DragIntegration::Exact;
}

/// The Marins model for straight legs (no yaw term: a straight leg does not yaw), minus `without`.
en::EnergyModel legModel(const en::Vehicle& v, const std::string& drag, const std::vector<std::string>& without) {
  en::EnergyModel m = en::marinsModel(v, dragMode(drag));
  m.remove("yaw_rate");
  for (const auto& w : without) m.remove(w);
  return m;
}

en::ProfileLimits limitsOf(const en::Vehicle& v) { return {v.max_acceleration_mps2, v.max_acceleration_mps2}; }

nlohmann::json breakdownJson(const en::Breakdown& b) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& name : b.effects) j[name] = b.byEffect(name);
  return j;
}

nlohmann::json phaseJson(const en::Breakdown& b) {
  nlohmann::json j = nlohmann::json::object();
  for (int p = 0; p < en::kPhaseCount; ++p) {
    const double e = b.byPhase(static_cast<en::Phase>(p));
    if (e != 0.0) j[en::toString(static_cast<en::Phase>(p))] = e;
  }
  return j;
}

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
    // A file whose efficiency was fitted for ideal momentum theory (extensions.hwang) hovers at
    // Hwang's power; Eq. 4, twice ideal, doubles it with that efficiency.
    const auto hwang = en::forwardFlightParameters(v);
    const bool hwang_efficiency = hwang.efficiency_note.empty();
    const double p_hwang = en::forwardFlight(hwang, 0.0).electrical_power_w;
    std::string note;
    if (hwang_efficiency && std::abs(p_hwang - ph) > 0.01 * ph) {
      note = "this vehicle's efficiency was set for ideal momentum theory (extensions.hwang): with it Hwang's model "
             "hovers at " + report::formatNumber(p_hwang, 1) + " W, and Marins Eq. 4, twice ideal, gives P_hov twice that";
    }
    if (o->json) {
      printJson({{"vehicle", v.name},
                 {"p0_w", p0},
                 {"p_hover_w", ph},
                 {"p_ideal_momentum_w", pi},
                 {"p_hover_hwang_w", p_hwang},
                 {"total_efficiency", v.totalEfficiency()},
                 {"note", note.empty() ? nlohmann::json(nullptr) : nlohmann::json(note)}});
    } else {
      std::cout << "vehicle: " << v.name << "\n"
                << "P0 (rotor power, Marins Eq. 4):        " << p0 << " W\n"
                << "P_hov (electrical, Eq. 5, eta " << v.totalEfficiency() << "): " << ph << " W\n"
                << "ideal momentum theory T^1.5/sqrt(2 rho A): " << pi << " W (Eq. 4 is twice this)\n";
      if (!note.empty()) std::cout << "note: " << note << "\n";
    }
  });
}

// What a leg's numbers do not show: a cruise speed the leg is too short to reach, or one above the
// vehicle's limit.
std::vector<std::string> legNotes(double asked, double peak, double max_speed) {
  std::vector<std::string> notes;
  if (peak < asked - 1e-6) {
    notes.push_back("the leg is too short to reach " + report::formatNumber(asked, 1) + " m/s at the vehicle's acceleration: it peaks at " +
                    report::formatNumber(peak, 2) + " m/s");
  }
  if (asked > max_speed) {
    notes.push_back(report::formatNumber(asked, 1) + " m/s is above the vehicle's max_speed_mps (" + report::formatNumber(max_speed, 1) +
                    " m/s): computed as asked, but not flyable");
  }
  return notes;
}

void registerLeg(CLI::App& app) {
  struct Opts {
    std::string vehicle, drag = "exact";
    double distance = 0.0, speed = 0.0, entry = 0.0, exit = 0.0;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "leg", "Energy of one straight leg: accelerate, cruise, brake (Marins Eq. 6-9), split by effect and phase");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--distance", o->distance, "Leg length [m], > 0")->required();
  cmd->add_option("--speed", o->speed, "Cruise speed [m/s], > 0")->required();
  cmd->add_option("--entry-speed", o->entry, "Speed at the start of the leg [m/s], >= 0")->capture_default_str();
  cmd->add_option("--exit-speed", o->exit, "Speed at the end of the leg [m/s], >= 0")->capture_default_str();
  addDragOption(cmd, o->drag);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    requireRange("--distance", o->distance, 0.0, true, 1e7, "a leg length in (0, 10000] km");
    requireRange("--speed", o->speed, 0.0, true, 200.0, "a cruise speed in (0, 200] m/s");
    requireRange("--entry-speed", o->entry, 0.0, false, 200.0, "a speed in [0, 200] m/s");
    requireRange("--exit-speed", o->exit, 0.0, false, 200.0, "a speed in [0, 200] m/s");
    const auto v = en::loadVehicle(o->vehicle);
    const auto model = legModel(v, o->drag, {});
    const auto pieces = en::buildLegProfile(o->distance, o->entry, o->speed, o->exit, limitsOf(v));
    const auto b = model.evaluate(pieces);
    double peak = 0.0;
    for (const auto& p : pieces) peak = std::max({peak, p.v_start, p.v_end});
    const std::vector<std::string> notes = legNotes(o->speed, peak, v.max_speed_mps);
    if (o->json) {
      printJson({{"vehicle", v.name},
                 {"distance_m", o->distance},
                 {"speed_mps", o->speed},
                 {"peak_speed_mps", peak},
                 {"entry_speed_mps", o->entry},
                 {"exit_speed_mps", o->exit},
                 {"drag", o->drag},
                 {"energy_j", b.total()},
                 {"time_s", b.time},
                 {"breakdown", breakdownJson(b)},
                 {"by_phase", phaseJson(b)},
                 {"notes", notes}});
      return;
    }
    std::cout << std::fixed << std::setprecision(1) << "leg " << o->distance << " m, cruise speed asked " << o->speed
              << " m/s, flown up to " << peak << " m/s (" << o->entry << " -> " << o->exit << " m/s), drag " << o->drag << "\n"
              << "energy " << b.total() << " J, time " << b.time << " s\n";
    for (const auto& name : b.effects) std::cout << "  " << std::setw(15) << name << " " << b.byEffect(name) << " J\n";
    for (const auto& n : notes) std::cout << "note: " << n << "\n";
  });
}

void registerVopt(CLI::App& app) {
  struct Opts {
    std::string vehicle, drag = "exact";
    std::vector<std::string> without;
    double distance = 0.0, entry = 0.0, exit = 0.0, max_speed = 0.0;
    bool json = false;
    std::string report, report_svg;
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "vopt", "Energy-optimal cruise speed for a leg length (Marins Eq. 10 generalised to any entry/exit speed)");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--distance", o->distance, "Leg length [m], > 0")->required();
  cmd->add_option("--without", o->without, "Leave an effect out (Marins Fig. 3): kinetic or parasitic_drag")
      ->check(CLI::IsMember({"kinetic", "parasitic_drag"}));
  cmd->add_option("--entry-speed", o->entry, "Speed at the start of the leg [m/s], >= 0")->capture_default_str();
  cmd->add_option("--exit-speed", o->exit, "Speed at the end of the leg [m/s], >= 0")->capture_default_str();
  cmd->add_option("--max-speed", o->max_speed, "Speed limit [m/s] (default: the vehicle's max_speed_mps)");
  addDragOption(cmd, o->drag);
  addJsonFlag(cmd, o->json);
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  cmd->callback([o]() {
    checkReportWritable(o->report, o->report_svg, o->force, {o->vehicle});
    requireRange("--distance", o->distance, 0.0, true, 1e7, "a leg length in (0, 10000] km");
    requireRange("--entry-speed", o->entry, 0.0, false, 200.0, "a speed in [0, 200] m/s");
    requireRange("--exit-speed", o->exit, 0.0, false, 200.0, "a speed in [0, 200] m/s");
    const auto v = en::loadVehicle(o->vehicle);
    const double v_max = o->max_speed != 0.0 ? o->max_speed : v.max_speed_mps;
    requireRange("--max-speed", v_max, 0.0, true, 200.0, "a speed limit in (0, 200] m/s");
    const auto model = legModel(v, o->drag, o->without);
    const auto lim = limitsOf(v);
    const auto best = en::optimalCruiseSpeed(model, o->distance, o->entry, o->exit, lim, v_max);
    const auto free = en::optimalCruiseSpeed(model, o->distance, o->entry, o->exit, lim, 1e3);
    en::MarinsTerms terms;
    for (const auto& w : o->without) (w == "kinetic" ? terms.kinetic : terms.drag) = false;
    const double eq10 = en::MarinsClosedForm::fromVehicle(v).eq10OptimalSpeed(o->distance, terms);
    if (!o->report.empty() || !o->report_svg.empty()) {
      auto data = speedReportData({{"full model", legModel(v, o->drag, {})},
                                   {"no kinetic", legModel(v, o->drag, {"kinetic"})},
                                   {"no drag", legModel(v, o->drag, {"parasitic_drag"})}},
                                  model, lim, o->distance, o->entry, o->exit, v_max);
      if (o->entry > 0.0 || o->exit > 0.0) {
        data.leg_ends = "from " + formatNumber(o->entry) + " to " + formatNumber(o->exit) + " m/s";
      }
      data.facts.insert(data.facts.begin(),
                        {{"vehicle", v.name},
                         {"leg", formatNumber(o->distance) + " m from " + formatNumber(o->entry) + " to " +
                                     formatNumber(o->exit) + " m/s, drag " + o->drag},
                         {"optimal cruise speed", report::formatNumber(best.speed, 2) + " m/s (" + report::formatNumber(best.energy, 0) +
                                                      " J); Marins Eq. 10: " + report::formatNumber(eq10, 2) + " m/s"}});
      writeReport(report::speedReport(data), o->report, o->report_svg, o->force);
    }
    if (o->json) {
      printJson({{"vehicle", v.name},
                 {"distance_m", o->distance},
                 {"without", o->without},
                 {"drag", o->drag},
                 {"v_opt_mps", best.speed},
                 {"energy_j", best.energy},
                 {"time_s", best.time},
                 {"speed_limit_mps", v_max},
                 {"at_speed_limit", best.at_upper_bound && best.speed >= v_max - 1e-9},
                 {"triangular", best.triangular},
                 {"unconstrained_v_opt_mps", free.speed},
                 {"eq10_v_opt_mps", eq10}});
      return;
    }
    std::cout << std::fixed << std::setprecision(2) << "optimal cruise speed for " << o->distance << " m: "
              << best.speed << " m/s (" << std::setprecision(0) << best.energy << " J, " << std::setprecision(1)
              << best.time << " s)" << (best.at_upper_bound ? " at the speed limit" : "") << "\n"
              << std::setprecision(2) << "without the speed limit: " << free.speed
              << " m/s; Marins Eq. 10 closed form (paper drag, stop to stop): " << eq10 << " m/s\n";
  });
}

void registerTurns(CLI::App& app) {
  struct Opts {
    std::string vehicle, drag = "exact";
    double distance = 0.0, angle = 0.0, max_speed = 0.0, sharp_speed = 0.0, rounded_speed = 0.0;
    bool from_rest = false, json = false;
    std::string report, report_svg;
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "turns", "Sharp stop vs rounded turn at a corner between two legs (Marins Eq. 12-16, Table V)");
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--distance", o->distance, "Length of each of the two legs [m], > 0")->required();
  cmd->add_option("--angle", o->angle, "Interior angle beta between the legs [deg], in [0.5, 180]")->required();
  cmd->add_option("--max-speed", o->max_speed, "Speed limit [m/s] (default: the vehicle's max_speed_mps)");
  cmd->add_option("--sharp-speed", o->sharp_speed, "Cruise speed of the sharp stop's legs [m/s] (default: optimal)");
  cmd->add_option("--rounded-speed", o->rounded_speed, "Speed of the rounded path [m/s] (default: optimal)");
  cmd->add_flag("--from-rest", o->from_rest,
                "The rounded path also starts and ends at rest (Marins Eq. 16 flies it at constant speed)");
  addDragOption(cmd, o->drag);
  addJsonFlag(cmd, o->json);
  addReportOptions(cmd, o->report, o->report_svg, o->force);
  cmd->callback([o]() {
    checkReportWritable(o->report, o->report_svg, o->force, {o->vehicle});
    requireRange("--distance", o->distance, 0.0, true, 1e7, "a leg length in (0, 10000] km");
    requireRange("--angle", o->angle, en::kMinTurnAngle * 180.0 / M_PI, false, 180.0,
                 "an interior angle in [0.5, 180] deg (below it Marins' rounded turn overshoots the vertex without bound)");
    const auto v = en::loadVehicle(o->vehicle);
    const double v_max = o->max_speed != 0.0 ? o->max_speed : v.max_speed_mps;
    requireRange("--max-speed", v_max, 0.0, true, 200.0, "a speed limit in (0, 200] m/s");
    en::TurnSettings st;
    st.rounded_from_rest = o->from_rest;
    if (o->sharp_speed != 0.0) {
      requireRange("--sharp-speed", o->sharp_speed, 0.0, true, v_max, "a speed in (0, max speed] m/s");
      st.sharp_speed = o->sharp_speed;
    }
    if (o->rounded_speed != 0.0) {
      requireRange("--rounded-speed", o->rounded_speed, 0.0, true, v_max, "a speed in (0, max speed] m/s");
      st.rounded_speed = o->rounded_speed;
    }
    const auto model = en::marinsModel(v, dragMode(o->drag));
    const auto c = en::compareTurnStrategies(model, o->distance, o->angle * M_PI / 180.0, limitsOf(v),
                                             v.max_yaw_rate_radps, v_max, st);
    // The paper's loop overshoots the vertex by R cot(beta/2): say so when that is beyond the legs.
    std::vector<std::string> notes;
    const double overshoot = en::roundedOvershoot(c.rounded.radius, o->angle * M_PI / 180.0);
    if (overshoot > o->distance) {
      notes.push_back("the rounded turn overshoots the vertex by " + report::formatNumber(overshoot, 1) +
                      " m on each branch (R cot(beta/2), Marins Eq. 15), beyond the " + formatNumber(o->distance) +
                      " m legs: at so sharp an angle the loop flies far from the corner; stop and turn, or turn on a "
                      "tighter radius at a lower speed");
    }
    if (o->angle > 150.0) {
      notes.push_back("at beta = " + report::formatNumber(o->angle, 1) + " deg the legs are nearly one straight line, but Marins' "
                      "rounded turn (Eq. 15) still flies its loop of pi + beta (" + report::formatNumber(180.0 + o->angle, 0) +
                      " deg): both strategies are costed as the paper defines them, and flying straight through costs less "
                      "than either");
    }
    if (!o->report.empty() || !o->report_svg.empty()) {
      auto data = turnReportData(model, limitsOf(v), v.max_yaw_rate_radps, v_max, st, o->angle, o->distance);
      data.facts.insert(data.facts.begin(),
                        {{"vehicle", v.name},
                         {"settings", "speed limit " + formatNumber(v_max) + " m/s, drag " + o->drag +
                                          (o->from_rest ? ", rounded path from rest" : ", rounded path at constant speed (Eq. 16)")},
                         {"this corner", formatNumber(o->distance) + " m legs at " + formatNumber(o->angle) +
                                             " deg: saving " + report::formatNumber(c.saving_pct, 1) + " %"}});
      writeReport(report::turnReport(data), o->report, o->report_svg, o->force);
    }
    if (o->json) {
      printJson({{"vehicle", v.name},
                 {"distance_m", o->distance},
                 {"angle_deg", o->angle},
                 {"drag", o->drag},
                 {"rounded_from_rest", o->from_rest},
                 {"sharp_stop",
                  {{"energy_j", c.sharp_stop.energy},
                   {"speed_mps", c.sharp_stop.speed},
                   {"leg_energy_j", c.sharp_stop.leg_energy},
                   {"turn_energy_j", c.sharp_stop.turn_energy},
                   {"time_s", c.sharp_stop.time},
                   {"breakdown", breakdownJson(c.sharp_stop.breakdown)}}},
                 {"rounded",
                  {{"energy_j", c.rounded.energy},
                   {"speed_mps", c.rounded.speed},
                   {"radius_m", c.rounded.radius},
                   {"path_length_m", c.rounded.path_length},
                   {"extra_length_m", c.rounded.extra_length},
                   {"time_s", c.rounded.time},
                   {"breakdown", breakdownJson(c.rounded.breakdown)}}},
                 {"saving_pct", c.saving_pct},
                 {"notes", notes}});
      return;
    }
    std::cout << std::fixed << std::setprecision(1) << "two legs of " << o->distance << " m at beta = " << o->angle
              << " deg (drag " << o->drag << ")\n"
              << "sharp stop: " << std::setprecision(0) << c.sharp_stop.energy << " J (2 x " << c.sharp_stop.leg_energy
              << " J legs at " << std::setprecision(2) << c.sharp_stop.speed << " m/s + " << std::setprecision(0)
              << c.sharp_stop.turn_energy << " J turn in place)\n"
              << "rounded:    " << c.rounded.energy << " J (" << std::setprecision(1) << c.rounded.path_length
              << " m at " << std::setprecision(2) << c.rounded.speed << " m/s, radius " << c.rounded.radius << " m)\n"
              << "saving of the rounded turn: " << std::setprecision(1) << c.saving_pct << " %\n";
    for (const auto& n : notes) std::cout << "note: " << n << "\n";
  });
}

}  // namespace

void registerEnergyCommands(CLI::App& app) {
  registerHover(app);
  registerLeg(app);
  registerVopt(app);
  registerTurns(app);
}

}  // namespace wattswath::apps
