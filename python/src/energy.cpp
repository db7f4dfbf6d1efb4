// Python bindings of the energy library: vehicles, effects and their coefficients, energy models
// built from effect names, the energy of a leg, the optimal cruise speed and the two turn strategies.
#include <cmath>
#include <optional>

#include "bindings.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/turns.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::python {
namespace {

namespace en = energy;

en::ProfileLimits limitsOf(const en::Vehicle& v) { return {v.max_acceleration_mps2, v.max_acceleration_mps2}; }

py::object batteryOf(const en::Vehicle& v) {
  if (!v.battery) return py::none();
  const en::Battery& b = *v.battery;
  return py::dict(py::arg("capacity_ah") = b.capacityAh(), py::arg("voltage_full_v") = b.voltageFull(),
                  py::arg("voltage_standard_v") = b.voltageStandard(), py::arg("mass_kg") = b.mass(),
                  py::arg("nominal_energy_j") = b.nominalEnergyJ(), py::arg("series") = b.series,
                  py::arg("parallel") = b.parallel);
}

// Sets coefficient `name` of effect `effect`, checking the coefficient's physical bounds.
void setCoefficient(en::EnergyModel& model, const std::string& effect, const std::string& name, double value) {
  en::Effect& e = model.effect(effect);  // std::out_of_range -> IndexError naming nothing: name it here
  std::vector<double> values;
  int found = -1;
  for (std::size_t i = 0; i < e.coefficients().size(); ++i) {
    const en::Coefficient& c = e.coefficients()[i];
    values.push_back(c.value);
    if (c.name != name) continue;
    found = static_cast<int>(i);
    if (!std::isfinite(value) || value < c.lower || value > c.upper)
      throw std::invalid_argument(effect + "." + name + " = " + std::to_string(value) + " " + c.unit +
                                  ": expected a finite value in [" + std::to_string(c.lower) + ", " +
                                  std::to_string(c.upper) + "] " + c.unit);
  }
  if (found < 0) {
    std::string known;
    for (const auto& c : e.coefficients()) known += (known.empty() ? "" : ", ") + c.name;
    throw std::invalid_argument("effect '" + effect + "' has no coefficient '" + name + "' (it has: " + known + ")");
  }
  values[static_cast<std::size_t>(found)] = value;
  e.setCoefficientValues(values);
}

const en::Effect& effectNamed(const en::EnergyModel& model, const std::string& name) {
  if (!model.has(name)) {
    std::string known;
    for (const auto& n : model.effectNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("the model has no effect '" + name + "' (it has: " + known + ")");
  }
  return model.effect(name);
}

py::list coefficientList(const en::EnergyModel& model) {
  py::list out;
  for (const auto& e : model.effects())
    for (const auto& c : e->coefficients())
      out.append(py::dict(py::arg("effect") = e->name(), py::arg("name") = c.name, py::arg("value") = c.value,
                          py::arg("unit") = c.unit, py::arg("lower") = c.lower, py::arg("upper") = c.upper,
                          py::arg("meaning") = c.meaning));
  return out;
}

py::dict coefficientValues(const en::EnergyModel& model) {
  py::dict out;
  for (const auto& e : model.effects()) {
    py::dict d;
    for (const auto& c : e->coefficients()) d[py::str(c.name)] = c.value;
    out[py::str(e->name())] = d;
  }
  return out;
}

en::MotionState stateOf(const Eigen::Vector3d& velocity, const Eigen::Vector3d& acceleration, double yaw_rate,
                        bool airborne) {
  en::MotionState s;
  s.velocity = velocity;
  s.acceleration = acceleration;
  s.yaw_rate = yaw_rate;
  s.heading = std::atan2(velocity.y(), velocity.x());
  s.airborne = airborne;
  return s;
}

void bindVehicle(py::module_& m) {
  py::class_<en::Vehicle>(m, "Vehicle", "A multirotor vehicle in SI units (data/vehicles/*.json, data/README.md).")
      .def_readonly("name", &en::Vehicle::name, "Human-readable name.")
      .def_readonly("mass_kg", &en::Vehicle::mass_kg, "Take-off mass [kg].")
      .def_readonly("rotor_count", &en::Vehicle::rotor_count, "Number of rotors [-].")
      .def_readonly("rotor_diameter_m", &en::Vehicle::rotor_diameter_m, "Propeller diameter [m].")
      .def_readonly("disk_area_m2", &en::Vehicle::disk_area_m2, "Total rotor disk area [m^2].")
      .def_readonly("motor_efficiency", &en::Vehicle::motor_efficiency, "Motor efficiency [-].")
      .def_readonly("propeller_efficiency", &en::Vehicle::propeller_efficiency, "Propeller efficiency [-].")
      .def_readonly("drag_area_m2", &en::Vehicle::drag_area_m2, "Drag area C_D A [m^2].")
      .def_readonly("max_acceleration_mps2", &en::Vehicle::max_acceleration_mps2, "Acceleration and braking [m/s^2].")
      .def_readonly("max_yaw_rate_radps", &en::Vehicle::max_yaw_rate_radps, "Maximum yaw rate [rad/s].")
      .def_readonly("max_speed_mps", &en::Vehicle::max_speed_mps, "Maximum horizontal speed [m/s].")
      .def_readonly("air_density_kgpm3", &en::Vehicle::air_density_kgpm3, "Air density [kg/m^3].")
      .def_readonly("gravity_mps2", &en::Vehicle::gravity_mps2, "Gravitational acceleration [m/s^2].")
      .def_property_readonly("battery", &batteryOf,
                             "The battery as a dict (capacity_ah, voltage_full_v, nominal_energy_j [J], ...) or None.")
      .def_property_readonly("total_efficiency", &en::Vehicle::totalEfficiency, "eta_mot * eta_prop [-].")
      .def_property_readonly("hover_power_w", &en::marinsHoverPowerW, "Electrical hover power (Marins Eq. 5) [W].")
      .def("to_json", &en::vehicleToJson, "The vehicle as JSON text (the schema load_vehicle reads).")
      .def("__repr__", [](const en::Vehicle& v) {
        return "<wattswath.Vehicle '" + v.name + "', " + std::to_string(v.mass_kg) + " kg>";
      });
  m.def("load_vehicle", &en::loadVehicle, py::arg("path"),
        "Reads and validates a vehicle JSON file; RuntimeError names the file and field.");
  m.def("parse_vehicle", &en::parseVehicle, py::arg("json_text"), py::arg("source") = "<string>",
        "Parses a vehicle from JSON text; `source` names it in error messages.");
}

void bindModel(py::module_& m) {
  py::class_<en::EnergyModel>(m, "EnergyModel", "A sum of physical effects, each with named coefficients.")
      .def_property_readonly("effect_names", &en::EnergyModel::effectNames, "Names of the effects, in order.")
      .def("has", &en::EnergyModel::has, py::arg("effect"), "Whether the model has the effect.")
      .def("remove", [](en::EnergyModel& mo, const std::string& n) { effectNamed(mo, n); mo.remove(n); },
           py::arg("effect"), "Removes an effect (ValueError when absent).")
      .def("meaning", [](const en::EnergyModel& mo, const std::string& n) { return effectNamed(mo, n).meaning(); },
           py::arg("effect"), "One sentence on what the effect is.")
      .def("coefficients", &coefficientValues, "{effect: {coefficient: value}} in each coefficient's SI unit.")
      .def("coefficient_info", &coefficientList,
           "Every coefficient as a dict: effect, name, value, unit, lower, upper, meaning.")
      .def("coefficient", [](const en::EnergyModel& mo, const std::string& e, const std::string& n) {
             return effectNamed(mo, e).coefficient(n);
           }, py::arg("effect"), py::arg("name"), "Value of one coefficient, in its unit.")
      .def("set_coefficient", [](en::EnergyModel& mo, const std::string& e, const std::string& n, double value) {
             effectNamed(mo, e);
             setCoefficient(mo, e, n, value);
           }, py::arg("effect"), py::arg("name"), py::arg("value"),
           "Sets one coefficient; ValueError when outside its physical bounds.")
      .def("power", [](const en::EnergyModel& mo, const Eigen::Vector3d& v, const Eigen::Vector3d& a, double yaw_rate,
                       bool airborne) { return mo.power(stateOf(v, a, yaw_rate, airborne)); },
           py::arg("velocity"), py::arg("acceleration") = Eigen::Vector3d::Zero().eval(), py::arg("yaw_rate") = 0.0,
           py::arg("airborne") = true,
           "Electrical power [W] at ENU velocity [m/s] and acceleration [m/s^2] (gravity removed), yaw rate [rad/s].")
      .def("level_power", &en::EnergyModel::levelPower, py::arg("speed"), py::arg("heading") = 0.0,
           "Steady level-flight power [W] at ground speed [m/s] and ENU heading [rad].")
      .def("with_candidate", [](const en::EnergyModel& mo, const std::string& n, const en::Vehicle& v) {
             return en::withCandidate(mo, n, v);
           }, py::arg("effect"), py::arg("vehicle"),
           "A copy with the candidate effect added, its coefficients from the vehicle (wind replaces drag).")
      .def("copy", [](const en::EnergyModel& mo) { return en::EnergyModel(mo); }, "A deep copy.")
      .def("__repr__", [](const en::EnergyModel& mo) {
        std::string s;
        for (const auto& n : mo.effectNames()) s += (s.empty() ? "" : ", ") + n;
        return "<wattswath.EnergyModel " + s + ">";
      });
  m.def("known_effects", &en::knownEffectNames, "Names of every effect build_model knows.");
  m.def("build_model", &en::buildModel, py::arg("vehicle"), py::arg("effects"),
        "An energy model of the named effects (e.g. ['hover', 'kinetic', 'parasitic_drag']), coefficients "
        "from the vehicle's physics; ValueError for an unknown name.");
  m.def("marins_model", [](const en::Vehicle& v, const std::string& drag) {
          if (drag != "exact" && drag != "paper")
            throw std::invalid_argument("drag = '" + drag + "': expected 'exact' or 'paper'");
          return en::marinsModel(v, drag == "exact" ? en::DragIntegration::Exact : en::DragIntegration::PaperCruiseSpeed);
        }, py::arg("vehicle"), py::arg("drag") = "exact",
        "Marins et al.'s model (hover, kinetic, parasitic drag, yaw); drag 'exact' or 'paper' (Eq. 9).");
}

py::dict legEnergy(const en::EnergyModel& model, const en::Vehicle& v, double distance, double speed, double v_in,
                   double v_out) {
  return breakdownDict(model.evaluate(en::buildLegProfile(distance, v_in, speed, v_out, limitsOf(v))));
}

py::dict optimalSpeed(const en::EnergyModel& model, const en::Vehicle& v, double distance, double v_in, double v_out,
                      std::optional<double> max_speed) {
  const auto o = en::optimalCruiseSpeed(model, distance, v_in, v_out, limitsOf(v), max_speed.value_or(v.max_speed_mps));
  return py::dict(py::arg("speed_mps") = o.speed, py::arg("energy_j") = o.energy, py::arg("time_s") = o.time,
                  py::arg("upper_bound_mps") = o.upper_bound, py::arg("at_upper_bound") = o.at_upper_bound,
                  py::arg("triangular") = o.triangular, py::arg("derivative_jspm") = o.derivative);
}

py::dict turns(const en::EnergyModel& model, const en::Vehicle& v, double distance, double beta) {
  const auto t = en::compareTurnStrategies(model, distance, beta, limitsOf(v), v.max_yaw_rate_radps, v.max_speed_mps);
  py::dict d;
  d["sharp_stop"] = py::dict(py::arg("energy_j") = t.sharp_stop.energy, py::arg("time_s") = t.sharp_stop.time,
                             py::arg("speed_mps") = t.sharp_stop.speed);
  d["rounded"] = py::dict(py::arg("energy_j") = t.rounded.energy, py::arg("time_s") = t.rounded.time,
                          py::arg("speed_mps") = t.rounded.speed, py::arg("radius_m") = t.rounded.radius);
  d["saving_pct"] = t.saving_pct;
  return d;
}

}  // namespace

void bindEnergy(py::module_& m) {
  bindVehicle(m);
  bindModel(m);
  m.def("leg_energy", &legEnergy, py::arg("model"), py::arg("vehicle"), py::arg("distance"), py::arg("speed"),
        py::arg("entry_speed") = 0.0, py::arg("exit_speed") = 0.0,
        "Energy of a straight leg of `distance` [m] cruising at `speed` [m/s] (accelerate / cruise / brake at the "
        "vehicle's acceleration): dict energy_j, time_s, length_m, by_effect, by_phase [J].");
  m.def("optimal_speed", &optimalSpeed, py::arg("model"), py::arg("vehicle"), py::arg("distance"),
        py::arg("entry_speed") = 0.0, py::arg("exit_speed") = 0.0, py::arg("max_speed") = py::none(),
        "The cruise speed minimising a leg's energy, at most max_speed (default the vehicle's) [m/s]: dict "
        "speed_mps, energy_j, time_s, at_upper_bound, triangular.");
  m.def("compare_turns", &turns, py::arg("model"), py::arg("vehicle"), py::arg("distance"), py::arg("angle"),
        "Two branches of `distance` [m] meeting at interior angle `angle` [rad]: stop and turn in place versus a "
        "rounded turn (Marins Sec. V-B): dict sharp_stop, rounded, saving_pct.");
}

}  // namespace wattswath::python
