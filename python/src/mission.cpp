// Python bindings of the mission library: mission files (.plan, .waypoints) and their prediction
// as the vehicle's autopilot flies them (energy, time, phases, items, battery, trajectory arrays).
#include "bindings.hpp"

#include <optional>
#include <utility>
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/mission/autopilot.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

namespace wattswath::python {
namespace {

namespace ms = mission;

py::dict totalsDict(const ms::Totals& t) {
  return py::dict(py::arg("energy_j") = t.energy_j, py::arg("time_s") = t.time_s, py::arg("distance_m") = t.distance_m);
}

py::dict batteryDict(const ms::BatteryPrediction& b) {
  if (!b.known) return py::dict(py::arg("known") = false);
  return py::dict(py::arg("known") = true, py::arg("usable_left_end") = b.usable_left_end,
                  py::arg("reserve_fraction") = b.reserve_fraction, py::arg("fits") = b.fits,
                  py::arg("depleted") = b.depleted, py::arg("depleted_at_s") = b.depleted_at_s,
                  py::arg("t_s") = toArray(b.t_s), py::arg("usable_left") = toArray(b.usable_left),
                  py::arg("voltage_v") = toArray(b.voltage_v), py::arg("energy_margin") = b.energy_margin,
                  py::arg("usable_left_end_with_margin") = b.usable_left_end_with_margin,
                  py::arg("fits_with_margin") = b.fits_with_margin, py::arg("verdict") = b.verdict);
}

py::list itemList(const std::vector<ms::ItemPrediction>& items) {
  py::list out;
  for (const auto& i : items)
    out.append(py::dict(py::arg("item") = i.item, py::arg("seq") = i.seq, py::arg("command") = i.command,
                        py::arg("reached_s") = i.reached_s, py::arg("completed_s") = i.completed_s,
                        py::arg("energy_j") = i.totals.energy_j, py::arg("time_s") = i.totals.time_s,
                        py::arg("distance_m") = i.totals.distance_m));
  return out;
}

py::dict trajectoryDict(const ms::FlownMission& f) {
  const auto& s = f.samples;
  std::vector<std::string> phase;
  for (const auto& x : s) phase.emplace_back(ms::toString(x.phase));
  py::dict d;
  d["t"] = arrayOf(s.size(), [&](std::size_t i) { return s[i].t; });
  d["position"] = rowsOf<3>(s.size(), [&](std::size_t i) { return s[i].position; });
  d["velocity"] = rowsOf<3>(s.size(), [&](std::size_t i) { return s[i].velocity; });
  d["step"] = arrayOf<int>(s.size(), [&](std::size_t i) { return s[i].step; });
  d["phase"] = phase;
  return d;
}

// Predicts `m` on vehicle `v` flown by the autopilot its file describes (ArduCopter 4.5 defaults without one).
// `wind` [m/s]: where the air moves to (east, north). `model` None: the vehicle's calibration
// (extensions.calibration: its model and its take-off delay, corner and speed-change behaviour and
// tracking error), as `wattswath predict` uses it without --effects.
py::dict predict(const ms::Mission& m, const energy::Vehicle& v, const py::object& model_or_none,
                 double reserve_fraction, double energy_margin, std::pair<double, double> wind) {
  const ms::AutopilotConfig ap = ms::parseAutopilot(v.autopilot_json, v.name);
  ms::PredictSettings s;
  s.reserve_fraction = reserve_fraction;
  s.energy_margin = energy_margin;
  s.wind = {wind.first, wind.second};
  std::optional<energy::EnergyModel> model;
  if (model_or_none.is_none()) {
    const auto cal = calibration::calibratedModel(v);
    if (!cal) {
      throw std::invalid_argument("predict_mission: model is None and vehicle " + v.name +
                                  " has no calibration (extensions.calibration): give a model (build_model) or a "
                                  "calibrated vehicle (calibrate_missions)");
    }
    model = cal->model;
    s.flight = calibration::calibratedFlight(*cal, s.flight);
  } else {
    model = model_or_none.cast<energy::EnergyModel>();
  }
  const ms::MissionPrediction p = ms::predictMission(m, v, *model, ap, s);
  py::dict phases;
  for (int i = 0; i < ms::kFlightPhaseCount; ++i)
    phases[ms::toString(static_cast<ms::FlightPhase>(i))] = totalsDict(p.phases[i]);
  py::dict d;
  d["energy_j"] = p.total.energy_j;
  d["time_s"] = p.total.time_s;
  d["distance_m"] = p.total.distance_m;
  d["autopilot"] = py::dict(py::arg("firmware") = ap.firmware, py::arg("version") = ap.version,
                            py::arg("model") = ms::toString(ap.family));
  d["phases"] = phases;
  d["items"] = itemList(p.items);
  d["breakdown"] = breakdownDict(p.breakdown);
  d["battery"] = batteryDict(p.battery);
  d["trajectory"] = trajectoryDict(p.flight);
  d["warnings"] = p.warnings;
  d["notes"] = p.flight.notes;
  return d;
}

ms::Mission readMission(const std::string& path, bool lenient) {
  ms::ReadOptions o;
  o.lenient = lenient;
  return ms::readMission(path, o);
}

}  // namespace

void bindMission(py::module_& m) {
  py::class_<ms::Mission>(m, "Mission", "A mission file: the planned home and its items in order.")
      .def_readonly("source", &ms::Mission::source, "File the mission was read from.")
      .def_readonly("format", &ms::Mission::format, "'plan' or 'waypoints'.")
      .def_readonly("warnings", &ms::Mission::warnings, "What was accepted leniently or ignored.")
      .def_property_readonly("home", [](const ms::Mission& x) {
            return py::make_tuple(x.home.lat_deg, x.home.lon_deg, x.home.alt_m);
          }, "Planned home (lat [deg], lon [deg], alt [m AMSL]).")
      .def_property_readonly("commands", [](const ms::Mission& x) {
            std::vector<std::string> out;
            for (const auto& i : x.items) out.push_back(ms::commandName(i.command));
            return out;
          }, "MAVLink command name of each item ('NAV_WAYPOINT', ...).")
      .def("__len__", [](const ms::Mission& x) { return x.items.size(); }, "Number of items (home excluded).")
      .def("__repr__", [](const ms::Mission& x) {
        return "<wattswath.Mission '" + x.source + "' (" + x.format + "), " + std::to_string(x.items.size()) + " items>";
      });
  m.def("read_mission", &readMission, py::arg("path"), py::arg("lenient") = false,
        "Reads a .plan (QGroundControl JSON) or .waypoints (QGC WPL 110) mission; lenient turns an unsupported "
        "command into a warning. RuntimeError names the item and field.");
  m.def("predict_mission", &predict, py::arg("mission"), py::arg("vehicle"), py::arg("model") = py::none(),
        py::arg("reserve_fraction") = 0.25, py::arg("energy_margin") = 0.10,
        py::arg("wind") = std::make_pair(0.0, 0.0),
        "Predicts the mission flown by the vehicle's autopilot model (its file's 'autopilot', else ArduCopter 4.5) "
        "from take-off command to landing: dict energy_j, time_s, distance_m, phases, items, breakdown, battery, "
        "trajectory {t [s], position N x 3 [m], velocity N x 3 [m/s], step, phase}, warnings. The battery verdict "
        "also checks energy_margin [-] more energy for the prediction's own error. wind (east, north) [m/s]: a steady "
        "wind, where the air moves to (ArduCopter models fly against the drag at air speed; the drag power is taken "
        "at air speed). model None: the vehicle's calibration (calibrate_missions, or a file `wattswath calibrate` "
        "wrote) with its take-off delay, corner and speed-change behaviour and tracking error, as `wattswath predict` "
        "uses it (its choice among disputed calibration values is the command line's only).");
}

}  // namespace wattswath::python
